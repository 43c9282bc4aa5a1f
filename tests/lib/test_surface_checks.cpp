// check_surface() and the exact predicates: each defect count on a hand-made mesh with exactly that defect, the
// clean closed shapes at zero, and the grid search against all pairs on random soups.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "geolab/predicates.hpp"
#include "geolab/surface_checks.hpp"

using geolab::PolygonSoup;
using glm::dvec3;

namespace {

PolygonSoup tetrahedron(dvec3 o = dvec3(0.0), double s = 1.0) {
    PolygonSoup m;
    m.positions = {o, o + dvec3(s, 0, 0), o + dvec3(0, s, 0), o + dvec3(0, 0, s)};
    for (auto f : {std::array<std::uint32_t, 3>{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}) m.add_face({f[0], f[1], f[2]});
    return m;
}

PolygonSoup cube_quads(double s = 1.0) {
    PolygonSoup m;
    for (int i = 0; i < 8; ++i) m.positions.push_back(s * dvec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
    m.add_face({0, 2, 3, 1});
    m.add_face({4, 5, 7, 6});
    m.add_face({0, 1, 5, 4});
    m.add_face({2, 6, 7, 3});
    m.add_face({0, 4, 6, 2});
    m.add_face({1, 3, 7, 5});
    return m;
}

//! Appends b's faces (indices shifted) to a.
void append(PolygonSoup& a, const PolygonSoup& b) {
    const auto base = std::uint32_t(a.positions.size());
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    for (std::size_t f = 0; f < b.n_faces(); ++f) {
        std::vector<std::uint32_t> vs;
        for (auto v : b.face(f)) vs.push_back(v + base);
        a.add_face(vs);
    }
}

//! A UV sphere of radius r: closed, outward, triangles only.
PolygonSoup sphere(int n, double r) {
    PolygonSoup m;
    const double pi = std::acos(-1.0);
    m.positions.push_back({0, 0, r});
    for (int i = 1; i < n; ++i)
        for (int j = 0; j < 2 * n; ++j) {
            const double t = pi * i / n, p = pi * j / n;
            m.positions.push_back(r * dvec3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)));
        }
    m.positions.push_back({0, 0, -r});
    auto ring = [&](int i, int j) { return std::uint32_t(1 + (i - 1) * 2 * n + (j % (2 * n))); };
    const auto south = std::uint32_t(m.positions.size() - 1);
    for (int j = 0; j < 2 * n; ++j) {
        m.add_face({0, ring(1, j), ring(1, j + 1)});
        m.add_face({south, ring(n - 1, j + 1), ring(n - 1, j)});
    }
    for (int i = 1; i + 1 < n; ++i)
        for (int j = 0; j < 2 * n; ++j) {
            m.add_face({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
            m.add_face({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
        }
    return m;
}

}  // namespace

TEST_CASE("exact predicates decide what doubles cannot") {
    // four points coplanar in exact arithmetic but far from the origin: the plain formula's rounding is larger
    // than the determinant of nearby non-coplanar points
    const double big = 1e8;
    const dvec3 a(big, big, big), b(big + 1, big, big), c(big, big + 1, big);
    CHECK(geolab::orient3d(a, b, c, dvec3(big + 0.5, big + 0.5, big)) == 0);
    CHECK(geolab::orient3d(a, b, c, dvec3(big + 0.5, big + 0.5, big + std::ldexp(1.0, -26))) != 0);
    CHECK(geolab::orient3d(a, b, c, dvec3(big, big, big + 1)) == -geolab::orient3d(a, b, c, dvec3(big, big, big - 1)));
    // Shewchuk's classic: points near the line y = x, orient2d of (0.5 + iε, 0.5 + jε), (12, 12), (24, 24)
    const double eps = std::ldexp(1.0, -53);
    int wrong_naive = 0;
    for (int i = 0; i < 64; ++i)
        for (int j = 0; j < 64; ++j) {
            const glm::dvec2 p(0.5 + i * eps, 0.5 + j * eps), q(12, 12), r(24, 24);
            // exact: det[p − r; q − r] = 12·(py − px), so the sign is that of py − px
            const int expected = p.x == p.y ? 0 : (p.y > p.x ? 1 : -1);
            const int got = geolab::orient2d(p, q, r);
            CHECK_MESSAGE(got == expected, "orient2d((0.5+", i, "ε, 0.5+", j, "ε), (12,12), (24,24))");
            const double naive = (p.x - r.x) * (q.y - r.y) - (p.y - r.y) * (q.x - r.x);
            wrong_naive += (naive > 0) - (naive < 0) != expected;
        }
    CHECK_MESSAGE(wrong_naive > 0, "the example must be one where the plain formula errs");
    // products that underflow: every difference is 2^-700 or 0, the determinant 2^-2100, below any double; the
    // sign must still come out (the shortcut for products with an exact zero factor must not take it for 0)
    const double t = std::ldexp(1.0, -700);
    CHECK(geolab::orient3d(dvec3(0, 0, 0), dvec3(t, 0, 0), dvec3(0, t, 0), dvec3(0, 0, t)) ==
          -geolab::orient3d(dvec3(0, 0, 0), dvec3(t, 0, 0), dvec3(0, t, 0), dvec3(0, 0, -t)));
    CHECK(geolab::orient3d(dvec3(0, 0, 0), dvec3(t, 0, 0), dvec3(0, t, 0), dvec3(0, 0, t)) != 0);
    CHECK(geolab::orient2d(glm::dvec2(0, 0), glm::dvec2(t, 0), glm::dvec2(0, t)) == 1);
    // four points in one axis-aligned plane (far from the origin, irrational-looking coordinates): exactly 0
    for (int axis = 0; axis < 3; ++axis) {
        auto in_plane = [&](double u, double v) {
            dvec3 p(0.0);
            p[axis] = 1e8 + 0.1;
            p[(axis + 1) % 3] = u;
            p[(axis + 2) % 3] = v;
            return p;
        };
        CHECK(geolab::orient3d(in_plane(0.3, 7.1), in_plane(-2.9, 1e-9), in_plane(5e7, -3.3), in_plane(1.0 / 3, 2.0 / 7)) == 0);
        dvec3 off = in_plane(1.0 / 3, 2.0 / 7);
        off[axis] = std::nextafter(off[axis], 1e9);
        CHECK(geolab::orient3d(in_plane(0.3, 7.1), in_plane(-2.9, 1e-9), in_plane(5e7, -3.3), off) != 0);
    }
    CHECK(geolab::collinear(dvec3(0, 0, 0), dvec3(1, 2, 3), dvec3(3, 6, 9)));
    CHECK_FALSE(geolab::collinear(dvec3(0, 0, 0), dvec3(1, 2, 3), dvec3(3, 6, 9.000000001)));
}

TEST_CASE("clean closed surfaces count zero defects") {
    for (double s : {1e-6, 1.0, 1e6}) {
        CAPTURE(s);
        auto t = geolab::check_surface(tetrahedron(dvec3(3 * s), s));
        CHECK(t.closed_manifold());
        CHECK(t.euler_characteristic == 2);
        CHECK(t.components == 1);
        auto c = geolab::check_surface(cube_quads(s));
        CHECK_MESSAGE(c.closed_manifold(), c.summary());
        CHECK(c.vertices == 8);
        CHECK(c.edges == 12);
        CHECK(c.euler_characteristic == 2);
    }
    auto sp = geolab::check_surface(sphere(24, 2.0));
    CHECK_MESSAGE(sp.closed_manifold(), sp.summary());
    CHECK(sp.euler_characteristic == 2);
    CHECK(sp.self_intersecting_pairs() == 0);
}

TEST_CASE("each defect is counted on a mesh that has exactly it") {
    SUBCASE("a missing face: boundary edges") {
        auto m = tetrahedron();
        m.indices.resize(9);
        m.offsets.resize(4);
        auto c = geolab::check_surface(m);
        CHECK(c.boundary_edges == 3);
        CHECK(c.euler_characteristic == 1);
        CHECK_FALSE(c.closed_manifold());
    }
    SUBCASE("three faces on an edge: non-manifold edge") {
        auto m = tetrahedron();
        m.positions.push_back({0.3, 0.3, -1});
        m.add_face({0, 1, 4});
        auto c = geolab::check_surface(m, {.self_intersections = false});
        CHECK(c.non_manifold_edges == 1);
        CHECK_FALSE(c.self_intersection_checked);
        CHECK_FALSE(c.closed_manifold());
    }
    SUBCASE("a flipped face: misoriented edges") {
        auto m = tetrahedron();
        std::swap(m.indices[0], m.indices[1]);
        auto c = geolab::check_surface(m);
        CHECK(c.misoriented_edges == 3);
        CHECK(c.boundary_edges == 0);
        CHECK(c.non_manifold_vertices == 0);
        CHECK(c.self_intersecting_pairs() == 0);
    }
    SUBCASE("two tetrahedra touching at one vertex: one non-manifold vertex, no non-manifold edge") {
        auto m = tetrahedron();
        auto n = tetrahedron(dvec3(0.0), -1.0);  // mirrored through the shared vertex at the origin
        append(m, n);
        // weld the second copy's origin onto the first's
        for (auto& i : m.indices)
            if (i == 4) i = 0;
        auto c = geolab::check_surface(m);
        CHECK(c.non_manifold_vertices == 1);
        CHECK(c.non_manifold_edges == 0);
        CHECK(c.boundary_edges == 0);
        CHECK(c.components == 1);
        CHECK(c.self_intersecting_pairs() == 0);
        CHECK_MESSAGE(!c.closed_manifold(), c.summary());
    }
    SUBCASE("a face listing a vertex twice; a face of three collinear points; coincident vertices") {
        auto m = tetrahedron();
        m.positions.push_back({2, 0, 0});
        m.positions.push_back({4, 0, 0});
        m.positions.push_back({1, 0, 0});  // a copy of vertex 1's position
        m.add_face({1, 4, 5});             // collinear
        m.add_face({1, 4, 4});             // repeated index (and zero area)
        m.add_face({6, 2, 3});             // uses the copy
        auto c = geolab::check_surface(m);
        CHECK(c.zero_area_faces == 2);
        CHECK(c.repeated_index_faces == 1);
        CHECK(c.coincident_vertices == 1);
        CHECK_FALSE(c.closed_manifold());
    }
    SUBCASE("two separate tetrahedra: two components, still closed") {
        auto m = tetrahedron();
        append(m, tetrahedron(dvec3(5, 0, 0)));
        auto c = geolab::check_surface(m);
        CHECK(c.components == 2);
        CHECK(c.euler_characteristic == 4);
        CHECK(c.closed_manifold());
    }
}

TEST_CASE("self-intersecting pairs, by what the two faces share") {
    SUBCASE("two triangles crossing like links of a chain (disjoint)") {
        PolygonSoup m;
        m.positions = {{-1, 0, 0}, {1, 0, 0}, {0, 2, 0}, {0, 1, -1}, {0, 1, 1}, {0, -1, 0}};
        m.add_face({0, 1, 2});
        m.add_face({3, 4, 5});
        auto c = geolab::check_surface(m);
        CHECK(c.intersecting_disjoint == 1);
        CHECK(c.self_intersecting_pairs() == 1);
    }
    SUBCASE("touching at one point only still counts for disjoint faces") {
        PolygonSoup m;
        m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.25, 0}, {0.25, 0.25, 1}, {1, 1, 1}};
        m.add_face({0, 1, 2});
        m.add_face({3, 4, 5});
        CHECK(geolab::check_surface(m).intersecting_disjoint == 1);
        m.positions[3].z = std::ldexp(1.0, -40);  // lifted by a hair: apart
        CHECK(geolab::check_surface(m).intersecting_disjoint == 0);
    }
    SUBCASE("sharing a vertex: apart, piercing, coplanar overlap") {
        PolygonSoup m;
        m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, -1, 1}};
        m.add_face({0, 1, 2});
        m.add_face({0, 3, 4});  // meets the first only at vertex 0
        CHECK(geolab::check_surface(m).intersecting_vertex_sharing == 0);
        m.positions[4] = {1, 1, -1};  // now edge 3–4 passes through the first triangle
        CHECK(geolab::check_surface(m).intersecting_vertex_sharing == 1);
        m.positions[3] = {1, 0.2, 0};  // coplanar, inside the first triangle's corner
        m.positions[4] = {0.2, 1, 0};
        CHECK(geolab::check_surface(m).intersecting_vertex_sharing == 1);
        m.positions[3] = {-1, 0, 0};  // coplanar, in the opposite corner: only the vertex
        m.positions[4] = {0, -1, 0};
        CHECK(geolab::check_surface(m).intersecting_vertex_sharing == 0);
    }
    SUBCASE("sharing an edge: a fold onto itself counts, a hinge does not") {
        PolygonSoup m;
        m.positions = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}};
        m.add_face({0, 1, 2});
        m.add_face({1, 0, 3});  // flat, on the other side
        CHECK(geolab::check_surface(m).intersecting_edge_sharing == 0);
        m.positions[3] = {0.3, 0.5, 0};  // folded onto the first
        CHECK(geolab::check_surface(m).intersecting_edge_sharing == 1);
        m.positions[3] = {0.3, 0.5, 1e-12};  // a hair above: a hinge
        CHECK(geolab::check_surface(m).intersecting_edge_sharing == 0);
    }
    SUBCASE("two interpenetrating cubes: every crossing found, and each face pair once") {
        auto m = cube_quads();
        auto n = cube_quads();
        for (auto& p : n.positions) p += dvec3(0.5, 0.5, 0.5);
        append(m, n);
        auto c = geolab::check_surface(m);
        // each of the three faces of either cube that cross into the other meets two faces of the other: 3·2 pairs
        // per cube → x=1 of A with y=0.5.. faces of B; counted by hand: the faces x=1, y=1, z=1 of A each cross the
        // faces of B at x=0.5, y=0.5, z=0.5 other than their parallel one: 3 · 2 = 6
        CHECK(c.intersecting_disjoint == 6);
        CHECK(c.components == 2);
    }
}

