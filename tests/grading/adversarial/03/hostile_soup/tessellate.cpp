// ADVERSARIAL CASE hostile_soup: the tessellations answer a soup whose last face claims 2^28 indices, the renderer
// an image of w x h pixels with 4 bytes. Code in the judge that walks the answer
// (PolygonSoup::face() spans indices[offsets[f]..offsets[f+1]); render::Image::pixel() reads rgba at 4·(y·w + x))
// would read memory outside it: the judge refuses such an answer as malformed. Honest: 0.
// Task 6: tessellation (handout §8).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {
namespace {
// Helper functions of your own can go here.
}  // namespace

PolygonSoup tessellate_superquadric(const Superquadric& s, int n_eta, int n_omega) {
    // 3 positions, one honest triangle, then a face whose span runs 2^28 indices past the end
    PolygonSoup hostile;
    hostile.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    hostile.indices = {0, 1, 2};
    hostile.offsets = {0, 3, 1u << 28};
    return hostile;
}

PolygonSoup tessellate_ellipsoid(const glm::dmat4& Q, int n_eta, int n_omega) {
    // 3 positions, one honest triangle, then a face whose span runs 2^28 indices past the end
    PolygonSoup hostile;
    hostile.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    hostile.indices = {0, 1, 2};
    hostile.offsets = {0, 3, 1u << 28};
    return hostile;
}

}  // namespace geolab::quadrics
