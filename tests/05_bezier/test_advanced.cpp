// Lab 05, Task 8 (advanced): rational Bézier curves and the exact circle; B-splines by de Boor, knot insertion.
// Expected values: the circle itself, and the Cox–de Boor recursion in long double.
#include "helpers.hpp"

using namespace lab05;

namespace {
// N_{i,p}(t) by the Cox–de Boor recursion (right-open spans; t at the domain's end uses the last span).
LD basis(const std::vector<double>& U, int i, int p, LD t, LD end) {
    if (p == 0) {
        if (t == end) return U[i] < t && U[i + 1] == t ? 1 : 0;
        return U[i] <= t && t < U[i + 1] ? 1 : 0;
    }
    LD a = 0, b = 0;
    if (U[i + p] > U[i]) a = (t - U[i]) / (LD(U[i + p]) - U[i]) * basis(U, i, p - 1, t, end);
    if (U[i + p + 1] > U[i + 1]) b = (LD(U[i + p + 1]) - t) / (LD(U[i + p + 1]) - U[i + 1]) * basis(U, i + 1, p - 1, t, end);
    return a + b;
}
glm::dvec3 ref_bspline(const BSpline& s, LD t) {
    const LD end = s.knots[s.points.size()];
    V3L c{};
    for (std::size_t i = 0; i < s.points.size(); ++i) c = c + basis(s.knots, int(i), s.degree, t, end) * L(s.points[i]);
    return D(c);
}
BSpline random_bspline(Rng& rng, int p, int n_points) {
    BSpline s;
    s.degree = p;
    s.points = rng.poly(n_points - 1);
    double k = 0;
    for (int i = 0; i < n_points + p + 1; ++i) {
        if (rng.integer(0, 3) > 0) k += rng.uniform(0.1, 1.0);  // some repeated knots
        s.knots.push_back(k);
    }
    // a non-empty domain
    if (s.knots[n_points] <= s.knots[p]) s.knots[n_points] = s.knots[p] + 1, s.knots.back() = s.knots[n_points] + 1;
    for (std::size_t i = 1; i < s.knots.size(); ++i) s.knots[i] = std::max(s.knots[i], s.knots[i - 1]);
    return s;
}
}  // namespace

