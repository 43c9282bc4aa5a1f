// Lab 09 — task 6: the spherical-coordinate octree; the spherical one-shot function.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"

namespace geolab::dc {

Octree build_spherical_octree(const ScalarField& f, int max_level, const glm::dvec3& origin, double r_min,
                              double r_max) {
    throw geolab::NotImplemented(__func__);
}

PolygonSoup dual_contour_spherical(const ScalarField& f, const SphericalParams& params, DcStats* stats) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::dc
