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
    throw geolab::NotImplemented(__func__);
}

BitGrid voxelize_surface(const PolygonSoup& mesh, const Dims& dims, int threads) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::voxels
