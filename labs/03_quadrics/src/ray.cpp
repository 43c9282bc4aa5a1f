// Task 4: rays (handout §6).
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {

Roots solve_quadratic(double alpha, double beta, double gamma) {
    throw geolab::NotImplemented(__func__);
}

std::vector<Hit> intersect(const glm::dmat4& Q, const Ray& ray, double t_min, double t_max) {
    throw geolab::NotImplemented(__func__);
}

std::vector<Hit> intersect_in_box(const glm::dmat4& Q, const Ray& ray, const Box3& box) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::quadrics
