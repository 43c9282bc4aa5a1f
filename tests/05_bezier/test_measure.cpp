// Lab 05, Task 3: arc length and its inverse, the tight bounding box, the closest point. Expected values: closed
// forms, composite Simpson (split at a cusp), the contract's adaptive rule and dense sampling refined by
// golden-section search, all in long double (helpers.hpp).
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab05;

namespace {
// Extremes of coordinate `axis` over [0, 1]: dense sampling then golden-section refinement (long double).
LD ref_extreme(const Poly3& P, int axis, bool max) {
    auto f = [&](LD t) {
        const V3L p = ref_deriv(P, t);
        const LD v = axis == 0 ? p.x : axis == 1 ? p.y : p.z;
        return max ? -v : v;
    };
    const int N = 1000;
    int best = 0;
    LD bv = f(0);
    for (int i = 1; i <= N; ++i)
        if (LD v = f(LD(i) / N); v < bv) bv = v, best = i;
    LD a = std::max<LD>(0, LD(best - 1) / N), b = std::min<LD>(1, LD(best + 1) / N);
    const LD g = (std::sqrt(LD(5)) - 1) / 2;
    for (int it = 0; it < 120; ++it) {
        const LD c = b - g * (b - a), d = a + g * (b - a);
        if (f(c) < f(d)) b = d; else a = c;
    }
    const LD v = std::min({f(a), f(b), bv});
    return max ? -v : v;
}
// Cubics with a cusp at a parameter that is not a split point of the halving (their speed has a kink there).
struct Cusp {
    double t0;
    Poly3 P;
};
std::vector<Cusp> cusps() {
    return {{1.0 / 3.0, cusp_cubic(1.0 / 3.0, {6, -3, 1.5}, {-9, 12, 3})},
            {0.7, cusp_cubic(0.7, {-2, 5, 0}, {4, -1, 2}, {1, 1, 1})},
            {0.15, cusp_cubic(0.15, {3, 3, -3}, {-1, 7, 2})}};
}
}  // namespace

