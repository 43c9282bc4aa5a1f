// Lab 08 hidden tests: run by the grader, left out of the student release. Same tasks (suites) as the public ones,
// same independent references (helpers.hpp): 128-bit indices, clipping, shapes' equations, formulas.
#include "geolab/grading/chain.hpp"
#include "helpers.hpp"

using namespace lab08;

namespace {
void check_grid(const BitGrid& got, const BitGrid& want, const std::string& what) {
    const std::string diff = first_difference(got, want);
    CHECK_MESSAGE(diff.empty(), what << ": " << diff);
    CHECK_MESSAGE(tail_clean(got), what << ": the bits past the last voxel must stay 0");
}
// Octahedron with the perturbation rule (see test_solid.cpp).
BitGrid octahedron_solid(Dims d, glm::dvec3 c, double r) {
    return grid_of(d, [&](std::int64_t i, std::int64_t j, std::int64_t k) {
        const glm::dvec3 p(i + 0.5, j + 0.5, k + 0.5);
        const double f = std::abs(p.x - c.x) + std::abs(p.y - c.y) + std::abs(p.z - c.z);
        return f < r || (f == r && p.x < c.x);
    });
}
}  // namespace

TEST_SUITE("Task 1: the packed grid") {
    TEST_CASE("packed grid hidden: random voxels of grids up to 2^40 voxels" * geolab::points(2) * geolab::hidden() *
              geolab::hint("64-bit unsigned arithmetic throughout")) {
        Rng rng(41);
        for (int n = 0; n < 300; ++n) {
            const Dims d{std::int64_t(rng.integer(1, 1 << 14)), std::int64_t(rng.integer(1, 1 << 13)), std::int64_t(rng.integer(1, 1 << 13))};
            const std::int64_t i = rng.integer(0, int(d.nx - 1)), j = rng.integer(0, int(d.ny - 1)), k = rng.integer(0, int(d.nz - 1));
            const unsigned __int128 want = (unsigned __int128)i + (unsigned __int128)d.nx * ((unsigned __int128)j + (unsigned __int128)d.ny * k);
            INFO("voxel_index(" << str(d) << ", " << i << ", " << j << ", " << k << ")");
            CHECK(voxel_index(d, i, j, k) == std::uint64_t(want));
        }
    }
}

TEST_SUITE("Task 2: the triangle-box test") {
    TEST_CASE("triangle-box hidden: far from the origin; thin slivers; all 13 axes" * geolab::points(3) * geolab::hidden() *
              geolab::hint("the same 13 axes at any position; no tolerance")) {
        Rng rng(77);
        int n_overlap = 0;
        for (int n = 0; n < 3000; ++n) {
            const glm::dvec3 base(rng.integer(-1000, 1000), rng.integer(-1000, 1000), rng.integer(-1000, 1000));
            std::array<glm::dvec3, 3> t;
            const glm::dvec3 a = base + glm::dvec3(rng.uniform(-1, 2), rng.uniform(-1, 2), rng.uniform(-1, 2));
            const glm::dvec3 dir(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2));
            const double w = n % 2 ? 0.05 : 1.0;
            t = {a, a + dir, a + 0.5 * dir + w * glm::dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1))};
            const auto i = std::int64_t(base.x), j = std::int64_t(base.y), k = std::int64_t(base.z);
            const bool want = expected_overlap(t, i, j, k);
            n_overlap += want;
            const bool got = triangle_overlaps_voxel(t[0], t[1], t[2], i, j, k);
            INFO("triangle " << str(t[0]) << " " << str(t[1]) << " " << str(t[2]) << ", voxel (" << i << ", " << j << ", " << k
                             << "): expected " << want << ", got " << got);
            CHECK(got == want);
        }
        CHECK(n_overlap > 300);
    }
}

