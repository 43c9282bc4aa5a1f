// ADVERSARIAL CASE forbidden_wrapper (see classify.cpp): evaluate is lib's XᵀQX through the helper in another file;
// the rest of Task 1 is the stub.
// Task 1: the matrix form (handout §3).
#include <cmath>
#include <stdexcept>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {
namespace helpers {
double xtqx(const glm::dmat4& Q, const glm::dvec3& x);
}

glm::dmat4 to_matrix(const Coefficients& k) {
    throw geolab::NotImplemented(__func__);
}

Coefficients to_coefficients(const glm::dmat4& Q) {
    throw geolab::NotImplemented(__func__);
}

double evaluate(const glm::dmat4& Q, const glm::dvec3& x) {
    return helpers::xtqx(Q, x);
}

glm::dvec3 gradient(const glm::dmat4& Q, const glm::dvec3& x) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::quadrics
