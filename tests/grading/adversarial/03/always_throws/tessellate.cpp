// ADVERSARIAL CASE always_throws: every function of lab 03 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
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
    throw std::invalid_argument(__func__);
}

PolygonSoup tessellate_ellipsoid(const glm::dmat4& Q, int n_eta, int n_omega) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::quadrics
