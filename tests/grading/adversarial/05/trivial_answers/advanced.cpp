// ADVERSARIAL CASE trivial_answers: every function of lab 05 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
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
    return {};
}

RationalCurve circle_arc(const glm::dvec3& center, double r, double a0, double a1) {
    return {};
}

glm::dvec3 de_boor(const BSpline& s, double t) {
    return {};
}

BSpline insert_knot(const BSpline& s, double t) {
    return {};
}

}  // namespace geolab::bezier
