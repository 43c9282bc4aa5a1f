// ADVERSARIAL CASE always_throws: every function of lab 05 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
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
    throw std::invalid_argument(__func__);
}

double parameter_at_length(const Poly3& P, double s, double tol) {
    throw std::invalid_argument(__func__);
}

Box bounding_box(const Poly3& P) {
    throw std::invalid_argument(__func__);
}

Closest closest_point(const Poly3& P, const glm::dvec3& q) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::bezier
