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
    throw geolab::NotImplemented(__func__);
}

double parameter_at_length(const Poly3& P, double s, double tol) {
    throw geolab::NotImplemented(__func__);
}

Box bounding_box(const Poly3& P) {
    throw geolab::NotImplemented(__func__);
}

Closest closest_point(const Poly3& P, const glm::dvec3& q) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::bezier
