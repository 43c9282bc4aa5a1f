// Lab 02, Task 5: the boundary surface (handout §7). Meshes from stored data (stored.hpp).
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab02;

TEST_SUITE("Task 5: boundary surface") {
    TEST_CASE("surface: a single tetrahedron gives 4 outward triangles" * geolab::points(2) *
              geolab::builds_on("Task 2") *
              geolab::hint("One polygon per boundary half-face, its vertices reversed (the cell is on the other side).")) {
        const Mesh m = stored_mesh("single tet");
        const PolygonSoup s = boundary_surface(m);
        REQUIRE_MESSAGE(s.n_faces() == 4, "expected 4 faces, got " << s.n_faces());
        CHECK_MESSAGE(s.n_vertices() == 4, "expected 4 vertices, got " << s.n_vertices());
        const double v = enclosed_volume(s);
        CHECK_MESSAGE(std::abs(v - 1.0 / 6.0) < 1e-12, "enclosed volume: expected +1/6 (outward faces), got " << v);
    }

    TEST_CASE("surface: every fixture's surface is closed / outward / a sphere / and encloses the cells' volume" *
              geolab::points(2) * geolab::builds_on("Task 2") *
              geolab::hint("Reverse each boundary half-face's loop; renumber the used vertices in increasing order.")) {
        for (const Fixture& f : stored_fixtures()) {
            INFO(describe(f));
            const Mesh m = stored_mesh(f);
            const PolygonSoup s = boundary_surface(m);
            const Reference r = reference(f.cells);
            const SoupTopology t = soup_topology(s);
            CHECK_MESSAGE(t.closed_oriented, "the surface is not closed and consistently oriented");
            CHECK_MESSAGE(t.F == r.boundary_faces, "faces: expected " << r.boundary_faces << ", got " << t.F);
            CHECK_MESSAGE(t.chi == 2, "Euler characteristic: expected 2 (a sphere), got " << t.chi);
            CHECK_MESSAGE(t.V == s.n_vertices(), "every soup vertex must be used by a face");
            const double want = cells_volume(f.cells), got = enclosed_volume(s);
            CHECK_MESSAGE(std::abs(got - want) <= 1e-9 * std::max(1.0, std::abs(want)),
                          "enclosed volume: expected " << want << " (outward), got " << got);
        }
    }

    TEST_CASE("surface: faces in half-face order / vertices renumbered in increasing mesh order" * geolab::points(2) *
              geolab::builds_on("Task 2") *
              geolab::hint("Polygon i is the i-th boundary half-face; soup vertex j is the j-th used mesh vertex.")) {
        for (const Fixture& f : stored_fixtures()) {
            INFO(describe(f));
            const Mesh m = stored_mesh(f);
            const PolygonSoup s = boundary_surface(m);
            std::vector<std::uint32_t> used;
            std::vector<HalfFace> hfs;
            for (HalfFace hf : m.halffaces())
                if (!m.cell(hf).is_valid()) {
                    hfs.push_back(hf);
                    for (auto v : loop_vertices(m, hf)) used.push_back(v);
                }
            std::sort(used.begin(), used.end());
            used.erase(std::unique(used.begin(), used.end()), used.end());
            REQUIRE_MESSAGE(s.n_vertices() == used.size(), "vertices: expected " << used.size() << ", got " << s.n_vertices());
            for (std::size_t j = 0; j < used.size(); ++j)
                REQUIRE_MESSAGE(s.positions[j] == m.position(Vertex{used[j]}), "soup vertex " << j << " should be v" << used[j]);
            REQUIRE(s.n_faces() == hfs.size());
            for (std::size_t i = 0; i < hfs.size(); ++i) {
                auto loop = loop_vertices(m, hfs[i]);
                std::reverse(loop.begin(), loop.end());
                std::vector<std::uint32_t> expected;
                for (auto v : loop) expected.push_back(std::uint32_t(std::lower_bound(used.begin(), used.end(), v) - used.begin()));
                const auto got = to_vec(s.face(i));
                REQUIRE_MESSAGE(got == expected, "polygon " << i << " (" << hfs[i] << "): expected " << list(expected)
                                                            << ", got " << list(got));
            }
        }
    }

    TEST_CASE("surface: after deleting cells the surface is still closed and outward" * geolab::points(3) *
              geolab::builds_on("Task 2") *
              geolab::hint("Skip deleted half-faces; a face whose cell was deleted is boundary on the other side now.")) {
        const CellList cl = fx::tet_grid(3, 0.3);
        // a corner cube removed (still a ball), then the centre cube removed (a ball with a cavity)
        for (int centre = 0; centre < 2; ++centre) {
            Mesh m = stored_mesh("tet grid 3");
            const std::uint32_t first = centre ? 6 * 13 : 0;  // cube (1,1,1) or cube (0,0,0)
            std::set<std::uint32_t> gone;
            for (std::uint32_t c = first; c < first + 6; ++c) gone.insert(c);
            // delete them through the kernel's marks (not your Task 3): clear cells and twins by hand
            for (std::uint32_t ci : gone) {
                const Cell c{ci};
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
            }
            CellList removed;
            removed.positions = cl.positions;
            for (std::uint32_t c : gone) {
                for (std::size_t i = 0; i < cl.n_faces(c); ++i) removed.add_face(cl.face(c, i));
                removed.close_cell();
            }
            INFO("input: tet grid 3 without cube " << (centre ? "(1,1,1), the centre" : "(0,0,0), a corner"));
            const PolygonSoup s = boundary_surface(m);
            const SoupTopology t = soup_topology(s);
            CHECK_MESSAGE(t.closed_oriented, "the surface is not closed and consistently oriented");
            const long chi = centre ? 4 : 2;
            CHECK_MESSAGE(t.chi == chi, "Euler characteristic: expected " << chi << ", got " << t.chi);
            const double want = 1.0 - cells_volume(removed), got = enclosed_volume(s);
            CHECK_MESSAGE(std::abs(got - want) < 1e-9, "enclosed volume: expected " << want << ", got " << got);
        }
    }
}
