// ADVERSARIAL CASE trivial_answers: every function of lab 07 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 1: exact signed distances of the primitives (handout §2).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/csg.hpp"
#include "geolab/quadric.hpp"

namespace geolab::csg {

// Helper functions of your own can go here.

double primitive_distance(const Node& leaf, const glm::dvec3& p) {
    return {};
}

}  // namespace geolab::csg
