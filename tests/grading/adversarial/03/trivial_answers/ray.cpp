// ADVERSARIAL CASE trivial_answers: every function of lab 03 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 4: rays (handout §6).
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {

Roots solve_quadratic(double alpha, double beta, double gamma) {
    return {};
}

std::vector<Hit> intersect(const glm::dmat4& Q, const Ray& ray, double t_min, double t_max) {
    return {};
}

std::vector<Hit> intersect_in_box(const glm::dmat4& Q, const Ray& ray, const Box3& box) {
    return {};
}

}  // namespace geolab::quadrics
