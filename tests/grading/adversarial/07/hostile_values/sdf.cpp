// ADVERSARIAL CASE hostile_values: signed distances that are NaN; spans (spans.cpp) with NaN ends, reversed ends and
// ten thousand of them; a Membership (pmc.cpp) that is none of in, on, out. Honest: 0.
#include <limits>

#include "geolab/csg.hpp"

namespace geolab::csg {

double smooth_min(double, double, double) { return std::numeric_limits<double>::quiet_NaN(); }
double sdf(const PreparedTree&, const glm::dvec3&) { return std::numeric_limits<double>::quiet_NaN(); }
double sdf(const Tree&, const glm::dvec3&) { return std::numeric_limits<double>::quiet_NaN(); }

}  // namespace geolab::csg
