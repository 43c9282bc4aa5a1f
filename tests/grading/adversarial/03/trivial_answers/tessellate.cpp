// ADVERSARIAL CASE trivial_answers: every function of lab 03 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
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
    return {};
}

PolygonSoup tessellate_ellipsoid(const glm::dmat4& Q, int n_eta, int n_omega) {
    return {};
}

}  // namespace geolab::quadrics
