// Task 1: the packed grid (handout §2).
#include <bit>
#include <stdexcept>
#include <string>

#include "geolab/voxels.hpp"

namespace geolab::voxels {

std::uint64_t voxel_index(const Dims& dims, std::int64_t i, std::int64_t j, std::int64_t k) {
    // BEGIN SOLUTION
    if (i < 0 || j < 0 || k < 0 || i >= dims.nx || j >= dims.ny || k >= dims.nz)
        throw std::out_of_range("voxel_index: voxel (" + std::to_string(i) + ", " + std::to_string(j) + ", " +
                                std::to_string(k) + ") is outside the grid " + std::to_string(dims.nx) + " x " +
                                std::to_string(dims.ny) + " x " + std::to_string(dims.nz));
    // 64-bit unsigned throughout: nx·ny alone can exceed 2^32
    return std::uint64_t(i) + std::uint64_t(dims.nx) * (std::uint64_t(j) + std::uint64_t(dims.ny) * std::uint64_t(k));
    // END SOLUTION
}

std::uint64_t count_set(const BitGrid& grid) {
    // BEGIN SOLUTION
    const std::uint64_t n = std::uint64_t(grid.dims.count());
    if (grid.words.size() != (n + 63) / 64)
        throw std::invalid_argument("count_set: " + std::to_string(grid.words.size()) + " words for " +
                                    std::to_string(n) + " voxels");
    std::uint64_t total = 0;
    for (std::uint64_t w : grid.words) total += std::uint64_t(std::popcount(w));
    return total;
    // END SOLUTION
}

}  // namespace geolab::voxels
