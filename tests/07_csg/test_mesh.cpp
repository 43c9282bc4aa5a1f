// Lab 07, Task 7: polygonized trees and volumes by the divergence theorem. Expected values: volumes computed by
// hand (two unit cubes offset by 0.5: overlap 0.5³ = 0.125, union 2 − 0.125 = 1.875, difference 1 − 0.125 =
// 0.875; unit cube ∩ octahedron |x|+|y|+|z| ≤ 1: 1 − 8 corners of (1/2)³/6 = 5/6).
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab07;

namespace {
PolygonSoup cube_soup(double s) {
    PolygonSoup m;
    for (int i = 0; i < 8; ++i) m.positions.push_back({(i & 1) ? s : 0.0, (i & 2) ? s : 0.0, (i & 4) ? s : 0.0});
    // quads counter-clockwise seen from outside
    m.add_face({0, 2, 3, 1});
    m.add_face({4, 5, 7, 6});
    m.add_face({0, 1, 5, 4});
    m.add_face({2, 6, 7, 3});
    m.add_face({0, 4, 6, 2});
    m.add_face({1, 3, 7, 5});
    return m;
}
}  // namespace

TEST_SUITE("Task 7: meshes and volumes") {
    TEST_CASE("volume: hand-made meshes — a cube of quads; moved; flipped" * geolab::points(2) *
              geolab::hint("Σ over faces fanned into triangles (v0, vi, vi+1) of v0 · (vi × vi+1) / 6; the result "
                           "does not depend on where the origin is for a closed mesh.")) {
        for (double s : {1.0, 2.0, 0.1}) {
            PolygonSoup m = cube_soup(s);
            const double v = volume(m);
            CHECK_MESSAGE(close(v, s * s * s, 1e-13), "cube of side " << s << ": expected " << s * s * s << ", got " << v);
            for (auto& p : m.positions) p += glm::dvec3(10, -3, 7);
            const double moved = volume(m);
            CHECK_MESSAGE(close(moved, s * s * s, 1e-12), "the cube moved by (10, −3, 7): got " << moved);
            std::vector<std::uint32_t> flipped;
            PolygonSoup f;
            f.positions = m.positions;
            for (std::size_t i = 0; i < m.n_faces(); ++i) {
                auto id = m.face(i);
                std::vector<std::uint32_t> r(id.rbegin(), id.rend());
                f.add_face(std::span<const std::uint32_t>(r));
            }
            CHECK_MESSAGE(close(volume(f), -s * s * s, 1e-12), "the cube with its faces reversed: expected negative");
        }
        PolygonSoup bad;
        bad.positions = {{0, 0, 0}};
        bad.add_face({0, 1, 2});
        CHECK_THROWS_AS(volume(bad), std::invalid_argument);
    }

    TEST_CASE("mesh_tree: two unit cubes offset by 0.5 — union 1.875; intersection 0.125; difference 0.875" *
              geolab::points(3) * geolab::builds_on("Task 1, Task 2") *
              geolab::hint("Polygonize sdf() over bounds(t) grown by 5% of its diagonal (so the mesh is closed), then "
                           "volume(). The cubes' faces are planes: linear interpolation along lattice edges finds them "
                           "exactly; only edges and corners are cut.")) {
        const Tree A = unit_cube_at({0, 0, 0}), B = unit_cube_at(glm::dvec3(0.5));
        struct Case { Op o; double want; const char* what; };
        for (Case c : {Case{Op::unite, 1.875, "union"}, Case{Op::intersect, 0.125, "intersection"},
                       Case{Op::subtract, 0.875, "difference"}}) {
            double last = inf;
            for (int res : {16, 48}) {
                const PolygonSoup m = mesh_tree(op(c.o, A, B), res);
                REQUIRE(m.is_triangle_soup());
                const double v = volume(m);
                const double err = std::abs(v - c.want);
                INFO(c.what << " of [0,1]³ and [0.5,1.5]³ at resolution " << res << ": volume " << v << ", expected "
                            << c.want);
                CHECK(err <= 0.05 * c.want + 0.02);
                CHECK(err <= last + 1e-12);
                last = err;
            }
            CHECK_MESSAGE(last <= 0.02 * c.want + 0.002, c.what << ": at resolution 48 the error " << last << " is too large");
        }
    }

    TEST_CASE("mesh_tree: unit cube ∩ octahedron |x|+|y|+|z| ≤ 1 has volume 5/6; errors fall with resolution" *
              geolab::points(2) *
                        geolab::builds_on("Task 1, Task 2") * geolab::hint("Half-spaces are unbounded: intersected with the cube, bounds() is "
                                               "finite and the mesh is closed.")) {
        const Tree t = op(Op::intersect, leaf(Shape::box, glm::dvec3(0.5)), octahedron(1.0));
        double last = inf;
        for (int res : {12, 24, 48}) {
            const double v = volume(mesh_tree(t, res));
            const double err = std::abs(v - 5.0 / 6);
            INFO("cube ∩ octahedron at resolution " << res << ": volume " << v << ", expected 5/6");
            CHECK(err < last);
            last = err;
        }
        CHECK(last < 0.01);
        CHECK_THROWS_AS(mesh_tree(octahedron(1.0), 0), std::invalid_argument);
        CHECK_THROWS_AS(mesh_tree(leaf(Shape::sphere, {1, 0, 0}), 1), std::invalid_argument);
        CHECK_MESSAGE(mesh_tree(leaf(Shape::sphere, {1, 0, 0}), 2).n_faces() > 0, "resolution 2 is allowed");
        CHECK_THROWS_AS(mesh_tree(leaf(Shape::halfspace, glm::dvec3(0)), 16), std::invalid_argument);
    }

    TEST_CASE("mesh_tree: the lattice is bounds(t) grown by 5% of its diagonal; resolution cells on the longest side" *
              geolab::points(1) * geolab::builds_on("Task 1, Task 2") *
              geolab::hint("Box b = bounds(t); pad = 0.05·|b.hi − b.lo|; polygonize(field, {b.lo − pad, b.hi + pad}, "
                           "resolution).")) {
        const Tree t = leaf(Shape::box, {1.0, 0.6, 0.4}, translate({0.3, -0.2, 0.1}));
        const int res = 10;
        const glm::dvec3 lo(-0.7, -0.8, -0.3), hi(1.3, 0.4, 0.5);
        const double pad = 0.05 * glm::length(hi - lo);
        const glm::dvec3 L = lo - pad;
        const double h = (hi.x - lo.x + 2 * pad) / res;
        const PolygonSoup m = mesh_tree(t, res);
        REQUIRE(m.n_vertices() > 0);
        // Every edge of the Freudenthal split joins lattice points i and i + e, e ∈ {0, 1}³: a vertex's lattice
        // coordinates u = (p − lo')/h have fractional parts that are 0 or all equal (the edge parameter).
        for (const glm::dvec3& p : m.positions) {
            std::vector<double> fr;
            for (int k = 0; k < 3; ++k) {
                const double u = (p[k] - L[k]) / h;
                if (std::abs(u - std::round(u)) > 1e-6) fr.push_back(u - std::floor(u));
            }
            bool ok = !fr.empty() && fr.size() < 3 + 1;
            for (double f : fr) ok = ok && std::abs(f - fr[0]) < 1e-6;
            INFO("vertex " << str(p) << " is not on an edge of the lattice lo − pad + i·h (lo = bounds(t).lo, pad = 5% "
                           "of the diagonal, h = " << h << ")");
            CHECK(ok);
        }
    }
}
