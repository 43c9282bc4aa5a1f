// ADVERSARIAL CASE always_throws: every function of lab 03 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 4: rays (handout §6).
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {

Roots solve_quadratic(double alpha, double beta, double gamma) {
    throw std::invalid_argument(__func__);
}

std::vector<Hit> intersect(const glm::dmat4& Q, const Ray& ray, double t_min, double t_max) {
    throw std::invalid_argument(__func__);
}

std::vector<Hit> intersect_in_box(const glm::dmat4& Q, const Ray& ray, const Box3& box) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::quadrics
