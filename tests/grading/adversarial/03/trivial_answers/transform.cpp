// ADVERSARIAL CASE trivial_answers: every function of lab 03 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 2: transforms (handout §4).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {

glm::dmat4 transform_quadric(const glm::dmat4& Q, const glm::dmat4& M) {
    return {};
}

}  // namespace geolab::quadrics
