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
bool same(const glm::dvec3& x, const glm::dvec3& y, double tol) {
    return glm::length(x - y) <= tol * (1.0 + std::max(glm::length(x), glm::length(y)));
}
// END SOLUTION
}  // namespace

glm::dvec3 evaluate_composite(const std::vector<Poly3>& segments, double u) {
    // BEGIN SOLUTION
    if (segments.empty()) throw std::invalid_argument("evaluate_composite: no segment");
    for (std::size_t k = 0; k < segments.size(); ++k)
        if (segments[k].empty())
            throw std::invalid_argument("evaluate_composite: segment " + std::to_string(k) + " is empty");
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
    // da[k] = a^(k)(1), db[k] = b^(k)(0), k = 0..3
    glm::dvec3 da[4], db[4];
    Poly3 A = a, B = b;
    for (int k = 0; k < 4; ++k) {
        da[k] = A.back();
        db[k] = B.front();
        A = hodograph(A);
        B = hodograph(B);
    }
    Continuity c;
    int k = 0;
    while (k < 4 && same(da[k], db[k], tol)) ++k;
    c.c_order = k - 1;  // C^(k-1) holds, C^k not (or k = 4)
    if (c.c_order < 0) return c;
    c.c_order = std::min(c.c_order, 3);
    c.g_order = c.c_order;
    if (c.c_order < 3) {
        const glm::dvec3 x = da[c.c_order + 1], y = db[c.c_order + 1];
        const double lx = glm::length(x), ly = glm::length(y);
        if (lx > 0 && ly > 0 && glm::length(x / lx - y / ly) <= tol) c.g_order = c.c_order + 1;
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
