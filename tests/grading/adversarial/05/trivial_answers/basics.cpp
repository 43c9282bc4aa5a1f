// ADVERSARIAL CASE trivial_answers: every function of lab 05 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 1: basics — Bernstein polynomials, de Casteljau, the Bernstein form (handout §2).
#include <cmath>
#include <stdexcept>

#include "geolab/bezier.hpp"

namespace geolab::bezier {

double bernstein(int n, int i, double t) {
    return {};
}

glm::dvec2 de_casteljau(const Poly2& P, double t) {
    return {};
}

glm::dvec3 de_casteljau(const Poly3& P, double t) {
    return {};
}

std::vector<Poly3> de_casteljau_triangle(const Poly3& P, double t) {
    return {};
}

glm::dvec2 evaluate_bernstein(const Poly2& P, double t) {
    return {};
}

glm::dvec3 evaluate_bernstein(const Poly3& P, double t) {
    return {};
}

}  // namespace geolab::bezier
