// ADVERSARIAL CASE hostile_values: a root count of 7 with NaN roots, a million NaN hits, hits at ±infinity;
// classify (classify.cpp) answers a type that is no QuadricType. The judge reads them within its bounds; tests that
// compare or index them fail. Honest: 0.
#include <cmath>
#include <limits>
#include <vector>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {

Roots solve_quadratic(double, double, double) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {7, nan, nan};
}

std::vector<Hit> intersect(const glm::dmat4&, const Ray&, double, double) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return std::vector<Hit>(1000000, Hit{nan, glm::dvec3(nan), glm::dvec3(nan)});
}

std::vector<Hit> intersect_in_box(const glm::dmat4&, const Ray&, const Box3&) {
    const double inf = std::numeric_limits<double>::infinity();
    return {Hit{-inf, glm::dvec3(inf), glm::dvec3(0)}, Hit{inf, glm::dvec3(-inf), glm::dvec3(0)}};
}

}  // namespace geolab::quadrics
