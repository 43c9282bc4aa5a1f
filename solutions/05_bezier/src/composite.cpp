// Task 4: composite curves — evaluation, continuity classes at a joint, C¹ and G¹ joins (handout §5).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/bezier.hpp"

namespace geolab::bezier {

namespace {
// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.
// x and y equal within tol · (1 + the larger length).
bool same(const glm::dvec3& x, const glm::dvec3& y, double tol) {
    return glm::length(x - y) <= tol * (1.0 + std::max(glm::length(x), glm::length(y)));
}
// x and y non-zero with unit vectors equal within tol (a zero vector gives 0/0 = NaN: never parallel).
bool parallel(const glm::dvec3& x, const glm::dvec3& y, double tol) {
    return glm::length(x / glm::length(x) - y / glm::length(y)) <= tol;
}
// END SOLUTION
}  // namespace

glm::dvec3 evaluate_composite(const std::vector<Poly3>& segments, double u) {
    // BEGIN SOLUTION
    if (segments.empty()) throw std::invalid_argument("evaluate_composite: no segment");
    const auto empty = std::find_if(segments.begin(), segments.end(), [](const Poly3& s) { return s.empty(); });
    if (empty != segments.end())
        throw std::invalid_argument("evaluate_composite: segment " + std::to_string(empty - segments.begin()) +
                                    " is empty");
    const double m = double(segments.size());
    if (!(u >= 0 && u <= m))
        throw std::invalid_argument("evaluate_composite: u = " + std::to_string(u) + " is outside [0, " +
                                    std::to_string(segments.size()) + "]");
    const std::size_t k = std::min(std::size_t(std::floor(u)), segments.size() - 1);
    return de_casteljau(segments[k], u - double(k));
    // END SOLUTION
}

Continuity continuity(const Poly3& a, const Poly3& b, double tol) {
    // BEGIN SOLUTION
    if (a.empty() || b.empty()) throw std::invalid_argument("continuity: a curve without control points");
    if (!(tol >= 0)) throw std::invalid_argument("continuity: tol must be >= 0");
    // Order k = 0..3: A = a^(k), B = b^(k) as Bézier curves; compare a^(k)(1) = A's last point with b^(k)(0).
    Continuity c;
    Poly3 A = a, B = b;
    for (int k = 0; k <= 3; ++k) {
        if (!same(A.back(), B.front(), tol)) {
            if (k > 0 && parallel(A.back(), B.front(), tol)) c.g_order = k;  // G^k = C^(k−1) + parallel k-th
            break;
        }
        c.c_order = c.g_order = k;
        A = hodograph(A);
        B = hodograph(B);
    }
    return c;
    // END SOLUTION
}

Poly3 join_c1(const Poly3& a, const Poly3& b) {
    // BEGIN SOLUTION
    if (a.size() < 2 || b.size() < 2) throw std::invalid_argument("join_c1: both curves need degree >= 1");
    const double n = double(a.size() - 1), m = double(b.size() - 1);
    Poly3 r = b;
    r[0] = a.back();
    r[1] = a.back() + (n / m) * (a.back() - a[a.size() - 2]);
    return r;
    // END SOLUTION
}

Poly3 join_g1(const Poly3& a, const Poly3& b) {
    // BEGIN SOLUTION
    if (a.size() < 2 || b.size() < 2) throw std::invalid_argument("join_g1: both curves need degree >= 1");
    const glm::dvec3 dir = a.back() - a[a.size() - 2];
    const double len = glm::length(b[1] - b[0]);
    if (glm::length(dir) == 0) throw std::invalid_argument("join_g1: a's last leg has zero length (no direction)");
    if (len == 0) throw std::invalid_argument("join_g1: b's first leg has zero length");
    Poly3 r = b;
    r[0] = a.back();
    r[1] = a.back() + len * glm::normalize(dir);
    return r;
    // END SOLUTION
}

}  // namespace geolab::bezier
