// Task 7: glyph outlines — flattening to a tolerance, the exact enclosed area by Green's theorem (handout §8).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/bezier.hpp"

namespace geolab::bezier {

Poly2 flatten_contour(const std::vector<QuadSegment>& contour, double tol) {
    // BEGIN SOLUTION
    if (!(tol > 0)) throw std::invalid_argument("flatten_contour: tol must be > 0");
    if (contour.empty()) throw std::invalid_argument("flatten_contour: empty contour");
    Poly2 out;
    for (const auto& s : contour) {
        const double dd = glm::length(s[0] - 2.0 * s[1] + s[2]);
        const int m = std::max(1, int(std::ceil(std::sqrt(dd / (4 * tol)))));
        const Poly2 P{s[0], s[1], s[2]};
        for (int k = 0; k < m; ++k) out.push_back(de_casteljau(P, double(k) / m));  // C(0) = P_0 exactly
    }
    return out;
    // END SOLUTION
}

double contour_area(const std::vector<QuadSegment>& contour) {
    // BEGIN SOLUTION
    if (contour.empty()) throw std::invalid_argument("contour_area: empty contour");
    // ∫ C × C' dt over a quadratic = (2 P0×P1 + 2 P1×P2 + P0×P2) / 3; the area is half the sum.
    auto cross = [](const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; };
    double twice6 = 0;  // 6 × (twice the area) accumulated, divided once at the end
    for (const auto& s : contour) twice6 += 2 * cross(s[0], s[1]) + 2 * cross(s[1], s[2]) + cross(s[0], s[2]);
    return twice6 / 6.0;
    // END SOLUTION
}

double glyph_area(const GlyphOutline& g) {
    // BEGIN SOLUTION
    double a = 0;
    for (const auto& c : g.contours) a += contour_area(c);
    return std::abs(a);
    // END SOLUTION
}

}  // namespace geolab::bezier
