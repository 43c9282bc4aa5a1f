// ADVERSARIAL CASE trivial_answers: every function of lab 05 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 2: operations — subdivision, restriction, hodograph, elevation, curvature and torsion (handout §3).
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/bezier.hpp"

namespace geolab::bezier {

Split subdivide(const Poly3& P, double t) {
    return {};
}

Poly3 restrict_to(const Poly3& P, double a, double b) {
    return {};
}

Poly3 hodograph(const Poly3& P) {
    return {};
}

glm::dvec3 derivative(const Poly3& P, double t) {
    return {};
}

glm::dvec3 second_derivative(const Poly3& P, double t) {
    return {};
}

Poly3 elevate(const Poly3& P) {
    return {};
}

double curvature(const Poly3& P, double t) {
    return {};
}

double torsion(const Poly3& P, double t) {
    return {};
}

double signed_curvature(const Poly2& P, double t) {
    return {};
}

}  // namespace geolab::bezier
