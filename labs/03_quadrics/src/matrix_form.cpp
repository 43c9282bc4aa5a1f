// Task 1: the matrix form (handout §3).
#include <cmath>
#include <stdexcept>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {

glm::dmat4 to_matrix(const Coefficients& k) {
    throw geolab::NotImplemented(__func__);
}

Coefficients to_coefficients(const glm::dmat4& Q) {
    throw geolab::NotImplemented(__func__);
}

double evaluate(const glm::dmat4& Q, const glm::dvec3& x) {
    throw geolab::NotImplemented(__func__);
}

glm::dvec3 gradient(const glm::dmat4& Q, const glm::dvec3& x) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::quadrics
