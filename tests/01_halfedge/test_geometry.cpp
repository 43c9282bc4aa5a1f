// Lab 01, Task 4: normals and areas (handout §6). Tolerances are relative to the size of the input. Meshes from
// stored connectivity (stored.hpp), never from your build_mesh.
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab01;

// A vertex normal sums the faces around the vertex, which your Task 3 walks (one_ring_faces): its tests build on it
// (geolab/grading/chain.hpp).
TEST_SUITE("Task 4: geometry") {
    TEST_CASE("geometry: cube face normals are outward unit axes and areas are 4" * geolab::points(2) *
              geolab::hint("Newell: n = sum of p_i x p_(i+1) around the face; the face is counter-clockwise seen from "
                           "where n points. area = |n| / 2.")) {
        for (bool triangulate : {false, true}) {
            const PolygonSoup soup = fx::cube(triangulate);
            INFO(std::string(triangulate ? "cube (triangles)" : "cube (quads)"));
            const Mesh m = stored_mesh(triangulate ? "cube (triangles)" : "cube (quads)", soup);
            for (Face f : m.faces()) {
                CAPTURE(f);
                // the outward axis: the largest coordinate of the face centroid
                glm::dvec3 c(0.0);
                for (auto v : soup.face(f.idx)) c += soup.positions[v];
                c /= double(soup.face(f.idx).size());
                glm::dvec3 axis(0.0);
                const int k = std::abs(c.x) > 0.9 ? 0 : std::abs(c.y) > 0.9 ? 1 : 2;
                axis[k] = c[k] > 0 ? 1.0 : -1.0;
                const glm::dvec3 n = face_normal(m, f);
                INFO("expected normal " << str(axis) << ", got " << str(n));
                CHECK(glm::length(n - axis) < 1e-12);
                CHECK(face_area(m, f) == doctest::Approx(triangulate ? 2.0 : 4.0).epsilon(1e-12));
            }
        }
    }

    TEST_CASE(
        "geometry: Newell's method handles a non-planar quad and a concave polygon" * geolab::points(2) *
        geolab::hint("Sum the cross products over ALL corners (Newell), not just the first three: the first corner "
                     "may be concave and a non-planar face has no single triangle normal.")) {
        // Twisted quad (0,0,0) (1,0,0) (1,1,1) (0,1,0): Newell vector (-1,-1,2), so n = (-1,-1,2)/sqrt 6, area
        // sqrt(6)/2.
        PolygonSoup quad;
        quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 1}, {0, 1, 0}};
        quad.add_face({0, 1, 2, 3});
        INFO(mesh_to_string(quad));
        const Mesh mq = stored_mesh("polygon(4)", quad);
        const glm::dvec3 nq = face_normal(mq, Face{0});
        const glm::dvec3 expect_q = glm::dvec3(-1, -1, 2) / std::sqrt(6.0);
        INFO("twisted quad: expected normal " << str(expect_q) << ", got " << str(nq));
        CHECK(glm::length(nq - expect_q) < 1e-12);
        CHECK(face_area(mq, Face{0}) == doctest::Approx(std::sqrt(6.0) / 2).epsilon(1e-12));

        // L-shaped hexagon in z = 5, counter-clockwise from +z, listed from the corner before the concave one:
        // normal (0,0,1), area 3. The cross product at the first corner alone points to -z.
        PolygonSoup ell;
        ell.positions = {{2, 1, 5}, {1, 1, 5}, {1, 2, 5}, {0, 2, 5}, {0, 0, 5}, {2, 0, 5}};
        ell.add_face({0, 1, 2, 3, 4, 5});
        INFO(mesh_to_string(ell));
        const Mesh ml = stored_mesh("polygon(6)", ell);
        const glm::dvec3 nl = face_normal(ml, Face{0});
        INFO("L-shape: expected normal (0, 0, 1), got " << str(nl));
        CHECK(glm::length(nl - glm::dvec3(0, 0, 1)) < 1e-12);
        CHECK(face_area(ml, Face{0}) == doctest::Approx(3.0).epsilon(1e-12));
    }

    TEST_CASE("geometry: icosphere vertex normals point along the position" * geolab::points(2) *
              geolab::builds_on("Task 3") *
              geolab::hint("Sum the normals of the faces around v weighted by their areas, then normalize.")) {
        const PolygonSoup soup = fx::icosphere(2);
        const Mesh m = stored_mesh("icosphere(2)", soup);
        for (Vertex v : m.vertices()) {
            const glm::dvec3 n = vertex_normal(m, v);
            const glm::dvec3 radial = glm::normalize(m.position(v));
            CAPTURE(v);
            INFO("expected about " << str(radial) << ", got " << str(n));
            CHECK(std::abs(glm::length(n) - 1.0) < 1e-12);
            CHECK(glm::dot(n, radial) > 0.999);
        }
    }

    TEST_CASE("geometry: vertex normals are weighted by face area" * geolab::points(2) * geolab::builds_on("Task 3") *
              geolab::hint("Add area(f) * normal(f), i.e. the Newell vectors, not the unit normals: a big face counts "
                           "more than a small one.")) {
        // Two triangles at vertex 0: (0, v1, v2) in z = 0 with cross (0,0,4) and (0, v2, v3) with cross (2,0,2).
        // Weighted: normalize(2,0,6) = (1,0,3)/sqrt 10. Unweighted would give normalize((0,0,1) + (1,0,1)/sqrt 2).
        const PolygonSoup tent = lab01::tent();
        INFO(mesh_to_string(tent));
        const Mesh mt = stored_mesh("tent", tent);
        const glm::dvec3 expect = glm::dvec3(1, 0, 3) / std::sqrt(10.0);
        const glm::dvec3 n0 = vertex_normal(mt, Vertex{0});
        INFO("vertex 0: expected " << str(expect) << ", got " << str(n0));
        CHECK(glm::length(n0 - expect) < 1e-12);

        // A bumpy sphere (icosphere(1) with radii 0.7 .. 1.3): compare with the weighted normals of the soup.
        PolygonSoup bumpy = fx::icosphere(1);
        for (std::size_t v = 0; v < bumpy.n_vertices(); ++v)
            bumpy.positions[v] *= 1.0 + 0.3 * std::sin(7.0 * double(v));
        const Mesh mb = stored_mesh("icosphere(1)", bumpy);
        const auto ref = reference_vertex_normals(bumpy);
        for (Vertex v : mb.vertices()) {
            CAPTURE(v);
            const glm::dvec3 n = vertex_normal(mb, v);
            INFO("bumpy icosphere: expected " << str(ref[v.idx]) << ", got " << str(n));
            CHECK(glm::length(n - ref[v.idx]) < 1e-9);
        }
    }

    TEST_CASE("geometry: a zero-area face and an isolated vertex have the zero normal and not NaN" *
              geolab::points(2) * geolab::builds_on("Task 3") *
              geolab::hint("Normalize only a vector of positive length: return (0, 0, 0) when |n| = 0 (0 / 0 is NaN). "
                           "A face of zero area adds nothing to a vertex normal.")) {
        auto check_zero = [](const glm::dvec3& n, const std::string& what) {
            INFO(what << ": expected (0, 0, 0), got " << str(n));
            CHECK((n.x == 0.0 && n.y == 0.0 && n.z == 0.0));
        };
        // A triangle whose corners lie on a line, and a quad whose four corners coincide.
        PolygonSoup line = polygon(3);
        line.positions = {{0, 0, 0}, {1, 1, 1}, {3, 3, 3}};
        PolygonSoup point = polygon(4);
        for (auto& p : point.positions) p = {0.5, -2, 7};
        for (const auto& [soup, key] : {std::pair{line, "triangle"}, std::pair{point, "polygon(4)"}}) {
            INFO(mesh_to_string(soup));
            const Mesh m = stored_mesh(key, soup);
            check_zero(face_normal(m, Face{0}), "face_normal of a zero-area face");
            CHECK_MESSAGE(face_area(m, Face{0}) == 0.0, "face_area: expected 0, got " << face_area(m, Face{0}));
            for (Vertex v : m.vertices()) check_zero(vertex_normal(m, v), "vertex_normal of a vertex whose faces have zero area");
        }
        // The tent with its second face flattened onto the line from vertex 0 to vertex 2: vertex 3 has only that
        // face (normal (0,0,0)); vertex 0's normal is the first face's, (0, 0, 1).
        PolygonSoup flat = tent();
        flat.positions[3] = {0, 1, 0};
        INFO(mesh_to_string(flat));
        const Mesh mt = stored_mesh("tent", flat);
        check_zero(vertex_normal(mt, Vertex{3}), "tent with face 1 flattened, vertex 3");
        check_zero(face_normal(mt, Face{1}), "tent with face 1 flattened, face 1");
        const glm::dvec3 n0 = vertex_normal(mt, Vertex{0});
        INFO("tent with face 1 flattened, vertex 0: expected (0, 0, 1), got " << str(n0));
        CHECK(glm::length(n0 - glm::dvec3(0, 0, 1)) < 1e-12);
        // An isolated vertex has no faces.
        const Fixture f = fixture("tetrahedron + isolated vertex");
        check_zero(vertex_normal(stored_mesh(f), Vertex{4}), "the isolated vertex 4 of 'tetrahedron + isolated vertex'");
    }

}  // TEST_SUITE