TEST_SUITE("Task 3: surface voxelization") {
    TEST_CASE("surface hidden: quads; meshes across the grid's border; several threads" * geolab::points(3) *
              geolab::hidden() * geolab::hint("fan-triangulate faces; clip voxel ranges to [0, n − 1]; threads must not race")) {
        Rng rng(3);
        std::vector<PolygonSoup> keep;  // every mesh stays alive: the grader keys its digests by address and size
        keep.reserve(6);
        for (int n = 0; n < 6; ++n) {
            const Dims d{std::int64_t(rng.integer(5, 14)), std::int64_t(rng.integer(5, 14)), std::int64_t(rng.integer(5, 14))};
            const glm::dvec3 c(rng.uniform(0, double(d.nx)), rng.uniform(0, double(d.ny)), rng.uniform(0, double(d.nz)));
            const PolygonSoup& s = keep.emplace_back(n % 2 ? icosphere(c, rng.uniform(1.5, 6), 2) : octahedron(glm::round(c) + 0.5, double(rng.integer(2, 6))));
            const BitGrid want = expected_surface(s, d);
            check_grid(voxelize_surface(s, d, 1), want, "mesh " + std::to_string(n) + " in " + str(d));
            check_grid(voxelize_surface(s, d, 3), want, "mesh " + std::to_string(n) + ", 3 threads");
        }
        // quads: a box written with 6 quads is the same as with 12 triangles
        PolygonSoup quads;
        const PolygonSoup tri = box_mesh({1, 2, 1}, {5, 6, 7});
        quads.positions = tri.positions;
        for (std::size_t f = 0; f < tri.n_faces(); f += 2) {
            const auto a = tri.face(f), b = tri.face(f + 1);
            quads.add_face({a[0], a[1], a[2], b[2]});
        }
        check_grid(voxelize_surface(quads, {8, 8, 8}, 1), expected_surface(tri, {8, 8, 8}), "a box of quads");
    }
}

TEST_SUITE("Task 4: solid voxelization") {
    TEST_CASE("solid hidden: octahedra with vertices at voxel centres; every axis; threads" * geolab::points(3) *
              geolab::hidden() * geolab::hint("exact predicates and the perturbation c + (ε, ε², ε³)")) {
        Rng rng(44);
        for (int n = 0; n < 8; ++n) {
            const Dims d{std::int64_t(rng.integer(6, 16)), std::int64_t(rng.integer(6, 16)), std::int64_t(rng.integer(6, 16))};
            const glm::dvec3 c(rng.integer(0, int(d.nx)) + 0.5, rng.integer(0, int(d.ny)) + 0.5, rng.integer(0, int(d.nz)) + 0.5);
            const double r = rng.integer(1, 7);
            const BitGrid want = octahedron_solid(d, c, r);
            for (int axis = 0; axis < 3; ++axis)
                check_grid(parity_fill(octahedron(c, r), d, axis, 1 + n % 3), want,
                           "octahedron " + str(c) + " r " + std::to_string(r) + " in " + str(d) + ", axis " + std::to_string(axis));
        }
    }
    TEST_CASE("solid hidden: closed meshes snapped to quarter voxels: the three axes agree" * geolab::points(3) *
              geolab::hidden() * geolab::hint("ties everywhere: vertices and edges on the rays; the perturbation decides")) {
        Rng rng(45);
        std::vector<PolygonSoup> keep;  // every mesh stays alive: the grader keys its digests by address and size
        keep.reserve(6);
        for (int n = 0; n < 6; ++n) {
            PolygonSoup& s = keep.emplace_back(icosphere({8, 8, 8}, rng.uniform(3, 7), 2));
            for (auto& p : s.positions) p = glm::round(p * 2.0) / 2.0;
            const Dims d{16, 16, 16};
            const BitGrid x = parity_fill(s, d, 0, 1), y = parity_fill(s, d, 1, 1), z = parity_fill(s, d, 2, 1);
            CHECK_MESSAGE(first_difference(y, x).empty(), "snapped sphere " << n << ": y vs x: " << first_difference(y, x));
            CHECK_MESSAGE(first_difference(z, x).empty(), "snapped sphere " << n << ": z vs x: " << first_difference(z, x));
            int checked = 0;  // and x is the solid: every voxel centre off the surface, by the winding number
            const std::string wrong = parity_spot_check(x, s, rng, -1, &checked);
            CHECK_MESSAGE(wrong.empty(), "snapped sphere " << n << ", axis x against the winding number: " << wrong);
            CHECK_MESSAGE(checked > 2000, "test self-check: only " << checked << " voxel centres off the surface");
            const SolidResult r = voxelize_solid(s, d, 2);
            CHECK(r.method == SolidMethod::parity);
            CHECK(r.axis_disagreements == 0);
            check_grid(r.grid, x, "voxelize_solid of snapped sphere " + std::to_string(n));
        }
    }
    TEST_CASE("solid hidden: elephant-with-holes goes through the flood fill" * geolab::points(2) * geolab::hidden() *
              geolab::builds_on("Task 3") *
              geolab::hint("boundary edges → flood_fill_solid of the surface, reported as SolidMethod::flood_fill")) {
        const PolygonSoup m = model_in_grid("elephant-with-holes", 40);
        const SolidResult r = voxelize_solid(m, {40, 40, 40}, 2);
        CHECK(r.method == SolidMethod::flood_fill);
        CHECK(r.boundary_edges == boundary_edges_by_map(m));
        const BitGrid surface = voxelize_surface(m, {40, 40, 40}, 1);  // the contract's solid of YOUR surface voxels
        check_grid(r.grid, expected_flood_fill(surface), "elephant-with-holes at 40³");
    }
}

