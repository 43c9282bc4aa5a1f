// ADVERSARIAL CASE hostile_values (see surface.cpp), Task 7: a camera of NaNs, a slab range of 2^62 layers ending
// before it starts, a store_layer that writes nothing, and a GL grid whose dims promise 2^60 voxels with one word.
#include <cstdint>
#include <limits>

#include "geolab/voxels.hpp"

namespace geolab::voxels {

glm::dmat4 slicing_camera(const Dims&, int) { return glm::dmat4(std::numeric_limits<double>::quiet_NaN()); }

SlabRange slab_range(const glm::dvec3&, const glm::dvec3&, const glm::dvec3&, const Dims&, int) {
    return {std::int64_t(1) << 62, -(std::int64_t(1) << 62)};
}

void store_layer(const std::vector<std::uint8_t>&, int, std::int64_t, BitGrid&) {}

BitGrid voxelize_gl(const PolygonSoup&, const Dims&, int) {
    BitGrid g;
    g.dims = {std::int64_t(1) << 20, std::int64_t(1) << 20, std::int64_t(1) << 20};
    g.words = {~0ull};
    return g;
}

}  // namespace geolab::voxels