TEST_CASE("the grid finds exactly the pairs an all-pairs search finds") {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 5; ++trial) {
        std::uniform_real_distribution<double> u(0.0, 10.0), d(-0.8, 0.8);
        PolygonSoup m;
        const int n = 300;
        for (int t = 0; t < n; ++t) {
            const dvec3 c(u(rng), u(rng), u(rng));
            for (int k = 0; k < 3; ++k) m.positions.push_back(c + dvec3(d(rng), d(rng), d(rng)));
            const auto b = std::uint32_t(3 * t);
            m.add_face({b, b + 1, b + 2});
        }
        auto c = geolab::check_surface(m);
        // all pairs, one face pair at a time
        std::size_t brute = 0;
        for (int a = 0; a < n; ++a)
            for (int b = a + 1; b < n; ++b) {
                PolygonSoup two;
                for (int k = 0; k < 3; ++k) two.positions.push_back(m.positions[3 * a + k]);
                for (int k = 0; k < 3; ++k) two.positions.push_back(m.positions[3 * b + k]);
                two.add_face({0, 1, 2});
                two.add_face({3, 4, 5});
                // a single pair's grid is one cell: this is the plain test
                brute += geolab::check_surface(two).intersecting_disjoint;
            }
        CAPTURE(trial);
        CHECK(c.intersecting_disjoint == brute);
        CHECK(brute > 0);
    }
}

TEST_CASE("check_surface rejects malformed soups with the face named") {
    PolygonSoup m = tetrahedron();
    m.indices[4] = 9;
    CHECK_THROWS_WITH_AS(geolab::check_surface(m), doctest::Contains("face 1 uses vertex 9"), std::invalid_argument);
    PolygonSoup two;
    two.positions = {{0, 0, 0}, {1, 0, 0}};
    two.add_face({0, 1});
    CHECK_THROWS_AS(geolab::check_surface(two), std::invalid_argument);
}