TEST_SUITE("Task 5: voxel CSG") {
    TEST_CASE("CSG hidden: add with zero and negative weights; empty grids" * geolab::points(1) * geolab::hidden() *
              geolab::hint("C1·F1 + C2·F2 exactly; a 0-voxel grid gives a 0-voxel grid")) {
        ValueGrid a, b;
        a.dims = b.dims = {2, 1, 1};
        a.values = {1.5, -2};
        b.values = {4, 0.25};
        const ValueGrid s = csg_add(a, b, 0, -1);
        REQUIRE(s.values.size() == 2);
        CHECK(s.values[0] == -4);
        CHECK(s.values[1] == -0.25);
        ValueGrid e;
        e.dims = {0, 3, 3};
        CHECK(csg_union(e, e).values.empty());
        CHECK(csg_subtract(a, b).values == std::vector<double>{0, 0});
    }
}

TEST_SUITE("Task 6: binvox") {
    TEST_CASE("binvox hidden: a voxelized bunny round trips; corrupted files never crash" * geolab::points(3) *
              geolab::hidden() * geolab::hint("every byte of a hostile file is checked; errors are geolab::IoError")) {
        Binvox b;
        b.grid = grid_of({24, 24, 24}, [](auto i, auto j, auto k) { return (i * 7 + j * 3 + k * k) % 5 < 2 || (i > 10 && j < 8); });
        b.translate = {-0.25, 1e-3, 12.5};
        b.scale = 3.75;
        const std::string bytes = encode_binvox(b);
        const Binvox back = decode_binvox(bytes);
        CHECK(first_difference(back.grid, b.grid).empty());
        Rng rng(66);
        int errors = 0;
        for (int n = 0; n < 400; ++n) {
            std::string bad = bytes;
            const int flips = rng.integer(1, 4);
            for (int f = 0; f < flips; ++f) bad[std::size_t(rng.integer(0, int(bad.size() - 1)))] = char(rng.integer(0, 255));
            if (n % 4 == 0) bad.resize(std::size_t(rng.integer(0, int(bad.size()))));
            try {
                const Binvox r = decode_binvox(bad, "corrupt");
                CHECK(r.grid.dims.nx == r.grid.dims.ny);
                CHECK(tail_clean(r.grid));
            } catch (const geolab::IoError&) {
                ++errors;
            }
        }
        CHECK(errors > 100);
    }
}
