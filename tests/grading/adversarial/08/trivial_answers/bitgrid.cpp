// ADVERSARIAL CASE trivial_answers: every function of lab 08 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 1: the packed grid (handout §2).
#include <bit>
#include <stdexcept>
#include <string>

#include "geolab/voxels.hpp"

namespace geolab::voxels {

std::uint64_t voxel_index(const Dims& dims, std::int64_t i, std::int64_t j, std::int64_t k) {
    return {};
}

std::uint64_t count_set(const BitGrid& grid) {
    return {};
}

}  // namespace geolab::voxels
