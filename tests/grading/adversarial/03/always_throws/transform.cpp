// ADVERSARIAL CASE always_throws: every function of lab 03 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 2: transforms (handout §4).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {

glm::dmat4 transform_quadric(const glm::dmat4& Q, const glm::dmat4& M) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::quadrics
