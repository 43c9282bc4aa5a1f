// Task 1: basics — Bernstein polynomials, de Casteljau, the Bernstein form (handout §2).
#include <cmath>
#include <stdexcept>

#include "geolab/bezier.hpp"

namespace geolab::bezier {

double bernstein(int n, int i, double t) {
    throw geolab::NotImplemented(__func__);
}

glm::dvec2 de_casteljau(const Poly2& P, double t) {
    throw geolab::NotImplemented(__func__);
}

glm::dvec3 de_casteljau(const Poly3& P, double t) {
    throw geolab::NotImplemented(__func__);
}

std::vector<Poly3> de_casteljau_triangle(const Poly3& P, double t) {
    throw geolab::NotImplemented(__func__);
}

glm::dvec2 evaluate_bernstein(const Poly2& P, double t) {
    throw geolab::NotImplemented(__func__);
}

glm::dvec3 evaluate_bernstein(const Poly3& P, double t) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::bezier
