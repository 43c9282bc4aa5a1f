// Lab 01, Task 4: normals and areas (handout §6). Tolerances are relative to the size of the input.
#include "helpers.hpp"

using namespace lab01;

TEST_SUITE("Task 4: geometry") {
    TEST_CASE("geometry: cube face normals are outward unit axes and areas are 4" * geolab::points(3) *
              geolab::hint("Newell: n = sum of p_i x p_(i+1) around the face; the face is counter-clockwise seen from "
                           "where n points. area = |n| / 2.")) {
        for (bool triangulate : {false, true}) {
            const PolygonSoup soup = fx::cube(triangulate);
            INFO((triangulate ? "cube (triangles)" : "cube (quads)"));
            const Mesh m = build_valid(soup, "cube");
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
        "geometry: Newell's method handles a non-planar quad and a concave polygon" * geolab::points(3) *
        geolab::hint("Sum the cross products over ALL corners (Newell), not just the first three: the first corner "
                     "may be concave and a non-planar face has no single triangle normal.")) {
        // Twisted quad (0,0,0) (1,0,0) (1,1,1) (0,1,0): Newell vector (-1,-1,2), so n = (-1,-1,2)/sqrt 6, area
        // sqrt(6)/2.
        PolygonSoup quad;
        quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 1}, {0, 1, 0}};
        quad.add_face({0, 1, 2, 3});
        INFO(mesh_to_string(quad));
        const Mesh mq = build_valid(quad, "twisted quad");
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
        const Mesh ml = build_valid(ell, "L-shape");
        const glm::dvec3 nl = face_normal(ml, Face{0});
        INFO("L-shape: expected normal (0, 0, 1), got " << str(nl));
        CHECK(glm::length(nl - glm::dvec3(0, 0, 1)) < 1e-12);
        CHECK(face_area(ml, Face{0}) == doctest::Approx(3.0).epsilon(1e-12));
    }

    TEST_CASE("geometry: icosphere vertex normals point along the position" * geolab::points(2) *
              geolab::hint("Sum the normals of the faces around v weighted by their areas, then normalize.")) {
        const PolygonSoup soup = fx::icosphere(2);
        const Mesh m = build_valid(soup, "icosphere(2)");
        for (Vertex v : m.vertices()) {
            const glm::dvec3 n = vertex_normal(m, v);
            const glm::dvec3 radial = glm::normalize(m.position(v));
            CAPTURE(v);
            INFO("expected about " << str(radial) << ", got " << str(n));
            CHECK(std::abs(glm::length(n) - 1.0) < 1e-12);
            CHECK(glm::dot(n, radial) > 0.999);
        }
    }

    TEST_CASE("geometry: vertex normals are weighted by face area" * geolab::points(2) *
              geolab::hint("Add area(f) * normal(f), i.e. the Newell vectors, not the unit normals: a big face counts "
                           "more than a small one.")) {
        // Two triangles at vertex 0: (0, v1, v2) in z = 0 with cross (0,0,4) and (0, v2, v3) with cross (2,0,2).
        // Weighted: normalize(2,0,6) = (1,0,3)/sqrt 10. Unweighted would give normalize((0,0,1) + (1,0,1)/sqrt 2).
        PolygonSoup tent;
        tent.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {-1, 0, 1}};
        tent.add_face({0, 1, 2});
        tent.add_face({0, 2, 3});
        INFO(mesh_to_string(tent));
        const Mesh mt = build_valid(tent, "tent");
        const glm::dvec3 expect = glm::dvec3(1, 0, 3) / std::sqrt(10.0);
        const glm::dvec3 n0 = vertex_normal(mt, Vertex{0});
        INFO("vertex 0: expected " << str(expect) << ", got " << str(n0));
        CHECK(glm::length(n0 - expect) < 1e-12);

        // A bumpy sphere (icosphere(1) with radii 0.7 .. 1.3): compare with the weighted normals of the soup.
        PolygonSoup bumpy = fx::icosphere(1);
        for (std::size_t v = 0; v < bumpy.n_vertices(); ++v)
            bumpy.positions[v] *= 1.0 + 0.3 * std::sin(7.0 * double(v));
        const Mesh mb = build_valid(bumpy, "bumpy icosphere(1)");
        const auto ref = reference_vertex_normals(bumpy);
        for (Vertex v : mb.vertices()) {
            CAPTURE(v);
            const glm::dvec3 n = vertex_normal(mb, v);
            INFO("bumpy icosphere: expected " << str(ref[v.idx]) << ", got " << str(n));
            CHECK(glm::length(n - ref[v.idx]) < 1e-9);
        }
    }

}  // TEST_SUITE
