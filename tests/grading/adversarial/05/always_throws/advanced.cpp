// ADVERSARIAL CASE always_throws: every function of lab 05 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
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
    throw std::invalid_argument(__func__);
}

RationalCurve circle_arc(const glm::dvec3& center, double r, double a0, double a1) {
    throw std::invalid_argument(__func__);
}

glm::dvec3 de_boor(const BSpline& s, double t) {
    throw std::invalid_argument(__func__);
}

BSpline insert_knot(const BSpline& s, double t) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::bezier
