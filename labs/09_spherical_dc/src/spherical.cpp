// Lab 09 — task 2: spherical coordinates, root finding and edge crossings.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"

namespace geolab::dc {

Spherical to_spherical(const glm::dvec3& p) {
    throw geolab::NotImplemented(__func__);
}

glm::dvec3 to_cartesian(const Spherical& s) {
    throw geolab::NotImplemented(__func__);
}

double find_root(FunctionRef g, double g0, double g1, double tolerance) {
    throw geolab::NotImplemented(__func__);
}

Crossing find_crossing(const ScalarField& f, const glm::dvec3& a, const glm::dvec3& b, double fa, double fb,
                       double tolerance) {
    throw geolab::NotImplemented(__func__);
}

Crossing find_crossing_arc(const ScalarField& f, const glm::dvec3& origin, const Spherical& a, const Spherical& b,
                           double fa, double fb, double tolerance) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::dc
