// Lab 08, Task 1: the packed grid. Expected indices from 128-bit arithmetic; counts voxel by voxel.
#include <stdexcept>

#include "helpers.hpp"

using namespace lab08;

namespace {
std::uint64_t index128(Dims d, std::int64_t i, std::int64_t j, std::int64_t k) {
    const unsigned __int128 n = (unsigned __int128)i + (unsigned __int128)d.nx * ((unsigned __int128)j + (unsigned __int128)d.ny * k);
    return std::uint64_t(n);
}
void check_index(Dims d, std::int64_t i, std::int64_t j, std::int64_t k) {
    const std::uint64_t want = index128(d, i, j, k), got = voxel_index(d, i, j, k);
    INFO("voxel_index(" << str(d) << ", " << i << ", " << j << ", " << k << "): expected " << want << ", got " << got);
    CHECK(got == want);
}
}  // namespace

TEST_SUITE("Task 1: the packed grid") {
    TEST_CASE("packed grid: voxel_index is x fastest; then y; then z" * geolab::points(2) *
              geolab::hint("index = i + nx·(j + ny·k)")) {
        check_index({4, 3, 2}, 0, 0, 0);
        check_index({4, 3, 2}, 1, 0, 0);
        check_index({4, 3, 2}, 0, 1, 0);
        check_index({4, 3, 2}, 0, 0, 1);
        check_index({4, 3, 2}, 3, 2, 1);
        check_index({1, 7, 5}, 0, 6, 4);
        check_index({9, 1, 1}, 8, 0, 0);
    }
    TEST_CASE("packed grid: voxel_index above 1024³ needs 64-bit arithmetic (no grid is allocated)" * geolab::points(2) *
              geolab::hint("nx·ny·k overflows 32 bits past 2048²·1024: cast to std::uint64_t before multiplying")) {
        for (Dims d : {Dims{2048, 2048, 2048}, Dims{4096, 4096, 4096}, Dims{1025, 1025, 1025}, Dims{70000, 70000, 200},
                       Dims{3, 1 << 20, 1 << 17}}) {
            check_index(d, d.nx - 1, d.ny - 1, d.nz - 1);
            check_index(d, 0, 0, d.nz - 1);
            check_index(d, d.nx / 2, d.ny / 3, d.nz / 2);
        }
        CHECK(voxel_index({2048, 2048, 2048}, 2047, 2047, 2047) == (std::uint64_t(1) << 33) - 1);
    }
    TEST_CASE("packed grid: voxel_index rejects voxels outside the grid" * geolab::points(1) *
              geolab::hint("std::out_of_range for any coordinate < 0 or >= its size (the far face is outside)")) {
        const Dims d{4, 3, 2};
        for (auto v : {std::array<std::int64_t, 3>{4, 0, 0}, {0, 3, 0}, {0, 0, 2}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1},
                       {std::int64_t(1) << 40, 0, 0}}) {
            INFO("voxel (" << v[0] << ", " << v[1] << ", " << v[2] << ") in a grid " << str(d) << ": expected std::out_of_range");
            CHECK_THROWS_AS(voxel_index(d, v[0], v[1], v[2]), std::out_of_range);
        }
        CHECK_THROWS_AS(voxel_index({0, 0, 0}, 0, 0, 0), std::out_of_range);
    }
    TEST_CASE("packed grid: count_set counts every set voxel; a wrong words size is an error" * geolab::points(2) *
              geolab::hint("popcount each word; the last word's unused bits are 0 by the invariant")) {
        Rng rng(8);
        for (Dims d : {Dims{1, 1, 1}, Dims{7, 5, 3}, Dims{8, 8, 1}, Dims{64, 1, 1}, Dims{65, 1, 1}, Dims{13, 17, 11}, Dims{0, 4, 4}}) {
            BitGrid g(d);
            const double p = rng.uniform(0.05, 0.95);
            for (std::int64_t k = 0; k < d.nz; ++k)
                for (std::int64_t j = 0; j < d.ny; ++j)
                    for (std::int64_t i = 0; i < d.nx; ++i)
                        if (rng.uniform(0, 1) < p) g.set(i, j, k);
            INFO("grid " << str(d) << ": expected " << count_bits(g) << " set voxels");
            CHECK(count_set(g) == count_bits(g));
        }
        BitGrid full({10, 10, 10});
        for (auto& w : full.words) w = ~std::uint64_t(0);
        full.words.back() &= (std::uint64_t(1) << (1000 % 64)) - 1;
        CHECK(count_set(full) == 1000);
        BitGrid bad({10, 10, 10});
        bad.words.pop_back();
        CHECK_THROWS_AS(count_set(bad), std::invalid_argument);
        bad.words.resize(40);
        CHECK_THROWS_AS(count_set(bad), std::invalid_argument);
    }
}
