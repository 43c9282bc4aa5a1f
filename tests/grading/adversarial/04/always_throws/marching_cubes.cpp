// ADVERSARIAL CASE always_throws: every function of lab 04 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 4: marching cubes (handout §5).
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/blobby.hpp"
#include "geolab/mc_tables.hpp"

namespace geolab::blobby {

int cube_index(const std::array<double, 8>& f, double iso) {
    throw std::invalid_argument(__func__);
}

glm::dvec3 edge_crossing(const glm::dvec3& p0, const glm::dvec3& p1, double f0, double f1, double iso) {
    throw std::invalid_argument(__func__);
}

McMesh marching_cubes(const Lattice& L, double iso) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::blobby
