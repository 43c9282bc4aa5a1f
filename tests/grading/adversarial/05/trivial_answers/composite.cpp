// ADVERSARIAL CASE trivial_answers: every function of lab 05 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 4: composite curves — evaluation, continuity classes at a joint, C¹ and G¹ joins (handout §5).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/bezier.hpp"

namespace geolab::bezier {

namespace {
// Helper functions of your own can go here.
}  // namespace

glm::dvec3 evaluate_composite(const std::vector<Poly3>& segments, double u) {
    return {};
}

Continuity continuity(const Poly3& a, const Poly3& b, double tol) {
    return {};
}

Poly3 join_c1(const Poly3& a, const Poly3& b) {
    return {};
}

Poly3 join_g1(const Poly3& a, const Poly3& b) {
    return {};
}

}  // namespace geolab::bezier
