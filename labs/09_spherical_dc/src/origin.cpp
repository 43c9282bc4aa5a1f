// Lab 09 — task 5: the origin of the spherical octree (smallest enclosing sphere, eq. 6 correction).
#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"

namespace geolab::dc {

Sphere minimal_enclosing_sphere(std::span<const glm::dvec3> points) {
    throw geolab::NotImplemented(__func__);
}

std::vector<glm::dvec3> correct_origin(const ScalarField& f, const glm::dvec3& x0, const OriginParams& params) {
    if (!(params.unit > 0.0)) throw std::invalid_argument("correct_origin: params.unit must be > 0");
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::dc
