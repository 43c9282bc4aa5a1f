// ADVERSARIAL CASE forbidden_wrapper (see primitives.cpp): the helper and its alias.
// Task 2: signed distances of CSG trees and the smooth minimum (handout §3).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geolab/csg.hpp"
#include "geolab/implicits.hpp"

namespace geolab::csg {
namespace helpers {
geolab::FieldPtr make_ball(glm::dvec3 c, double r) { return geolab::sphere(c, r); }
geolab::FieldPtr round_thing(glm::dvec3 c, double r) __attribute__((alias("_ZN6geolab3csg7helpers9make_ballEN3glm3vecILi3EdLNS2_9qualifierE0EEEd")));
double lib_distance(double radius, const glm::dvec3& p) { return round_thing(glm::dvec3(0.0), radius)->value(p); }
}  // namespace helpers

double smooth_min(double a, double b, double k) {
    throw geolab::NotImplemented(__func__);
}

// Helper functions of your own can go here.

double sdf(const PreparedTree& t, const glm::dvec3& x) {
    throw geolab::NotImplemented(__func__);
}

double sdf(const Tree& t, const glm::dvec3& x) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::csg
