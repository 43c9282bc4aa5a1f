// ADVERSARIAL CASE always_throws: every function of lab 05 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
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
    throw std::invalid_argument(__func__);
}

Continuity continuity(const Poly3& a, const Poly3& b, double tol) {
    throw std::invalid_argument(__func__);
}

Poly3 join_c1(const Poly3& a, const Poly3& b) {
    throw std::invalid_argument(__func__);
}

Poly3 join_g1(const Poly3& a, const Poly3& b) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::bezier
