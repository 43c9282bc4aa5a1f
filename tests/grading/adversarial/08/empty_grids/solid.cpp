// ADVERSARIAL CASE empty_grids (see surface.cpp): parity gives an empty grid of the right size for every axis and
// thread count, the flood fill gives back its input, the solid is empty and claims parity on a closed mesh.
#include "geolab/voxels.hpp"

namespace geolab::voxels {

BitGrid parity_fill_layers(const PolygonSoup&, const Dims& dims, int, std::int64_t k0, std::int64_t k1, int) {
    return BitGrid(Dims{dims.nx, dims.ny, k1 - k0});
}

BitGrid parity_fill(const PolygonSoup&, const Dims& dims, int, int) { return BitGrid(dims); }

std::uint64_t count_boundary_edges(const PolygonSoup&) { return 0; }

BitGrid flood_fill_solid(const BitGrid& surface) { return surface; }

SolidResult voxelize_solid(const PolygonSoup&, const Dims& dims, int) {
    SolidResult r;
    r.grid = BitGrid(dims);
    r.method = SolidMethod::parity;
    return r;
}

}  // namespace geolab::voxels
