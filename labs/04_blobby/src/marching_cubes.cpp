// Task 4: marching cubes (handout §5).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include "geolab/blobby.hpp"
#include "geolab/mc_tables.hpp"

namespace geolab::blobby {

namespace {
// Helper functions of your own can go here.
}  // namespace

int cube_index(const std::array<double, 8>& f, double iso) {
    throw geolab::NotImplemented(__func__);
}

glm::dvec3 edge_crossing(const glm::dvec3& p0, const glm::dvec3& p1, double f0, double f1, double iso) {
    throw geolab::NotImplemented(__func__);
}

McMesh marching_cubes(const Lattice& lattice, double iso) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::blobby
