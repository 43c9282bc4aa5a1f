// ADVERSARIAL CASE hostile_soup: mesh_tree answers a soup whose last face claims 2^28 indices, render_image an image
// of w x h pixels with 4 bytes. Code in the judge that walks the answer
// (PolygonSoup::face() spans indices[offsets[f]..offsets[f+1]); render::Image::pixel() reads rgba at 4·(y·w + x))
// would read memory outside it: the judge refuses such an answer as malformed. Honest: 0.
// Task 7: meshes of CSG trees and their volumes (handout §8).
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/csg.hpp"
#include "geolab/polygonize.hpp"

namespace geolab::csg {

// Helper functions of your own can go here.

PolygonSoup mesh_tree(const Tree& t, int resolution) {
    // 3 positions, one honest triangle, then a face whose span runs 2^28 indices past the end
    PolygonSoup hostile;
    hostile.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    hostile.indices = {0, 1, 2};
    hostile.offsets = {0, 3, 1u << 28};
    return hostile;
}

double volume(const PolygonSoup& mesh) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::csg
