// ADVERSARIAL CASE always_throws: every function of lab 07 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
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
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::csg
