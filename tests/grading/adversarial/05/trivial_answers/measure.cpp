// ADVERSARIAL CASE trivial_answers: every function of lab 05 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 3: measures — arc length, its inverse, the tight bounding box, the closest point (handout §4).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/bezier.hpp"

namespace geolab::bezier {

namespace {
// Helper functions of your own can go here.
}  // namespace

double arc_length(const Poly3& P, double a, double b, double tol) {
    return {};
}

double parameter_at_length(const Poly3& P, double s, double tol) {
    return {};
}

Box bounding_box(const Poly3& P) {
    return {};
}

Closest closest_point(const Poly3& P, const glm::dvec3& q) {
    return {};
}

}  // namespace geolab::bezier
