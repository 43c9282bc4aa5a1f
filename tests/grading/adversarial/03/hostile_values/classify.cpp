// ADVERSARIAL CASE hostile_values (see ray.cpp): a QuadricType of 99.
#include "geolab/quadrics.hpp"

namespace geolab::quadrics {

QuadricType classify(const glm::dmat4&) { return static_cast<QuadricType>(99); }

}  // namespace geolab::quadrics
