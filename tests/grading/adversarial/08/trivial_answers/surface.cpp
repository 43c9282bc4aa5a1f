// ADVERSARIAL CASE trivial_answers: every function of lab 08 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 3: surface voxelization (handout §4).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>

#include "geolab/voxels.hpp"

namespace geolab::voxels {

// Helper functions of your own can go here.

BitGrid voxelize_surface_layers(const PolygonSoup& mesh, const Dims& dims, std::int64_t k0, std::int64_t k1,
                                int threads) {
    return {};
}

BitGrid voxelize_surface(const PolygonSoup& mesh, const Dims& dims, int threads) {
    return {};
}

}  // namespace geolab::voxels
