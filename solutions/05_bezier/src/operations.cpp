// Task 2: operations — subdivision, restriction, hodograph, elevation, curvature and torsion (handout §3).
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/bezier.hpp"

namespace geolab::bezier {

Split subdivide(const Poly3& P, double t) {
    // BEGIN SOLUTION
    if (P.empty()) throw std::invalid_argument("subdivide: no control points");
    if (!std::isfinite(t)) throw std::invalid_argument("subdivide: t is not finite");
    const std::size_t n = P.size() - 1;
    Split s;
    s.left.resize(n + 1);
    s.right.resize(n + 1);
    Poly3 b = P;
    s.left[0] = b[0];
    s.right[n] = b[n];
    for (std::size_t r = 1; r <= n; ++r) {
        for (std::size_t k = 0; k + r <= n; ++k) b[k] = (1.0 - t) * b[k] + t * b[k + 1];
        s.left[r] = b[0];
        s.right[n - r] = b[n - r];
    }
    return s;
    // END SOLUTION
}

Poly3 restrict_to(const Poly3& P, double a, double b) {
    // BEGIN SOLUTION
    if (P.empty()) throw std::invalid_argument("restrict_to: no control points");
    if (!std::isfinite(a) || !std::isfinite(b)) throw std::invalid_argument("restrict_to: a or b is not finite");
    if (a == b) throw std::invalid_argument("restrict_to: a == b (an empty interval)");
    // C on [a, 1] is the right half at a; [a, b] is the left half of that at (b − a)/(1 − a) (a negative
    // parameter extrapolates backwards: a > b reverses the direction). For a = 1 restrict the reversed curve.
    if (a == 1.0) return restrict_to(Poly3(P.rbegin(), P.rend()), 0.0, 1.0 - b);
    const Poly3 right = subdivide(P, a).right;
    return subdivide(right, (b - a) / (1.0 - a)).left;
    // END SOLUTION
}

Poly3 hodograph(const Poly3& P) {
    // BEGIN SOLUTION
    if (P.empty()) throw std::invalid_argument("hodograph: no control points");
    if (P.size() == 1) return Poly3{glm::dvec3(0.0)};
    const double n = double(P.size() - 1);
    Poly3 d(P.size() - 1);
    for (std::size_t k = 0; k < d.size(); ++k) d[k] = n * (P[k + 1] - P[k]);
    return d;
    // END SOLUTION
}

glm::dvec3 derivative(const Poly3& P, double t) {
    // BEGIN SOLUTION
    return de_casteljau(hodograph(P), t);
    // END SOLUTION
}

glm::dvec3 second_derivative(const Poly3& P, double t) {
    // BEGIN SOLUTION
    return de_casteljau(hodograph(hodograph(P)), t);
    // END SOLUTION
}

Poly3 elevate(const Poly3& P) {
    // BEGIN SOLUTION
    if (P.empty()) throw std::invalid_argument("elevate: no control points");
    // P_k goes into Q_k with weight 1 − k/(n+1) and into Q_(k+1) with weight (k+1)/(n+1): the ends get P_0 and
    // P_n alone, every inner Q_k its two terms of the formula.
    const std::size_t n = P.size() - 1;
    Poly3 Q(n + 2, glm::dvec3(0.0));
    for (std::size_t k = 0; k <= n; ++k) {
        Q[k] += (1.0 - double(k) / double(n + 1)) * P[k];
        Q[k + 1] += (double(k + 1) / double(n + 1)) * P[k];
    }
    return Q;
    // END SOLUTION
}

double curvature(const Poly3& P, double t) {
    // BEGIN SOLUTION
    const glm::dvec3 d1 = derivative(P, t), d2 = second_derivative(P, t);
    const double s = glm::length(d1);
    if (s == 0) return 0.0;
    return glm::length(glm::cross(d1, d2)) / (s * s * s);
    // END SOLUTION
}

double torsion(const Poly3& P, double t) {
    // BEGIN SOLUTION
    const glm::dvec3 d1 = derivative(P, t), d2 = second_derivative(P, t);
    const glm::dvec3 d3 = de_casteljau(hodograph(hodograph(hodograph(P))), t);
    const glm::dvec3 c = glm::cross(d1, d2);
    const double c2 = glm::dot(c, c);
    if (c2 == 0) return 0.0;
    return glm::dot(c, d3) / c2;
    // END SOLUTION
}

double signed_curvature(const Poly2& P, double t) {
    // BEGIN SOLUTION
    if (P.empty()) throw std::invalid_argument("signed_curvature: no control points");
    Poly3 P3;
    for (const auto& p : P) P3.emplace_back(p, 0.0);
    const glm::dvec3 d1 = derivative(P3, t), d2 = second_derivative(P3, t);
    const double s = glm::length(d1);
    if (s == 0) return 0.0;
    return (d1.x * d2.y - d1.y * d2.x) / (s * s * s);
    // END SOLUTION
}

}  // namespace geolab::bezier
