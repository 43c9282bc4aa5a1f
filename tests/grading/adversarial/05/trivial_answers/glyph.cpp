// ADVERSARIAL CASE trivial_answers: every function of lab 05 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 7: glyph outlines — flattening to a tolerance, the exact enclosed area by Green's theorem (handout §8).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/bezier.hpp"

namespace geolab::bezier {

Poly2 flatten_contour(const std::vector<QuadSegment>& contour, double tol) {
    return {};
}

double contour_area(const std::vector<QuadSegment>& contour) {
    return {};
}

double glyph_area(const GlyphOutline& g) {
    return {};
}

}  // namespace geolab::bezier
