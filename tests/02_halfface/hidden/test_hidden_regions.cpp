// Lab 02 hidden tests of Task 6 (region decomposition): run by the grader, left out of the student release. Meshes
// from the independent builder of builder.hpp, never from build_mesh.
#include <cstdint>

#include "brute_regions.hpp"
#include "builder.hpp"
#include "geolab/volume_fixtures.hpp"
#include "helpers.hpp"
#include "region_fixtures.hpp"

using namespace lab02;

namespace {
void check_against_brute(const CellList& cl, const Mesh& m, const std::vector<std::int32_t>& labels,
                         const std::string& what) {
    INFO("input: " << what);
    const RegionComplex want = brute_region_complex(cl, labels, m);
    const RegionComplex got = region_complex(m, labels);
    const std::string diff = first_difference(want, got);
    CHECK_MESSAGE(diff.empty(), diff);
}
}  // namespace

TEST_SUITE("Task 6: regions") {
    TEST_CASE("regions (hidden): lib's tetrahedralised ball with a torus region (the paper's example)" *
              geolab::points(2) * geolab::hidden()) {
        for (int n : {5, 8}) {
            const CellList cl = cells_from(geolab::volume_fixtures::ball_with_torus(n));
            const Mesh m = hidden_build(cl);
            INFO("input: volume_fixtures::ball_with_torus(" << n << "), " << cl.n_cells() << " tets");
            const RegionComplex rc = region_complex(m, cl.labels);
            REQUIRE_MESSAGE(
                (rc.regions.size() == 2 && rc.patches.size() == 2 && rc.curves.empty() && rc.corners.empty()),
                "expected 2 regions, 2 patches, 0 curves, 0 corners; got " << counts_text(rc));
            CHECK(rc.regions[0].label == 0);
            CHECK(rc.regions[1].label == 1);
            CHECK_MESSAGE((rc.patches[0].chi == 2 && rc.patches[0].boundary_loops == 0 &&
                           rc.patches[0].regions[1] == invalid_index),
                          "patch 0: the sphere between region 0 and the outside, χ 2; got χ " << rc.patches[0].chi);
            CHECK_MESSAGE((rc.patches[1].chi == 0 && rc.patches[1].boundary_loops == 0 &&
                           rc.patches[1].regions == std::array<std::uint32_t, 2>{0, 1}),
                          "patch 1: the torus between regions 0 and 1, χ 0; got χ " << rc.patches[1].chi);
            check_against_brute(cl, m, cl.labels, "ball_with_torus(" + std::to_string(n) + ")");
            if (n % 2) continue;  // x = 0 is a lattice plane for even n only
            // the solid torus cut by the plane x = 0 into two halves (labels 1 and 2): the torus surface becomes two
            // annuli (χ 0, 2 loops each), the cut two disks, their rims two closed curves (meridians), no corner
            std::vector<std::int32_t> cut = cl.labels;
            for (std::size_t c = 0; c < cut.size(); ++c)
                if (cut[c] == 1 && list_centroid(cl, c).x > 0) cut[c] = 2;
            const RegionComplex rcut = region_complex(m, cut);
            CHECK_MESSAGE((rcut.regions.size() == 3 && rcut.patches.size() == 5 && rcut.curves.size() == 2 &&
                           rcut.corners.empty()),
                          "the torus cut in halves: expected 3 regions, 5 patches, 2 curves, 0 corners; got "
                              << counts_text(rcut));
            check_against_brute(cl, m, cut, "ball_with_torus(" + std::to_string(n) + ") with the torus cut at x = 0");
            // every label also cut by the planes x = 0, y = 0, z = 0: a true CW complex (handout §8), 16 regions,
            // 44 disks, 42 curves none closed, 15 corners: 15 − 42 + 44 − 16 = 1
            std::vector<std::int32_t> octants = cl.labels;
            for (std::size_t c = 0; c < octants.size(); ++c) {
                const glm::dvec3 x = list_centroid(cl, c);
                octants[c] = octants[c] * 8 + int(x.x > 0) + 2 * int(x.y > 0) + 4 * int(x.z > 0);
            }
            const RegionComplex cw = region_complex(m, octants);
            CHECK_MESSAGE(
                (cw.regions.size() == 16 && cw.patches.size() == 44 && cw.curves.size() == 42 &&
                 cw.corners.size() == 15),
                "cut into octants: expected 16 regions, 44 patches, 42 curves, 15 corners; got " << counts_text(cw));
            for (const Patch& p : cw.patches)
                CHECK_MESSAGE((p.chi == 1 && p.boundary_loops == 1), "a patch is not a disk");
            for (const Curve& c : cw.curves) CHECK_MESSAGE(c.ends[0] != invalid_index, "a curve is closed");
        }
    }

    TEST_CASE("regions (hidden): tetgen's elephant cut by planes / a slab through it" * geolab::points(1) *
              geolab::hidden()) {
        const CellList cl = tet_model("elephant");
        const Mesh m = hidden_build(cl);
        glm::dvec3 lo(1e300), hi(-1e300);
        for (const auto& p : cl.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
        const glm::dvec3 mid = 0.5 * (lo + hi);
        const auto quadrants =
            labels_by_centroid(cl, [&](const glm::dvec3& p) { return int(p.x > mid.x) + 2 * int(p.y > mid.y); });
        check_against_brute(cl, m, quadrants, "elephant (tetgen) in four quadrants");
        const double t = 0.1 * (hi.z - lo.z);
        const auto slab =
            labels_by_centroid(cl, [&](const glm::dvec3& p) { return std::abs(p.z - mid.z) < t ? 1 : 0; });
        check_against_brute(cl, m, slab, "elephant (tetgen) with a slab |z - mid| < 0.1 depth");
    }

    TEST_CASE("regions (hidden): random labels on grids and mixed cells / a checkerboard" * geolab::points(1) *
              geolab::hidden()) {
        std::uint32_t seed = 12345;
        auto next = [&] { return seed = seed * 1664525u + 1013904223u, seed >> 16; };
        for (auto& [name, cl] :
             std::vector<std::pair<std::string, CellList>>{{"tet grid 4", fx::tet_grid(4, 0.3)},
                                                           {"hex grid 4", fx::hex_grid(4)},
                                                           {"prisms and pyramids", fx::prisms_and_pyramids()}}) {
            const Mesh m = hidden_build(cl);
            for (int round = 0; round < 3; ++round) {
                std::vector<std::int32_t> labels(cl.n_cells());
                for (auto& l : labels) l = std::int32_t(next() % (2 + round));
                check_against_brute(cl, m, labels, name + " with random labels, round " + std::to_string(round));
            }
        }
        // a checkerboard of hex grid 3: every interior edge has 4 interface faces, the patches pinch at vertices
        const CellList hex = fx::hex_grid(3);
        std::vector<std::int32_t> board(27);
        for (int c = 0; c < 27; ++c) board[c] = (c % 3 + c / 3 % 3 + c / 9) % 2;
        check_against_brute(hex, hidden_build(hex), board, "hex grid 3 as a checkerboard");
    }
}
