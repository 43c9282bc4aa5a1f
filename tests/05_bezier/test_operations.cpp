// Lab 05, Task 2: subdivision, restriction, hodograph, derivatives, elevation, curvature and torsion. Expected
// values from the Bernstein form and its derivatives in long double (helpers.hpp).
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab05;

TEST_SUITE("Task 2: operations") {
    TEST_CASE("subdivide: the left half is C on (0; t); the right half C on (t; 1)" * geolab::points(3) *
              geolab::hint("left = the first point of every de Casteljau row (P_0^0, P_0^1, ..., P_0^n); right = the "
                           "last point of every row, from the bottom (P_0^n, P_1^(n−1), ..., P_n^0). Do not swap them.")) {
        Rng rng(10);
        for (int n = 1; n <= 7; ++n)
            for (double t : {0.5, 0.25, 0.3, 0.8125}) {
                const Poly3 P = rng.dyadic_poly(n);
                const Split s = subdivide(P, t);
                INFO("degree " << n << ", t = " << t << ", P = " << str(P) << ": left " << str(s.left) << ", right "
                               << str(s.right));
                REQUIRE(s.left.size() == P.size());
                REQUIRE(s.right.size() == P.size());
                CHECK(s.left.front() == P.front());
                CHECK(s.right.back() == P.back());
                CHECK(s.left.back() == s.right.front());
                for (double x : {0.0, 0.125, 0.5, 0.75, 1.0}) {
                    const glm::dvec3 wl = ref_point(P, LD(t) * x), wr = ref_point(P, t + (1 - LD(t)) * x);
                    const glm::dvec3 gl = ref_point(s.left, x), gr = ref_point(s.right, x);
                    INFO("at s = " << x << ": left(s) = " << str(gl) << " should be C(t s) = " << str(wl)
                                   << "; right(s) = " << str(gr) << " should be C(t + (1 − t) s) = " << str(wr));
                    CHECK(close3(gl, wl, 1e-13, scale_of(P)));
                    CHECK(close3(gr, wr, 1e-13, scale_of(P)));
                }
            }
        CHECK_THROWS_AS(subdivide(Poly3{}, 0.5), std::invalid_argument);
        CHECK_THROWS_AS(subdivide(rng.poly(2), std::nan("")), std::invalid_argument);
    }

    TEST_CASE("restrict_to: C on (a; b) reparametrised to (0; 1); a > b reverses" * geolab::points(2) *
              geolab::hint("Two subdivisions: the right part at a, then the left part of that at (b − a)/(1 − a). "
                           "Mind a = 1.")) {
        Rng rng(11);
        const std::pair<double, double> ranges[] = {{0.25, 0.75}, {0.0, 0.5}, {0.5, 1.0}, {0.1, 0.9},
                                                    {0.75, 0.25}, {1.0, 0.0}, {1.0, 0.5}, {0.3, 0.31}};
        for (int n = 1; n <= 6; ++n)
            for (const auto& [a, b] : ranges) {
                const Poly3 P = rng.poly(n);
                const Poly3 R = restrict_to(P, a, b);
                REQUIRE(R.size() == P.size());
                for (double x : {0.0, 0.25, 0.5, 1.0}) {
                    const glm::dvec3 want = ref_point(P, a + (LD(b) - a) * x), got = ref_point(R, x);
                    INFO("degree " << n << ", [a, b] = [" << a << ", " << b << "], s = " << x << ": expected C(a + (b−a)s) = "
                                   << str(want) << ", got " << str(got));
                    CHECK(close3(got, want, 1e-12, scale_of(P)));
                }
            }
        CHECK_THROWS_AS(restrict_to(rng.poly(3), 0.5, 0.5), std::invalid_argument);
        // the error names restrict_to (the header: errors name the function), whatever it calls
        CHECK_THROWS_WITH_AS(restrict_to(rng.poly(3), 0.25, std::nan("")), doctest::Contains("restrict_to"),
                             std::invalid_argument);
        CHECK_THROWS_WITH_AS(restrict_to(rng.poly(3), std::numeric_limits<double>::infinity(), 0.5),
                             doctest::Contains("restrict_to"), std::invalid_argument);
    }

    TEST_CASE("hodograph: n (P_(k+1) − P_k); and C'(t) from it" * geolab::points(3) * geolab::builds_on("Task 1") *
              geolab::hint("The derivative of a degree-n Bézier curve is a degree n − 1 curve with control points "
                           "n (P_(k+1) − P_k): do not forget the factor n (handout §3).")) {
        const Poly3 cubic{{0, 0, 0}, {1, 2, 0}, {3, 3, 1}, {4, 0, 2}};
        const Poly3 h = hodograph(cubic);
        INFO("hodograph of " << str(cubic) << ": expected [(3, 6, 0), (6, 3, 3), (3, -9, 3)], got " << str(h));
        REQUIRE(h.size() == 3);
        CHECK(h[0] == glm::dvec3(3, 6, 0));
        CHECK(h[1] == glm::dvec3(6, 3, 3));
        CHECK(h[2] == glm::dvec3(3, -9, 3));
        CHECK(hodograph(Poly3{{1, 2, 3}}) == Poly3{glm::dvec3(0.0)});
        Rng rng(12);
        for (int n = 1; n <= 9; ++n)
            for (int rep = 0; rep < 4; ++rep) {
                const Poly3 P = rng.poly(n);
                for (double t : {0.0, 0.2, 0.5, 0.9, 1.0}) {
                    const glm::dvec3 want = D(ref_deriv(P, t, 1)), got = derivative(P, t);
                    INFO("degree " << n << ", t = " << t << ": C'(t) expected " << str(want) << ", got " << str(got));
                    CHECK(close3(got, want, 1e-12, n * scale_of(P)));
                }
            }
        CHECK_THROWS_AS(hodograph(Poly3{}), std::invalid_argument);
    }

    TEST_CASE("second derivative: C''(t) = n (n − 1) Σ Δ²P_k B_k^(n−2)(t)" * geolab::points(1) *
              geolab::builds_on("Task 1") *
              geolab::hint("The hodograph of the hodograph. A line (n = 1) has C'' = 0.")) {
        Rng rng(13);
        for (int n = 1; n <= 9; ++n)
            for (double t : {0.0, 0.3, 0.5, 1.0}) {
                const Poly3 P = rng.poly(n);
                const glm::dvec3 want = D(ref_deriv(P, t, 2)), got = second_derivative(P, t);
                INFO("degree " << n << ", t = " << t << ": C''(t) expected " << str(want) << ", got " << str(got));
                CHECK(close3(got, want, 1e-11, n * n * scale_of(P)));
            }
    }

    TEST_CASE("elevate: one more control point; the same curve; known points" * geolab::points(2) *
              geolab::hint("Q_k = (k/(n+1)) P_(k−1) + (1 − k/(n+1)) P_k; the ends stay (handout §3).")) {
        const Poly3 quad{{0, 0, 0}, {3, 3, 0}, {6, 0, 0}};
        const Poly3 e = elevate(quad);
        INFO("elevate " << str(quad) << ": expected [(0,0,0), (2,2,0), (4,2,0), (6,0,0)], got " << str(e));
        REQUIRE(e.size() == 4);
        CHECK(e[0] == glm::dvec3(0, 0, 0));
        CHECK(e[1] == glm::dvec3(2, 2, 0));
        CHECK(e[2] == glm::dvec3(4, 2, 0));
        CHECK(e[3] == glm::dvec3(6, 0, 0));
        Rng rng(14);
        for (int n = 0; n <= 8; ++n) {
            const Poly3 P = rng.poly(n);
            Poly3 Q = P;
            for (int r = 0; r < 3; ++r) Q = elevate(Q);
            REQUIRE(Q.size() == P.size() + 3);
            for (double t : {0.0, 0.1, 0.5, 0.7, 1.0}) {
                INFO("degree " << n << " elevated 3 times, t = " << t << ": expected " << str(ref_point(P, t))
                               << ", got " << str(ref_point(Q, t)));
                CHECK(close3(ref_point(Q, t), ref_point(P, t), 1e-13, scale_of(P)));
            }
        }
    }

    TEST_CASE("curvature; torsion and signed curvature against the derivatives' formulas" * geolab::points(3) *
              geolab::builds_on("Task 1") *
              geolab::hint("κ = |C' × C''| / |C'|³, τ = (C' × C'') · C''' / |C' × C''|², signed κ = (x'y'' − y'x'') "
                           "/ |C'|³: positive turning left.")) {
        // y = x² on [−1, 1]: κ = 2 at the vertex, turning left
        const Poly2 parabola{{-1, 1}, {0, -1}, {1, 1}};
        const double k_vertex = signed_curvature(parabola, 0.5);
        INFO("parabola y = x² " << str(parabola) << " at t = 1/2: signed curvature expected 2, got " << num(k_vertex));
        CHECK(std::abs(k_vertex - 2) <= 1e-14);
        CHECK(std::abs(curvature(lift(parabola), 0.5) - 2) <= 1e-14);
        CHECK(torsion(lift(parabola), 0.5) == 0.0);
        const Poly2 rev{{1, 1}, {0, -1}, {-1, 1}};  // reversed: turns right
        CHECK(std::abs(signed_curvature(rev, 0.5) + 2) <= 1e-14);
        // x = 1 ± ... at t = 0: κ = 2 / (1 + 4)^(3/2) at x = −1 (y' = −2 along x)
        CHECK(std::abs(signed_curvature(parabola, 0.0) - 2 / std::pow(5.0, 1.5)) <= 1e-14);
        Rng rng(15);
        for (int n = 3; n <= 7; ++n)
            for (double t : {0.1, 0.5, 0.8}) {
                const Poly3 P = rng.poly(n);
                const V3L d1 = ref_deriv(P, t, 1), d2 = ref_deriv(P, t, 2), d3 = ref_deriv(P, t, 3);
                const V3L c = cross(d1, d2);
                const double k = double(norm(c) / std::pow(norm(d1), 3)), tau = double(dot(c, d3) / dot(c, c));
                const double gk = curvature(P, t), gtau = torsion(P, t);
                INFO("degree " << n << ", t = " << t << ", P = " << str(P) << ": κ expected " << num(k) << ", got "
                               << num(gk) << "; τ expected " << num(tau) << ", got " << num(gtau));
                CHECK(std::abs(gk - k) <= 1e-10 * (1 + k));
                CHECK(std::abs(gtau - tau) <= 1e-9 * (1 + std::abs(tau)));
                Poly2 P2;
                for (const auto& p : P) P2.emplace_back(p.x, p.y);
                const LD sx = d1.x, sy = d1.y;
                const double sk = double((sx * d2.y - sy * d2.x) / std::pow(std::sqrt(sx * sx + sy * sy), 3));
                CHECK(std::abs(signed_curvature(P2, t) - sk) <= 1e-10 * (1 + std::abs(sk)));
            }
        // a plane cubic has no torsion; a straight line no curvature
        const Poly3 line{{0, 0, 0}, {1, 1, 1}, {3, 3, 3}};
        CHECK(curvature(line, 0.4) <= 1e-15);
        CHECK(torsion(line, 0.4) == 0.0);
        // where C' = 0 (the cusp of (0,0) (2,2) (0,2) (2,0) at t = 1/2, exactly) all three are 0, not NaN
        const Poly2 cusp{{0, 0}, {2, 2}, {0, 2}, {2, 0}};
        const double kc = curvature(lift(cusp), 0.5), sc = signed_curvature(cusp, 0.5), tc = torsion(lift(cusp), 0.5);
        INFO("cusp " << str(cusp) << " at t = 1/2 (C' = 0): expected κ = signed κ = τ = 0, got " << num(kc) << ", "
                     << num(sc) << ", " << num(tc));
        CHECK(kc == 0.0);
        CHECK(sc == 0.0);
        CHECK(tc == 0.0);
        // |C'| = 1 exactly: (0,0) (1/2,0) (1,1) at t = 0 has C' = (1, 0), C'' = (0, 2): κ = 2, turning left
        const Poly2 unit_speed{{0, 0}, {0.5, 0}, {1, 1}};
        CHECK(signed_curvature(unit_speed, 0.0) == 2.0);
        CHECK(curvature(lift(unit_speed), 0.0) == 2.0);
    }
}
