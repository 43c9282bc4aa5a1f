// ADVERSARIAL CASE hostile_values (see sdf.cpp).
#include <limits>
#include <vector>

#include "geolab/csg.hpp"

namespace geolab::csg {

void primitive_spans(const Node&, const Ray&, std::vector<Span>& out) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    out.assign(10000, Span{nan, nan, glm::dvec3(nan), glm::dvec3(nan)});
    out[0] = Span{5, -5, glm::dvec3(0), glm::dvec3(0)};
}

}  // namespace geolab::csg
