// Lab 05 hidden tests: run by the grader, left out of the student release. Same tasks (suites), other inputs:
// high degrees, far and tiny scales, the whole alphabet, the whole teapot tessellated, random knot vectors.
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab05;

TEST_SUITE("Task 1: basics") {
    TEST_CASE("basics hidden: degrees up to 40 stay accurate by de Casteljau; the triangle at t = 0.3" *
              geolab::points(3) * geolab::hidden() *
              geolab::hint("de Casteljau only mixes points convexly: it stays accurate at any degree.")) {
        Rng rng(201);
        for (int n : {15, 20, 30, 40})
            for (double t : {0.001, 0.3, 0.5, 0.77, 0.999}) {
                const Poly3 P = rng.poly(n, 1);
                const glm::dvec3 want = ref_point(P, t), got = de_casteljau(P, t);
                INFO("degree " << n << " at t = " << t << ": expected " << str(want) << ", got " << str(got));
                CHECK(close3(got, want, 1e-13, 1));
                const auto rows = de_casteljau_triangle(P, t);
                REQUIRE(rows.size() == std::size_t(n + 1));
                CHECK(close3(rows[n][0], want, 1e-13, 1));
                CHECK(rows[1].size() == std::size_t(n));
            }
        // far from the origin and tiny
        for (double s : {1e9, 1e-9}) {
            const Poly3 P = rng.poly(5, s);
            CHECK(close3(de_casteljau(P, 0.37), ref_point(P, 0.37), 1e-14, s));
        }
    }
}

TEST_SUITE("Task 2: operations") {
    TEST_CASE("operations hidden: subdivision at random t reproduces the curve; elevation many times converges to it" *
              geolab::points(3) * geolab::builds_on("Task 1") * geolab::hidden() *
              geolab::hint("Both halves keep P's degree; left on [0, t], right on [t, 1]. Elevation never changes the "
                           "curve; its control polygon approaches it.")) {
        Rng rng(202);
        for (int n = 1; n <= 12; ++n) {
            const Poly3 P = rng.poly(n);
            const double t = rng.uniform(0.01, 0.99);
            const Split s = subdivide(P, t);
            for (double x : {0.1, 0.45, 0.9}) {
                CHECK(close3(ref_point(s.left, x), ref_point(P, t * x), 1e-12, scale_of(P)));
                CHECK(close3(ref_point(s.right, x), ref_point(P, t + (1 - t) * x), 1e-12, scale_of(P)));
            }
            // hodograph of the halves = scaled hodograph of P: the left half's speed is t |C'(t s)|
            CHECK(close3(D(ref_deriv(s.left, 0.5, 1)), t * D(ref_deriv(P, 0.5 * t, 1)), 1e-11, n * scale_of(P)));
            CHECK(close3(derivative(s.right, 0.0), (1 - t) * D(ref_deriv(P, t, 1)), 1e-11, n * scale_of(P)));
        }
        const Poly3 P{{0, 0, 0}, {1, 3, 0}, {3, -2, 1}, {4, 1, 0}};
        Poly3 Q = P;
        double prev = 1e300;
        for (int r = 0; r < 64; ++r) {
            Q = elevate(Q);
            if (r % 16 == 15) {
                // the control points' distance to the curve at the Greville parameters shrinks
                double worst = 0;
                const int m = int(Q.size()) - 1;
                for (int k = 0; k <= m; ++k) worst = std::max(worst, glm::length(Q[k] - ref_point(P, LD(k) / m)));
                INFO("after " << r + 1 << " elevations the control polygon is within " << worst << " of the curve");
                CHECK(worst < prev);
                prev = worst;
            }
        }
        CHECK(prev < 0.15);
    }
}

