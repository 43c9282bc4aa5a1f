// Lab 02, Task 1: build_mesh (handout §3). Checked against brute-force counts from the cell list and validate().
#include "helpers.hpp"

using namespace lab02;

namespace {

// build_mesh must throw E whose message contains every part of `parts`.
template <class E>
void expect_error(const CellList& cl, const std::string& input, const std::vector<std::string>& parts) {
    INFO("input: " << input);
    try {
        (void)build_mesh(cl);
        FAIL("build_mesh accepted it: expected " << (std::is_same_v<E, geolab::TopologyError> ? "a TopologyError"
                                                                                                 : "std::invalid_argument")
                                                 << " with a message naming " << list(parts));
    } catch (const E& e) {
        const std::string what = e.what();
        for (const std::string& p : parts)
            CHECK_MESSAGE(what.find(p) != std::string::npos,
                          "the message must contain '" << p << "'; got: " << what);
    }
}

// build_mesh must throw a TopologyError whose message is exactly `expected` (the contract gives these in full).
void expect_message(const CellList& cl, const std::string& input, const std::string& expected) {
    INFO("input: " << input);
    try {
        (void)build_mesh(cl);
        FAIL("build_mesh accepted it: expected a TopologyError \"" << expected << "\"");
    } catch (const geolab::TopologyError& e) {
        CHECK_MESSAGE(std::string(e.what()) == expected, "expected the message \"" << expected << "\"; got: " << e.what());
    }
}

void check_counts(const Mesh& m, const CellList& cl, const std::string& what) {
    const Reference r = reference(cl);
    INFO("input: " << what);
    CHECK_MESSAGE(m.n_vertices() == r.V, "vertices: expected " << r.V << ", got " << m.n_vertices());
    CHECK_MESSAGE(m.n_edges() == r.E, "edges: expected " << r.E << ", got " << m.n_edges());
    CHECK_MESSAGE(m.n_faces() == r.F, "faces: expected " << r.F << ", got " << m.n_faces());
    CHECK_MESSAGE(m.n_halffaces() == 2 * r.F, "half-faces: expected " << 2 * r.F << ", got " << m.n_halffaces());
    CHECK_MESSAGE(m.n_cells() == r.C, "cells: expected " << r.C << ", got " << m.n_cells());
    std::size_t bnd = 0;
    for (HalfFace hf : m.halffaces()) bnd += m.is_boundary(hf);
    CHECK_MESSAGE(bnd == r.boundary_faces, "half-faces without a cell: expected " << r.boundary_faces
                                                                                 << " (one per boundary face), got " << bnd);
}

// Each cell's half-faces are its listed faces in order; the cycles match; the first user's loop starts at its
// listed first vertex; faces are numbered in order of first use.
void check_cells(const Mesh& m, const CellList& cl, const std::string& what) {
    INFO("input: " << what);
    std::map<std::vector<std::uint32_t>, std::uint32_t> first_use;  // face key -> face index expected
    for (std::size_t c = 0; c < cl.n_cells(); ++c) {
        CAPTURE(c);
        const auto hfs = m.halffaces(Cell{std::uint32_t(c)});
        REQUIRE_MESSAGE(hfs.size() == cl.n_faces(c), "cell " << c << ": expected " << cl.n_faces(c)
                                                             << " half-faces, got " << hfs.size());
        for (std::size_t i = 0; i < hfs.size(); ++i) {
            const auto listed = to_vec(cl.face(c, i));
            const auto got = loop_vertices(m, hfs[i]);
            CHECK_MESSAGE(rotate_min(got) == rotate_min(listed), "cell " << c << " face " << i << ": half-face " << hfs[i]
                                                                          << " has loop " << list(got) << ", expected the cycle "
                                                                          << list(listed));
            CHECK_MESSAGE(m.cell(hfs[i]) == Cell{std::uint32_t(c)},
                          "cell(" << hfs[i] << ") should be c" << c << ", got " << m.cell(hfs[i]));
            const auto key = face_key(listed);
            auto [it, fresh] = first_use.insert({key, std::uint32_t(first_use.size())});
            CHECK_MESSAGE(Mesh::face(hfs[i]).idx == it->second, "cell " << c << " face " << i << " " << list(listed)
                                                                        << ": faces are numbered in order of first use, expected f"
                                                                        << it->second << ", got " << Mesh::face(hfs[i]));
            if (fresh) {
                CHECK_MESSAGE(hfs[i].idx % 2 == 0, "the first cell using a face gets half-face 2f, got " << hfs[i]);
                CHECK_MESSAGE(got.front() == listed.front(), "cell " << c << " face " << i << ": the loop of 2f starts at "
                                                                     << "the vertex the cell lists first (" << listed.front()
                                                                     << "), got " << got.front());
            } else {
                CHECK_MESSAGE(hfs[i].idx % 2 == 1, "the second cell using a face gets half-face 2f+1, got " << hfs[i]);
            }
        }
    }
}

}  // namespace

