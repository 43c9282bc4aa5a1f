// ADVERSARIAL CASE always_throws: every function of lab 07 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 2: signed distances of CSG trees and the smooth minimum (handout §3).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geolab/csg.hpp"

namespace geolab::csg {

double smooth_min(double a, double b, double k) {
    throw std::invalid_argument(__func__);
}

// Helper functions of your own can go here.

double sdf(const PreparedTree& t, const glm::dvec3& x) {
    throw std::invalid_argument(__func__);
}

double sdf(const Tree& t, const glm::dvec3& x) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::csg