TEST_SUITE("Task 3: measures") {
    TEST_CASE("measures hidden: a long curve at scale 1e6; loops for the closest point; a cusp" * geolab::points(3) *
              geolab::builds_on("Task 1, Task 2") *
              geolab::hidden() *
              geolab::hint("Scale the tolerance logic with the curve; the closest point must be the global one.")) {
        Rng rng(203);
        const Poly3 P = rng.poly(5, 1e6);
        const double got = arc_length(P, 0, 1, 1e-3);
        // the same by the parameter at half the length, twice
        const double th = parameter_at_length(P, 0.5 * got, 1e-3);
        CHECK(std::abs(arc_length(P, 0, th, 1e-3) - 0.5 * got) <= 3e-3);
        // the curve is at least as long as its chord and at most as long as its polygon
        double poly = 0;
        for (std::size_t k = 0; k + 1 < P.size(); ++k) poly += glm::length(P[k + 1] - P[k]);
        CHECK(got >= glm::length(P.back() - P.front()));
        CHECK(got <= poly);
        // a cubic loop: the nearest point to the loop's centre-ish query is not at an end
        const Poly3 loop{{0, 0, 0}, {3, 3, 0}, {-1, 3, 0}, {2, 0, 0}};
        for (const glm::dvec3 q : {glm::dvec3(1, 1, 0), glm::dvec3(1, 2.5, 0.5), glm::dvec3(0.5, -1, 0), glm::dvec3(1, 1, 3)}) {
            const LD tr = ref_closest_t(loop, q);
            const double want = double(norm(ref_deriv(loop, tr) - L(q)));
            const Closest c = closest_point(loop, q);
            INFO("loop cubic, q = " << str(q) << ": expected distance " << num(want) << ", got " << num(c.distance));
            CHECK(std::abs(c.distance - want) <= 1e-9 * 4);
        }
        // a cusp (C' = 0 at t = 1/2): the bounding box still exact
        const Poly3 cusp{{0, 0, 0}, {2, 2, 0}, {0, 2, 0}, {2, 0, 0}};
        const Box b = bounding_box(cusp);
        CHECK(std::abs(b.hi.y - 1.5) <= 1e-12);
        CHECK(std::abs(b.lo.x - 0) <= 1e-12);
        CHECK(std::abs(b.hi.x - 2) <= 1e-12);
    }
}

TEST_SUITE("Task 4: composite curves") {
    TEST_CASE("composite hidden: joints built at random; each class recognised" * geolab::points(2) *
              geolab::builds_on("Task 2") * geolab::hidden() *
              geolab::hint("Gᵏ = Cᵏ⁻¹ + parallel k-th derivatives (same direction); Cᵏ needs equal ones.")) {
        Rng rng(204);
        for (int rep = 0; rep < 20; ++rep) {
            const int n = rng.integer(3, 5);
            const Poly3 a = rng.poly(n);
            const Poly3 b0 = rng.poly(n);
            const Poly3 c1 = join_c1(a, b0);  // the student's own join, then classified
            const Continuity k = continuity(a, c1, 1e-10);
            INFO("random C1 join, degree " << n << ": got C" << k.c_order << " / G" << k.g_order);
            CHECK(k.c_order >= 1);
            CHECK(k.g_order >= 1);
            Poly3 g = c1;
            g[1] = g[0] + 1.7 * (g[1] - g[0]);  // the tangent 1.7 times longer: G1, not C1
            const Continuity kg = continuity(a, g, 1e-10);
            CHECK(kg.c_order == 0);
            CHECK(kg.g_order == 1);
        }
    }
}

TEST_SUITE("Task 5: tensor-product patches") {
    TEST_CASE("patches hidden: non-square degrees; u and v kept apart; normals of random patches" * geolab::points(3) *
              geolab::builds_on("Task 1, Task 2") *
              geolab::hidden() *
              geolab::hint("P_ij = points[i (degree_v + 1) + j], i along u; S_u differentiates along i.")) {
        Rng rng(205);
        for (auto [du, dv] : {std::pair{1, 5}, {5, 1}, {2, 6}, {6, 3}, {3, 1}}) {
            const BezierPatch S = random_patch(rng, du, dv);
            for (int k = 0; k < 6; ++k) {
                const double u = rng.uniform(0, 1), v = rng.uniform(0, 1);
                INFO("degrees " << du << " × " << dv << " at (" << num(u) << ", " << num(v) << ")");
                CHECK(close3(patch_point(S, u, v), D(ref_patch(S, u, v)), 1e-13, 3));
                CHECK(close3(patch_du(S, u, v), D(ref_patch(S, u, v, 1, 0)), 1e-12, 20));
                CHECK(close3(patch_dv(S, u, v), D(ref_patch(S, u, v, 0, 1)), 1e-12, 20));
            }
        }
    }
}

