// Task 7: glyph outlines — flattening to a tolerance, the exact enclosed area by Green's theorem (handout §8).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/bezier.hpp"

namespace geolab::bezier {

Poly2 flatten_contour(const std::vector<QuadSegment>& contour, double tol) {
    throw geolab::NotImplemented(__func__);
}

double contour_area(const std::vector<QuadSegment>& contour) {
    throw geolab::NotImplemented(__func__);
}

double glyph_area(const GlyphOutline& g) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::bezier
