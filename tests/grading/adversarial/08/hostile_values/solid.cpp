// ADVERSARIAL CASE hostile_values (see surface.cpp).
#include <cstdint>
#include <limits>

#include "geolab/voxels.hpp"

namespace geolab::voxels {

BitGrid parity_fill_layers(const PolygonSoup&, const Dims& dims, int, std::int64_t k0, std::int64_t k1, int) {
    BitGrid g;  // negative sizes and three words
    g.dims = {-dims.nx, dims.ny, k0 - k1};
    g.words.assign(3, ~0ull);
    return g;
}

BitGrid parity_fill(const PolygonSoup&, const Dims& dims, int, int) {
    BitGrid g;
    g.dims = {-dims.nx, dims.ny, -dims.nz};
    g.words.assign(3, ~0ull);
    return g;
}

std::uint64_t count_boundary_edges(const PolygonSoup&) { return std::numeric_limits<std::uint64_t>::max(); }

BitGrid flood_fill_solid(const BitGrid& surface) {
    BitGrid g = surface;
    g.words.clear();
    return g;
}

SolidResult voxelize_solid(const PolygonSoup&, const Dims& dims, int) {
    SolidResult r;
    r.grid.dims = dims;
    r.grid.words.assign(1, ~0ull);
    r.method = static_cast<SolidMethod>(7);
    r.boundary_edges = std::numeric_limits<std::uint64_t>::max();
    r.axis_disagreements = std::numeric_limits<std::uint64_t>::max();
    return r;
}

}  // namespace geolab::voxels
