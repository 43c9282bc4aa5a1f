// Lab 02, Task 6: region decomposition into the paper's cell complex (handout §8). Meshes from stored data
// (stored.hpp), never from your build_mesh; expected complexes from hand counts (derived in the comments) and
// from a brute-force decomposition of the cell list (region_fixtures.hpp).
#include "helpers.hpp"
#include "region_fixtures.hpp"

using namespace lab02;

namespace {
// Checks region_complex(m, labels) against the brute force; `what` names the input.
void check_against_brute(const CellList& cl, const Mesh& m, const std::vector<std::int32_t>& labels,
                         const std::string& what, const std::set<std::uint32_t>& deleted = {}) {
    INFO("input: " << what);
    const RegionComplex want = brute_region_complex(cl, labels, m, deleted);
    const RegionComplex got = region_complex(m, labels);
    const std::string diff = first_difference(want, got);
    CHECK_MESSAGE(diff.empty(), diff);
}
// The cube (i, j, k) of an n³ Kuhn tet grid that holds tet c (6 tets per cube, cubes in (k n + j) n + i order).
std::array<int, 3> kuhn_cube_of(int n, std::size_t c) {
    const int q = int(c / 6);
    return {q % n, (q / n) % n, q / (n * n)};
}
// Labels of an n³ Kuhn tet grid from its cubes: f(i, j, k).
template <class F>
std::vector<std::int32_t> cube_labels(int n, F&& f) {
    std::vector<std::int32_t> l(6 * n * n * n);
    for (std::size_t c = 0; c < l.size(); ++c) {
        const auto q = kuhn_cube_of(n, c);
        l[c] = f(q[0], q[1], q[2]);
    }
    return l;
}
// Marks cells deleted through the kernel alone (not your Task 3), as delete_cell's contract says.
void kernel_delete(Mesh& m, Cell c) {
    m.set_deleted(c, true);
    for (HalfFace hf : m.halffaces(c)) {
        m.set_cell(hf, Cell{});
        const HalfEdge h0 = m.halfedge(hf);
        HalfEdge h = h0;
        do {
            m.set_twin(h, HalfEdge{});
            h = m.next(h);
        } while (h != h0);
        if (!m.cell(Mesh::opposite(hf)).is_valid()) m.set_deleted(Mesh::face(hf), true);
    }
    m.rebuild_vertex_cache();
}
// Every patch a disk (χ 1, one boundary loop).
void check_all_disks(const RegionComplex& rc) {
    for (std::size_t p = 0; p < rc.patches.size(); ++p)
        CHECK_MESSAGE((rc.patches[p].chi == 1 && rc.patches[p].boundary_loops == 1),
                      "patch " << p << ": expected a disk (χ 1, 1 boundary loop), got χ " << rc.patches[p].chi << ", "
                               << rc.patches[p].boundary_loops << " loops");
}
}  // namespace

