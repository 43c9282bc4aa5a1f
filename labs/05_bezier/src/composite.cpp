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
    throw geolab::NotImplemented(__func__);
}

Continuity continuity(const Poly3& a, const Poly3& b, double tol) {
    throw geolab::NotImplemented(__func__);
}

Poly3 join_c1(const Poly3& a, const Poly3& b) {
    throw geolab::NotImplemented(__func__);
}

Poly3 join_g1(const Poly3& a, const Poly3& b) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::bezier
