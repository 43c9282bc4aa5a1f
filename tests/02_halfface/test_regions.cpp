// Lab 02, Task 6: region decomposition into the paper's cell complex (handout §8). Meshes from stored data
// (stored.hpp), never from your build_mesh; expected complexes from hand counts (derived in the comments) and, whole,
// from stored data made by an independent brute-force decomposition of each case's cell list (region_fixtures.hpp).
#include "helpers.hpp"
#include "region_fixtures.hpp"

using namespace lab02;

namespace {
// Your region_complex on case `key` (its stored mesh, cells deleted through the kernel), compared whole with the
// stored expected complex; returns yours for the hand counts of the test.
RegionComplex check_case(const std::string& key) {
    const RegionCase c = region_case(key);
    INFO("input: " << key);
    const RegionComplex got = region_complex(case_mesh(c), c.labels);
    const std::string diff = first_difference(stored_complex(key), got);
    CHECK_MESSAGE(diff.empty(), diff);
    return got;
}
// Every patch a disk (χ 1, one boundary loop).
void check_all_disks(const RegionComplex& rc) {
    for (std::size_t p = 0; p < rc.patches.size(); ++p)
        CHECK_MESSAGE((rc.patches[p].chi == 1 && rc.patches[p].boundary_loops == 1),
                      "patch " << p << ": expected a disk (χ 1, 1 boundary loop), got χ " << rc.patches[p].chi << ", "
                               << rc.patches[p].boundary_loops << " loops");
}
bool counts_are(const RegionComplex& rc, std::size_t r, std::size_t p, std::size_t c, std::size_t k) {
    return rc.regions.size() == r && rc.patches.size() == p && rc.curves.size() == c && rc.corners.size() == k;
}
}  // namespace

