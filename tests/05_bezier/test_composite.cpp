// Lab 05, Task 4: composite curves and continuity at a joint. Joints built by construction (the class known), the
// derivatives for checks from the Bernstein form in long double.
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab05;

namespace {
const Poly3 A{{0, 0, 0}, {1, 1, 0}, {2, 1, 1}, {3, 0, 1}};  // a cubic ending at (3, 0, 1)
// b's points for a joint with A: b0 = A3, b1 = A3 + f (A3 − A2), b2 chosen by the caller, b3 anything.
Poly3 joined(double f, const glm::dvec3& b2, const glm::dvec3& b3 = {6, 2, 0}) {
    const glm::dvec3 a3 = A[3], a2 = A[2];
    return {a3, a3 + f * (a3 - a2), b2, b3};
}
// The second differences: a''(1) = 6 (A3 − 2A2 + A1); b''(0) = 6 (b2 − 2 b1 + b0). b2 for b''(0) = s a''(1).
glm::dvec3 b2_for(double f, double s) {
    const glm::dvec3 b0 = A[3], b1 = A[3] + f * (A[3] - A[2]);
    return s * (A[3] - 2.0 * A[2] + A[1]) + 2.0 * b1 - b0;
}
std::string str(const Continuity& c) {
    return "C" + std::to_string(c.c_order) + " / G" + std::to_string(c.g_order);
}
}  // namespace

