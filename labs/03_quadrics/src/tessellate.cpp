// Task 6: tessellation (handout §8).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {
namespace {
// Helper functions of your own can go here.
}  // namespace

PolygonSoup tessellate_superquadric(const Superquadric& s, int n_eta, int n_omega) {
    throw geolab::NotImplemented(__func__);
}

PolygonSoup tessellate_ellipsoid(const glm::dmat4& Q, int n_eta, int n_omega) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::quadrics
