// Lab 01, Task 3: topology (handout §5). Meshes from stored connectivity (stored.hpp), never from your build_mesh.
#include "helpers.hpp"

using namespace lab01;

TEST_SUITE("Task 3: topology") {
    TEST_CASE("topology: valence is the number of edges at each vertex" * geolab::points(3) *
              geolab::hint("Count the outgoing half-edges once around the vertex; on the boundary the walk from the "
                           "boundary half-edge already meets every edge once.")) {
        for (const Fixture& f : manifold_fixtures()) {
            INFO(describe(f));
            const Mesh m = stored_mesh(f);
            const auto nb = neighbours(f.soup);
            const auto on_boundary = boundary_vertices(f.soup);
            for (Vertex v : m.vertices()) {
                CAPTURE(v);
                INFO(std::string(on_boundary[v.idx] ? "a boundary vertex" : "an interior or isolated vertex"));
                CHECK(valence(m, v) == int(nb[v.idx].size()));
            }
        }
    }

    TEST_CASE("topology: one_ring_vertices and one_ring_faces list the neighbours and faces around a vertex" *
              geolab::points(3) *
              geolab::hint("Same walk as outgoing_halfedges: to_vertex(h) for the vertices, face(h) for the faces, "
                           "skipping boundary half-edges (no invalid faces).")) {
        std::vector<Vertex> ring{Vertex{9}};
        std::vector<Face> faces{Face{9}};
        for (const Fixture& f : manifold_fixtures()) {
            INFO(describe(f));
            const Mesh m = stored_mesh(f);
            const auto nb = neighbours(f.soup);
            const auto vf = vertex_faces(f.soup);
            for (Vertex v : m.vertices()) {
                CAPTURE(v);
                one_ring_vertices(m, v, ring);
                one_ring_faces(m, v, faces);
                std::set<std::uint32_t> ring_set, face_set;
                for (Vertex w : ring) ring_set.insert(w.idx);
                for (Face g : faces) {
                    CHECK_MESSAGE(g.is_valid(), "one_ring_faces listed an invalid face (the boundary)");
                    face_set.insert(g.idx);
                }
                CHECK(ring.size() == nb[v.idx].size());
                CHECK(ring_set == nb[v.idx]);
                CHECK(faces.size() == vf[v.idx].size());
                CHECK(face_set == vf[v.idx]);
                // the order is the one of the walk h -> next(twin(h)) from halfedge(v)
                if (!ring.empty()) CHECK(ring.front() == m.to_vertex(m.halfedge(v)));
            }
        }
        const Mesh tet = stored_mesh("tetrahedron", fx::tetrahedron());
        std::vector<std::uint32_t> ids;
        for (Vertex w : one_ring_vertices(tet, Vertex{0})) ids.push_back(w.idx);
        INFO("tetrahedron vertex 0 (faces 0 1 2, 0 3 1, 0 2 3): the one ring must be a rotation of 1 3 2");
        REQUIRE(ids.size() == 3);
        std::rotate(ids.begin(), std::find(ids.begin(), ids.end(), 1u), ids.end());
        CHECK(ids == std::vector<std::uint32_t>{1, 3, 2});
    }

    TEST_CASE("topology: euler_characteristic is V - E + F on every fixture" * geolab::points(2) *
              geolab::hint("chi = V - E + F, with isolated vertices counted in V.")) {
        for (const Fixture& f : manifold_fixtures()) {
            INFO(describe(f));
            const Mesh m = stored_mesh(f);
            CHECK(euler_characteristic(m) == f.chi);
        }
    }

    TEST_CASE(
        "topology: boundary_loops finds each hole as a closed next loop" * geolab::points(2) *
        geolab::hint("Visit half-edges in index order; an unvisited boundary half-edge starts a loop that follows "
                     "next until back. Loops start at their lowest half-edge.")) {
        for (const Fixture& f : manifold_fixtures()) {
            INFO(describe(f));
            const Mesh m = stored_mesh(f);
            const auto loops = boundary_loops(m);
            CHECK(int(loops.size()) == f.loops);
            std::size_t total = 0;
            for (std::size_t i = 0; i < loops.size(); ++i) {
                CAPTURE(i);
                const auto& loop = loops[i];
                REQUIRE(!loop.empty());
                total += loop.size();
                CHECK(loop.front() == *std::min_element(loop.begin(), loop.end()));
                if (i > 0) CHECK(loops[i - 1].front() < loop.front());
                for (std::size_t k = 0; k < loop.size(); ++k) {
                    CHECK(m.is_boundary(loop[k]));
                    CHECK(m.next(loop[k]) == loop[(k + 1) % loop.size()]);
                }
            }
            CHECK(total == boundary_edges(f.soup).size());
        }
        const Mesh g = stored_mesh("grid(4 x 4)", fx::grid(4, 4));
        const auto loops = boundary_loops(g);
        REQUIRE(loops.size() == 1);
        CHECK(loops[0].size() == 16);
    }

    TEST_CASE(
        "topology: connected_components labels vertices joined by edges alike" * geolab::points(2) *
        geolab::hint("Flood fill (stack or queue) over the one rings, starting from each unlabelled vertex in index "
                     "order; isolated vertices are components of their own.")) {
        for (const Fixture& f : manifold_fixtures()) {
            INFO(describe(f));
            const Mesh m = stored_mesh(f);
            const Components c = connected_components(m);
            CHECK(c.count == f.components);
            REQUIRE(c.vertex_component.size() == m.n_vertices());
            const auto roots = component_roots(f.soup);
            int next_new = 0;  // labels appear in order of the lowest vertex
            for (std::uint32_t v = 0; v < m.n_vertices(); ++v) {
                CAPTURE(v);
                const int label = c.vertex_component[v];
                if (label == next_new) ++next_new;
                CHECK_MESSAGE(label < next_new, "component labels must be numbered in order of their lowest vertex");
                for (std::uint32_t w = 0; w < v; ++w)
                    if ((roots[w] == roots[v]) != (c.vertex_component[w] == label))
                        FAIL_CHECK("vertices " << w << " and " << v << " are "
                                               << std::string(roots[w] == roots[v] ? "connected" : "not connected")
                                               << " but got labels " << c.vertex_component[w] << " and " << label);
            }
        }
    }

    TEST_CASE("topology: genus is 0 for spheres and disks and 1 for the torus" * geolab::points(2) *
              geolab::hint("Per component with faces: g = (2 - chi - b) / 2 with b its boundary loops; sum them.")) {
        for (const Fixture& f : manifold_fixtures()) {
            INFO(describe(f));
            const Mesh m = stored_mesh(f);
            CHECK(genus(m) == f.genus);
        }
        // Two tori side by side: genus 2.
        const int g = genus(two_tori_mesh());
        CHECK_MESSAGE(g == 2, "two tori side by side (torus(8, 6) and torus(7, 5)): expected genus 2, got " << g);
    }

    TEST_CASE("topology: genus and components of meshes with 64 and 128 and more components" * geolab::points(2) *
              geolab::hint("Keep one counter per component (sized by the number of components, not by a constant) and "
                           "sum g_c over exactly the components that have faces.")) {
        struct Case {
            const char* name;
            Mesh mesh;
            int components, chi, genus;
        };
        const Mesh torus = stored_mesh("torus(8 x 6 triangles)", fx::torus(8, 6));
        const Mesh tori = two_tori_mesh();
        for (const Case& c : {Case{"64 tetrahedra", tetrahedra_in_a_row_mesh(64), 64, 128, 0},
                              Case{"128 tetrahedra", tetrahedra_in_a_row_mesh(128), 128, 256, 0},
                              Case{"127 tetrahedra then torus(8, 6)", tetrahedra_in_a_row_mesh(127, torus), 128, 254, 1},
                              Case{"62 tetrahedra then two tori", tetrahedra_in_a_row_mesh(62, tori), 64, 124, 2},
                              Case{"130 tetrahedra then two tori", tetrahedra_in_a_row_mesh(130, tori), 132, 260, 2}}) {
            INFO(std::string(c.name) << " (tetrahedra 3 apart along x, each a closed sphere): expected " << c.components
                        << " components, chi " << c.chi << ", genus " << c.genus);
            const Components comp = connected_components(c.mesh);
            CHECK_MESSAGE(comp.count == c.components, "connected_components: got " << comp.count);
            CHECK_MESSAGE(euler_characteristic(c.mesh) == c.chi, "euler_characteristic: got " << euler_characteristic(c.mesh));
            const int g = genus(c.mesh);
            CHECK_MESSAGE(g == c.genus, "genus: got " << g);
        }
    }

}  // TEST_SUITE
