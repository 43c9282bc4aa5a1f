// ADVERSARIAL CASE always_throws: every function of lab 05 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 1: basics — Bernstein polynomials, de Casteljau, the Bernstein form (handout §2).
#include <cmath>
#include <stdexcept>

#include "geolab/bezier.hpp"

namespace geolab::bezier {

double bernstein(int n, int i, double t) {
    throw std::invalid_argument(__func__);
}

glm::dvec2 de_casteljau(const Poly2& P, double t) {
    throw std::invalid_argument(__func__);
}

glm::dvec3 de_casteljau(const Poly3& P, double t) {
    throw std::invalid_argument(__func__);
}

std::vector<Poly3> de_casteljau_triangle(const Poly3& P, double t) {
    throw std::invalid_argument(__func__);
}

glm::dvec2 evaluate_bernstein(const Poly2& P, double t) {
    throw std::invalid_argument(__func__);
}

glm::dvec3 evaluate_bernstein(const Poly3& P, double t) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::bezier
