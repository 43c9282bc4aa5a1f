// Lab 08, Task 4: solid voxelization. Expected grids from the shapes' own equations with the same perturbation
// (c + (ε, ε², ε³)), worked out by hand for boxes and octahedra; volumes from the divergence theorem.
#include <list>

#include "geolab/grading/chain.hpp"
#include "helpers.hpp"

using namespace lab08;

namespace {
void check_grid(const BitGrid& got, const BitGrid& want, const std::string& what) {
    const std::string diff = first_difference(got, want);
    CHECK_MESSAGE(diff.empty(), what << ": " << diff);
    CHECK_MESSAGE(tail_clean(got), what << ": the bits past the last voxel must stay 0");
}
// Box [lo, hi]: the perturbed centre p + (ε, ε², ε³) is inside iff lo ≤ p < hi on every axis.
BitGrid box_solid(Dims d, glm::dvec3 lo, glm::dvec3 hi) {
    return grid_of(d, [&](std::int64_t i, std::int64_t j, std::int64_t k) {
        const glm::dvec3 p(i + 0.5, j + 0.5, k + 0.5);
        return lo.x <= p.x && p.x < hi.x && lo.y <= p.y && p.y < hi.y && lo.z <= p.z && p.z < hi.z;
    });
}
// Octahedron |x−c.x| + |y−c.y| + |z−c.z| ≤ r: on the surface the ε term decides, sign(p.x − c.x) with 0 → +.
BitGrid octahedron_solid(Dims d, glm::dvec3 c, double r) {
    return grid_of(d, [&](std::int64_t i, std::int64_t j, std::int64_t k) {
        const glm::dvec3 p(i + 0.5, j + 0.5, k + 0.5);
        const double f = std::abs(p.x - c.x) + std::abs(p.y - c.y) + std::abs(p.z - c.z);
        return f < r || (f == r && p.x < c.x);
    });
}
}  // namespace

