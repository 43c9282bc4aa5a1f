// Lab 01, Task 1: build_mesh (handout §3). Every test first builds valid meshes, so a stub fails them all.
// The last test is the lab's one end-to-end check (your build_mesh, then your queries on a real scan); every test
// of Tasks 2-5 gets its mesh without your build_mesh (stored.hpp).
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab01;

TEST_SUITE("Task 1: build the mesh") {
    TEST_CASE("build_mesh: tetrahedron has 4 vertices 6 edges 4 faces and passes validate" * geolab::points(2) *
              geolab::hint(
                  "One edge per undirected edge of the soup, its two half-edges created together; see handout §3.1")) {
        const Fixture f = fixture("tetrahedron");
        INFO(describe(f));
        const Mesh m = build_valid(f);
        CHECK(m.n_vertices() == 4);
        CHECK(m.n_edges() == 6);
        CHECK(m.n_halfedges() == 12);
        CHECK(m.n_faces() == 4);
        for (Vertex v : m.vertices()) CHECK(m.position(v) == f.soup.positions[v.idx]);
    }

    TEST_CASE("build_mesh: validate passes on every fixture of the family" * geolab::points(3) *
              geolab::hint("Read validate()'s message: it names the first broken invariant and the element. "
                           "Handout §3.4 lists the invariants.")) {
        for (const Fixture& f : manifold_fixtures()) {
            INFO(describe(f));
            build_valid(f);
        }
    }

    TEST_CASE("build_mesh: vertex edge and face counts match the soup on every fixture" * geolab::points(2) *
              geolab::hint("E must count each undirected edge once: a matched pair u->v / v->u is one edge; an "
                           "unmatched u->v is one edge whose twin is a boundary half-edge.")) {
        for (const Fixture& f : manifold_fixtures()) {
            INFO(describe(f));
            const Mesh m = build_valid(f);
            CHECK(m.n_vertices() == std::size_t(f.V));
            CHECK(m.n_edges() == undirected_edges(f.soup).size());
            CHECK(m.n_edges() == std::size_t(f.E));
            CHECK(m.n_faces() == std::size_t(f.F));
        }
    }

    TEST_CASE("build_mesh: each face's next cycle visits the soup face in order" * geolab::points(3) *
              geolab::hint("halfedge(f) goes from soup.face(f)[0] to soup.face(f)[1]; next goes on to [2], ... and "
                           "from the last corner back to the first (counter-clockwise). Handout §3.2.")) {
        for (const Fixture& f : manifold_fixtures()) {
            INFO(describe(f));
            const Mesh m = build_valid(f);
            for (Face face : m.faces()) {
                const auto corners = f.soup.face(face.idx);
                const std::size_t n = corners.size();
                Halfedge h = m.halfedge(face);
                CAPTURE(face);
                REQUIRE(m.from_vertex(h).idx == corners[0]);
                for (std::size_t i = 0; i < n; ++i) {
                    CAPTURE(i);
                    CHECK(m.face(h) == face);
                    CHECK(m.to_vertex(h).idx == corners[(i + 1) % n]);
                    h = m.next(h);
                }
                CHECK_MESSAGE(h == m.halfedge(face),
                              "after " << n << " steps of next the walk is not back at halfedge(f)");
            }
        }
    }

    TEST_CASE("build_mesh: every soup edge is one edge whose twins run opposite ways" * geolab::points(3) *
              geolab::hint("The twin of u->v is v->u (not another u->v). With the h ^ 1 layout, add_edge(u, v) makes "
                           "both; the corner v->u of the neighbouring face must get the second one.")) {
        for (const Fixture& f : manifold_fixtures()) {
            INFO(describe(f));
            const Mesh m = build_valid(f);
            const auto face_of = face_of_directed_edge(f.soup);
            std::set<VertexPair> seen;
            for (Halfedge h : m.halfedges()) {
                CAPTURE(h);
                const VertexPair uv{m.from_vertex(h).idx, m.to_vertex(h).idx};
                CHECK(m.from_vertex(m.twin(h)) == m.to_vertex(h));
                CHECK(m.twin(m.twin(h)) == h);
                // A face half-edge u->v is the soup's u->v; a boundary half-edge u->v has v->u in the soup.
                if (m.is_boundary(h)) {
                    CHECK_MESSAGE(!face_of.count(uv), "boundary half-edge "
                                                          << uv.first << "->" << uv.second
                                                          << " but a soup face uses that directed edge");
                    CHECK_MESSAGE(face_of.count({uv.second, uv.first}), "boundary half-edge "
                                                                            << uv.first << "->" << uv.second
                                                                            << " has no soup face on the other side");
                } else {
                    CHECK_MESSAGE(face_of.count(uv), "half-edge " << uv.first << "->" << uv.second << " with face "
                                                                  << m.face(h)
                                                                  << " but no soup face has that directed edge");
                    if (face_of.count(uv)) CHECK(m.face(h).idx == std::uint32_t(face_of.at(uv)));
                }
                CHECK_MESSAGE(seen.insert(uv).second,
                              "directed edge " << uv.first << "->" << uv.second << " appears twice");
            }
            CHECK(seen.size() == 2 * undirected_edges(f.soup).size());
        }
    }

    TEST_CASE("build_mesh: the boundary half-edges of a grid form one closed loop" * geolab::points(2) *
              geolab::hint("An unmatched u->v gets a boundary twin v->u (no face). Its next is the boundary half-edge "
                           "leaving u, so each hole becomes a loop like a face. Handout §3.3.")) {
        for (auto [nx, ny] : {std::pair{4, 4}, std::pair{3, 2}}) {
            const PolygonSoup soup = fx::grid(nx, ny);
            INFO("grid(" << nx << ", " << ny << ")");
            const Mesh m = build_valid(soup, "grid");
            std::vector<Halfedge> boundary;
            for (Halfedge h : m.halfedges())
                if (m.is_boundary(h)) boundary.push_back(h);
            REQUIRE_MESSAGE(
                boundary.size() == std::size_t(2 * (nx + ny)),
                "expected 2(nx + ny) = " << 2 * (nx + ny) << " boundary half-edges, found " << boundary.size());
            // Walk next from the first boundary half-edge: it must stay on the boundary and meet all of them.
            std::set<Halfedge> met;
            Halfedge h = boundary.front();
            for (std::size_t i = 0; i < boundary.size(); ++i) {
                CAPTURE(h);
                CHECK_MESSAGE(m.is_boundary(h), "next of a boundary half-edge left the boundary");
                CHECK(m.from_vertex(m.next(h)) == m.to_vertex(h));
                met.insert(h);
                h = m.next(h);
            }
            CHECK_MESSAGE(h == boundary.front(),
                          "the boundary loop does not close after " << boundary.size() << " steps");
            CHECK(met.size() == boundary.size());
        }
    }

    TEST_CASE(
        "build_mesh: boundary vertices store a boundary half-edge" * geolab::points(2) *
        geolab::hint("After the faces are linked, set halfedge(v) to the boundary half-edge leaving v where there "
                     "is one: is_boundary(v) relies on it. Handout §3.3.")) {
        for (const char* name : {"grid(4 x 4)", "grid(6 x 6) with two holes", "open box (5 quads)", "open pyramid",
                                 "house (quad + triangle)"}) {
            const Fixture f = fixture(name);
            INFO(describe(f));
            const Mesh m = build_valid(f);
            const auto on_boundary = boundary_vertices(f.soup);
            for (Vertex v : m.vertices()) {
                CAPTURE(v);
                REQUIRE(m.halfedge(v).is_valid());
                CHECK(m.from_vertex(m.halfedge(v)) == v);
                CHECK_MESSAGE(m.is_boundary(m.halfedge(v)) == bool(on_boundary[v.idx]),
                              std::string(on_boundary[v.idx] ? "boundary vertex whose halfedge(v) has a face"
                                                  : "interior vertex whose halfedge(v) is a boundary half-edge"));
            }
        }
    }

    TEST_CASE("build_mesh: an isolated vertex is kept with an invalid halfedge" * geolab::points(2) *
              geolab::hint("Create every soup vertex, used or not; a vertex no face uses keeps halfedge(v) invalid.")) {
        const Fixture f = fixture("tetrahedron + isolated vertex");
        INFO(describe(f));
        const Mesh m = build_valid(f);
        REQUIRE(m.n_vertices() == 5);
        CHECK_FALSE(m.halfedge(Vertex{4}).is_valid());
        CHECK(m.is_isolated(Vertex{4}));
        CHECK(m.position(Vertex{4}) == glm::dvec3(5.0, 5.0, 5.0));
        for (std::uint32_t v = 0; v < 4; ++v) CHECK(m.halfedge(Vertex{v}).is_valid());
    }

    TEST_CASE("build_mesh: the bowtie is rejected as a complex vertex naming vertex 0" * geolab::points(2) *
              geolab::hint("Two boundary half-edges leaving one vertex (or a walk around it that misses faces) means "
                           "its faces form several fans. Message format: see build_mesh in halfedge.hpp.")) {
        build_valid(fx::tetrahedron(), "tetrahedron");  // a valid soup must build first
        const PolygonSoup soup = fx::bowtie();
        INFO("bowtie:\n" << mesh_to_string(soup));
        CHECK_THROWS_AS(build_mesh(soup), geolab::TopologyError);
        const std::string msg = build_error_message(soup);
        CAPTURE(msg);
        CHECK(contains(msg, "complex vertex 0"));
        CHECK(contains(msg, "face 0"));
        CHECK(contains(msg, "face 1"));
    }

    TEST_CASE("build_mesh: the fan is rejected as a complex edge naming vertices 0 and 1" * geolab::points(2) *
              geolab::hint("Count the faces on each undirected edge: u->v and v->u together at most 2.")) {
        build_valid(fx::tetrahedron(), "tetrahedron");
        const PolygonSoup soup = fx::fan();
        INFO("fan:\n" << mesh_to_string(soup));
        CHECK_THROWS_AS(build_mesh(soup), geolab::TopologyError);
        const std::string msg = build_error_message(soup);
        CAPTURE(msg);
        CHECK(contains(msg, "complex edge between vertex 0 and vertex 1"));
        CHECK(contains(msg, "face 0"));
        CHECK(contains(msg, "face 1"));
        CHECK(contains(msg, "face 2"));
        // the same at a vertex of high valence: a third face on the edge from the top apex (vertex 40) to vertex 1
        // of apex_first_bipyramid(40), which faces 0 and 39 share
        PolygonSoup crowded = apex_first_bipyramid(40);
        crowded.positions.push_back({0.5, 0.5, 0.5});
        crowded.add_face({1, 40, 42});
        INFO("bipyramid(40) plus face 80 = (1, 40, 42)");
        const std::string crowded_msg = build_error_message(crowded);
        CAPTURE(crowded_msg);
        CHECK(contains(crowded_msg, "complex edge between vertex 1 and vertex 40: used by face 0, face 39, face 80 "));
    }

    TEST_CASE("build_mesh: a flipped face is rejected as inconsistent orientation naming it and its neighbour" *
              geolab::points(2) *
              geolab::hint("A directed edge u->v used by two faces means they disagree on orientation: name those two "
                           "faces (two different ones) and that edge.")) {
        build_valid(fx::tetrahedron(), "tetrahedron");
        struct Case {
            const char* name;
            PolygonSoup soup;
            std::size_t flipped;
        };
        for (const Case& c : {Case{"cube (quads) with face 3 flipped", fx::flip_face(fx::cube(false), 3), 3},
                              Case{"icosphere(1) with face 57 flipped", fx::flip_face(fx::icosphere(1), 57), 57},
                              Case{"grid(3 x 3) with face 8 flipped", fx::flip_face(fx::grid(3, 3), 8), 8}}) {
            INFO(std::string(c.name));
            CHECK_THROWS_AS(build_mesh(c.soup), geolab::TopologyError);
            const std::string msg = build_error_message(c.soup);
            CAPTURE(msg);
            CHECK(contains(msg, "inconsistent orientation"));
            CHECK(contains(msg, "face " + std::to_string(c.flipped) + " "));
        }
        // Face 0 flipped: it has the lowest index of the faces on its edges. The bipyramid's apices have 40 corners
        // each (not a handful): the flipped faces there disagree at a high-valence vertex.
        for (int n : {15, 16, 17, 40}) {  // apex valences around the length of a short scan, and above it
            const PolygonSoup b = apex_first_bipyramid(n);
            const Mesh m = build_valid(b, "bipyramid(" + std::to_string(n) + ")");
            CHECK(m.n_edges() == std::size_t(3 * n));
            CHECK(m.n_faces() == std::size_t(2 * n));
        }
        for (const Case& c : {Case{"bipyramid(40) with face 0 flipped", fx::flip_face(apex_first_bipyramid(40), 0), 0},
                              Case{"bipyramid(40) with face 17 flipped", fx::flip_face(apex_first_bipyramid(40), 17), 17},
                              Case{"bipyramid(40) with face 63 flipped", fx::flip_face(apex_first_bipyramid(40), 63), 63},
                              Case{"tetrahedron with face 0 flipped", fx::flip_face(fx::tetrahedron(), 0), 0},
                              Case{"cube (quads) with face 0 flipped", fx::flip_face(fx::cube(false), 0), 0},
                              Case{"icosphere(1) with face 0 flipped", fx::flip_face(fx::icosphere(1), 0), 0},
                              Case{"grid(3 x 3) with face 0 flipped", fx::flip_face(fx::grid(3, 3), 0), 0},
                              Case{"grid(3 x 3) with face 8 flipped", fx::flip_face(fx::grid(3, 3), 8), 8}}) {
            INFO(std::string(c.name));
            CHECK_THROWS_AS(build_mesh(c.soup), geolab::TopologyError);
            check_orientation_message(c.soup, c.flipped);
        }
    }

    TEST_CASE("build_mesh: invalid soups are rejected with std::invalid_argument" * geolab::points(1) *
              geolab::hint("Call geolab::check_soup(soup) first: it rejects bad indices and degenerate faces.")) {
        build_valid(fx::tetrahedron(), "tetrahedron");
        PolygonSoup out_of_range = fx::tetrahedron();
        out_of_range.add_face({0, 1, 9});
        PolygonSoup two_corners = fx::tetrahedron();
        two_corners.add_face({0, 1});
        PolygonSoup repeated = fx::tetrahedron();
        repeated.add_face({0, 1, 1});
        for (const auto* s : {&out_of_range, &two_corners, &repeated}) {
            INFO(mesh_to_string(*s));
            CHECK_THROWS_AS(build_mesh(*s), std::invalid_argument);
        }
    }

    TEST_CASE("build_mesh: a complex edge inside a larger mesh is reported with exactly the faces on it" *
              geolab::points(2) *
              geolab::hint("List every face that uses u->v or v->u, each once, in increasing order: the message is "
                           "'complex edge between vertex u and vertex v: used by face A, face B, face C (a manifold "
                           "edge has at most 2 faces)' with u < v.")) {
        build_valid(fx::tetrahedron(), "tetrahedron");
        // icosphere(1) plus extra triangles hung on one of its edges, each with a new vertex; the extra faces first or
        // last, running either way along the edge.
        const PolygonSoup sphere = fx::icosphere(1);
        const auto c0 = sphere.face(17);
        const std::uint32_t u = c0[0], v = c0[1], w = std::uint32_t(sphere.n_vertices());
        struct Case {
            const char* name;
            std::vector<std::vector<std::uint32_t>> extra;
            bool extra_first;
        };
        for (const Case& c : {Case{"one extra face u->v, last", {{u, v, w}}, false},
                              Case{"one extra face v->u, first", {{v, u, w}}, true},
                              Case{"two extra faces, last", {{v, u, w}, {u, v, w + 1}}, false},
                              Case{"two extra faces, first", {{w, u, v}, {w + 1, v, u}}, true}}) {
            PolygonSoup soup;
            soup.positions = sphere.positions;
            for (std::size_t i = 0; i < c.extra.size(); ++i) soup.positions.push_back({0.1 * double(i), 2.0, 0.0});
            if (c.extra_first)
                for (const auto& f : c.extra) soup.add_face(f);
            for (std::size_t f = 0; f < sphere.n_faces(); ++f) soup.add_face(sphere.face(f));
            if (!c.extra_first)
                for (const auto& f : c.extra) soup.add_face(f);
            // The faces on the edge, by brute force.
            std::string list;
            int n = 0;
            for (std::size_t f = 0; f < soup.n_faces(); ++f) {
                const auto vs = soup.face(f);
                bool on_edge = false;
                for (std::size_t i = 0; i < vs.size(); ++i) {
                    const auto a = vs[i], b = vs[(i + 1) % vs.size()];
                    on_edge |= (a == u && b == v) || (a == v && b == u);
                }
                if (on_edge) list += (n++ ? ", face " : "face ") + std::to_string(f);
            }
            const std::string expect = "build_mesh: complex edge between vertex " + std::to_string(std::min(u, v)) +
                                       " and vertex " + std::to_string(std::max(u, v)) + ": used by " + list +
                                       " (a manifold edge has at most 2 faces)";
            INFO("icosphere(1) (80 faces) with " << std::string(c.name) << " on its edge " << u << "-" << v << " (" << n
                                                 << " faces on it)");
            CHECK_THROWS_AS(build_mesh(soup), geolab::TopologyError);
            const std::string msg = build_error_message(soup);
            CHECK_MESSAGE(msg == expect, "expected '" << expect << "', got '" << msg << "'");
        }
    }

    TEST_CASE("whole chain: bunny00 and holes built by your build_mesh answer your queries like brute force" *
              geolab::points(2) * geolab::time_limit(60) * geolab::whole_chain() *
              geolab::hint("The lab's one end-to-end test: your build_mesh on two real scans (bunny00 is closed, holes "
                           "has 7 boundary loops), then your Task 3 functions on them. If the other tests pass and "
                           "this fails, look at boundary vertices and holes.")) {
        for (const char* name : {"bunny00", "holes"}) {
            const PolygonSoup soup = load_model(name);
            INFO("model " << std::string(name) << ": " << soup.n_vertices() << " vertices, " << soup.n_faces() << " faces");
            const Mesh m = build_valid(soup, name);
            const int chi = int(soup.n_vertices()) - int(undirected_edges(soup).size()) + int(soup.n_faces());
            // each answer once: a message that called your code again would crash the test when it throws
            const int got_chi = euler_characteristic(m);
            CHECK_MESSAGE(got_chi == chi, "euler_characteristic: expected " << chi << ", got " << got_chi);
            const int loops = count_boundary_loops(soup);
            const std::size_t got_loops = boundary_loops(m).size();
            CHECK_MESSAGE(int(got_loops) == loops, "boundary_loops: expected " << loops << " loops, got " << got_loops);
            const auto roots = component_roots(soup);
            const int components = int(std::set<std::uint32_t>(roots.begin(), roots.end()).size());
            const int got_components = connected_components(m).count;
            CHECK_MESSAGE(got_components == components,
                          "connected_components: expected " << components << ", got " << got_components);
            if (components == 1) {
                const int got_genus = genus(m);
                CHECK_MESSAGE(got_genus == (2 - chi - loops) / 2,
                              "genus: expected " << (2 - chi - loops) / 2 << ", got " << got_genus);
            }
            check_valence_histogram(m, soup);
        }
    }

}  // TEST_SUITE
