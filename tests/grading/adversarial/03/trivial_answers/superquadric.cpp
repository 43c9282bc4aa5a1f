// ADVERSARIAL CASE trivial_answers: every function of lab 03 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 5: superquadrics (handout §7).
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {
namespace {
// Helper functions of your own can go here.
}  // namespace

double spow(double x, double e) {
    return {};
}

double inside_outside(const Superquadric& s, const glm::dvec3& x) {
    return {};
}

glm::dvec3 superquadric_point(const Superquadric& s, double eta, double omega) {
    return {};
}

glm::dvec3 superquadric_normal(const Superquadric& s, double eta, double omega) {
    return {};
}

double superquadric_volume(const Superquadric& s) {
    return {};
}

std::optional<Hit> intersect_superquadric(const Superquadric& s, const Ray& ray, double t_min, double t_max) {
    return {};
}

}  // namespace geolab::quadrics
