// ADVERSARIAL CASE trivial_answers: every function of lab 08 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
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
    return {};
}

BitGrid parity_fill(const PolygonSoup& mesh, const Dims& dims, int axis, int threads) {
    return {};
}

std::uint64_t count_boundary_edges(const PolygonSoup& mesh) {
    return {};
}

BitGrid flood_fill_solid(const BitGrid& surface) {
    return {};
}

SolidResult voxelize_solid(const PolygonSoup& mesh, const Dims& dims, int threads) {
    return {};
}

}  // namespace geolab::voxels
