// ADVERSARIAL CASE trivial_answers: every function of lab 03 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 1: the matrix form (handout §3).
#include <cmath>
#include <stdexcept>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {

glm::dmat4 to_matrix(const Coefficients& k) {
    return {};
}

Coefficients to_coefficients(const glm::dmat4& Q) {
    return {};
}

double evaluate(const glm::dmat4& Q, const glm::dvec3& x) {
    return {};
}

glm::dvec3 gradient(const glm::dmat4& Q, const glm::dvec3& x) {
    return {};
}

}  // namespace geolab::quadrics
