// ADVERSARIAL CASE always_throws: every function of lab 03 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 1: the matrix form (handout §3).
#include <cmath>
#include <stdexcept>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {

glm::dmat4 to_matrix(const Coefficients& k) {
    throw std::invalid_argument(__func__);
}

Coefficients to_coefficients(const glm::dmat4& Q) {
    throw std::invalid_argument(__func__);
}

double evaluate(const glm::dmat4& Q, const glm::dvec3& x) {
    throw std::invalid_argument(__func__);
}

glm::dvec3 gradient(const glm::dmat4& Q, const glm::dvec3& x) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::quadrics
