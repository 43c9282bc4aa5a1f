// ADVERSARIAL CASE trivial_answers: every function of lab 08 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 2: the triangle–box test (handout §3).
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "geolab/voxels.hpp"

namespace geolab::voxels {

// Helper functions of your own can go here.

bool triangle_overlaps_voxel(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, std::int64_t i,
                             std::int64_t j, std::int64_t k) {
    return {};
}

}  // namespace geolab::voxels
