// ADVERSARIAL CASE trivial_answers: every function of lab 04 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 4: marching cubes (handout §5).
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/blobby.hpp"
#include "geolab/mc_tables.hpp"

namespace geolab::blobby {

int cube_index(const std::array<double, 8>& f, double iso) {
    return {};
}

glm::dvec3 edge_crossing(const glm::dvec3& p0, const glm::dvec3& p1, double f0, double f1, double iso) {
    return {};
}

McMesh marching_cubes(const Lattice& L, double iso) {
    return {};
}

}  // namespace geolab::blobby
