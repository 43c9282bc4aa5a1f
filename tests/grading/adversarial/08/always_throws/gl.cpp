// ADVERSARIAL CASE always_throws: every function of lab 08 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 7: voxelization through the graphics pipeline (handout §9).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "geolab/render/slicer.hpp"
#include "geolab/voxels.hpp"

namespace geolab::voxels {

// Helper functions of your own can go here.

glm::dmat4 slicing_camera(const Dims& dims, int axis) {
    throw std::invalid_argument(__func__);
}

SlabRange slab_range(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const Dims& dims, int axis) {
    throw std::invalid_argument(__func__);
}

void store_layer(const std::vector<std::uint8_t>& image, int axis, std::int64_t k, BitGrid& grid) {
    throw std::invalid_argument(__func__);
}

BitGrid voxelize_gl(const PolygonSoup& mesh, const Dims& dims, int axis) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::voxels
