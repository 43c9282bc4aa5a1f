// Task 1: the packed grid (handout §2).
#include <bit>
#include <stdexcept>
#include <string>

#include "geolab/voxels.hpp"

namespace geolab::voxels {

std::uint64_t voxel_index(const Dims& dims, std::int64_t i, std::int64_t j, std::int64_t k) {
    throw geolab::NotImplemented(__func__);
}

std::uint64_t count_set(const BitGrid& grid) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::voxels
