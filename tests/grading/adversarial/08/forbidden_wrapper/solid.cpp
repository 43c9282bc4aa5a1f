// ADVERSARIAL CASE forbidden_wrapper (see bitgrid.cpp): count_boundary_edges calls the helper through a table of
// function pointers; check_surface's count is of edges in one face, which is what "odd use" means on the tests'
// meshes. The other functions are the stubs.
#include <stdexcept>

#include "geolab/voxels.hpp"

namespace geolab::voxels {
namespace helpers {
std::uint64_t edges_of(const PolygonSoup& mesh);
}
namespace {
std::uint64_t (*const table[])(const PolygonSoup&) = {&helpers::edges_of};
}

BitGrid parity_fill_layers(const PolygonSoup& mesh, const Dims& dims, int axis, std::int64_t k0, std::int64_t k1,
                           int threads) {
    throw geolab::NotImplemented(__func__);
}

BitGrid parity_fill(const PolygonSoup& mesh, const Dims& dims, int axis, int threads) {
    throw geolab::NotImplemented(__func__);
}

std::uint64_t count_boundary_edges(const PolygonSoup& mesh) {
    check_soup(mesh);
    volatile int k = 0;
    return table[k](mesh);
}

BitGrid flood_fill_solid(const BitGrid& surface) { throw geolab::NotImplemented(__func__); }

SolidResult voxelize_solid(const PolygonSoup& mesh, const Dims& dims, int threads) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::voxels
