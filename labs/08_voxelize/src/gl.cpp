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
    throw geolab::NotImplemented(__func__);
}

SlabRange slab_range(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const Dims& dims, int axis) {
    throw geolab::NotImplemented(__func__);
}

void store_layer(const std::vector<std::uint8_t>& image, int axis, std::int64_t k, BitGrid& grid) {
    throw geolab::NotImplemented(__func__);
}

BitGrid voxelize_gl(const PolygonSoup& mesh, const Dims& dims, int axis) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::voxels
