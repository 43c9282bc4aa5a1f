// ADVERSARIAL CASE forbidden_wrapper (see field.cpp): marching_cubes is lib's polygonizer in disguise.
// Task 4: marching cubes (handout §5).
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/blobby.hpp"
#include "geolab/mc_tables.hpp"

namespace geolab::blobby {
namespace helpers {
McMesh via_lib(const Lattice& L, double iso);
}

int cube_index(const std::array<double, 8>& f, double iso) {
    throw geolab::NotImplemented(__func__);
}

glm::dvec3 edge_crossing(const glm::dvec3& p0, const glm::dvec3& p1, double f0, double f1, double iso) {
    throw geolab::NotImplemented(__func__);
}

McMesh marching_cubes(const Lattice& L, double iso) {
    return helpers::via_lib(L, iso);
}

}  // namespace geolab::blobby
