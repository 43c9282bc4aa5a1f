// Task 8 (advanced): rational Bézier curves and the exact circle; B-splines by de Boor, knot insertion (handout §9).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/vec4.hpp>

#include "geolab/bezier.hpp"

namespace geolab::bezier {

namespace {
// Helper functions of your own can go here.
}  // namespace

glm::dvec3 rational_point(const RationalCurve& c, double t) {
    throw geolab::NotImplemented(__func__);
}

RationalCurve circle_arc(const glm::dvec3& center, double r, double a0, double a1) {
    throw geolab::NotImplemented(__func__);
}

glm::dvec3 de_boor(const BSpline& s, double t) {
    throw geolab::NotImplemented(__func__);
}

BSpline insert_knot(const BSpline& s, double t) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::bezier
