// ADVERSARIAL CASE empty_grids: surface voxelization and parity answer an empty grid of the right size (no work),
// with any thread count; the solid is the same empty grid. Honest: 0. Tests that only compare the student's grids
// with each other (three axes agree, threads agree) pass on empty grids unless they also check a count.
#include "geolab/voxels.hpp"

namespace geolab::voxels {

BitGrid voxelize_surface_layers(const PolygonSoup&, const Dims& dims, std::int64_t k0, std::int64_t k1, int) {
    return BitGrid(Dims{dims.nx, dims.ny, k1 - k0});
}

BitGrid voxelize_surface(const PolygonSoup&, const Dims& dims, int) { return BitGrid(dims); }

}  // namespace geolab::voxels