TEST_SUITE("Task 4: solid voxelization") {
    TEST_CASE("solid: parity along each axis fills boxes; centres on faces follow the perturbation" * geolab::points(2) *
              geolab::hint("a voxel is set when the ray from its centre to −axis crosses an odd number of triangles; a "
                           "centre exactly on a face is decided by c + (ε, ε², ε³)")) {
        const Dims d{10, 10, 10};
        struct C {
            glm::dvec3 lo, hi;
        };
        for (const C& c : {C{{2, 2, 2}, {6, 6, 6}}, C{{1.5, 1.5, 1.5}, {5.5, 5.5, 5.5}}, C{{0.5, 2.5, 1}, {9.5, 3.5, 8.75}},
                           C{{-3, 4.5, 2.2}, {4.5, 20, 7.5}}})
            for (int axis = 0; axis < 3; ++axis)
                check_grid(parity_fill(box_mesh(c.lo, c.hi), d, axis, 1), box_solid(d, c.lo, c.hi),
                           "box " + str(c.lo) + " - " + str(c.hi) + ", axis " + std::to_string(axis));
        // centres on faces: 4 layers each way, 64 voxels exactly
        CHECK(count_bits(box_solid(d, {1.5, 1.5, 1.5}, {5.5, 5.5, 5.5})) == 64);
    }
    TEST_CASE("solid: rays through edges and vertices (octahedra with vertices at voxel centres)" * geolab::points(2) *
              geolab::hint("a ray through a shared edge or vertex must count exactly one crossing: decide orient2d = 0 "
                           "by the perturbation (simulation of simplicity), not by ≥ 0 or > 0")) {
        struct C {
            glm::dvec3 c;
            double r;
            Dims d;
        };
        for (const C& c : {C{{4.5, 4.5, 4.5}, 3, {9, 9, 9}}, C{{5.5, 4.5, 6.5}, 4, {12, 10, 12}}, C{{3.5, 3.5, 3.5}, 2, {7, 7, 7}},
                           C{{4, 4, 4}, 3, {8, 8, 8}}, C{{5.5, 5.5, 5.5}, 5.5, {11, 11, 11}}})
            for (int axis = 0; axis < 3; ++axis)
                check_grid(parity_fill(octahedron(c.c, c.r), c.d, axis, 1), octahedron_solid(c.d, c.c, c.r),
                           "octahedron centre " + str(c.c) + " r " + std::to_string(c.r) + ", axis " + std::to_string(axis));
    }
    TEST_CASE("solid: parity_fill_layers is that slab of parity_fill; along z the triangles below it count" *
              geolab::points(2) *
              geolab::hint("voxel (i, j, k) of the whole grid is voxel (i, j, k − k0) of the layers; a ray along −z goes "
                           "on below layer k0 (and below the grid): every triangle under the slab flips its columns")) {
        const Dims d{10, 9, 12};
        struct C {
            PolygonSoup s;
            BitGrid want;
            std::string what;
        };
        const glm::dvec3 lo(1.5, 2.25, -3), hi(8.5, 7, 9.5);  // its bottom below the grid
        for (const C& c : {C{box_mesh(lo, hi), box_solid(d, lo, hi), "box " + str(lo) + " - " + str(hi)},
                           C{box_mesh({2, 2, 2}, {6, 6, 6}), box_solid(d, {2, 2, 2}, {6, 6, 6}), "box [2, 6]³"},
                           C{octahedron({4.5, 4.5, 5.5}, 4), octahedron_solid(d, {4.5, 4.5, 5.5}, 4),
                             "octahedron centre (4.5, 4.5, 5.5) r 4"}})
            for (int axis = 0; axis < 3; ++axis)
                for (auto [k0, k1] : {std::pair<std::int64_t, std::int64_t>{0, 12}, {5, 9}, {7, 8}, {11, 12}, {2, 6}, {4, 4}}) {
                    const std::string what = c.what + ", axis " + std::to_string(axis) + ", layers [" + std::to_string(k0) +
                                             ", " + std::to_string(k1) + ")";
                    check_grid(parity_fill_layers(c.s, d, axis, k0, k1, 1), layers_of(c.want, k0, k1), what);
                }
        const BitGrid oct = octahedron_solid(d, {4.5, 4.5, 5.5}, 4);
        check_grid(parity_fill_layers(octahedron({4.5, 4.5, 5.5}, 4), d, 2, 3, 11, 3), layers_of(oct, 3, 11),
                   "octahedron, axis 2, layers [3, 11), 3 threads");
        const PolygonSoup cube = box_mesh({1, 1, 1}, {3, 3, 3});
        for (auto [k0, k1] : {std::pair<std::int64_t, std::int64_t>{-1, 2}, {3, 2}, {0, 5}}) {
            INFO("parity_fill_layers of a 4³ grid, layers [" << k0 << ", " << k1 << "): expected std::invalid_argument");
            CHECK_THROWS_AS(parity_fill_layers(cube, {4, 4, 4}, 2, k0, k1, 1), std::invalid_argument);
        }
        CHECK_THROWS_AS(parity_fill_layers(cube, {4, 4, 4}, 3, 0, 4, 1), std::invalid_argument);
        CHECK_THROWS_AS(parity_fill_layers(cube, {4, 4, 4}, 0, 0, 4, 0), std::invalid_argument);
        CHECK_THROWS_AS(parity_fill_layers(cube, {4, 4, 64}, 2, 0, 64, 0), std::invalid_argument);
        check_grid(parity_fill_layers(box_mesh({0.2, 0.3, 0.1}, {0.9, 0.8, 0.7}), {1, 1, 1}, 2, 0, 1, 1),
                   box_solid({1, 1, 1}, {0.2, 0.3, 0.1}, {0.9, 0.8, 0.7}), "a 1 x 1 x 1 grid, box [0.2,0.9]x[0.3,0.8]x[0.1,0.7], axis 2");
    }
    TEST_CASE("solid: tall grids and long rows (faces on many layer planes; 1; 2 and 4 threads)" * geolab::points(1) *
              geolab::hint("however the work is split, every column gets every flip, and the prefix XOR runs along the "
                           "whole column: across words, rows and layers")) {
        struct C {
            PolygonSoup s;
            BitGrid want;
            std::string what;
        };
        // 65 x 33 and 63 x 33: rows start one bit past a word (a 64-bit piece reaches into the next word), and some
        // rows start at a word while the row before does not (rows 64 and 65 of 65 x 33, 64 of 63 x 33)
        const Dims tall{8, 8, 64}, wide{130, 5, 6}, odd{65, 2, 5}, odd2{63, 3, 4}, odd3{65, 33, 2}, odd4{63, 33, 2}, four{16, 16, 64};
        for (const C& c : {C{box_mesh({1, 1, 8}, {7, 7, 16}), box_solid(tall, {1, 1, 8}, {7, 7, 16}), "box [1,7]x[1,7]x[8,16] in 8 x 8 x 64"},
                           C{box_mesh({2, 1.5, 16.5}, {6.5, 7, 48}), box_solid(tall, {2, 1.5, 16.5}, {6.5, 7, 48}), "box [2,6.5]x[1.5,7]x[16.5,48]"},
                           C{box_mesh({0, 0, -5}, {8, 8, 70}), box_solid(tall, {0, 0, -5}, {8, 8, 70}), "a box around the whole grid"},
                           C{octahedron({3.5, 4.5, 31.5}, 4), octahedron_solid(tall, {3.5, 4.5, 31.5}, 4), "octahedron centre (3.5, 4.5, 31.5) r 4"},
                           C{box_mesh({1.5, 1, 1}, {128.5, 4, 5}), box_solid(wide, {1.5, 1, 1}, {128.5, 4, 5}), "box [1.5,128.5]x[1,4]x[1,5] in 130 x 5 x 6"},
                           C{box_mesh({-3, 1, 1}, {64, 4, 5}), box_solid(wide, {-3, 1, 1}, {64, 4, 5}), "box [-3,64]x[1,4]x[1,5] in 130 x 5 x 6"},
                           C{box_mesh({2, 0.5, 1}, {60, 1.5, 4}), box_solid(odd, {2, 0.5, 1}, {60, 1.5, 4}), "box [2,60]x[0.5,1.5]x[1,4] in 65 x 2 x 5"},
                           C{box_mesh({1, 0.5, 0}, {62, 2, 3}), box_solid(odd2, {1, 0.5, 0}, {62, 2, 3}), "box [1,62]x[0.5,2]x[0,3] in 63 x 3 x 4"},
                           C{box_mesh({1.2, 0.2, 0.2}, {63.2, 32.8, 1.8}), box_solid(odd3, {1.2, 0.2, 0.2}, {63.2, 32.8, 1.8}), "box [1.2,63.2]x[0.2,32.8]x[0.2,1.8] in 65 x 33 x 2"},
                           C{box_mesh({1.2, 0.2, 0.2}, {64.2, 32.8, 1.8}), box_solid(odd3, {1.2, 0.2, 0.2}, {64.2, 32.8, 1.8}), "box [1.2,64.2]x[0.2,32.8]x[0.2,1.8] in 65 x 33 x 2"},
                           C{box_mesh({1.2, 0.2, 0.2}, {62.2, 32.8, 1.8}), box_solid(odd4, {1.2, 0.2, 0.2}, {62.2, 32.8, 1.8}), "box [1.2,62.2]x[0.2,32.8]x[0.2,1.8] in 63 x 33 x 2"},
                           C{box_mesh({2, 2, 3}, {14, 9, 60}), box_solid(four, {2, 2, 3}, {14, 9, 60}), "box [2,14]x[2,9]x[3,60] in 16 x 16 x 64 (4 words a layer)"}})
            for (int t : {1, 2, 4}) {
                for (int axis = 0; axis < 3; ++axis)
                    check_grid(parity_fill(c.s, c.want.dims, axis, t), c.want, c.what + ", axis " + std::to_string(axis) + ", " + std::to_string(t) + " thread(s)");
                check_grid(voxelize_solid(c.s, c.want.dims, t).grid, c.want, c.what + ", voxelize_solid, " + std::to_string(t) + " thread(s)");
            }
    }
    TEST_CASE("solid: a sphere's volume converges with resolution" * geolab::points(1) *
              geolab::hint("count · h³ → the enclosed volume; the error is about one layer of voxels, O(1/res)")) {
        double prev = 1e300;
        std::vector<PolygonSoup> keep;  // every mesh stays alive: the grader keys its digests by address and size
        keep.reserve(4);
        const PolygonSoup s = icosphere({0.1, -0.2, 0.3}, 1.0, 4);
        for (std::int64_t res : {16, 32, 64, 128}) {
            const Grid g = fit_grid(s, res, 1);
            const PolygonSoup& u = keep.emplace_back(to_grid_units(s, g));
            const double want = mesh_volume(u);
            const double got = double(count_bits(parity_fill(u, g.dims, 2, 1)));
            const double rel = std::abs(got - want) / want;
            INFO("icosphere at " << res << "³: " << got << " voxels, enclosed volume " << want << " voxels, relative error " << rel);
            CHECK(rel < 2.0 / double(res));
            CHECK(rel < prev);
            prev = rel;
        }
    }
    TEST_CASE("solid: the three axes agree voxel for voxel on every closed model of the course set (40³)" *
              geolab::points(2) * geolab::time_limit(120) *
              geolab::hint("exact predicates plus the same perturbed point for all three axes: a closed mesh's parity "
                           "does not depend on the ray's direction")) {
        int closed = 0, spot_checks = 0;
        Rng rng(80);
        std::list<PolygonSoup> keep;  // every mesh stays alive: the grader keys its digests by address and size
        std::vector<std::filesystem::path> files;
        for (const auto& e : std::filesystem::directory_iterator(geolab::models_dir()))
            if (e.path().extension() == ".off") files.push_back(e.path());
        std::sort(files.begin(), files.end());
        for (const auto& f : files) {
            PolygonSoup m;
            try {
                m = geolab::read_mesh(f);
                if (m.n_faces() == 0) continue;
                geolab::check_soup(m);
            } catch (const std::exception&) {
                continue;  // not a readable mesh: not part of the set
            }
            if (boundary_edges_by_map(m) != 0) continue;
            ++closed;
            const Grid g = fit_grid(m, 40, 1);
            const PolygonSoup& u = keep.emplace_back(to_grid_units(m, g));
            const BitGrid x = parity_fill(u, g.dims, 0, 1), y = parity_fill(u, g.dims, 1, 1), z = parity_fill(u, g.dims, 2, 1);
            CHECK_MESSAGE(first_difference(y, x).empty(), f.filename().string() << ": axis y vs axis x: " << first_difference(y, x));
            CHECK_MESSAGE(first_difference(z, x).empty(), f.filename().string() << ": axis z vs axis x: " << first_difference(z, x));
            // agreeing is not enough (an empty grid agrees with itself): axis x is the solid at 24 voxel centres
            int checked = 0;
            const std::string wrong = parity_spot_check(x, u, rng, 24, &checked);
            CHECK_MESSAGE(wrong.empty(), f.filename().string() << ", axis x against the winding number: " << wrong);
            spot_checks += checked;
        }
        CHECK_MESSAGE(spot_checks >= 12 * closed, "test self-check: only " << spot_checks << " voxel centres away from the surfaces");
        CHECK_MESSAGE(closed >= 20, "test self-check: only " << closed << " closed models found in " << geolab::models_dir());
    }
    TEST_CASE("solid: count_boundary_edges counts the edges of odd use" * geolab::points(1) *
              geolab::hint("fan-triangulate, merge exactly equal positions, count each undirected edge; odd = boundary")) {
        CHECK(count_boundary_edges(box_mesh({0, 0, 0}, {1, 1, 1})) == 0);
        PolygonSoup open = box_mesh({0, 0, 0}, {1, 1, 1});
        open.indices.resize(open.indices.size() - 3);
        open.offsets.pop_back();
        CHECK(count_boundary_edges(open) == 3);  // one triangle removed
        open.indices.resize(open.indices.size() - 3);
        open.offsets.pop_back();
        CHECK(count_boundary_edges(open) == 4);  // a whole face removed
        // every triangle with its own three vertices (a "triangle soup" file): still closed
        PolygonSoup split;
        const PolygonSoup o = octahedron({1, 2, 3}, 1.5);
        for (std::size_t f = 0; f < o.n_faces(); ++f) {
            const auto vs = o.face(f);
            const auto b = std::uint32_t(split.positions.size());
            for (auto v : vs) split.positions.push_back(o.positions[v]);
            split.add_face({b, b + 1, b + 2});
        }
        CHECK(count_boundary_edges(split) == 0);
        // quads (fans) and a doubled face
        PolygonSoup q;
        q.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
        q.add_face({0, 1, 2, 3});
        CHECK(count_boundary_edges(q) == 4);
        q.add_face({0, 3, 2, 1});
        CHECK(count_boundary_edges(q) == 0);
        for (const char* name : {"head", "lion", "elephant-with-holes", "cow", "bunny00"}) {
            const PolygonSoup m = load_model(name);
            INFO(name << ": expected " << boundary_edges_by_map(m) << " boundary edges");
            CHECK(count_boundary_edges(m) == boundary_edges_by_map(m));
        }
    }
    TEST_CASE("solid: flood_fill_solid fills what the outside cannot reach" * geolab::points(2) *
              geolab::hint("6-connected flood from every unset voxel on the grid's border; the rest is solid")) {
        const Dims d{8, 7, 6};
        auto shell_of = [&](int a0, int a1, int b0, int b1, int c0, int c1) {
            return grid_of(d, [=](std::int64_t i, std::int64_t j, std::int64_t k) {
                const bool in = i >= a0 && i <= a1 && j >= b0 && j <= b1 && k >= c0 && k <= c1;
                return in && !(i > a0 && i < a1 && j > b0 && j < b1 && k > c0 && k < c1);
            });
        };
        const BitGrid closed = shell_of(1, 6, 1, 5, 1, 4);
        const BitGrid want = grid_of(d, [](std::int64_t i, std::int64_t j, std::int64_t k) {
            return i >= 1 && i <= 6 && j >= 1 && j <= 5 && k >= 1 && k <= 4;
        });
        check_grid(flood_fill_solid(closed), want, "a closed shell");
        BitGrid holed = closed;
        holed.set(3, 0 + 1, 2, false);  // a hole in the face j = 1
        check_grid(flood_fill_solid(holed), holed, "a shell with a one-voxel hole");
        // a shell touching the grid's border: its inside is not reached
        const BitGrid border = shell_of(0, 7, 0, 6, 0, 5);
        const BitGrid all = grid_of(d, [](std::int64_t, std::int64_t, std::int64_t) { return true; });
        check_grid(flood_fill_solid(border), all, "a shell on the grid's border");
        check_grid(flood_fill_solid(BitGrid(d)), BitGrid(d), "an empty grid");
        // cups: every voxel of the grid's border except the inside of one face; the inside is reached through that
        // face only, so the solid is the cup itself
        const Dims c{6, 5, 4};
        for (int face = 0; face < 6; ++face) {
            const BitGrid cup = grid_of(c, [&](std::int64_t i, std::int64_t j, std::int64_t k) {
                const std::int64_t x[3] = {i, j, k}, n[3] = {c.nx, c.ny, c.nz};
                const int a = face / 2;
                const std::int64_t at = face % 2 == 0 ? 0 : n[a] - 1;
                bool border = false, inside_open = x[a] == at;
                for (int e = 0; e < 3; ++e) {
                    border = border || x[e] == 0 || x[e] == n[e] - 1;
                    if (e != a) inside_open = inside_open && x[e] > 0 && x[e] < n[e] - 1;
                }
                return border && !inside_open;
            });
            check_grid(flood_fill_solid(cup), cup, "6 x 5 x 4: the border without the inside of face " +
                                                       std::string(face % 2 == 0 ? "0" : "n - 1") + " along axis " + std::to_string(face / 2));
        }
        // 7 x 3 x 3 = 63 voxels: the whole border encloses its middle row; the last word's 64th bit stays 0
        const Dims d63{7, 3, 3};
        const BitGrid shell63 = grid_of(d63, [&](std::int64_t i, std::int64_t j, std::int64_t k) {
            return i == 0 || j == 0 || k == 0 || i == 6 || j == 2 || k == 2;
        });
        check_grid(flood_fill_solid(shell63), grid_of(d63, [](std::int64_t, std::int64_t, std::int64_t) { return true; }),
                   "7 x 3 x 3 (63 voxels), the whole border set");
    }
    TEST_CASE("solid: voxelize_solid uses parity on a closed mesh" * geolab::points(1) *
              geolab::hint("count_boundary_edges = 0 → the AND of the three parity fills; report which")) {
        const Dims d{12, 12, 12};
        const SolidResult c = voxelize_solid(octahedron({5.5, 5.5, 5.5}, 4), d, 1);
        CHECK(c.method == SolidMethod::parity);
        CHECK(c.boundary_edges == 0);
        CHECK(c.axis_disagreements == 0);
        check_grid(c.grid, octahedron_solid(d, {5.5, 5.5, 5.5}, 4), "closed octahedron");
        // one voxel: a closed box around its centre fills it
        const SolidResult one = voxelize_solid(box_mesh({0.2, 0.3, 0.1}, {0.9, 0.8, 0.7}), {1, 1, 1}, 1);
        check_grid(one.grid, box_solid({1, 1, 1}, {0.2, 0.3, 0.1}, {0.9, 0.8, 0.7}), "a 1 x 1 x 1 grid, box [0.2,0.9]x[0.3,0.8]x[0.1,0.7]");
        CHECK_THROWS_AS(voxelize_solid(octahedron({5.5, 5.5, 5.5}, 4), d, 0), std::invalid_argument);
        CHECK_THROWS_AS(voxelize_solid(box_mesh({1, 1, 1}, {3, 3, 60}), {4, 4, 64}, 0), std::invalid_argument);
    }
    // The open-mesh path is flood_fill_solid of voxelize_surface by the contract: your voxelize_solid calls your
    // surface voxelization (Task 3, which applies Task 2's rule), so this test builds on those tasks.
    TEST_CASE("solid: voxelize_solid uses the flood fill of the surface on open meshes" * geolab::points(1) *
              geolab::builds_on("Task 3") *
              geolab::hint("count_boundary_edges > 0 → flood_fill_solid of the surface voxels; report which")) {
        const Dims d{12, 12, 12};
        // a cube [2, 8]³ whose top face has a hole much smaller than a voxel: the surface voxels close it
        PolygonSoup holed = box_mesh({2, 2, 2}, {8, 8, 8});
        // replace the top face (z = 8, the second quad: triangles 2 and 3) by a fan around a tiny hole
        PolygonSoup h;
        h.positions = holed.positions;
        for (std::size_t f = 0; f < holed.n_faces(); ++f) {
            if (f == 2 || f == 3) continue;
            const auto vs = holed.face(f);
            h.add_face({vs[0], vs[1], vs[2]});
        }
        const auto b = std::uint32_t(h.positions.size());
        const double e = 0.01;
        for (glm::dvec3 p : {glm::dvec3(5 - e, 5 - e, 8), glm::dvec3(5 + e, 5 - e, 8), glm::dvec3(5 + e, 5 + e, 8), glm::dvec3(5 - e, 5 + e, 8)})
            h.positions.push_back(p);
        const std::uint32_t c4[4] = {4, 5, 7, 6};  // the top face's corners, counter-clockwise seen from +z
        for (int s = 0; s < 4; ++s) {
            const std::uint32_t a0 = c4[s], a1 = c4[(s + 1) % 4], i0 = b + std::uint32_t(s), i1 = b + std::uint32_t((s + 1) % 4);
            h.add_face({a0, a1, i1});
            h.add_face({a0, i1, i0});
        }
        REQUIRE(boundary_edges_by_map(h) == 4);
        const SolidResult o = voxelize_solid(h, d, 1);
        CHECK(o.method == SolidMethod::flood_fill);
        CHECK(o.boundary_edges == 4);
        check_grid(o.grid, box_solid(d, {2, 2, 2}, {8, 8, 8}), "a cube with a tiny hole in its top");
        // real meshes with holes
        // real meshes with holes: the head and lion masks are open shells, so the flood fill reaches both sides and
        // leaves the surface voxels plus what they enclose (a few pockets)
        for (const std::string name : {"head", "lion", "elephant-with-holes"}) {
            const PolygonSoup m = model_in_grid(name, 48);
            const SolidResult r = voxelize_solid(m, {48, 48, 48}, 1);
            INFO(name << ": method " << int(r.method) << ", " << r.boundary_edges << " boundary edges");
            CHECK(r.method == SolidMethod::flood_fill);
            CHECK(r.boundary_edges == boundary_edges_by_map(m));
            // the contract's solid of YOUR surface voxels (their correctness is Task 3's business)
            check_grid(r.grid, expected_flood_fill(voxelize_surface(m, {48, 48, 48}, 1)), name + ": flood fill of its surface");
        }
    }
    TEST_CASE("solid: 2; 3 and 8 threads give exactly the 1-thread parity (bunny00; 96³)" * geolab::points(2) *
              geolab::time_limit(60) * geolab::hint("threads flipping bits of one word race: std::atomic_ref's fetch_xor")) {
        const PolygonSoup m = model_in_grid("bunny00", 96);
        for (int axis = 0; axis < 3; ++axis) {
            const BitGrid one = parity_fill(m, {96, 96, 96}, axis, 1);
            CHECK(count_bits(one) > 100000);
            for (int t : {2, 3, 8}) check_grid(parity_fill(m, {96, 96, 96}, axis, t), one, std::to_string(t) + " threads, axis " + std::to_string(axis));
        }
        // one flip per column (a triangle under each column's centre):
        // a 512 x 512 layer in row order: threads that take the triangles in turn write neighbouring bits at once;
        // a 128 x 128 layer shuffled, many times: whatever block of triangles a thread takes, its bits lie in every
        // word, written at any moment by any thread
        for (const std::int64_t n : {512, 128}) {
            const bool shuffle = n == 128;
            const PolygonSoup layer = dust(n, n, 1.2, shuffle);
            const Dims e{n, n, 3};
            const BitGrid want = grid_of(e, [](std::int64_t, std::int64_t, std::int64_t k) { return k >= 1; });
            for (int rep = 0; rep < (shuffle ? 60 : 4); ++rep)
                for (int t : {2, 8})
                    check_grid(parity_fill(layer, e, 2, t), want, (shuffle ? "shuffled dust layer " : "dust layer ") + str(e) + ", " + std::to_string(t) + " threads");
        }
    }
}
