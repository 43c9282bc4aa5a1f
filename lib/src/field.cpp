#include "geolab/field.hpp"

#include <glm/geometric.hpp>

namespace geolab {

double Box::diagonal() const { return glm::length(hi - lo); }

glm::dvec3 ScalarField::gradient(const glm::dvec3& p) const {
    // central differences, step relative to the field's extent (1e-6 if the box is degenerate)
    double diag = bounds().diagonal();
    double h = (diag > 0.0 && diag < 1e300) ? 1e-6 * diag : 1e-6;
    glm::dvec3 g;
    for (int i = 0; i < 3; ++i) {
        glm::dvec3 e(0.0);
        e[i] = h;
        g[i] = (value(p + e) - value(p - e)) / (2.0 * h);
    }
    return g;
}

}  // namespace geolab
