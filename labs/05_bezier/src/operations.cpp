// Task 2: operations — subdivision, restriction, hodograph, elevation, curvature and torsion (handout §3).
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/bezier.hpp"

namespace geolab::bezier {

Split subdivide(const Poly3& P, double t) {
    throw geolab::NotImplemented(__func__);
}

Poly3 restrict_to(const Poly3& P, double a, double b) {
    throw geolab::NotImplemented(__func__);
}

Poly3 hodograph(const Poly3& P) {
    throw geolab::NotImplemented(__func__);
}

glm::dvec3 derivative(const Poly3& P, double t) {
    throw geolab::NotImplemented(__func__);
}

glm::dvec3 second_derivative(const Poly3& P, double t) {
    throw geolab::NotImplemented(__func__);
}

Poly3 elevate(const Poly3& P) {
    throw geolab::NotImplemented(__func__);
}

double curvature(const Poly3& P, double t) {
    throw geolab::NotImplemented(__func__);
}

double torsion(const Poly3& P, double t) {
    throw geolab::NotImplemented(__func__);
}

double signed_curvature(const Poly2& P, double t) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::bezier
