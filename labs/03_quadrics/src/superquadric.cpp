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
    throw geolab::NotImplemented(__func__);
}

double inside_outside(const Superquadric& s, const glm::dvec3& x) {
    throw geolab::NotImplemented(__func__);
}

glm::dvec3 superquadric_point(const Superquadric& s, double eta, double omega) {
    throw geolab::NotImplemented(__func__);
}

glm::dvec3 superquadric_normal(const Superquadric& s, double eta, double omega) {
    throw geolab::NotImplemented(__func__);
}

double superquadric_volume(const Superquadric& s) {
    throw geolab::NotImplemented(__func__);
}

std::optional<Hit> intersect_superquadric(const Superquadric& s, const Ray& ray, double t_min, double t_max) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::quadrics