TEST_SUITE("Task 6: regions") {
    TEST_CASE(
        "regions: the paper's example (a box with a ring-shaped region) gives a sphere χ 2 and a torus χ 0 and no "
        "curves" *
        geolab::points(3) *
        geolab::hint("Regions by a flood fill through faces whose two cells have the same label; interface faces "
                     "are those with different regions (or the outside) on their two sides.")) {
        const Fixture f = region_stored_fixtures()[0];
        const Mesh m = stored_mesh(f);
        const std::vector<std::int32_t>& labels = f.cells.labels;
        INFO("input: " << f.name << " (75 unit cubes; the middle layer's 8 cubes around the centre cube labelled 1)");
        const RegionComplex rc = region_complex(m, labels);
        REQUIRE_MESSAGE((rc.regions.size() == 2 && rc.patches.size() == 2 && rc.curves.empty() && rc.corners.empty()),
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
        check_against_brute(f.cells, m, labels, f.name);
    }

    TEST_CASE("regions: a region is a connected component: two corner blobs with one label are two regions" *
              geolab::points(1) *
              geolab::hint("Join two cells only through a face they share; number regions by their lowest cell.")) {
        const CellList cl = fx::tet_grid(3, 0.3);
        const Mesh m = stored_mesh("tet grid 3");
        // cubes (0,0,0) and (2,2,2): label 1, not connected: regions are cube 0's tets, the rest, cube 26's tets
        const auto corners = cube_labels(3, [](int i, int j, int k) { return (i == j && j == k && i != 1) ? 1 : 0; });
        const RegionComplex rc = region_complex(m, corners);
        INFO("input: tet grid 3 with label 1 on cubes (0,0,0) and (2,2,2)");
        REQUIRE_MESSAGE(rc.regions.size() == 3, "expected 3 regions, got " << rc.regions.size());
        CHECK_MESSAGE((rc.regions[0].cells == std::vector<Cell>{Cell{0}, Cell{1}, Cell{2}, Cell{3}, Cell{4}, Cell{5}}),
                      "region 0 should be cube (0,0,0)'s tets 0..5, got " << handles_text(rc.regions[0].cells));
        CHECK(rc.regions[0].label == 1);
        CHECK(rc.regions[1].label == 0);
        CHECK(rc.regions[1].cells.size() == 150);
        CHECK(rc.regions[2].label == 1);
        CHECK(rc.regions[2].cells.front() == Cell{156});
        check_against_brute(cl, m, corners, "tet grid 3, cubes (0,0,0) and (2,2,2) labelled 1");
        // cubes (0,0,0) and (1,1,0) touch along an edge only: still two regions of label 1
        const auto edge = cube_labels(3, [](int i, int j, int k) { return k == 0 && i == j && i < 2 ? 1 : 0; });
        const RegionComplex re = region_complex(m, edge);
        CHECK_MESSAGE(re.regions.size() == 3,
                      "cubes touching along an edge: expected 3 regions, got " << re.regions.size());
        check_against_brute(cl, m, edge, "tet grid 3, cubes (0,0,0) and (1,1,0) labelled 1 (they share an edge)");
        // cubes (0,0,0) and (1,0,0) share a face: one region
        const auto face = cube_labels(3, [](int i, int j, int k) { return k == 0 && j == 0 && i < 2 ? 1 : 0; });
        CHECK(region_complex(m, face).regions.size() == 2);
    }

    TEST_CASE("regions: a cube cut in halves: three disk patches and one closed curve without corners" *
              geolab::points(1) *
              geolab::hint("k(e) counts the interface faces at edge e; a curve edge has k(e) >= 3. A curve all of "
                           "whose vertices have two curve edges is closed: no corner.")) {
        const Fixture hex{"hex grid 2", fx::hex_grid(2)};
        const Mesh m = stored_mesh(hex);
        std::vector<std::int32_t> halves(8);
        for (std::size_t c = 0; c < 8; ++c) halves[c] = std::int32_t(c % 2);  // x < 1/2: 0, else 1
        const RegionComplex rc = region_complex(m, halves);
        INFO("input: hex grid 2 cut at x = 1/2");
        REQUIRE_MESSAGE(
            (rc.regions.size() == 2 && rc.patches.size() == 3 && rc.curves.size() == 1 && rc.corners.empty()),
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
        check_against_brute(hex.cells, m, halves, "hex grid 2 cut at x = 1/2");
        const Fixture tets{"tet grid 2", fx::tet_grid(2, 0.3)};
        const auto tet_halves = cube_labels(2, [](int i, int, int) { return i; });
        const RegionComplex rt = region_complex(stored_mesh(tets), tet_halves);
        CHECK_MESSAGE((rt.patches.size() == 3 && rt.curves.size() == 1 && rt.corners.empty()),
                      "tet grid 2 cut at x = 1/2: expected 3 patches, 1 curve, 0 corners; got " << counts_text(rt));
        check_against_brute(tets.cells, stored_mesh(tets), tet_halves, "tet grid 2 cut at x = 1/2");
    }

    TEST_CASE("regions: octants of a hex grid and a tet grid give 8 regions / 20 disks / 18 curves / 7 corners" *
              geolab::points(2) *
              geolab::hint("Curves join curve edges through vertices with exactly two curve edges; every other vertex "
                           "with curve edges is a corner. Number each kind by its lowest element.")) {
        // 8 octants; patches: 8 outer (3 squares each) + 12 inner quarter planes; curves: 6 half-axes from the
        // centre + 12 arcs on the surface (each plane's rim cut at the 4 face centres it passes); corners: the
        // centre (6 curves) and the 6 face centres (5 curves each). 7 − 18 + 20 − 8 = 1: a true CW complex.
        const Fixture hex{"hex grid 2", fx::hex_grid(2)}, tets{"tet grid 2", fx::tet_grid(2, 0.3)};
        std::vector<std::int32_t> own(8);
        for (std::size_t c = 0; c < 8; ++c) own[c] = std::int32_t(c);
        const auto octant = cube_labels(2, [](int i, int j, int k) { return i + 2 * j + 4 * k; });
        for (const auto& [fix, labels] : {std::pair{hex, own}, std::pair{tets, octant}}) {
            INFO("input: " << fix.name << " in octants");
            const Mesh m = stored_mesh(fix);
            const RegionComplex rc = region_complex(m, labels);
            REQUIRE_MESSAGE(
                (rc.regions.size() == 8 && rc.patches.size() == 20 && rc.curves.size() == 18 && rc.corners.size() == 7),
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
            check_against_brute(fix.cells, m, labels, fix.name + " in octants");
        }
    }

    TEST_CASE("regions: three regions meeting along a curve give 6 disks and 4 curves from corner to corner" *
              geolab::points(1) *
              geolab::hint("A curve's ends are the corners at its two ends, the lower index first.")) {
        // A = {x < 1/3}, B = {x > 1/3, y < 1/3}, C = the rest of tet grid 3. Curves: the line x = y = 1/3 inside
        // (where A|B, A|C, B|C meet), and the rims of the three interfaces on the surface; all four run from the
        // corner (1/3, 1/3, 0) to the corner (1/3, 1/3, 1). 2 − 4 + 6 − 3 = 1.
        const CellList cl = fx::tet_grid(3, 0.3);
        const Mesh m = stored_mesh("tet grid 3");
        const auto labels = cube_labels(3, [](int i, int j, int) { return i == 0 ? 0 : j == 0 ? 1 : 2; });
        INFO("input: tet grid 3 as A = {x < 1/3}, B = {x > 1/3, y < 1/3}, C = the rest");
        const RegionComplex rc = region_complex(m, labels);
        REQUIRE_MESSAGE(
            (rc.regions.size() == 3 && rc.patches.size() == 6 && rc.curves.size() == 4 && rc.corners.size() == 2),
            "expected 3 regions, 6 patches, 4 curves, 2 corners; got " << counts_text(rc));
        check_all_disks(rc);
        for (std::size_t i = 0; i < 4; ++i) {
            CHECK_MESSAGE((rc.curves[i].ends == std::array<std::uint32_t, 2>{0, 1}),
                          "curve " << i << " runs from corner 0 to corner 1");
            CHECK_MESSAGE(rc.curves[i].patches.size() == 3,
                          "curve " << i << ": 3 patches meet along it, got " << rc.curves[i].patches.size());
        }
        for (const Corner& k : rc.corners) {
            const glm::dvec3 p = m.position(k.vertex);
            CHECK_MESSAGE((std::abs(p.x - 1.0 / 3) < 1e-12 && std::abs(p.y - 1.0 / 3) < 1e-12),
                          "corner at " << p.x << " " << p.y << " " << p.z);
            CHECK(k.curves == (std::vector<std::uint32_t>{0, 1, 2, 3}));
        }
        CHECK(complex_chi(rc) == 1);
        check_against_brute(cl, m, labels, "tet grid 3 in three regions");
    }

    TEST_CASE("regions: a region touching the boundary / a cube of six pyramids with six labels" * geolab::points(1) *
              geolab::hint("Outside is a region of its own for the interface test: a face with one cell is an "
                           "interface face.")) {
        // the bottom-centre cube of tet grid 3 labelled 1: outer patch with a square hole, the cube's bottom, its
        // other five sides; one closed curve (the square on the bottom), no corner
        const CellList cl = fx::tet_grid(3, 0.3);
        const Mesh m = stored_mesh("tet grid 3");
        const auto touching = cube_labels(3, [](int i, int j, int k) { return i == 1 && j == 1 && k == 0 ? 1 : 0; });
        const RegionComplex rc = region_complex(m, touching);
        CHECK_MESSAGE((rc.regions.size() == 2 && rc.patches.size() == 3 && rc.curves.size() == 1 && rc.corners.empty()),
                      "tet grid 3, cube (1,1,0) labelled 1: expected 2 regions, 3 patches, 1 curve, 0 corners; got "
                          << counts_text(rc));
        check_all_disks(rc);
        check_against_brute(cl, m, touching, "tet grid 3, cube (1,1,0) labelled 1");
        // six pyramids around the cube's centre, each its own region: 6 bases + 12 shared triangles; curves: the 12
        // cube edges and the 8 half-diagonals; corners: the 8 cube corners (4 curves) and the centre (8)
        const Fixture pyr{"cube of 6 pyramids", fx::cube_of_pyramids()};
        const Mesh mp = stored_mesh(pyr);
        const std::vector<std::int32_t> six{10, 11, 12, 13, 14, 15};
        const RegionComplex rp = region_complex(mp, six);
        INFO("input: cube of 6 pyramids, labels 10..15");
        REQUIRE_MESSAGE(
            (rp.regions.size() == 6 && rp.patches.size() == 18 && rp.curves.size() == 20 && rp.corners.size() == 9),
            "expected 6 regions, 18 patches, 20 curves, 9 corners; got " << counts_text(rp));
        for (std::size_t r = 0; r < 6; ++r) CHECK(rp.regions[r].label == six[r]);
        CHECK(rp.corners.back().vertex == Vertex{8});
        CHECK(rp.corners.back().curves.size() == 8);
        check_against_brute(pyr.cells, mp, six, pyr.name);
    }

    TEST_CASE("regions: every stored mesh with one region per cell / with one label for all (against brute force)" *
              geolab::points(1) *
              geolab::hint("Prisms, pyramids and general polyhedra: walk each face's half-edges, "
                           "whatever their number.")) {
        for (const Fixture& f : stored_fixtures()) {
            const Mesh m = stored_mesh(f);
            std::vector<std::int32_t> own(f.cells.n_cells()), one(f.cells.n_cells(), 7);
            for (std::size_t c = 0; c < own.size(); ++c) own[c] = std::int32_t(c % 3 == 1 ? -int(c) : int(c));
            check_against_brute(f.cells, m, own, f.name + ", every cell its own label");
            const RegionComplex rc = region_complex(m, one);
            INFO("input: " << f.name << ", one label");
            CHECK_MESSAGE((rc.regions.size() == 1 && rc.patches.size() == 1 && rc.curves.empty() && rc.corners.empty()),
                          "one label: expected 1 region, 1 patch (the boundary sphere), 0 curves, 0 corners; got "
                              << counts_text(rc));
            if (rc.patches.size() == 1) CHECK(rc.patches[0].chi == 2);
        }
    }

    TEST_CASE("regions: deleted cells are outside / the label count is checked" * geolab::points(1) *
              geolab::hint("Skip deleted cells and faces; throw std::invalid_argument before anything else when "
                           "labels.size() != n_cells().")) {
        const CellList cl = fx::tet_grid(3, 0.3);
        Mesh m = stored_mesh("tet grid 3");
        std::set<std::uint32_t> gone;
        for (std::uint32_t c = 6 * 13; c < 6 * 14; ++c) kernel_delete(m, Cell{c}), gone.insert(c);  // the centre cube
        const std::vector<std::int32_t> zero(m.n_cells(), 0);
        const RegionComplex rc = region_complex(m, zero);
        INFO("input: tet grid 3 without its centre cube (deleted), one label");
        REQUIRE_MESSAGE(
            (rc.regions.size() == 1 && rc.patches.size() == 2 && rc.curves.empty()),
            "a ball with a cavity: expected 1 region, 2 patches (two spheres), no curve; got " << counts_text(rc));
        CHECK(rc.regions[0].cells.size() == 156);
        CHECK_MESSAGE((rc.patches[0].chi == 2 && rc.patches[1].chi == 2), "both patches are spheres");
        check_against_brute(cl, m, zero, "tet grid 3 without its centre cube", gone);
        const auto halves = cube_labels(3, [](int i, int, int) { return i == 0 ? 1 : 0; });
        check_against_brute(cl, m, halves, "tet grid 3 without its centre cube, x < 1/3 labelled 1", gone);
        try {
            (void)region_complex(m, std::vector<std::int32_t>(5, 0));
            FAIL("region_complex accepted 5 labels for 162 cells");
        } catch (const std::invalid_argument& e) {
            CHECK_MESSAGE(std::string(e.what()).find("5 labels for 162 cells") != std::string::npos,
                          "the message must say '5 labels for 162 cells'; got: " << e.what());
        }
    }
}
