// The radius ratio of a tetrahedron (see tet_quality.hpp).
#include "geolab/tet_quality.hpp"

#include <cmath>
#include <glm/geometric.hpp>

namespace geolab {

double tet_radius_ratio(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
    const glm::dvec3 u = b - a, v = c - a, w = d - a;
    const double det = glm::dot(u, glm::cross(v, w));  // 6 V
    if (det == 0.0 || !std::isfinite(det)) return 0.0;
    // total face area A
    const double area = 0.5 * (glm::length(glm::cross(u, v)) + glm::length(glm::cross(u, w)) +
                               glm::length(glm::cross(v, w)) + glm::length(glm::cross(c - b, d - b)));
    // circumcentre relative to a: (|u|² v×w + |v|² w×u + |w|² u×v) / (2 det)
    const glm::dvec3 o =
        (glm::dot(u, u) * glm::cross(v, w) + glm::dot(v, v) * glm::cross(w, u) + glm::dot(w, w) * glm::cross(u, v)) /
        (2.0 * det);
    const double R = glm::length(o);
    return 9.0 * (det / 6.0) / (area * R);
}

}  // namespace geolab
