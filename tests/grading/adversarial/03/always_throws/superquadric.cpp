// ADVERSARIAL CASE always_throws: every function of lab 03 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
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
    throw std::invalid_argument(__func__);
}

double inside_outside(const Superquadric& s, const glm::dvec3& x) {
    throw std::invalid_argument(__func__);
}

glm::dvec3 superquadric_point(const Superquadric& s, double eta, double omega) {
    throw std::invalid_argument(__func__);
}

glm::dvec3 superquadric_normal(const Superquadric& s, double eta, double omega) {
    throw std::invalid_argument(__func__);
}

double superquadric_volume(const Superquadric& s) {
    throw std::invalid_argument(__func__);
}

std::optional<Hit> intersect_superquadric(const Superquadric& s, const Ray& ray, double t_min, double t_max) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::quadrics
