// Task 2: transforms (handout §4).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {

glm::dmat4 transform_quadric(const glm::dmat4& Q, const glm::dmat4& M) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::quadrics