TEST_SUITE("Task 8: advanced") {
    TEST_CASE("rational quadratic: an exact circular arc; equal weights give the polynomial curve" *
              geolab::points(1) *
              geolab::hint("Homogeneous de Casteljau on (w P, w), then divide. The arc's middle weight is "
                           "cos(half the angle) and P_1 is where the end tangents meet.")) {
        const glm::dvec3 c{1, 2, 3};
        for (auto [a0, a1] : {std::pair{0.0, pi / 2}, {pi / 3, pi}, {-2.0, -0.5}, {1.0, 1.001}}) {
            const RationalCurve arc = circle_arc(c, 2.0, a0, a1);
            REQUIRE(arc.points.size() == 3);
            REQUIRE(arc.weights.size() == 3);
            CHECK(close3(rational_point(arc, 0), c + 2.0 * glm::dvec3(std::cos(a0), std::sin(a0), 0), 1e-15, 4));
            CHECK(close3(rational_point(arc, 1), c + 2.0 * glm::dvec3(std::cos(a1), std::sin(a1), 0), 1e-15, 4));
            double prev = a0 - 1e-9;
            for (int k = 0; k <= 32; ++k) {
                const glm::dvec3 p = rational_point(arc, k / 32.0);
                const double r = glm::length(p - c), ang = std::atan2(p.y - c.y, p.x - c.x);
                INFO("arc " << a0 << " → " << a1 << " at t = " << k / 32.0 << ": " << str(p) << " at distance "
                            << num(r) << " from the centre (expected 2)");
                CHECK(std::abs(r - 2) <= 1e-14 * 2);
                CHECK(std::abs(p.z - 3.0) <= 1e-14);
                const double unwrapped = ang < prev - pi ? ang + 2 * pi : ang;
                CHECK(unwrapped >= prev - 1e-15);  // counter-clockwise
                prev = unwrapped;
            }
        }
        Rng rng(50);
        const Poly3 P = rng.poly(4);
        const RationalCurve same{P, {2.5, 2.5, 2.5, 2.5, 2.5}};
        for (double t : {0.0, 0.3, 0.5, 1.0}) CHECK(close3(rational_point(same, t), ref_point(P, t), 1e-14, 4));
        CHECK_THROWS_AS(circle_arc(c, 1.0, 0.0, 4.0), std::invalid_argument);
        CHECK_THROWS_AS(circle_arc(c, 1.0, 0.0, pi), std::invalid_argument);  // a1 − a0 = π: the tangents never meet
        CHECK_THROWS_AS(circle_arc(c, 1.0, 0.5, 0.5), std::invalid_argument);
        CHECK_THROWS_AS(circle_arc(c, 0.0, 0.0, 1.0), std::invalid_argument);
        CHECK_THROWS_AS(circle_arc(c, -1.0, 0.0, 1.0), std::invalid_argument);
        CHECK_THROWS_AS(circle_arc(c, std::numeric_limits<double>::infinity(), 0.0, 1.0), std::invalid_argument);
        CHECK_THROWS_AS(rational_point(RationalCurve{P, {1, 1}}, 0.5), std::invalid_argument);
        CHECK_THROWS_AS(rational_point(RationalCurve{P, {1, 1, 0, 1, 1}}, 0.5), std::invalid_argument);
    }

    TEST_CASE("de Boor: known values; clamped knots give the Bézier curve; random knot vectors" * geolab::points(2) *
              geolab::hint("Find the span t_k ≤ t < t_(k+1), then p rounds of (1 − α):α mixes with α = (t − t_i) / "
                           "(t_(i+p+1−r) − t_i). At the domain's end use the last non-empty span.")) {
        const BSpline uni{3, {0, 1, 2, 3, 4, 5, 6, 7}, {{0, 0, 0}, {6, 0, 0}, {6, 6, 0}, {0, 6, 6}}};
        const glm::dvec3 w3 = (uni.points[0] + 4.0 * uni.points[1] + uni.points[2]) / 6.0;
        const glm::dvec3 g3 = de_boor(uni, 3);
        INFO("uniform cubic at t = 3: expected (P0 + 4P1 + P2)/6 = " << str(w3) << ", got " << str(g3));
        CHECK(close3(g3, w3, 1e-15, 10));
        CHECK(close3(de_boor(uni, 4), (uni.points[1] + 4.0 * uni.points[2] + uni.points[3]) / 6.0, 1e-15, 10));
        Rng rng(51);
        for (int p = 1; p <= 5; ++p) {
            BSpline bz;
            bz.degree = p;
            bz.points = rng.poly(p);
            for (int i = 0; i <= p; ++i) bz.knots.push_back(0);
            for (int i = 0; i <= p; ++i) bz.knots.push_back(1);
            for (double t : {0.0, 0.25, 0.6, 1.0}) {
                const glm::dvec3 got = de_boor(bz, t);
                INFO("clamped degree " << p << " at t = " << t << ": expected the Bézier point " << str(ref_point(bz.points, t))
                                       << ", got " << str(got));
                CHECK(close3(got, ref_point(bz.points, t), 1e-14, 4));
            }
            for (int rep = 0; rep < 4; ++rep) {
                const BSpline s = random_bspline(rng, p, p + 1 + rep);
                const double lo = s.knots[p], hi = s.knots[s.points.size()];
                for (int k = 0; k <= 10; ++k) {
                    const double t = lo + (hi - lo) * k / 10.0;
                    const glm::dvec3 got = de_boor(s, t);
                    INFO("degree " << p << ", knots " << s.knots.size() << ", t = " << num(t) << ": expected "
                                   << str(ref_bspline(s, t)) << ", got " << str(got));
                    CHECK(close3(got, ref_bspline(s, t), 1e-12, 4));
                }
            }
        }
        CHECK_THROWS_AS(de_boor(uni, 2.5), std::invalid_argument);
        CHECK_THROWS_AS(de_boor(uni, 4.5), std::invalid_argument);  // the domain is [t_3, t_4] = [3, 4]
        CHECK_THROWS_AS(de_boor(uni, 4.000000000000001), std::invalid_argument);
        CHECK_THROWS_AS(de_boor(BSpline{3, {1, 0, 2, 3, 4, 5, 6, 7}, uni.points}, 3.5), std::invalid_argument);
        // degree 1 with knots 0, 1, 1, 2: the domain [t_1, t_2] = [1, 1] is empty
        CHECK_THROWS_AS(de_boor(BSpline{1, {0, 1, 1, 2}, {{0, 0, 0}, {1, 0, 0}}}, 1.0), std::invalid_argument);
        CHECK_THROWS_AS(de_boor(BSpline{0, {0, 1, 2, 3, 4}, uni.points}, 1.5), std::invalid_argument);
        CHECK_THROWS_AS(de_boor(BSpline{3, {std::nan(""), 1, 2, 3, 4, 5, 6, 7}, uni.points}, 3), std::invalid_argument);
        CHECK_THROWS_AS(de_boor(BSpline{3, {0, 1, 2}, uni.points}, 3), std::invalid_argument);
        CHECK_THROWS_AS(de_boor(BSpline{3, {0, 1, 2, 3, 5, 4, 6, 7}, uni.points}, 3), std::invalid_argument);
    }

    TEST_CASE("knot insertion: one more knot and point; the same curve" * geolab::points(1) *
              geolab::hint("Boehm: Q_i = (1 − α_i) P_(i−1) + α_i P_i for k − p + 1 ≤ i ≤ k, α_i = (t − t_i)/(t_(i+p) − t_i); "
                           "points before are kept, points after shift by one.")) {
        Rng rng(52);
        for (int p = 1; p <= 4; ++p)
            for (int rep = 0; rep < 4; ++rep) {
                const BSpline s = random_bspline(rng, p, p + 2 + rep);
                const double lo = s.knots[p], hi = s.knots[s.points.size()];
                const double tk = lo + (hi - lo) * rng.uniform(0, 0.999);
                CHECK_THROWS_AS(insert_knot(s, hi), std::invalid_argument);  // inside the domain only
                const BSpline r = insert_knot(s, tk);
                REQUIRE(r.knots.size() == s.knots.size() + 1);
                REQUIRE(r.points.size() == s.points.size() + 1);
                CHECK(std::is_sorted(r.knots.begin(), r.knots.end()));
                for (int k = 0; k <= 12; ++k) {
                    const double t = lo + (hi - lo) * k / 12.0;
                    INFO("degree " << p << ", inserted " << num(tk) << ", t = " << num(t) << ": before "
                                   << str(ref_bspline(s, t)) << ", after " << str(ref_bspline(r, t)));
                    CHECK(close3(ref_bspline(r, t), ref_bspline(s, t), 1e-12, 4));
                }
            }
    }
}
