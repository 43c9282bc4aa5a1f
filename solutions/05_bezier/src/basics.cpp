// Task 1: basics — Bernstein polynomials, de Casteljau, the Bernstein form (handout §2).
#include <cmath>
#include <stdexcept>

#include "geolab/bezier.hpp"

namespace geolab::bezier {

double bernstein(int n, int i, double t) {
    // BEGIN SOLUTION
    if (n < 0) throw std::invalid_argument("bernstein: negative degree n = " + std::to_string(n));
    if (i < 0 || i > n) return 0.0;
    double c = 1.0;  // C(n, i), built as a product of exact-as-possible ratios
    for (int k = 1; k <= i; ++k) c = c * double(n - i + k) / double(k);
    return c * std::pow(t, i) * std::pow(1.0 - t, n - i);
    // END SOLUTION
}

glm::dvec2 de_casteljau(const Poly2& P, double t) {
    // BEGIN SOLUTION
    if (P.empty()) throw std::invalid_argument("de_casteljau: no control points");
    // In place from the back: after round r, b[k] = P_(k−r)^r for k = r..n; b[n] ends as P_0^n.
    Poly2 b = P;
    const std::size_t n = P.size() - 1;
    for (std::size_t r = 1; r <= n; ++r)
        for (std::size_t k = n; k >= r; --k) b[k] = (1.0 - t) * b[k - 1] + t * b[k];
    return b[n];
    // END SOLUTION
}

glm::dvec3 de_casteljau(const Poly3& P, double t) {
    // BEGIN SOLUTION
    if (P.empty()) throw std::invalid_argument("de_casteljau: no control points");
    // In place from the back: after round r, b[k] = P_(k−r)^r for k = r..n; b[n] ends as P_0^n.
    Poly3 b = P;
    const std::size_t n = P.size() - 1;
    for (std::size_t r = 1; r <= n; ++r)
        for (std::size_t k = n; k >= r; --k) b[k] = (1.0 - t) * b[k - 1] + t * b[k];
    return b[n];
    // END SOLUTION
}

std::vector<Poly3> de_casteljau_triangle(const Poly3& P, double t) {
    // BEGIN SOLUTION
    if (P.empty()) throw std::invalid_argument("de_casteljau_triangle: no control points");
    std::vector<Poly3> rows{P};
    for (std::size_t r = 1; r < P.size(); ++r) {
        const Poly3& prev = rows.back();
        Poly3 row(prev.size() - 1);
        for (std::size_t k = 0; k < row.size(); ++k) row[k] = (1.0 - t) * prev[k] + t * prev[k + 1];
        rows.push_back(std::move(row));
    }
    return rows;
    // END SOLUTION
}

glm::dvec2 evaluate_bernstein(const Poly2& P, double t) {
    // BEGIN SOLUTION
    if (P.empty()) throw std::invalid_argument("evaluate_bernstein: no control points");
    const int n = int(P.size()) - 1;
    glm::dvec2 c(0.0);
    for (int k = 0; k <= n; ++k) c += bernstein(n, k, t) * P[k];
    return c;
    // END SOLUTION
}

glm::dvec3 evaluate_bernstein(const Poly3& P, double t) {
    // BEGIN SOLUTION
    if (P.empty()) throw std::invalid_argument("evaluate_bernstein: no control points");
    const int n = int(P.size()) - 1;
    glm::dvec3 c(0.0);
    for (int k = 0; k <= n; ++k) c += bernstein(n, k, t) * P[k];
    return c;
    // END SOLUTION
}

}  // namespace geolab::bezier
