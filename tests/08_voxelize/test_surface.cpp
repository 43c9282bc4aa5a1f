// Lab 08, Task 3: surface voxelization. Expected grids by construction (boxes on voxel planes) and by the clipping
// rule voxel by voxel (helpers.hpp).
#include "geolab/grading/chain.hpp"
#include "helpers.hpp"

using namespace lab08;

namespace {
void check_grid(const BitGrid& got, const BitGrid& want, const std::string& what) {
    const std::string diff = first_difference(got, want);
    INFO(what << ": expected " << count_bits(want) << " voxels, got " << (got.dims == want.dims ? count_bits(got) : 0));
    CHECK_MESSAGE(diff.empty(), what << ": " << diff);
    CHECK_MESSAGE(tail_clean(got), what << ": the bits past the last voxel must stay 0");
}
// The shell of the box of voxels [a, b]³ (both inclusive).
BitGrid shell(Dims d, std::int64_t a, std::int64_t b) {
    return grid_of(d, [&](std::int64_t i, std::int64_t j, std::int64_t k) {
        const bool in = i >= a && i <= b && j >= a && j <= b && k >= a && k <= b;
        const bool inner = i > a && i < b && j > a && j < b && k > a && k < b;
        return in && !inner;
    });
}
}  // namespace

// voxelize_surface applies triangle_overlaps_voxel's rule (its contract): your surface voxelization calls your
// Task 2, so the tests that voxelize something build on it (geolab/grading/chain.hpp).
TEST_SUITE("Task 3: surface voxelization") {
    TEST_CASE("surface: a cube on voxel boundaries gets no extra layer" * geolab::points(4) * geolab::builds_on("Task 2") *
              geolab::hint("a face in the plane x = m belongs to the layer behind its normal only (Task 2's rule)")) {
        const Dims d{10, 10, 10};
        check_grid(voxelize_surface(box_mesh({2, 2, 2}, {6, 6, 6}), d, 1), shell(d, 2, 5), "outward cube [2, 6]³");
        // inward normals: the layer behind each face is outside the cube
        const BitGrid faces_outside = grid_of(d, [](std::int64_t i, std::int64_t j, std::int64_t k) {
            const int on = (i == 1 || i == 6) + (j == 1 || j == 6) + (k == 1 || k == 6);
            const int in = (i >= 2 && i <= 5) + (j >= 2 && j <= 5) + (k >= 2 && k <= 5);
            return on == 1 && in == 2;  // six 4 x 4 layers, no edges or corners
        });
        check_grid(voxelize_surface(box_mesh({2, 2, 2}, {6, 6, 6}, true), d, 1), faces_outside, "inward cube [2, 6]³");
        // faces between voxel planes: the layer they cross
        check_grid(voxelize_surface(box_mesh({2.5, 2.5, 2.5}, {6.5, 6.5, 6.5}), d, 1), shell(d, 2, 6), "cube [2.5, 6.5]³");
        // a non-cubic grid
        const Dims e{9, 6, 4};
        const BitGrid want = grid_of(e, [](std::int64_t i, std::int64_t j, std::int64_t k) {
            const bool in = i >= 1 && i <= 7 && j >= 1 && j <= 4 && k >= 1 && k <= 2;
            return in && !(i > 1 && i < 7 && j > 1 && j < 4 && k > 1 && k < 2);
        });
        check_grid(voxelize_surface(box_mesh({1, 1, 1}, {8, 5, 3}), e, 1), want, "box [1,8]x[1,5]x[1,3] in 9 x 6 x 4");
    }
    TEST_CASE("surface: the grid's far faces" * geolab::points(2) * geolab::builds_on("Task 2") *
              geolab::hint("voxel ranges end at n − 1: a mesh on the far face x = n belongs to layer n − 1")) {
        for (std::int64_t n : {3, 8, 13}) {
            const Dims d{n, n, n};
            const double m = double(n);
            check_grid(voxelize_surface(box_mesh({0, 0, 0}, {m, m, m}), d, 1), shell(d, 0, n - 1),
                       "the cube filling a " + std::to_string(n) + "³ grid");
        }
        // a mesh that pokes out of the grid: only the voxels inside
        const Dims d{6, 6, 6};
        const PolygonSoup big = box_mesh({-2.5, 1.5, 1.5}, {8.5, 4.5, 4.5});
        check_grid(voxelize_surface(big, d, 1), expected_surface(big, d), "a box poking out of both ends of x");
        const PolygonSoup far = box_mesh({1.25, 1.25, 5.5}, {4.75, 4.75, 9});
        check_grid(voxelize_surface(far, d, 1), expected_surface(far, d), "a box through the far face z = 6");
    }
    TEST_CASE("surface: spheres and octahedra agree with the rule voxel by voxel" * geolab::points(3) * geolab::builds_on("Task 2") *
              geolab::hint("every voxel of each triangle's bounding box, tested with triangle_overlaps_voxel")) {
        struct C {
            PolygonSoup s;
            Dims d;
            std::string what;
        };
        for (const C& c : {C{icosphere({6.3, 5.7, 6.1}, 4.6, 2), {13, 12, 13}, "icosphere r 4.6"},
                           C{octahedron({5, 5, 5}, 4), {10, 10, 10}, "octahedron, vertices on voxel corners"},
                           C{octahedron({4.5, 4.5, 4.5}, 3), {9, 9, 9}, "octahedron, vertices at voxel centres"},
                           C{icosphere({2, 2, 2}, 7, 1), {8, 8, 8}, "a sphere larger than the grid"}})
            check_grid(voxelize_surface(c.s, c.d, 1), expected_surface(c.s, c.d), c.what);
    }
    TEST_CASE("surface: 2; 3 and 8 threads give exactly the 1-thread grid (bunny00; 96³)" * geolab::points(3) * geolab::builds_on("Task 2") *
              geolab::time_limit(60) *
              geolab::hint("threads that OR bits into the same 64-bit word race: use std::atomic_ref's fetch_or, or give "
                           "each thread whole words")) {
        const PolygonSoup m = model_in_grid("bunny00", 96);
        const Dims d{96, 96, 96};
        const BitGrid one = voxelize_surface(m, d, 1);
        CHECK(count_bits(one) > 20000);
        for (int rep = 0; rep < 3; ++rep)
            for (int t : {2, 3, 8}) check_grid(voxelize_surface(m, d, t), one, std::to_string(t) + " threads");
        // every voxel of a 512 x 512 layer set by its own triangle: threads write the same words at the same time
        const PolygonSoup layer = dust(512, 512, 1.2);
        const Dims e{512, 512, 3};
        const BitGrid want = grid_of(e, [](std::int64_t, std::int64_t, std::int64_t k) { return k == 1; });
        for (int rep = 0; rep < 12; ++rep)
            for (int t : {2, 8}) check_grid(voxelize_surface(layer, e, t), want, "dust layer, " + std::to_string(t) + " threads");
    }
    TEST_CASE("surface: bad arguments are errors" * geolab::points(1) *
              geolab::hint("threads < 1 and invalid soups (check_soup) throw std::invalid_argument")) {
        CHECK_THROWS_AS(voxelize_surface(box_mesh({1, 1, 1}, {2, 2, 2}), {4, 4, 4}, 0), std::invalid_argument);
        PolygonSoup bad = box_mesh({1, 1, 1}, {2, 2, 2});
        bad.indices[5] = 99;
        CHECK_THROWS_AS(voxelize_surface(bad, {4, 4, 4}, 1), std::invalid_argument);
        const BitGrid empty = voxelize_surface(box_mesh({1, 1, 1}, {2, 2, 2}), {0, 0, 0}, 1);
        CHECK(empty.words.empty());
    }
}
