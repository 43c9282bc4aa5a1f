// ADVERSARIAL CASE always_throws: every function of lab 08 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 2: the triangle–box test (handout §3).
#include <stdexcept>
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "geolab/voxels.hpp"

namespace geolab::voxels {

// Helper functions of your own can go here.

bool triangle_overlaps_voxel(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, std::int64_t i,
                             std::int64_t j, std::int64_t k) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::voxels