TEST_SUITE("Task 1: build") {
    TEST_CASE("build: a single tetrahedron has 4 vertices / 6 edges / 4 faces / 8 half-faces / 1 cell" * geolab::points(2) *
              geolab::hint("Handout §3: one Face per distinct polygon, two half-faces per face (2f for the cell, 2f+1 "
                           "outside), one half-edge per corner of each half-face.")) {
        const CellList cl = fx::single_tet();
        const Mesh m = build_mesh(cl);
        check_counts(m, cl, "single tet");
        CHECK_MESSAGE(m.n_halfedges() == 24, "half-edges: expected 24 (3 per half-face), got " << m.n_halfedges());
        require_valid(m, "single tet");
        check_cells(m, cl, "single tet");
    }

    TEST_CASE("build: every fixture (tets / hexes / prisms / pyramids / polyhedra) validates with the right counts" *
              geolab::points(2) *
              geolab::hint("Match faces shared by two cells (the same vertex cycle, listed in opposite directions): "
                           "e.g. sort the faces by their smallest-vertex rotation.")) {
        for (const Fixture& f : stored_fixtures()) {
            const Mesh m = build_mesh(f.cells);
            require_valid(m, f.name);
            check_counts(m, f.cells, f.name);
        }
        // a triangle (0 1 3) made of three corners of the quad (0 1 3 2): two different faces
        CellList hex_and_tet = fx::hex_grid(1);
        hex_and_tet.positions.push_back({0.7, 0.3, -1});  // 8, below the cube
        hex_and_tet.add_tet(0, 3, 1, 8);
        const Mesh m = build_mesh(hex_and_tet);
        require_valid(m, "a hexahedron and a tetrahedron on three corners of its bottom quad");
        check_counts(m, hex_and_tet, "a hexahedron and a tetrahedron on three corners of its bottom quad");
    }

    TEST_CASE("build: each cell lists its faces in order / numbered by first use / 2f for the first cell" *
              geolab::points(2) *
              geolab::hint("halffaces(c) keeps the list's face order; a face's number is the order of its first use; "
                           "2f is the first user's side and starts at the vertex it lists first.")) {
        for (const Fixture& f : stored_fixtures()) check_cells(build_mesh(f.cells), f.cells, f.name);
    }

    TEST_CASE("build: mate / prev / twin and the vertex cache agree with the derived relations in every configuration" *
              geolab::points(2) *
              geolab::hint("mate(h): the same edge in the opposite half-face, reversed; twin(h): the same edge in the "
                           "cell's other half-face; prev: the loop backwards; call rebuild_vertex_cache().")) {
        for (const Fixture& f : stored_fixtures()) {
            INFO(describe(f));
            const Mesh m = build_mesh(f.cells);
            require_valid(m, f.name);
            // (relations of an empty mesh agree trivially: the mesh must be the fixture's)
            REQUIRE_MESSAGE((m.n_cells() == f.cells.n_cells() && m.n_vertices() == f.cells.n_vertices()),
                            "the mesh has " << m.n_cells() << " cells and " << m.n_vertices() << " vertices, the list "
                                            << f.cells.n_cells() << " and " << f.cells.n_vertices());
            for_each_config(m, [&](const auto& x, const char* config) {
                INFO("configuration: " << config);
                for (HalfEdge h : m.halfedges()) {
                    REQUIRE_MESSAGE(x.prev(h) == m.prev(h), h << ": prev derived " << x.prev(h) << ", stored " << m.prev(h));
                    REQUIRE_MESSAGE(x.mate(h) == m.mate(h), h << ": mate derived " << x.mate(h) << ", stored " << m.mate(h));
                }
                for (Vertex v : m.vertices())
                    REQUIRE_MESSAGE(x.vertex_halffaces(v) == m.vertex_halffaces(v),
                                    v << ": half-faces around it " << list(x.vertex_halffaces(v)) << " (this configuration), "
                                      << list(m.vertex_halffaces(v)) << " (your cache)");
            });
        }
    }

    TEST_CASE("build: the two tetrahedra share one face / whose sides belong to cell 0 and cell 1" * geolab::points(1) *
              geolab::hint("The face listed (0 1 2) by cell 0 and (0 2 1) by cell 1 is one Face with both sides used.")) {
        const CellList cl = fx::two_tets();
        const Mesh m = build_mesh(cl);
        require_valid(m, "two tets");
        const HalfFace shared = m.halffaces(Cell{0})[0];
        CHECK_MESSAGE(m.cell(Mesh::opposite(shared)) == Cell{1}, "the other side of cell 0's first face should be c1, got "
                                                                     << m.cell(Mesh::opposite(shared)));
        CHECK(m.halffaces(Cell{1})[0] == Mesh::opposite(shared));
        std::size_t boundary = 0;
        for (HalfFace hf : m.halffaces()) boundary += m.is_boundary(hf);
        CHECK_MESSAGE(boundary == 6, "6 boundary faces expected, got " << boundary);
    }

    TEST_CASE("build: degenerate cells are rejected with a message naming the cell" * geolab::points(2) *
              geolab::hint("Check each cell first: at least 4 faces, each face at least 3 distinct vertices, no face "
                           "twice. Message: \"build_mesh: degenerate cell C: ...\".")) {
        CellList three_faces = fx::single_tet();
        three_faces.add_polyhedron({{0, 2, 1}, {0, 1, 3}, {1, 2, 3}});
        expect_error<geolab::TopologyError>(three_faces, "cell 1 with 3 faces", {"degenerate cell 1: it has 3 faces"});
        CellList empty_cell = fx::two_tets();
        empty_cell.cell_begin = {0, 4, 4, 8};  // cell 1 has no face
        expect_error<geolab::TopologyError>(empty_cell, "cell 1 with no face", {"degenerate cell 1: it has 0 faces"});
        CellList empty_face = fx::two_tets();
        empty_face.face_begin[2] = empty_face.face_begin[1];  // face 1 of cell 0 has no vertex (face 2 takes them)
        expect_error<geolab::TopologyError>(empty_face, "cell 0 with a face of 0 vertices",
                                            {"degenerate cell 0: face 1 has 0 vertices"});
        CellList two_gon = fx::single_tet();
        two_gon.add_polyhedron({{0, 2, 1}, {0, 1}, {1, 2, 3}, {2, 0, 3}, {0, 1, 3}});
        expect_error<geolab::TopologyError>(two_gon, "cell 1 with a 2-vertex face", {"degenerate cell 1"});
        CellList repeated = fx::single_tet();
        repeated.add_polyhedron({{0, 2, 1}, {0, 1, 2, 1, 3}, {1, 2, 3}, {2, 0, 3}});
        expect_error<geolab::TopologyError>(repeated, "cell 1 with a face repeating vertex 1",
                                            {"degenerate cell 1", "face 1 repeats vertex 1"});
        CellList twice;
        twice.positions = fx::single_tet().positions;
        twice.add_polyhedron({{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {1, 3, 0}});
        expect_error<geolab::TopologyError>(twice, "cell 0 listing face (0 1 3) twice",
                                            {"degenerate cell 0", "faces 1 and 4 are the same polygon (0 1 3)"});
        CellList twice_first;  // the polygon that sorts first, twice
        twice_first.positions = twice.positions;
        twice_first.add_polyhedron({{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {1, 0, 2}});
        expect_error<geolab::TopologyError>(twice_first, "cell 0 listing face (0 2 1) twice",
                                            {"faces 0 and 4 are the same polygon (0 2 1)"});
        CellList twice_last;  // the polygon that sorts last, twice
        twice_last.positions = twice.positions;
        twice_last.add_polyhedron({{2, 3, 1}, {0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}});
        expect_error<geolab::TopologyError>(twice_last, "cell 0 listing face (1 2 3) twice",
                                            {"faces 0 and 3 are the same polygon (2 3 1)"});
    }

    TEST_CASE("build: a cell that is not closed is rejected naming the cell and an edge" * geolab::points(2) *
              geolab::hint("Inside one cell each directed edge of its faces must be matched by exactly one use of the "
                           "reverse edge. Message: \"build_mesh: cell C is not closed: the edge from vertex u to vertex v "
                           "...\".")) {
        CellList flipped = fx::two_tets();
        flipped.add_polyhedron({{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}});  // one face flipped
        expect_error<geolab::TopologyError>(flipped, "cell 2 with a flipped face",
                                            {"cell 2 is not closed", "the edge from vertex 0 to vertex 1 is used 2 time(s) in "
                                                                     "that direction and 0 time(s) in the other"});
        CellList flipped_late = fx::two_tets();
        flipped_late.add_polyhedron({{0, 2, 1}, {0, 1, 3}, {1, 3, 2}, {2, 0, 3}});  // its face (1 2 3) flipped
        expect_error<geolab::TopologyError>(flipped_late, "cell 2 with its face (1 2 3) flipped",
                                            {"cell 2 is not closed", "the edge from vertex 1 to vertex 3 is used 2 time(s) in "
                                                                     "that direction and 0 time(s) in the other"});
        // a hexahedron with its top face listed clockwise (seen from outside)
        const CellList grid = fx::hex_grid(2);
        CellList hexes;
        hexes.positions = grid.positions;
        for (std::size_t c = 0; c < grid.n_cells(); ++c) {
            for (std::size_t i = 0; i < grid.n_faces(c); ++i) {
                std::vector<std::uint32_t> f = to_vec(grid.face(c, i));
                if (c == 5 && i == 1) std::reverse(f.begin(), f.end());
                hexes.add_face(f);
            }
            hexes.close_cell(CellType::hexahedron);
        }
        expect_error<geolab::TopologyError>(hexes, "hex grid 2 with cell 5's top face mis-oriented",
                                            {"cell 5 is not closed", "the edge from vertex"});
        CellList open;
        open.positions = fx::hex_grid(1).positions;
        open.add_polyhedron({{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {1, 3, 7, 5}, {3, 2, 6, 7}});  // a box without a lid
        expect_error<geolab::TopologyError>(open, "a box without one side", {"cell 0 is not closed"});
    }

    TEST_CASE("build: a face used by three cells is rejected naming the face and the cells" * geolab::points(2) *
              geolab::hint("Group equal faces; a group of 3 or more: \"build_mesh: face (a b c) is used by 3 or more "
                           "cells: cell A, cell B, cell C\".")) {
        CellList cl = fx::two_tets();
        cl.positions.push_back({0.3, 0.3, 2});  // 5: another apex above
        cl.add_tet(0, 1, 2, 5);
        expect_message(cl, "three tets on face (0 1 2)",
                       "build_mesh: face (0 2 1) is used by 3 or more cells: cell 0, cell 1, cell 2");
    }

    TEST_CASE("build: two cells listing a shared face the same way are rejected (inconsistent orientation)" *
              geolab::points(1) *
              geolab::hint("A shared face must be listed in opposite directions by its two cells. Message: "
                           "\"build_mesh: inconsistent orientation: cell A and cell B both list face (a b c) in the "
                           "same direction\".")) {
        CellList cl = fx::single_tet();
        cl.positions.push_back({0.3, 0.3, 1.5});
        cl.add_polyhedron({{0, 1, 4}, {1, 2, 4}, {2, 0, 4}, {0, 2, 1}});  // an inverted tet on the same base side
        expect_message(cl, "two tets on the same side of face (0 2 1)",
                       "build_mesh: inconsistent orientation: cell 0 and cell 1 both list face (0 2 1) in the same "
                       "direction");
        CellList later = fx::single_tet();  // the same two cells after an unrelated cell 0
        for (const auto& p : {glm::dvec3(2, 0, 0), glm::dvec3(3, 0, 0), glm::dvec3(2, 1, 0), glm::dvec3(2, 0, 1),
                              glm::dvec3(2.3, 0.3, 1.5)})
            later.positions.push_back(p);
        later.add_tet(4, 5, 6, 7);                                          // cell 1: its face 0 is (4 6 5)
        later.add_polyhedron({{4, 5, 8}, {5, 6, 8}, {6, 4, 8}, {4, 6, 5}});  // cell 2 lists (4 6 5) too
        expect_message(later, "cells 1 and 2 on the same side of face (4 6 5)",
                       "build_mesh: inconsistent orientation: cell 1 and cell 2 both list face (4 6 5) in the same "
                       "direction");
    }

    TEST_CASE("build: an index out of range or a non-finite position is std::invalid_argument" * geolab::points(1) *
              geolab::hint("Check the data before anything else: \"build_mesh: cell C face I: vertex N out of range (M "
                           "vertices)\".")) {
        CellList bad = fx::single_tet();
        bad.add_tet(0, 1, 2, 9);
        expect_error<std::invalid_argument>(bad, "cell 1 uses vertex 9 of 4", {"cell 1 face 1: vertex 9 out of range (4 vertices)"});
        CellList first;
        first.positions = fx::single_tet().positions;
        first.add_tet(0, 1, 4, 3);  // its face 0 is (0 4 1)
        expect_error<std::invalid_argument>(first, "cell 0 uses vertex 4 of 4 in its face 0",
                                            {"cell 0 face 0: vertex 4 out of range (4 vertices)"});
        CellList nan = fx::single_tet();
        nan.positions[2].y = std::nan("");
        expect_error<std::invalid_argument>(nan, "vertex 2 is NaN", {"vertex 2 has a position that is not finite"});
        CellList inf = fx::single_tet();
        inf.positions[0].z = std::numeric_limits<double>::infinity();
        expect_error<std::invalid_argument>(inf, "vertex 0 has z = +infinity", {"vertex 0 has a position that is not finite"});
        // offsets that do not fit
        CellList no_cells = fx::two_tets();
        no_cells.cell_begin = std::vector<std::uint32_t>{};  // empty, without even room for one element
        expect_error<std::invalid_argument>(no_cells, "two tets with cell_begin empty", {"offsets do not match its faces"});
        CellList no_faces = fx::two_tets();
        no_faces.face_begin = std::vector<std::uint32_t>{};
        expect_error<std::invalid_argument>(no_faces, "two tets with face_begin empty", {"offsets do not match its faces"});
        CellList short_faces = fx::two_tets();
        short_faces.face_begin.pop_back();
        short_faces.face_vertices.resize(short_faces.face_begin.back());
        expect_error<std::invalid_argument>(short_faces, "two tets with 7 faces for 8 face offsets of the cells",
                                            {"offsets do not match its faces"});
        CellList extra_vertex = fx::two_tets();
        extra_vertex.face_vertices.push_back(0);
        expect_error<std::invalid_argument>(extra_vertex, "two tets with one vertex index more than the faces use",
                                            {"offsets do not match its faces"});
        CellList late_start = fx::two_tets();
        late_start.cell_begin[0] = 1;  // face 0 belongs to no cell
        expect_error<std::invalid_argument>(late_start, "two tets with cell_begin (1 4 8)", {"offsets do not match its faces"});
        CellList late_vertices = fx::two_tets();
        late_vertices.face_begin[0] = 1;  // vertex index 0 belongs to no face
        expect_error<std::invalid_argument>(late_vertices, "two tets with face_begin (1 3 6 ...)",
                                            {"offsets do not match its faces"});
        CellList down = fx::two_tets();
        down.cell_begin = {0, 9, 8};  // cell 1 would end before it starts
        expect_error<std::invalid_argument>(down, "two tets with cell_begin (0 9 8)", {"cell 1 has decreasing offsets"});
        CellList face_down = fx::two_tets();
        face_down.face_begin[1] = 7;  // face 1 of cell 0 would end before it starts
        expect_error<std::invalid_argument>(face_down, "two tets with face_begin (0 7 6 ...)",
                                            {"cell 0 face 1 has decreasing offsets"});
        CellList first_face_down = fx::two_tets();
        first_face_down.face_begin[4] = 16;  // face 0 of cell 1 would end (15) before it starts
        expect_error<std::invalid_argument>(first_face_down, "two tets with face_begin (0 3 6 9 16 15 ...)",
                                            {"cell 1 face 0 has decreasing offsets"});
    }

    TEST_CASE("build: tetgen meshes of real models (sphere and bunny00) validate with the right counts" *
              geolab::points(1) *
              geolab::hint("Real data is large (bunny00: 131,557 tets): match faces by sorting, not by scanning.")) {
        for (const char* name : {"sphere", "bunny00"}) {
            const CellList cl = tet_model(name);
            INFO("input: " << name << " tetrahedralised by tetgen (" << cl.n_cells() << " tets)");
            const Mesh m = build_mesh(cl);
            require_valid(m, name);
            check_counts(m, cl, name);
            // the boundary faces are the model's triangles
            const PolygonSoup surface = surface_model(name);
            std::size_t bnd = 0;
            for (HalfFace hf : m.halffaces()) bnd += m.is_boundary(hf);
            CHECK_MESSAGE(bnd == surface.n_faces(), "boundary faces: expected " << surface.n_faces() << " (the model's "
                                                                                 << "triangles), got " << bnd);
        }
    }
}
