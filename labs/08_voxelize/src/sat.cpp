// Task 2: the triangle–box test (handout §3).
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "geolab/voxels.hpp"

namespace geolab::voxels {

// Helper functions of your own can go here.

bool triangle_overlaps_voxel(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, std::int64_t i,
                             std::int64_t j, std::int64_t k) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::voxels
