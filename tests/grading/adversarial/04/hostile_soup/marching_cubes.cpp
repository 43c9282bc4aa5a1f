// ADVERSARIAL CASE hostile_soup: marching_cubes answers a mesh whose last face claims 2^28 indices. Code in the
// judge that walks the answer
// (PolygonSoup::face() spans indices[offsets[f]..offsets[f+1]); render::Image::pixel() reads rgba at 4·(y·w + x))
// would read memory outside it: the judge refuses such an answer as malformed. Honest: 0.
// Task 4: marching cubes (handout §5).
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/blobby.hpp"
#include "geolab/mc_tables.hpp"

namespace geolab::blobby {

int cube_index(const std::array<double, 8>& f, double iso) {
    throw geolab::NotImplemented(__func__);
}

glm::dvec3 edge_crossing(const glm::dvec3& p0, const glm::dvec3& p1, double f0, double f1, double iso) {
    throw geolab::NotImplemented(__func__);
}

McMesh marching_cubes(const Lattice& L, double iso) {
    McMesh m;
    m.soup.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.soup.indices = {0, 1, 2};
    m.soup.offsets = {0, 3, 1u << 28};  // the last face's span runs 2^28 indices past the end
    m.normals.assign(3, glm::dvec3(0, 0, 1));
    return m;
}

}  // namespace geolab::blobby
