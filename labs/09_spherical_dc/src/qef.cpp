// Lab 09 — task 1: the quadratic error function of dual contouring.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"

namespace geolab::dc {

void Qef::add(const glm::dvec3& p, const glm::dvec3& n) {
    throw geolab::NotImplemented(__func__);
}

double Qef::error(const glm::dvec3& x) const {
    throw geolab::NotImplemented(__func__);
}

glm::dvec3 Qef::solve(double tau, glm::dvec3* mass_point_out, int* rank_out) const {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::dc
