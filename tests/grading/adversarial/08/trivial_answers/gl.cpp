// ADVERSARIAL CASE trivial_answers: every function of lab 08 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
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
    return {};
}

SlabRange slab_range(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const Dims& dims, int axis) {
    return {};
}

void store_layer(const std::vector<std::uint8_t>& image, int axis, std::int64_t k, BitGrid& grid) {
    return;
}

BitGrid voxelize_gl(const PolygonSoup& mesh, const Dims& dims, int axis) {
    return {};
}

}  // namespace geolab::voxels
