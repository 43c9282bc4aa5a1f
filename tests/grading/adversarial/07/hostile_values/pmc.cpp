// ADVERSARIAL CASE hostile_values (see sdf.cpp).
#include "geolab/csg.hpp"

namespace geolab::csg {

Membership classify(const Tree&, const glm::dvec3&, double) { return static_cast<Membership>(42); }

}  // namespace geolab::csg
