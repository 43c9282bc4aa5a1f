// ADVERSARIAL CASE always_throws: every function of lab 08 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
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
    throw std::invalid_argument(__func__);
}

BitGrid parity_fill(const PolygonSoup& mesh, const Dims& dims, int axis, int threads) {
    throw std::invalid_argument(__func__);
}

std::uint64_t count_boundary_edges(const PolygonSoup& mesh) {
    throw std::invalid_argument(__func__);
}

BitGrid flood_fill_solid(const BitGrid& surface) {
    throw std::invalid_argument(__func__);
}

SolidResult voxelize_solid(const PolygonSoup& mesh, const Dims& dims, int threads) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::voxels
