// ADVERSARIAL CASE always_throws: every function of lab 05 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 7: glyph outlines — flattening to a tolerance, the exact enclosed area by Green's theorem (handout §8).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/bezier.hpp"

namespace geolab::bezier {

Poly2 flatten_contour(const std::vector<QuadSegment>& contour, double tol) {
    throw std::invalid_argument(__func__);
}

double contour_area(const std::vector<QuadSegment>& contour) {
    throw std::invalid_argument(__func__);
}

double glyph_area(const GlyphOutline& g) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::bezier