TEST_SUITE("Task 6: the Utah teapot") {
    TEST_CASE("teapot hidden: the whole teapot tessellated at n = 8: vertex count by an independent weld; outward" *
              geolab::points(3) * geolab::builds_on("Task 1, Task 2") * geolab::hidden() *
              geolab::hint("Weld border samples of all patches (also collapsed edges); drop triangles with a repeated "
                           "vertex; flip = true for outward.")) {
        const auto& T = teapot();
        const int n = 8;
        const double tol = 1e-9;
        // independent weld: border samples merge with the first earlier border sample within tol
        std::vector<glm::dvec3> border;
        std::size_t vertices = 0, faces = 0;
        for (const auto& S : T) {
            std::vector<long> id((n + 1) * (n + 1));
            for (int i = 0; i <= n; ++i)
                for (int j = 0; j <= n; ++j) {
                    const glm::dvec3 p = D(ref_patch(S, LD(i) / n, LD(j) / n));
                    if (i == 0 || j == 0 || i == n || j == n) {
                        long found = -1;
                        for (std::size_t k = 0; k < border.size() && found < 0; ++k)
                            if (glm::length(border[k] - p) <= tol) found = long(k);
                        if (found < 0) {
                            border.push_back(p);
                            ++vertices;
                            found = long(border.size()) - 1;
                        }
                        id[i * (n + 1) + j] = found;
                    } else {
                        ++vertices;
                        id[i * (n + 1) + j] = -2 - (i * (n + 1) + j);  // unique, never equal to another
                    }
                }
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    const long a = id[i * (n + 1) + j], b = id[(i + 1) * (n + 1) + j], c = id[(i + 1) * (n + 1) + j + 1],
                               d = id[i * (n + 1) + j + 1];
                    faces += (a != b && b != c && a != c) + (a != c && c != d && a != d);
                }
        }
        const PatchMesh m = tessellate_patches(T, n, tol, true);
        INFO("teapot at n = 8: expected " << vertices << " vertices and " << faces << " triangles, got "
                                          << m.soup.n_vertices() << " and " << m.soup.n_faces());
        CHECK(m.soup.n_vertices() == vertices);
        CHECK(m.soup.n_faces() == faces);
        REQUIRE(m.normals.size() == m.soup.n_vertices());
        for (const auto& nr : m.normals) REQUIRE(std::abs(glm::length(nr) - 1) <= 1e-12);
        // the lid's top and the bottom's centre: +z and −z outward
        for (std::size_t k = 0; k < m.soup.n_vertices(); ++k) {
            const glm::dvec3 p = m.soup.positions[k];
            if (p == glm::dvec3(0, 0, 3.15)) CHECK(m.normals[k].z > 0.999);
            if (p == glm::dvec3(0, 0, 0)) CHECK(m.normals[k].z < -0.999);
        }
    }
}

TEST_SUITE("Task 7: glyphs") {
    TEST_CASE("glyphs hidden: the areas of A–Z; a–z; 0–9 and a few symbols against finely flattened outlines" *
              geolab::points(4) * geolab::hidden() *
              geolab::hint("Exact from the control points: Σ over segments of (2 P0×P1 + 2 P1×P2 + P0×P2)/6.")) {
        std::u32string chars = U"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789&%@#?ß§";
        for (char32_t ch : chars) {
            const GlyphOutline g = geolab::read_glyph(geolab::default_font_path(), ch);
            LD want = 0;
            for (const auto& c : g.contours) want += sampled_area(c, 3000);
            want = std::abs(want);
            const double got = glyph_area(g);
            INFO("DejaVu Sans U+" << std::hex << unsigned(ch) << std::dec << ": expected " << double(want) << ", got "
                                  << num(got));
            CHECK(std::abs(got - double(want)) <= 1e-6 * double(want) + 1e-9);
            // scaled by 1/2048 (an em of 1): the area scales by the square
            GlyphOutline s = g;
            for (auto& c : s.contours)
                for (auto& seg : c)
                    for (auto& p : seg) p /= 2048.0;
            CHECK(std::abs(glyph_area(s) - got / (2048.0 * 2048.0)) <= 1e-12 * (1 + got / (2048.0 * 2048.0)));
        }
    }
}

TEST_SUITE("Task 8: advanced") {
    TEST_CASE("advanced hidden: a full circle from four arcs; insertion of an existing knot; de Boor at span ends" *
              geolab::points(1) * geolab::hidden() *
              geolab::hint("Every point of each arc is at distance r; inserting a knot never changes the curve.")) {
        const glm::dvec3 c{-3, 0.5, 1e3};
        for (int q = 0; q < 4; ++q) {
            const RationalCurve arc = circle_arc(c, 1e-3, q * pi / 2, (q + 1) * pi / 2);
            for (int k = 0; k <= 16; ++k)
                CHECK(std::abs(glm::length(rational_point(arc, k / 16.0) - c) - 1e-3) <= 1e-12 * 1e3);
        }
        const BSpline s{2, {0, 0, 0, 1, 1, 2, 3, 3, 3}, {{0, 0, 0}, {1, 2, 0}, {2, 0, 1}, {3, 3, 0}, {4, 0, 0}, {5, 1, 1}}};
        const BSpline r = insert_knot(s, 1.0);
        REQUIRE(r.points.size() == 7);
        for (double t : {0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0}) {
            const glm::dvec3 before = de_boor(s, t), after = de_boor(r, t);
            INFO("t = " << t << ": " << str(before) << " vs after inserting 1: " << str(after));
            CHECK(close3(before, after, 1e-14, 5));
        }
        // a knot of multiplicity p = 2 at 1: the curve passes through P_2 there
        CHECK(close3(de_boor(s, 1.0), s.points[2], 1e-15, 5));
        CHECK(close3(de_boor(s, 3.0), s.points.back(), 1e-15, 5));
    }
}
