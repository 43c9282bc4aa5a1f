// ADVERSARIAL CASE trivial_answers: every function of lab 07 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 2: signed distances of CSG trees and the smooth minimum (handout §3).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geolab/csg.hpp"

namespace geolab::csg {

double smooth_min(double a, double b, double k) {
    return {};
}

// Helper functions of your own can go here.

double sdf(const PreparedTree& t, const glm::dvec3& x) {
    return {};
}

double sdf(const Tree& t, const glm::dvec3& x) {
    return {};
}

}  // namespace geolab::csg
