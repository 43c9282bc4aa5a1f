// ADVERSARIAL CASE always_throws: every function of lab 05 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 2: operations — subdivision, restriction, hodograph, elevation, curvature and torsion (handout §3).
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/bezier.hpp"

namespace geolab::bezier {

Split subdivide(const Poly3& P, double t) {
    throw std::invalid_argument(__func__);
}

Poly3 restrict_to(const Poly3& P, double a, double b) {
    throw std::invalid_argument(__func__);
}

Poly3 hodograph(const Poly3& P) {
    throw std::invalid_argument(__func__);
}

glm::dvec3 derivative(const Poly3& P, double t) {
    throw std::invalid_argument(__func__);
}

glm::dvec3 second_derivative(const Poly3& P, double t) {
    throw std::invalid_argument(__func__);
}

Poly3 elevate(const Poly3& P) {
    throw std::invalid_argument(__func__);
}

double curvature(const Poly3& P, double t) {
    throw std::invalid_argument(__func__);
}

double torsion(const Poly3& P, double t) {
    throw std::invalid_argument(__func__);
}

double signed_curvature(const Poly2& P, double t) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::bezier
