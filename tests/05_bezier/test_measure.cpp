// Lab 05, Task 3: arc length and its inverse, the tight bounding box, the closest point. Expected values: closed
// forms, composite Simpson and dense sampling refined by golden-section search, all in long double.
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab05;

namespace {
// ∫_a^b |C'(t)| dt by composite Simpson (4096 panels) in long double.
LD ref_length(const Poly3& P, LD a, LD b) {
    const int N = 2048;
    const LD h = (b - a) / N;
    LD s = 0;
    for (int i = 0; i <= N; ++i) {
        const LD w = (i == 0 || i == N) ? 1 : (i % 2 ? 4 : 2);
        s += w * norm(ref_deriv(P, a + i * h, 1));
    }
    return s * h / 3;
}
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
}  // namespace

TEST_SUITE("Task 3: measures") {
    TEST_CASE("arc length: a straight cubic; the parabola y = x²; and random curves to the requested tolerance" *
              geolab::points(3) * geolab::builds_on("Task 1, Task 2") *
              geolab::hint("Integrate |C'| by Gauss–Legendre mapped to [a, b]; halve intervals where the 5- and "
                           "10-point rules disagree by more than their share of tol (handout §4).")) {
        const Poly3 line{{0, 0, 0}, {3, 0, 0}, {3, 0, 0}, {4, 0, 0}};  // x(t) non-uniform but monotone: length 4
        const double length = arc_length(line, 0, 1, 1e-12);  // once: an INFO must not call your code again
        INFO("straight cubic " << str(line) << ": expected length 4, got " << num(length));
        CHECK(std::abs(length - 4) <= 2e-12);
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
        // a tolerance below rounding still ends (at rounding accuracy)
        CHECK(std::abs(arc_length(parabola, 0, 1, 1e-300) - want) <= 1e-12);
        CHECK_THROWS_AS(arc_length(parabola, 0, 1, 0), std::invalid_argument);
        CHECK_THROWS_AS(arc_length(parabola, 0.5, 0.25, 1e-6), std::invalid_argument);
        CHECK_THROWS_AS(arc_length(parabola, 0, 1.5, 1e-6), std::invalid_argument);
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
        for (int n = 2; n <= 6; ++n) {
            const Poly3 P = rng.poly(n, 2);
            const double total = double(ref_length(P, 0, 1));
            for (double f : {0.1, 0.37, 0.5, 0.9}) {
                const double t = parameter_at_length(P, f * total, 1e-10);
                const double len = double(ref_length(P, 0, t));
                INFO("degree " << n << ", P = " << str(P) << ", s = " << num(f * total) << ": got t = " << num(t)
                               << " whose length is " << num(len));
                CHECK(std::abs(len - f * total) <= 1e-8 * (1 + total));
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
        Rng rng(23);
        for (int n = 2; n <= 7; ++n)
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
