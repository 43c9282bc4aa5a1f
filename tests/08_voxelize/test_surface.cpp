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
    TEST_CASE("surface: a cube on voxel boundaries gets no extra layer" * geolab::points(2) *
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
    TEST_CASE("surface: the grid's far faces" * geolab::points(2) *
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
    TEST_CASE("surface: spheres and octahedra agree with the rule voxel by voxel" * geolab::points(2) *
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
        // single triangles with vertices on a half-voxel lattice: normals and edge axes with components 0 and ±1
        // (the normal (1, 1, 1) among them)
        const Dims d6{6, 6, 6};
        PolygonSoup t111;
        t111.positions = {{3, 2, 2}, {2, 3, 2}, {2, 2, 3}};
        t111.add_face({0, 1, 2});
        check_grid(voxelize_surface(t111, d6, 1), expected_surface(t111, d6), "triangle (3,2,2) (2,3,2) (2,2,3), normal (1,1,1)");
        Rng rng(8);
        for (int n = 0; n < 150; ++n) {
            PolygonSoup t;
            for (int v = 0; v < 3; ++v)
                t.positions.push_back(glm::dvec3(rng.integer(1, 11), rng.integer(1, 11), rng.integer(1, 11)) * 0.5);
            t.add_face({0, 1, 2});
            check_grid(voxelize_surface(t, d6, 1), expected_surface(t, d6),
                       "triangle " + str(t.positions[0]) + " " + str(t.positions[1]) + " " + str(t.positions[2]) + " in 6 x 6 x 6");
        }
    }
    TEST_CASE("surface: 2; 3 and 8 threads give exactly the 1-thread grid (bunny00; 96³)" * geolab::points(2) *
              geolab::time_limit(60) *
              geolab::hint("threads that OR bits into the same 64-bit word race: use std::atomic_ref's fetch_or, or give "
                           "each thread whole words")) {
        const PolygonSoup m = model_in_grid("bunny00", 96);
        const Dims d{96, 96, 96};
        const BitGrid one = voxelize_surface(m, d, 1);
        CHECK(count_bits(one) > 20000);
        for (int t : {2, 3, 8}) check_grid(voxelize_surface(m, d, t), one, std::to_string(t) + " threads");
        // every voxel of a layer set by its own triangle:
        // a 512 x 512 layer in row order: threads that take the triangles in turn write neighbouring bits at once;
        // a 128 x 128 layer shuffled, many times: whatever block of triangles a thread takes, its bits lie in every
        // word, written at any moment by any thread
        for (const std::int64_t n : {512, 128}) {
            const bool shuffle = n == 128;
            const PolygonSoup layer = dust(n, n, 1.2, shuffle);
            const Dims e{n, n, 3};
            const BitGrid want = grid_of(e, [](std::int64_t, std::int64_t, std::int64_t k) { return k == 1; });
            for (int rep = 0; rep < (shuffle ? 60 : 4); ++rep)
                for (int t : {2, 8})
                    check_grid(voxelize_surface(layer, e, t), want, (shuffle ? "shuffled dust layer " : "dust layer ") + str(e) + ", " + std::to_string(t) + " threads");
        }
    }
    TEST_CASE("surface: triangles only an edge cross-product axis separates from a voxel of their box" *
              geolab::points(1) *
              geolab::hint("Task 2's nine edge axes matter here too: a voxel of the bounding box that neither the box's "
                           "normals nor the triangle's normal separate may still be missed")) {
        // 64 such triangles, each near its own voxel (6·a, 6·b, 6·c) of a 24³ grid, in one soup
        const auto tris = edge_axis_triangles(64, 13);
        REQUIRE_MESSAGE(tris.size() == 64, "test self-check: only " << tris.size() << " edge-axis triangles found");
        PolygonSoup soup;
        for (std::size_t n = 0; n < tris.size(); ++n) {
            const glm::dvec3 offset(6.0 * double(n % 4) + 2, 6.0 * double(n / 4 % 4) + 2, 6.0 * double(n / 16) + 2);
            const auto b = std::uint32_t(soup.positions.size());
            for (const glm::dvec3& p : tris[n]) soup.positions.push_back(p + offset);
            soup.add_face({b, b + 1, b + 2});
        }
        const Dims d{24, 24, 24};
        const BitGrid want = expected_surface(soup, d);
        for (std::size_t n = 0; n < tris.size(); ++n)
            REQUIRE_MESSAGE(!want.get(std::int64_t(6 * (n % 4) + 2), std::int64_t(6 * (n / 4 % 4) + 2), std::int64_t(6 * (n / 16) + 2)),
                            "test self-check: triangle " << n << " meets its voxel");
        check_grid(voxelize_surface(soup, d, 1), want, "64 edge-axis triangles " + str(tris[0][0]) + " ... in 24³");
    }
    TEST_CASE("surface: the layers k0 to k1 are that slab of the whole grid" * geolab::points(2) *
              geolab::hint("voxel (i, j, k) of the whole grid is voxel (i, j, k − k0) of the layers; a face on the "
                           "slab's boundary plane follows Task 2's rule like any other")) {
        struct C {
            PolygonSoup s;
            Dims d;
            std::string what;
        };
        for (const C& c : {C{box_mesh({2, 2, 2}, {6, 6, 6}), {10, 10, 10}, "outward cube [2, 6]³"},
                           C{box_mesh({2, 2, 2}, {6, 6, 6}, true), {10, 10, 10}, "inward cube [2, 6]³"},
                           C{icosphere({6.3, 5.7, 6.1}, 4.6, 2), {13, 12, 13}, "icosphere r 4.6"},
                           C{octahedron({5, 5, 5}, 4), {11, 9, 10}, "octahedron, vertices on voxel corners"}}) {
            const BitGrid whole = expected_surface(c.s, c.d);
            const std::int64_t n = c.d.nz;
            for (auto [k0, k1] : {std::pair<std::int64_t, std::int64_t>{0, n}, {0, 2}, {2, 6}, {6, n}, {1, 7}, {n - 1, n}, {3, 3}}) {
                const std::string what = c.what + ", layers [" + std::to_string(k0) + ", " + std::to_string(k1) + ")";
                check_grid(voxelize_surface_layers(c.s, c.d, k0, k1, 1), layers_of(whole, k0, k1), what);
            }
            check_grid(voxelize_surface_layers(c.s, c.d, 1, n - 1, 3), layers_of(whole, 1, n - 1), c.what + ", 3 threads");
        }
        const PolygonSoup cube = box_mesh({1, 1, 1}, {3, 3, 3});
        for (auto [k0, k1] : {std::pair<std::int64_t, std::int64_t>{-1, 2}, {3, 2}, {0, 5}}) {
            INFO("voxelize_surface_layers of a 4³ grid, layers [" << k0 << ", " << k1 << "): expected std::invalid_argument");
            CHECK_THROWS_AS(voxelize_surface_layers(cube, {4, 4, 4}, k0, k1, 1), std::invalid_argument);
        }
    }
    TEST_CASE("surface: tall grids and long rows (faces on many layer planes; 1; 2 and 4 threads)" * geolab::points(1) *
              geolab::hint("however the work is split (by triangles, rows or layers), every layer gets every voxel "
                           "of every triangle that belongs to it, and rows longer than a word are whole")) {
        struct C {
            PolygonSoup s;
            Dims d;
            std::string what;
        };
        for (const C& c : {C{box_mesh({1, 1, 8}, {7, 7, 16}), {8, 8, 64}, "box [1,7]x[1,7]x[8,16] in 8 x 8 x 64"},
                           C{box_mesh({1, 1, 16}, {7, 7, 48}, true), {8, 8, 64}, "inward box [1,7]x[1,7]x[16,48]"},
                           C{box_mesh({2, 2, 24}, {6, 6, 40}), {8, 8, 64}, "box [2,6]x[2,6]x[24,40]"},
                           C{box_mesh({0, 0, 0}, {8, 8, 64}), {8, 8, 64}, "the box filling 8 x 8 x 64"},
                           C{octahedron({4, 4, 32}, 4), {8, 8, 64}, "octahedron centre (4, 4, 32) r 4"},
                           C{icosphere({4.1, 3.9, 30.3}, 3.6, 2), {8, 8, 64}, "icosphere r 3.6 across layers 26..34"},
                           C{box_mesh({1.5, 1, 1}, {128.5, 4, 5}), {130, 5, 6}, "box [1.5,128.5]x[1,4]x[1,5] in 130 x 5 x 6"}})
            for (int t : {1, 2, 4}) check_grid(voxelize_surface(c.s, c.d, t), expected_surface(c.s, c.d), c.what + ", " + std::to_string(t) + " thread(s)");
    }
    TEST_CASE("surface: bad arguments are errors" * geolab::points(1) *
              geolab::hint("threads < 1 and invalid soups (check_soup) throw std::invalid_argument")) {
        CHECK_THROWS_AS(voxelize_surface(box_mesh({1, 1, 1}, {2, 2, 2}), {4, 4, 4}, 0), std::invalid_argument);
        PolygonSoup bad = box_mesh({1, 1, 1}, {2, 2, 2});
        bad.indices[5] = 99;
        CHECK_THROWS_AS(voxelize_surface(bad, {4, 4, 4}, 1), std::invalid_argument);
        const BitGrid empty = voxelize_surface(box_mesh({1, 1, 1}, {2, 2, 2}), {0, 0, 0}, 1);
        CHECK(empty.words.empty());
        CHECK_THROWS_AS(voxelize_surface_layers(box_mesh({1, 1, 1}, {2, 2, 2}), {4, 4, 64}, 0, 64, 0), std::invalid_argument);
        // a triangle of zero area (its vertices on a line) belongs to no voxel
        PolygonSoup flat;
        flat.positions = {{0.5, 0.5, 0.5}, {1.5, 1.5, 1.5}, {3.5, 3.5, 3.5}};
        flat.add_face({0, 1, 2});
        CHECK_MESSAGE(count_bits(voxelize_surface(flat, {4, 4, 4}, 1)) == 0,
                      "the zero-area triangle (0.5,0.5,0.5) (1.5,1.5,1.5) (3.5,3.5,3.5): expected no voxels, got "
                          << count_bits(voxelize_surface(flat, {4, 4, 4}, 1)));
        // one voxel
        PolygonSoup one;
        one.positions = {{0.2, 0.3, 0.5}, {0.8, 0.4, 0.5}, {0.5, 0.9, 0.6}};
        one.add_face({0, 1, 2});
        CHECK_MESSAGE(count_bits(voxelize_surface(one, {1, 1, 1}, 1)) == 1,
                      "a triangle inside the only voxel of a 1 x 1 x 1 grid: expected 1 voxel, got " << count_bits(voxelize_surface(one, {1, 1, 1}, 1)));
    }
}