TEST_SUITE("Task 4: composite curves") {
    TEST_CASE("composite evaluation: segment k covers (k; k + 1); an inner joint belongs to the next segment" *
              geolab::points(2) * geolab::builds_on("Task 1") *
              geolab::hint("k = floor(u) clamped to the last segment; t = u − k. u outside [0, m]: invalid_argument.")) {
        const std::vector<Poly3> segs{{{0, 0, 0}, {1, 0, 0}}, {{5, 5, 5}, {6, 6, 6}, {7, 5, 5}}, {{9, 9, 9}, {10, 8, 8}}};
        CHECK(evaluate_composite(segs, 0.0) == glm::dvec3(0, 0, 0));
        CHECK(evaluate_composite(segs, 0.5) == glm::dvec3(0.5, 0, 0));
        const glm::dvec3 at1 = evaluate_composite(segs, 1.0);
        INFO("u = 1 is segment 1 at t = 0: expected (5, 5, 5), got " << str(at1));
        CHECK(at1 == glm::dvec3(5, 5, 5));
        CHECK(evaluate_composite(segs, 1.5) == glm::dvec3(6, 5.5, 5.5));
        CHECK(evaluate_composite(segs, 2.0) == glm::dvec3(9, 9, 9));
        CHECK(evaluate_composite(segs, 3.0) == glm::dvec3(10, 8, 8));
        CHECK(evaluate_composite(segs, 2.25) == glm::dvec3(9.25, 8.75, 8.75));
        CHECK_THROWS_AS(evaluate_composite(segs, -0.1), std::invalid_argument);
        CHECK_THROWS_AS(evaluate_composite(segs, 3.1), std::invalid_argument);
        CHECK_THROWS_AS(evaluate_composite({}, 0.0), std::invalid_argument);
        // an empty segment anywhere (first, middle, last) is an error, whichever segment u falls in
        for (std::size_t e = 0; e < segs.size(); ++e) {
            std::vector<Poly3> bad = segs;
            bad[e].clear();
            INFO("segment " << e << " empty");
            CHECK_THROWS_AS(evaluate_composite(bad, 2.5), std::invalid_argument);
        }
    }

    TEST_CASE("continuity classes: C⁰ only; G¹ but not C¹; C¹; G² but not C²; C²; C³; apart" * geolab::points(4) *
              geolab::builds_on("Task 2") *
              geolab::hint("Cᵏ: derivatives 0..k equal. Gᵏ (lecture): Cᵏ⁻¹ plus k-th derivatives parallel in the same "
                           "direction. G¹ is NOT C¹: a tangent of another length is still G¹ (handout §5).")) {
        struct Case {
            const char* name;
            Poly3 b;
            int c, g;
        };
        const Case cases[] = {
            {"apart", {{3, 0, 1.5}, {4, 0, 0}, {5, 1, 0}, {6, 2, 0}}, -1, -1},
            {"C0 only (a corner)", {A[3], A[3] + glm::dvec3(0, 1, 0), {5, 1, 0}, {6, 2, 0}}, 0, 0},
            {"G1 but not C1 (tangent twice as long)", joined(2.0, {7, 1, 0}), 0, 1},
            {"G1 but not C1 (tangent half as long)", joined(0.5, {7, 1, 0}), 0, 1},
            {"tangent reversed: C0 only", joined(-1.0, {7, 1, 0}), 0, 0},
            {"C1, second derivatives not parallel", joined(1.0, {7, 1, 5}), 1, 1},
            {"G2 but not C2", joined(1.0, b2_for(1.0, 3.0)), 1, 2},
            {"C2, not C3", joined(1.0, b2_for(1.0, 1.0), {9, 9, 9}), 2, 2},
        };
        for (const auto& k : cases) {
            const Continuity got = continuity(A, k.b, 1e-12);
            INFO(k.name << ": a = " << lab05::str(A) << ", b = " << lab05::str(k.b) << "; expected C" << k.c << " / G"
                        << k.g << ", got " << str(got));
            CHECK(got.c_order == k.c);
            CHECK(got.g_order == k.g);
        }
        // a cubic split in two (by hand, at 1/2) is C³ at the split
        const glm::dvec3 p01 = 0.5 * (A[0] + A[1]), p12 = 0.5 * (A[1] + A[2]), p23 = 0.5 * (A[2] + A[3]);
        const glm::dvec3 q0 = 0.5 * (p01 + p12), q1 = 0.5 * (p12 + p23), m = 0.5 * (q0 + q1);
        const Continuity c3 = continuity({A[0], p01, q0, m}, {m, q1, p23, A[3]}, 1e-12);
        INFO("two halves of one cubic: expected C3 / G3, got " << str(c3));
        CHECK(c3.c_order == 3);
        CHECK(c3.g_order == 3);
        CHECK_THROWS_AS(continuity(A, {}, 1e-9), std::invalid_argument);
        // ends apart although the end points are parallel as vectors (a at (1, 1, 0), b from (2, 2, 0)): not G0
        const Continuity ap = continuity({{0, 0, 0}, {1, 1, 0}}, {{2, 2, 0}, {3, 0, 0}}, 1e-9);
        INFO("a ends at (1, 1, 0), b starts at (2, 2, 0): expected C-1 / G-1, got " << str(ap));
        CHECK(ap.c_order == -1);
        CHECK(ap.g_order == -1);
        // a G1 joint with short tangents ((0.1, 0, 0) and (0.4, 0, 0): lengths below 1) is still G1
        const Continuity gs = continuity({{0, 0, 0}, {0.1, 0, 0}}, {{0.1, 0, 0}, {0.3, 0, 0}, {0.4, 0.1, 0}}, 1e-12);
        INFO("short tangents (0.1, 0, 0) and (0.4, 0, 0): expected C0 / G1, got " << str(gs));
        CHECK(gs.c_order == 0);
        CHECK(gs.g_order == 1);
    }

    TEST_CASE("continuity with different degrees and a tolerance" * geolab::points(2) * geolab::builds_on("Task 2") *
              geolab::hint("Derivatives at the joint come from each curve's own degree: a'(1) = n (a_n − a_(n−1)), "
                           "b'(0) = m (b_1 − b_0).")) {
        // quadratic b joined C¹ to cubic A: b1 = A3 + (3/2)(A3 − A2)
        const Poly3 b{A[3], A[3] + 1.5 * (A[3] - A[2]), {8, 0, 0}};
        const Continuity c = continuity(A, b, 1e-12);
        INFO("cubic → quadratic with b1 = A3 + 3/2 (A3 − A2): expected C1, got " << str(c));
        CHECK(c.c_order == 1);
        // the quadratic with b1 = A3 + (A3 − A2) is G1, not C1
        const Continuity g = continuity(A, Poly3{A[3], 2.0 * A[3] - A[2], {8, 0, 0}}, 1e-12);
        CHECK(g.c_order == 0);
        CHECK(g.g_order == 1);
        // a gap of 1e-9 is a joint at tol 1e-6, not at 1e-12
        Poly3 near = b;
        near[0] += glm::dvec3(1e-9, 0, 0);
        CHECK(continuity(A, near, 1e-6).c_order >= 0);
        CHECK(continuity(A, near, 1e-12).c_order == -1);
        // tol = 0 is allowed: an exact C1 join (dyadic points) is C1 at tol 0
        const Poly3 exact{A[3], 2.0 * A[3] - A[2], {8, 0, 0}, {9, 1, 0}};
        CHECK(continuity(A, exact, 0.0).c_order == 1);
        const Poly3 ax{{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 0, 0}};  // its last leg along x: exact unit tangent
        const Continuity g0 = continuity(ax, Poly3{{3, 0, 0}, {5, 0, 0}, {6, 1, 0}}, 0.0);
        INFO("G1 joint along x at tol 0: expected C0 / G1, got " << str(g0));
        CHECK(g0.c_order == 0);
        CHECK(g0.g_order == 1);
        CHECK_THROWS_AS(continuity(A, exact, -1.0), std::invalid_argument);
        // the comparison is |x − y| ≤ tol (1 + the LARGER length): ends near the origin 1.5e-6 apart are not a joint
        // at tol 1e-6 (the bound is 1e-6 (1 + ~0)); end points of lengths 1 and 3 (2 apart) are one at tol 0.6
        // (0.6 (1 + 3) = 2.4) and would not be with the smaller length (0.6 (1 + 1) = 1.2)
        const Continuity gap = continuity({{1, 1, 0}, {0, 0, 0}}, {{1.5e-6, 0, 0}, {1, 0, 0}}, 1e-6);
        INFO("ends 1.5e-6 apart at the origin, tol 1e-6: expected C-1, got " << str(gap));
        CHECK(gap.c_order == -1);
        const Continuity big_tol = continuity({{0, 0, 0}, {1, 0, 0}}, {{3, 0, 0}, {4, 0, 0}}, 0.6);
        INFO("ends (1, 0, 0) and (3, 0, 0) at tol 0.6: expected C0 or more, got " << str(big_tol));
        CHECK(big_tol.c_order >= 0);
        // the tolerance is relative to the vectors' lengths: a C1 join at scale 1e6 off by 1e-7 is C1 at tol 1e-12
        Poly3 big = A, bigb = exact;
        for (auto& p : big) p *= 1e6;
        for (auto& p : bigb) p *= 1e6;
        bigb[1] += glm::dvec3(1e-7, 0, 0);
        const Continuity cb = continuity(big, bigb, 1e-12);
        INFO("C1 join scaled by 1e6, b1 moved by 1e-7 (relative 1e-13): expected C1, got " << str(cb));
        CHECK(cb.c_order == 1);
    }

    TEST_CASE("join_c1 and join_g1 produce the joints they promise" * geolab::points(3) *
              geolab::hint("C¹: b_1 = a_n + (n/m)(a_n − a_(n−1)). G¹: the direction of a's last leg with the length of "
                           "b's first leg. Other points of b stay.")) {
        Rng rng(30);
        for (int n = 1; n <= 5; ++n)
            for (int m = 1; m <= 5; ++m) {
                const Poly3 a = rng.poly(n), b = rng.poly(m);
                const Poly3 c1 = join_c1(a, b);
                REQUIRE(c1.size() == b.size());
                const glm::dvec3 da = D(ref_deriv(a, 1, 1)), db = D(ref_deriv(c1, 0, 1));
                INFO("degrees " << n << " → " << m << ": a'(1) = " << str(da) << ", joined b'(0) = " << str(db));
                CHECK(c1[0] == a.back());
                CHECK(close3(da, db, 1e-12, glm::length(da)));
                for (int k = 2; k <= m; ++k) CHECK(c1[k] == b[k]);
                const Poly3 g1 = join_g1(a, b);
                REQUIRE(g1.size() == b.size());
                CHECK(g1[0] == a.back());
                const glm::dvec3 ua = glm::normalize(a[n] - a[n - 1]), ub = glm::normalize(g1[1] - g1[0]);
                INFO("G1 join: unit tangents " << str(ua) << " and " << str(ub));
                CHECK(close3(ua, ub, 1e-12));
                CHECK(std::abs(glm::length(g1[1] - g1[0]) - glm::length(b[1] - b[0])) <= 1e-12 * (1 + scale_of(b)));
                for (int k = 2; k <= m; ++k) CHECK(g1[k] == b[k]);
            }
        CHECK_THROWS_AS(join_c1(Poly3{{1, 2, 3}}, A), std::invalid_argument);
        CHECK_THROWS_AS(join_c1(A, Poly3{{1, 2, 3}}), std::invalid_argument);
        CHECK_THROWS_AS(join_g1(Poly3{{1, 2, 3}}, A), std::invalid_argument);
        CHECK_THROWS_AS(join_g1(A, Poly3{{1, 2, 3}}), std::invalid_argument);
        CHECK_THROWS_AS(join_g1(Poly3{{1, 1, 1}, {1, 1, 1}}, A), std::invalid_argument);
        CHECK_THROWS_AS(join_g1(A, Poly3{{1, 1, 1}, {1, 1, 1}, {2, 0, 0}}), std::invalid_argument);  // b_1 = b_0
        // a first leg of length exactly 1 is a length like any other
        const Poly3 g_unit = join_g1(Poly3{{0, 0, 0}, {2, 0, 0}}, Poly3{{5, 5, 5}, {5, 6, 5}, {7, 7, 7}});
        CHECK(glm::length(g_unit[1] - g_unit[0]) == 1.0);
    }
}
