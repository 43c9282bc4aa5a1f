// Lab 01, Task 2: the lecture's queries (handout §4). Meshes from stored connectivity (stored.hpp), never from
// your build_mesh.
#include "helpers.hpp"

using namespace lab01;

TEST_SUITE("Task 2: the lecture's queries") {
    TEST_CASE(
        "queries: edge_vertices and edge_faces give each edge's ends and the faces on its two sides" *
        geolab::points(3) *
        geolab::hint("edge_vertices(e) = (from_vertex, to_vertex) of halfedge(e, 0); edge_faces(e) = the faces of "
                     "halfedge(e, 0) and halfedge(e, 1), invalid where there is a hole.")) {
        for (const Fixture& f : manifold_fixtures()) {
            INFO(describe(f));
            const Mesh m = stored_mesh(f);
            const auto face_of = face_of_directed_edge(f.soup);
            std::set<VertexPair> seen;
            for (Edge e : m.edges()) {
                CAPTURE(e);
                const auto [a, b] = edge_vertices(m, e);
                CHECK(a == m.from_vertex(m.halfedge(e, 0)));
                CHECK(b == m.to_vertex(m.halfedge(e, 0)));
                seen.insert({std::min(a.idx, b.idx), std::max(a.idx, b.idx)});
                const auto [fa, fb] = edge_faces(m, e);
                const Face expect_a =
                    face_of.count({a.idx, b.idx}) ? Face{std::uint32_t(face_of.at({a.idx, b.idx}))} : Face{};
                const Face expect_b =
                    face_of.count({b.idx, a.idx}) ? Face{std::uint32_t(face_of.at({b.idx, a.idx}))} : Face{};
                CHECK_MESSAGE(fa == expect_a, "edge_faces(e).first: expected " << expect_a << " (the face using " << a
                                                                               << "->" << b << "), got " << fa);
                CHECK_MESSAGE(fb == expect_b, "edge_faces(e).second: expected " << expect_b << " (the face using " << b
                                                                                << "->" << a << "), got " << fb);
            }
            CHECK_MESSAGE(seen == undirected_edges(f.soup),
                          "edge_vertices over all edges must list each soup edge once");
        }
    }

    TEST_CASE(
        "queries: face_halfedges starts at halfedge(f) and follows next once around" * geolab::points(3) *
        geolab::hint("Follow next until you are back at the first half-edge; do not list it twice and do not stop "
                     "one early. Clear the output vector first.")) {
        std::vector<Halfedge> buffer{Halfedge{7}, Halfedge{3}};  // reused across calls, must be cleared each time
        for (const Fixture& f : manifold_fixtures()) {
            INFO(describe(f));
            const Mesh m = stored_mesh(f);
            for (Face face : m.faces()) {
                CAPTURE(face);
                face_halfedges(m, face, buffer);
                const std::size_t n = f.soup.face(face.idx).size();
                REQUIRE_MESSAGE(buffer.size() == n, "face " << face.idx << " has " << n
                                                            << " corners but face_halfedges "
                                                            << "returned " << buffer.size() << " half-edges");
                CHECK(buffer.front() == m.halfedge(face));
                for (std::size_t i = 0; i < n; ++i) {
                    CHECK(m.face(buffer[i]) == face);
                    CHECK(m.next(buffer[i]) == buffer[(i + 1) % n]);
                }
                CHECK(face_halfedges(m, face) == buffer);
            }
        }
    }

    TEST_CASE("queries: outgoing_halfedges turn by next of twin from halfedge(v) and meet every edge at v" *
              geolab::points(4) *
              geolab::hint("The lecture: edge = edge->pair->next until back at the start, i.e. h = next(twin(h)). "
                           "Start at halfedge(v); stop when you are back; clear the output first.")) {
        std::vector<Halfedge> buffer{Halfedge{1}};
        for (const Fixture& f : manifold_fixtures()) {
            INFO(describe(f));
            const Mesh m = stored_mesh(f);
            const auto nb = neighbours(f.soup);
            for (Vertex v : m.vertices()) {
                CAPTURE(v);
                outgoing_halfedges(m, v, buffer);
                REQUIRE_MESSAGE(buffer.size() == nb[v.idx].size(),
                                "vertex " << v.idx << " has " << nb[v.idx].size()
                                          << " edges but outgoing_halfedges returned " << buffer.size());
                if (buffer.empty()) continue;
                CHECK(buffer.front() == m.halfedge(v));
                std::set<std::uint32_t> ends;
                for (std::size_t i = 0; i < buffer.size(); ++i) {
                    CHECK(m.from_vertex(buffer[i]) == v);
                    CHECK(m.next(m.twin(buffer[i])) == buffer[(i + 1) % buffer.size()]);
                    ends.insert(m.to_vertex(buffer[i]).idx);
                }
                CHECK(ends == nb[v.idx]);
                CHECK(outgoing_halfedges(m, v) == buffer);
            }
        }
        // On the tetrahedron, the faces at vertex 0 are 0 1 2, 0 3 1, 0 2 3: next(twin(0->1)) = 0->3, then 0->2.
        const Mesh tet = stored_mesh("tetrahedron", fx::tetrahedron());
        std::vector<std::uint32_t> ends;
        for (Halfedge h : outgoing_halfedges(tet, Vertex{0})) ends.push_back(tet.to_vertex(h).idx);
        INFO("tetrahedron vertex 0: the ends of its outgoing half-edges must be a rotation of 1 3 2");
        REQUIRE(ends.size() == 3);
        std::rotate(ends.begin(), std::find(ends.begin(), ends.end(), 1u), ends.end());
        CHECK(ends == std::vector<std::uint32_t>{1, 3, 2});
    }

}  // TEST_SUITE