TEST_SUITE("Task 3: measures") {
    TEST_CASE("arc length: a straight cubic; the parabola y = x²; and random curves to the requested tolerance" *
              geolab::points(3) * geolab::builds_on("Task 1, Task 2") *
              geolab::hint("Integrate |C'| by Gauss–Legendre mapped to [a, b]; halve intervals where the 5- and "
                           "10-point rules disagree by more than their share of tol (handout §4).")) {
        const Poly3 line{{0, 0, 0}, {3, 0, 0}, {3, 0, 0}, {4, 0, 0}};  // x(t) non-uniform but monotone: length 4
        const double l4 = arc_length(line, 0, 1, 1e-12);
        INFO("straight cubic " << str(line) << ": expected length 4, got " << num(l4));
        CHECK(std::abs(l4 - 4) <= 2e-12);
        const Poly3 parabola{{-1, 1, 0}, {0, -1, 0}, {1, 1, 0}};
        const double want = std::sqrt(5.0) + 0.5 * std::asinh(2.0);
        const double got = arc_length(parabola, 0, 1, 1e-12);
        INFO("parabola y = x² on [−1, 1]: expected √5 + asinh(2)/2 = " << num(want) << ", got " << num(got));
        CHECK(std::abs(got - want) <= 2e-12);
        CHECK(std::abs(arc_length(parabola, 0, 0.5, 1e-12) - want / 2) <= 2e-12);  // symmetric halves
        CHECK(arc_length(parabola, 0.3, 0.3, 1e-9) == 0.0);
        Rng rng(20);
        for (int n = 2; n <= 7; ++n)
            for (double tol : {1e-4, 1e-8, 1e-11}) {
                const Poly3 P = rng.poly(n, 2);
                const double a = rng.uniform(0, 0.5), b = rng.uniform(0.5, 1);
                const double w = double(ref_length(P, a, b)), g = arc_length(P, a, b, tol);
                INFO("degree " << n << ", [" << num(a) << ", " << num(b) << "], tol " << tol << ", P = " << str(P)
                               << ": expected " << num(w) << ", got " << num(g));
                CHECK(std::abs(g - w) <= tol + 1e-12 * w);
            }
        // a cusp: |C'| has a kink, where the 5- and 10-point rules disagree until the interval around it is small
        for (const auto& c : cusps())
            for (double tol : {1e-4, 1e-8, 1e-11}) {
                const double w = double(ref_length_kinked(c.P, 0, 1, c.t0)), g = arc_length(c.P, 0, 1, tol);
                INFO("cubic with a cusp at t = " << num(c.t0) << ", P = " << str(c.P) << ", tol " << tol
                                                  << ": expected length " << num(w) << ", got " << num(g));
                CHECK(std::abs(g - w) <= tol + 1e-13 * w);
            }
        // a tolerance below rounding still ends (at rounding accuracy)
        CHECK(std::abs(arc_length(parabola, 0, 1, 1e-300) - want) <= 1e-12);
        CHECK_THROWS_AS(arc_length(parabola, 0, 1, 0), std::invalid_argument);
        CHECK_THROWS_AS(arc_length(parabola, 0.5, 0.25, 1e-6), std::invalid_argument);
        CHECK_THROWS_AS(arc_length(parabola, 0, 1.5, 1e-6), std::invalid_argument);
    }

    TEST_CASE("arc length: the contract's rule (cut at the speed's stationary points; shares of tol); tol below "
              "rounding; |C'| not finite" *
              geolab::points(2) *
              geolab::builds_on("Task 1, Task 2") *
              geolab::hint("Cut [a, b] at the roots of C' · C'' (the speed's extremes; a cusp is one). On each piece keep "
                           "an interval when its 5- and 10-point values differ by at most tol · (its length) / (b − a); "
                           "otherwise halve it. Refuse a hodograph point whose length is not finite (handout §4).")) {
        // The sum of the kept 10-point values, computed in long double by the test (its own Gauss–Legendre nodes
        // and stationary points): another share of tol, no halving, or halving too far keeps other intervals.
        std::vector<Poly3> curves;
        for (const auto& c : cusps()) curves.push_back(c.P);
        Rng rng(24);
        for (int k = 0; k < 4; ++k) curves.push_back(rng.poly(5, 2));
        for (const auto& P : curves)
            for (double tol : {1e-3, 1e-4})
                for (auto [a, b] : {std::pair{0.0, 1.0}, {0.1, 0.9}, {0.25, 0.5}}) {
                    const AdaptiveLength want = adaptive_length(P, a, b, tol);
                    REQUIRE(want.margin > 1e-6);  // the test's input: no interval is near a tie
                    const double got = arc_length(P, a, b, tol);
                    INFO("P = " << str(P) << ", [" << a << ", " << b << "], tol " << tol << ": the rule keeps "
                                << want.leaves << " intervals and gives " << num(double(want.value)) << "; got "
                                << num(got));
                    CHECK(std::abs(got - double(want.value)) <= 1e-11 * double(want.value));
                }
        // tol below rounding: T = 1e-14 (b − a) max |n ΔP_k| ends the halving; small, unit and large scales, short
        // intervals around a cusp
        for (double scale : {1e-3, 1.0, 1e6})
            for (const auto& c : cusps())
                for (auto [a, b] : {std::pair{0.0, 1.0}, {c.t0 - 1e-4, c.t0 + 3e-4}}) {
                    Poly3 P = c.P;
                    for (auto& p : P) p *= scale;
                    const double w = double(ref_length_kinked(P, a, b, c.t0)), g = arc_length(P, a, b, 1e-300);
                    INFO("cusp at t = " << num(c.t0) << " scaled by " << scale << ", [" << num(a) << ", " << num(b)
                                        << "], tol 1e-300: expected " << num(w) << ", got " << num(g));
                    CHECK(std::abs(g - w) <= 1e-12 * w);
                }
        const Poly3 huge{{-1e308, 0, 0}, {1e308, 0, 0}};  // C' = 2e308: overflows
        CHECK_THROWS_AS(arc_length(huge, 0, 1, 1e-6), std::invalid_argument);
        const Poly3 long_leg{{0, 0, 0}, {1e200, 1e200, 0}};  // C' finite, |C'| overflows (x² + y²)
        CHECK_THROWS_AS(arc_length(long_leg, 0, 1, 1e-6), std::invalid_argument);
        const Poly3 nan_point{{0, 0, 0}, {1, std::nan(""), 0}, {2, 0, 0}};
        CHECK_THROWS_AS(arc_length(nan_point, 0, 1, 1e-6), std::invalid_argument);
    }

    TEST_CASE("parameter at length: the inverse of the arc length" * geolab::points(3) *
              geolab::builds_on("Task 1, Task 2") *
              geolab::hint("Solve length(0, t) = s: Newton (the derivative is |C'(t)|) inside a bracket, bisecting "
                           "when Newton leaves it.")) {
        const Poly3 line{{0, 0, 0}, {3, 0, 0}, {3, 0, 0}, {4, 0, 0}};  // x(t) = 9t − 9t² ... ; length to x is x
        for (double s : {0.0, 0.5, 1.0, 2.0, 3.5, 4.0}) {
            const double t = parameter_at_length(line, s, 1e-12);
            const double x = ref_point(line, t).x;
            INFO("straight cubic: the point at length " << s << " has x = " << s << "; got t = " << num(t)
                                                        << " with x = " << num(x));
            CHECK(std::abs(x - s) <= 1e-10);
        }
        Rng rng(21);
        for (int n = 1; n <= 6; ++n)
            for (double tol : {1e-3, 1e-10}) {
                const Poly3 P = rng.poly(n, 2);
                const double total = double(ref_length(P, 0, 1));
                for (double f : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0}) {
                    const double t = parameter_at_length(P, f * total, tol);
                    const double len = double(ref_length(P, 0, t));
                    INFO("degree " << n << ", P = " << str(P) << ", s = " << num(f * total) << ", tol " << tol
                                   << ": got t = " << num(t) << " whose length is " << num(len));
                    CHECK(std::abs(len - f * total) <= tol + 1e-13 * total);
                }
            }
        // through a cusp (the speed is 0 there)
        for (const auto& c : cusps()) {
            const double total = double(ref_length_kinked(c.P, 0, 1, c.t0));
            for (double f : {0.2, 0.5, 0.8}) {
                const double t = parameter_at_length(c.P, f * total, 1e-9);
                const double len = double(ref_length_kinked(c.P, 0, t, c.t0));
                INFO("cusp at t = " << num(c.t0) << ", s = " << num(f * total) << ": got t = " << num(t)
                                    << " whose length is " << num(len));
                CHECK(std::abs(len - f * total) <= 1e-9 + 1e-13 * total);
            }
        }
        // a tol below what the lengths resolve (1e-300 on curves about 1e6 long) still ends, with t as good as
        // doubles allow (the bracket closes on one side or the other)
        for (int k = 0; k < 3; ++k) {
            Poly3 big = rng.poly(4, 1);
            for (auto& p : big) p *= 1e6;
            const double big_total = double(ref_length(big, 0, 1));
            for (double f : {0.1, 0.4, 0.55, 0.7, 0.85}) {
                const double tb = parameter_at_length(big, f * big_total, 1e-300);
                const double lb = double(ref_length(big, 0, tb));
                INFO("curve of length " << num(big_total) << ", s = " << num(f * big_total) << ", tol 1e-300: got t = "
                                        << num(tb) << " whose length is " << num(lb));
                CHECK(std::abs(lb - f * big_total) <= 1e-12 * big_total);
            }
        }
        CHECK_THROWS_AS(parameter_at_length(line, -1, 1e-9), std::invalid_argument);
        CHECK_THROWS_AS(parameter_at_length(line, 5, 1e-9), std::invalid_argument);
    }

    TEST_CASE("bounding box: tight (the extremes of each coordinate) and inside the control points' box" *
              geolab::points(3) * geolab::builds_on("Task 1, Task 2") *
              geolab::hint("Per axis: the ends and C at the roots in (0, 1) of that coordinate of C'. The control "
                           "points' box is only an upper bound (convex hull property), not the answer.")) {
        const Poly3 parabola{{-1, 1, 0}, {0, -1, 0}, {1, 1, 0}};
        const Box b = bounding_box(parabola);
        INFO("parabola y = x², x ∈ [−1, 1]: expected box (−1, 0, 0)–(1, 1, 0), got " << str(b.lo) << "–" << str(b.hi));
        CHECK(std::abs(b.lo.y) <= 1e-15);
        CHECK(b.lo.x == -1);
        CHECK(b.hi == glm::dvec3(1, 1, 0));
        Rng rng(22);
        for (int n = 1; n <= 9; ++n)
            for (int rep = 0; rep < 4; ++rep) {
                const Poly3 P = rng.poly(n);
                const Box g = bounding_box(P);
                glm::dvec3 clo = P[0], chi = P[0];
                for (const auto& p : P) clo = glm::min(clo, p), chi = glm::max(chi, p);
                const double diag = glm::length(chi - clo);
                for (int axis = 0; axis < 3; ++axis) {
                    const double lo = double(ref_extreme(P, axis, false)), hi = double(ref_extreme(P, axis, true));
                    INFO("degree " << n << ", P = " << str(P) << ", axis " << axis << ": expected [" << num(lo) << ", "
                                   << num(hi) << "], got [" << num(g.lo[axis]) << ", " << num(g.hi[axis]) << "]");
                    CHECK(std::abs(g.lo[axis] - lo) <= 1e-12 * (diag + 1));
                    CHECK(std::abs(g.hi[axis] - hi) <= 1e-12 * (diag + 1));
                    CHECK(g.lo[axis] >= clo[axis]);
                    CHECK(g.hi[axis] <= chi[axis]);
                }
            }
        // a single point; an x coordinate with a double root of x' (x(t) = (t − 1/3)³ + 1: monotone, its box from the
        // ends; only noise changes the sign of x' near 1/3)
        const Box pt = bounding_box(Poly3{{1.5, -2, 3}});
        CHECK(pt.lo == glm::dvec3(1.5, -2, 3));
        CHECK(pt.hi == glm::dvec3(1.5, -2, 3));
        const Poly3 flat_x = cusp_cubic(1.0 / 3.0, {-1.0 / 3.0, 0, 0}, {1, 0, 0}, {0, 1, 0});  // x' = (t − 1/3)², y = 1
        const Box fx = bounding_box(flat_x);
        INFO("x' = (t − 1/3)² (a double root), P = " << str(flat_x) << ": expected x in [" << num(flat_x[0].x) << ", "
                                                       << num(flat_x[3].x) << "], got [" << num(fx.lo.x) << ", "
                                                       << num(fx.hi.x) << "]");
        CHECK(std::abs(fx.lo.x - flat_x[0].x) <= 1e-15);
        CHECK(std::abs(fx.hi.x - flat_x[3].x) <= 1e-15);
        CHECK_THROWS_AS(bounding_box(Poly3{}), std::invalid_argument);
    }

    TEST_CASE("closest point: the global minimum; at the ends too" * geolab::points(3) *
              geolab::builds_on("Task 1, Task 2") *
              geolab::hint("Bracket candidates (sampling or subdivision), refine each by Newton on (C − q)·C' = 0 "
                           "clamped to [0, 1], and compare with both ends: a local minimum is not enough.")) {
        const Poly3 parabola{{-1, 1, 0}, {0, -1, 0}, {1, 1, 0}};
        const Closest c0 = closest_point(parabola, {0, -1, 0});  // below the vertex
        INFO("parabola, q = (0, −1, 0): expected t = 0.5, point (0, 0, 0), distance 1; got t = " << num(c0.t) << ", "
                                                                                                 << str(c0.point));
        CHECK(std::abs(c0.t - 0.5) <= 1e-9);
        CHECK(std::abs(c0.distance - 1) <= 1e-12);
        const Closest c1 = closest_point(parabola, {3, 0.5, 0});  // beyond the right end
        CHECK(c1.t == 1.0);
        CHECK(c1.point == glm::dvec3(1, 1, 0));
        const Closest c2 = closest_point(parabola, {-2, 1.5, 0});
        CHECK(c2.t == 0.0);
        // equally near ends (an arch y = 1 − x² seen from straight below): the smallest t
        const Poly3 arch{{-1, 0, 0}, {0, 2, 0}, {1, 0, 0}};
        const Closest ce = closest_point(arch, {0, -5, 0});
        INFO("arch y = 1 − x², q = (0, −5, 0): both ends at distance √26; expected t = 0, got t = " << num(ce.t));
        CHECK(ce.t == 0.0);
        CHECK(std::abs(ce.distance - std::sqrt(26.0)) <= 1e-15 * 6);
        // a single point; q on the curve; q at the vertex's centre of curvature (a multiple root of (C − q)·C')
        const Closest cp = closest_point(Poly3{{1, 2, 3}}, {4, 6, 3});
        CHECK(cp.t == 0.0);
        CHECK(cp.distance == 5.0);
        const Closest on = closest_point(parabola, {0.25, 0.0625, 0});  // C(5/8) = (1/4, 1/16, 0)
        INFO("q = C(5/8) on the parabola: expected distance 0 at t = 0.625, got " << num(on.distance) << " at t = "
                                                                                  << num(on.t));
        CHECK(on.distance <= 1e-9);
        CHECK(std::abs(on.t - 0.625) <= 1e-9);
        const Closest cc = closest_point(parabola, {0, 0.5, 0});  // the centre of curvature of the vertex
        CHECK(std::abs(cc.distance - 0.5) <= 1e-12);
        Rng rng(23);
        for (int n = 1; n <= 7; ++n)
            for (int rep = 0; rep < 6; ++rep) {
                const Poly3 P = rng.poly(n);
                const glm::dvec3 q{rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)};
                const LD tr = ref_closest_t(P, q);
                const double want = double(norm(ref_deriv(P, tr) - L(q)));
                const Closest got = closest_point(P, q);
                const double scale = scale_of(P) + glm::length(q);
                INFO("degree " << n << ", P = " << str(P) << ", q = " << str(q) << ": expected distance " << num(want)
                               << " at t = " << num(double(tr)) << ", got " << num(got.distance) << " at t = "
                               << num(got.t));
                CHECK(std::abs(got.distance - want) <= 1e-9 * scale);
                CHECK(got.t >= 0);
                CHECK(got.t <= 1);
                CHECK(close3(got.point, ref_point(P, got.t), 1e-12, scale));
                CHECK(std::abs(got.distance - glm::length(got.point - q)) <= 1e-12 * scale);
            }
    }
}