TEST_SUITE("Task 6: regions") {
    TEST_CASE(
        "regions: the paper's example (a box with a ring-shaped region) gives a sphere χ 2 and a torus χ 0 and no "
        "curves" *
        geolab::points(3) *
        geolab::hint("Regions by a flood fill through faces whose two cells have the same label; interface faces "
                     "are those with different regions (or the outside) on their two sides.")) {
        INFO("input: a box of 5 x 5 x 3 unit cubes whose middle layer's 8 cubes around the centre cube are labelled 1");
        const RegionComplex rc = check_case("paper: ring in a box");
        REQUIRE_MESSAGE(counts_are(rc, 2, 2, 0, 0),
                        "expected 2 regions, 2 patches, 0 curves, 0 corners; got " << counts_text(rc));
        // region 0 holds cell 0 (label 0: 67 cubes), region 1 the ring (label 1: 8 cubes)
        CHECK_MESSAGE((rc.regions[0].label == 0 && rc.regions[0].cells.size() == 67),
                      "region 0: expected label 0 with 67 cells, got label " << rc.regions[0].label << " with "
                                                                             << rc.regions[0].cells.size());
        CHECK_MESSAGE((rc.regions[1].label == 1 && rc.regions[1].cells.size() == 8),
                      "region 1: expected label 1 with 8 cells, got label " << rc.regions[1].label << " with "
                                                                            << rc.regions[1].cells.size());
        // patch 0 (face 0 is the bottom of cell 0): the box's surface, 110 quads, V 112, E 220: a sphere
        const Patch& s = rc.patches[0];
        CHECK_MESSAGE((s.regions == std::array<std::uint32_t, 2>{0, invalid_index}),
                      "patch 0 lies between region 0 and the outside");
        CHECK_MESSAGE((s.F == 110 && s.V == 112 && s.E == 220 && s.chi == 2 && s.boundary_loops == 0),
                      "patch 0 (the outer sphere): expected F 110, V 112, E 220, χ 2, 0 loops; got F "
                          << s.F << ", V " << s.V << ", E " << s.E << ", χ " << s.chi << ", " << s.boundary_loops
                          << " loops");
        // patch 1: the ring's surface: 8 top + 8 bottom + 12 outer + 4 inner quads, 2 × 16 vertices, 2 × 24 + 16 edges
        const Patch& t = rc.patches[1];
        CHECK_MESSAGE((t.regions == std::array<std::uint32_t, 2>{0, 1}), "patch 1 lies between regions 0 and 1");
        CHECK_MESSAGE((t.F == 32 && t.V == 32 && t.E == 64 && t.chi == 0 && t.boundary_loops == 0),
                      "patch 1 (the torus): expected F 32, V 32, E 64, χ 0, 0 loops; got F "
                          << t.F << ", V " << t.V << ", E " << t.E << ", χ " << t.chi << ", " << t.boundary_loops
                          << " loops");
        CHECK(rc.regions[0].patches == std::vector<std::uint32_t>{0, 1});
        CHECK(rc.regions[1].patches == std::vector<std::uint32_t>{1});
        // not a CW complex: 0 − 0 + 2 − 2 = 0, while the box is a ball (χ 1)
        CHECK(complex_chi(rc) == 0);
    }

    TEST_CASE("regions: a region is a connected component: two corner blobs with one label are two regions" *
              geolab::points(1) *
              geolab::hint("Join two cells only through a face they share; number regions by their lowest cell.")) {
        // cubes (0,0,0) and (2,2,2) labelled 1, not connected: regions are cube 0's tets, the rest, cube 26's tets
        const RegionComplex rc = check_case("tet grid 3: cubes (0,0,0) and (2,2,2) labelled 1");
        INFO("input: tet grid 3 with label 1 on cubes (0,0,0) and (2,2,2)");
        REQUIRE_MESSAGE(rc.regions.size() == 3, "expected 3 regions, got " << rc.regions.size());
        CHECK_MESSAGE((rc.regions[0].cells == std::vector<Cell>{Cell{0}, Cell{1}, Cell{2}, Cell{3}, Cell{4}, Cell{5}}),
                      "region 0 should be cube (0,0,0)'s tets 0..5, got " << handles_text(rc.regions[0].cells));
        CHECK(rc.regions[0].label == 1);
        CHECK(rc.regions[1].label == 0);
        CHECK(rc.regions[1].cells.size() == 150);
        CHECK(rc.regions[2].label == 1);
        CHECK(rc.regions[2].cells.front() == Cell{156});
        // cubes (0,0,0) and (1,1,0) touch along an edge only: still two regions of label 1
        const RegionComplex re = check_case("tet grid 3: cubes (0,0,0) and (1,1,0) labelled 1 (sharing an edge)");
        CHECK_MESSAGE(re.regions.size() == 3,
                      "cubes touching along an edge: expected 3 regions, got " << re.regions.size());
        // cubes (0,0,0) and (1,0,0) share a face: one region
        const auto face = cube_labels(3, [](int i, int j, int k) { return k == 0 && j == 0 && i < 2 ? 1 : 0; });
        CHECK(region_complex(stored_mesh("tet grid 3"), face).regions.size() == 2);
    }

    TEST_CASE("regions: a cube cut in halves: three disk patches and one closed curve without corners" *
              geolab::points(1) *
              geolab::hint("k(e) counts the interface faces at edge e; a curve edge has k(e) >= 3. A curve all of "
                           "whose vertices have two curve edges is closed: no corner.")) {
        const RegionComplex rc = check_case("hex grid 2: halves x < 1/2");
        INFO("input: hex grid 2 cut at x = 1/2");
        REQUIRE_MESSAGE(counts_are(rc, 2, 3, 1, 0),
                        "expected 2 regions, 3 patches, 1 curve, 0 corners; got " << counts_text(rc));
        check_all_disks(rc);
        // each half's outer surface: 4 + 4 · 2 quads; the cut: 4 quads; the curve: the cut's square rim, 8 edges
        CHECK(rc.patches[0].F + rc.patches[1].F + rc.patches[2].F == 28);
        CHECK_MESSAGE(rc.curves[0].edges.size() == 8,
                      "the closed curve has 8 edges, got " << rc.curves[0].edges.size());
        CHECK_MESSAGE((rc.curves[0].ends == std::array<std::uint32_t, 2>{invalid_index, invalid_index}),
                      "a closed curve has no ends");
        CHECK_MESSAGE(rc.curves[0].patches == (std::vector<std::uint32_t>{0, 1, 2}),
                      "all three patches meet along the curve");
        CHECK(complex_chi(rc) == 0);
        const RegionComplex rt = check_case("tet grid 2: halves x < 1/2");
        CHECK_MESSAGE(counts_are(rt, 2, 3, 1, 0),
                      "tet grid 2 cut at x = 1/2: expected 3 patches, 1 curve, 0 corners; got " << counts_text(rt));
    }

    TEST_CASE("regions: octants of a hex grid and a tet grid give 8 regions / 20 disks / 18 curves / 7 corners" *
              geolab::points(2) *
              geolab::hint("Curves join curve edges through vertices with exactly two curve edges; every other vertex "
                           "with curve edges is a corner. Number each kind by its lowest element.")) {
        // 8 octants; patches: 8 outer (3 squares each) + 12 inner quarter planes; curves: 6 half-axes from the
        // centre + 12 arcs on the surface (each plane's rim cut at the 4 face centres it passes); corners: the
        // centre (6 curves) and the 6 face centres (5 curves each). 7 − 18 + 20 − 8 = 1: a true CW complex.
        for (const char* key : {"hex grid 2: octants", "tet grid 2: octants"}) {
            INFO("input: " << key);
            const RegionComplex rc = check_case(key);
            REQUIRE_MESSAGE(counts_are(rc, 8, 20, 18, 7),
                            "expected 8 regions, 20 patches, 18 curves, 7 corners; got " << counts_text(rc));
            check_all_disks(rc);
            std::vector<std::size_t> degrees;
            for (const Corner& k : rc.corners) degrees.push_back(k.curves.size());
            std::sort(degrees.begin(), degrees.end());
            CHECK_MESSAGE(
                degrees == (std::vector<std::size_t>{5, 5, 5, 5, 5, 5, 6}),
                "curves per corner: expected six corners with 5 and the centre with 6, got " << list(degrees));
            for (std::size_t i = 0; i < rc.curves.size(); ++i)
                CHECK_MESSAGE((rc.curves[i].ends[0] != invalid_index && rc.curves[i].ends[1] != invalid_index &&
                               rc.curves[i].ends[0] < rc.curves[i].ends[1]),
                              "curve " << i << ": expected two different corners at its ends, lower first");
            CHECK(complex_chi(rc) == 1);
        }
    }

    TEST_CASE("regions: three regions meeting along a curve give 6 disks and 4 curves from corner to corner" *
              geolab::points(1) *
              geolab::hint("A curve's ends are the corners at its two ends, the lower index first.")) {
        // A = {x < 1/3}, B = {x > 1/3, y < 1/3}, C = the rest of tet grid 3. Curves: the line x = y = 1/3 inside
        // (where A|B, A|C, B|C meet), and the rims of the three interfaces on the surface; all four run from the
        // corner (1/3, 1/3, 0) to the corner (1/3, 1/3, 1). 2 − 4 + 6 − 3 = 1.
        const Mesh m = stored_mesh("tet grid 3");
        const RegionComplex rc = check_case("tet grid 3: three regions along a line");
        INFO("input: tet grid 3 as A = {x < 1/3}, B = {x > 1/3, y < 1/3}, C = the rest");
        REQUIRE_MESSAGE(counts_are(rc, 3, 6, 4, 2),
                        "expected 3 regions, 6 patches, 4 curves, 2 corners; got " << counts_text(rc));
        check_all_disks(rc);
        for (std::size_t i = 0; i < 4; ++i) {
            CHECK_MESSAGE((rc.curves[i].ends == std::array<std::uint32_t, 2>{0, 1}),
                          "curve " << i << " runs from corner 0 to corner 1");
            CHECK_MESSAGE(rc.curves[i].patches.size() == 3,
                          "curve " << i << ": 3 patches meet along it, got " << rc.curves[i].patches.size());
        }
        for (const Corner& k : rc.corners) {
            REQUIRE(k.vertex.idx < m.n_vertices());
            const glm::dvec3 p = m.position(k.vertex);
            CHECK_MESSAGE((std::abs(p.x - 1.0 / 3) < 1e-12 && std::abs(p.y - 1.0 / 3) < 1e-12),
                          "corner at " << p.x << " " << p.y << " " << p.z);
            CHECK(k.curves == (std::vector<std::uint32_t>{0, 1, 2, 3}));
        }
        CHECK(complex_chi(rc) == 1);
    }

    TEST_CASE("regions: a region touching the boundary / a cube of six pyramids with six labels" * geolab::points(1) *
              geolab::hint("Outside is a region of its own for the interface test: a face with one cell is an "
                           "interface face.")) {
        // the bottom-centre cube of tet grid 3 labelled 1: outer patch with a square hole, the cube's bottom, its
        // other five sides; one closed curve (the square on the bottom), no corner
        const RegionComplex rc = check_case("tet grid 3: cube (1,1,0) labelled 1 (touching the boundary)");
        CHECK_MESSAGE(counts_are(rc, 2, 3, 1, 0),
                      "tet grid 3, cube (1,1,0) labelled 1: expected 2 regions, 3 patches, "
                      "1 curve, 0 corners; got "
                          << counts_text(rc));
        check_all_disks(rc);
        // six pyramids around the cube's centre, each its own region: 6 bases + 12 shared triangles; curves: the 12
        // cube edges and the 8 half-diagonals; corners: the 8 cube corners (4 curves) and the centre (8)
        const RegionComplex rp = check_case("cube of 6 pyramids: labels 10..15");
        INFO("input: cube of 6 pyramids, labels 10..15");
        REQUIRE_MESSAGE(counts_are(rp, 6, 18, 20, 9),
                        "expected 6 regions, 18 patches, 20 curves, 9 corners; got " << counts_text(rp));
        for (std::size_t r = 0; r < 6; ++r) CHECK(rp.regions[r].label == std::int32_t(10 + r));
        CHECK(rp.corners.back().vertex == Vertex{8});
        CHECK(rp.corners.back().curves.size() == 8);
    }

    TEST_CASE("regions: every stored mesh with one region per cell / with one label for all" * geolab::points(1) *
              geolab::hint("Prisms, pyramids and general polyhedra: walk each face's half-edges, whatever their "
                           "number.")) {
        for (const Fixture& f : stored_fixtures()) {
            (void)check_case(f.name + ": every cell its own label");
            const std::vector<std::int32_t> one(f.cells.n_cells(), 7);
            const RegionComplex rc = region_complex(stored_mesh(f), one);
            INFO("input: " << f.name << ", one label");
            CHECK_MESSAGE(counts_are(rc, 1, 1, 0, 0),
                          "one label: expected 1 region, 1 patch (the boundary sphere), 0 curves, 0 corners; got "
                              << counts_text(rc));
            if (rc.patches.size() == 1) CHECK(rc.patches[0].chi == 2);
        }
    }

    TEST_CASE("regions: deleted cells are outside / the label count is checked" * geolab::points(1) *
              geolab::hint("Skip deleted cells and faces; throw std::invalid_argument before anything else when "
                           "labels.size() != n_cells().")) {
        const RegionComplex rc = check_case("tet grid 3 without its centre cube: one label");
        INFO("input: tet grid 3 without its centre cube (deleted), one label");
        REQUIRE_MESSAGE(
            (rc.regions.size() == 1 && rc.patches.size() == 2 && rc.curves.empty()),
            "a ball with a cavity: expected 1 region, 2 patches (two spheres), no curve; got " << counts_text(rc));
        CHECK(rc.regions[0].cells.size() == 156);
        CHECK_MESSAGE((rc.patches[0].chi == 2 && rc.patches[1].chi == 2), "both patches are spheres");
        (void)check_case("tet grid 3 without its centre cube: x < 1/3 labelled 1");
        const Mesh m = case_mesh(region_case("tet grid 3 without its centre cube: one label"));
        try {
            (void)region_complex(m, std::vector<std::int32_t>(5, 0));
            FAIL("region_complex accepted 5 labels for 162 cells");
        } catch (const std::invalid_argument& e) {
            CHECK_MESSAGE(std::string(e.what()).find("5 labels for 162 cells") != std::string::npos,
                          "the message must say '5 labels for 162 cells'; got: " << e.what());
        }
    }
}
