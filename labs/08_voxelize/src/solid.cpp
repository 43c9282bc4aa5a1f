// Task 4: solid voxelization (handout §5).
#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cstdint>
#include <cmath>
#include <stdexcept>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "geolab/predicates.hpp"
#include "geolab/voxels.hpp"

namespace geolab::voxels {

// Helper functions of your own can go here.

BitGrid parity_fill_layers(const PolygonSoup& mesh, const Dims& dims, int axis, std::int64_t k0, std::int64_t k1,
                           int threads) {
    throw geolab::NotImplemented(__func__);
}

BitGrid parity_fill(const PolygonSoup& mesh, const Dims& dims, int axis, int threads) {
    throw geolab::NotImplemented(__func__);
}

std::uint64_t count_boundary_edges(const PolygonSoup& mesh) {
    throw geolab::NotImplemented(__func__);
}

BitGrid flood_fill_solid(const BitGrid& surface) {
    throw geolab::NotImplemented(__func__);
}

SolidResult voxelize_solid(const PolygonSoup& mesh, const Dims& dims, int threads) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::voxels
