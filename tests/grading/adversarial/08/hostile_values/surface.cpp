// ADVERSARIAL CASE hostile_values: answers no test can use safely: grids whose dims promise 2^60 voxels with one
// word, negative dims, counts of 2^64 - 1, an enum value outside SolidMethod, NaN densities, a .binvox of 16 MB.
// The judge reads them within its bounds and tests that index them stop (standard-library assertions), never
// reading outside the answer. Honest: 0.
#include <cstdint>
#include <limits>

#include "geolab/voxels.hpp"

namespace geolab::voxels {

BitGrid voxelize_surface_layers(const PolygonSoup&, const Dims&, std::int64_t, std::int64_t, int) {
    BitGrid g;  // a size that promises 2^60 voxels, one word
    g.dims = {std::int64_t(1) << 20, std::int64_t(1) << 20, std::int64_t(1) << 20};
    g.words = {~0ull};
    return g;
}

BitGrid voxelize_surface(const PolygonSoup&, const Dims& dims, int) {
    BitGrid g;
    g.dims = {std::int64_t(1) << 20, std::int64_t(1) << 20, std::int64_t(1) << 20};
    g.words = {~0ull};
    return g;
}

}  // namespace geolab::voxels
