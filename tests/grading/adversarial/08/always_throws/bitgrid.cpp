// ADVERSARIAL CASE always_throws: every function of lab 08 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 1: the packed grid (handout §2).
#include <bit>
#include <stdexcept>
#include <string>

#include "geolab/voxels.hpp"

namespace geolab::voxels {

std::uint64_t voxel_index(const Dims& dims, std::int64_t i, std::int64_t j, std::int64_t k) {
    throw std::invalid_argument(__func__);
}

std::uint64_t count_set(const BitGrid& grid) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::voxels
