// ADVERSARIAL CASE always_throws: every function of lab 08 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
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
    throw std::invalid_argument(__func__);
}

BitGrid voxelize_surface(const PolygonSoup& mesh, const Dims& dims, int threads) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::voxels
