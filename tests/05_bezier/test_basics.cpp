// Lab 05, Task 1: Bernstein polynomials, de Casteljau, the Bernstein form. Expected values: exact dyadic
// arithmetic and the Bernstein form in long double (helpers.hpp).
#include "helpers.hpp"

using namespace lab05;

TEST_SUITE("Task 1: basics") {
    TEST_CASE("bernstein: known values; non-negative on (0; 1); partition of unity; symmetry" * geolab::points(3) *
              geolab::hint("B_i^n(t) = C(n, i) t^i (1 − t)^(n − i); 0 when i < 0 or i > n (handout §2).")) {
        CHECK(bernstein(3, 1, 0.5) == 0.375);
        CHECK(bernstein(3, 0, 0.5) == 0.125);
        CHECK(bernstein(4, 2, 0.5) == 0.375);
        CHECK(bernstein(0, 0, 0.3) == 1.0);
        CHECK(bernstein(2, 2, 0.25) == 0.0625);
        CHECK(bernstein(5, 6, 0.5) == 0.0);
        CHECK(bernstein(5, -1, 0.5) == 0.0);
        for (int n = 1; n <= 20; ++n)
            for (int s = 0; s <= 16; ++s) {
                const double t = s / 16.0;
                double sum = 0;
                for (int i = 0; i <= n; ++i) {
                    const double b = bernstein(n, i, t), want = double(bern(n, i, t));
                    INFO("B_" << i << "^" << n << "(" << t << "): expected " << want << ", got " << b);
                    CHECK(b >= 0);
                    CHECK(std::abs(b - want) <= 1e-14 * (1 + want));
                    CHECK(std::abs(b - bernstein(n, n - i, 1 - t)) <= 1e-15);
                    sum += b;
                }
                INFO("Σ_i B_i^" << n << "(" << t << ") = " << num(sum) << ", expected 1");
                CHECK(std::abs(sum - 1) <= 1e-13);
            }
        CHECK_THROWS_AS(bernstein(-1, 0, 0.5), std::invalid_argument);
    }

    TEST_CASE("de Casteljau: the lecture's quiz (−8;4); (−4;4); (0;0); (4;−4) at t = 1/2 is (−2; 1.5)" *
              geolab::points(3) *
              geolab::hint("Repeated (1 − t):t interpolation of neighbouring points, n rounds (handout §2).")) {
        const Poly2 quiz{{-8, 4}, {-4, 4}, {0, 0}, {4, -4}};
        const glm::dvec2 got = de_casteljau(quiz, 0.5);
        INFO("quiz cubic at t = 1/2: expected (-2, 1.5), got " << str(got));
        CHECK(got.x == -2.0);
        CHECK(got.y == 1.5);
        // the same in 3D, lifted, and at the ends
        const glm::dvec3 g3 = de_casteljau(lift(quiz), 0.5);
        CHECK(g3 == glm::dvec3(-2, 1.5, 0));
        CHECK(de_casteljau(quiz, 0.0) == glm::dvec2(-8, 4));
        CHECK(de_casteljau(quiz, 1.0) == glm::dvec2(4, -4));
        // t = 1/4 exactly: (27·P0 + 27·P1 + 9·P2 + P3)/64 → x = (−216 − 108 + 0 + 4)/64 = −5, y = (108+108+0−4)/64
        const glm::dvec2 q = de_casteljau(quiz, 0.25);
        INFO("quiz cubic at t = 1/4: expected (-5, 3.3125), got " << str(q));
        CHECK(q.x == -5.0);
        CHECK(q.y == 3.3125);
    }

    TEST_CASE("de Casteljau: any degree in 2D and 3D; exact at dyadic t on dyadic points" * geolab::points(2) *
              geolab::hint("n rounds for n + 1 points; P_k^r = (1 − t) P_k^(r−1) + t P_(k+1)^(r−1). Degree 0 is the "
                           "point itself. Empty input: std::invalid_argument.")) {
        Rng rng(1);
        for (int n = 0; n <= 12; ++n)
            for (int rep = 0; rep < 4; ++rep) {
                const Poly3 P = rng.dyadic_poly(n);
                for (double t : {0.0, 0.125, 0.25, 0.5, 0.75, 1.0}) {
                    const glm::dvec3 want = ref_point(P, t), got = de_casteljau(P, t);
                    INFO("degree " << n << ", P = " << str(P) << ", t = " << t << ": expected " << str(want)
                                   << ", got " << str(got));
                    if (n <= 6) CHECK(got == want);  // dyadic: exact (long double reference rounds the same)
                    else CHECK(close3(got, want, 1e-13, scale_of(P)));
                    Poly2 P2;
                    for (const auto& p : P) P2.emplace_back(p.x, p.y);
                    const glm::dvec2 g2 = de_casteljau(P2, t);
                    CHECK(std::abs(g2.x - want.x) <= 1e-13 * (1 + scale_of(P)));
                    CHECK(std::abs(g2.y - want.y) <= 1e-13 * (1 + scale_of(P)));
                }
            }
        CHECK_THROWS_AS(de_casteljau(Poly3{}, 0.5), std::invalid_argument);
        CHECK_THROWS_AS(de_casteljau(Poly2{}, 0.5), std::invalid_argument);
    }

    TEST_CASE("de Casteljau triangle: row r has n + 1 − r points; each the (1 − t):t mix of the row above" *
              geolab::points(2) *
              geolab::hint("Row 0 is P itself; row n is the single point C(t). Check your loop bounds: an "
                           "off-by-one leaves a row too long or a point unmixed.")) {
        Rng rng(2);
        for (int n = 0; n <= 7; ++n)
            for (double t : {0.3, 0.5, 0.125}) {
                const Poly3 P = rng.dyadic_poly(n);
                const auto rows = de_casteljau_triangle(P, t);
                INFO("degree " << n << " at t = " << t << ", P = " << str(P));
                REQUIRE(rows.size() == std::size_t(n + 1));
                CHECK(rows[0] == P);
                for (int r = 1; r <= n; ++r) {
                    REQUIRE(rows[r].size() == std::size_t(n + 1 - r));
                    for (int k = 0; k <= n - r; ++k) {
                        const glm::dvec3 want = (1.0 - t) * rows[r - 1][k] + t * rows[r - 1][k + 1];
                        INFO("row " << r << " point " << k << ": expected " << str(want) << ", got "
                                    << str(rows[r][k]));
                        CHECK(close3(rows[r][k], want, 1e-15, scale_of(P)));
                    }
                }
                CHECK(close3(rows[n][0], ref_point(P, t), 1e-14, scale_of(P)));
            }
    }

    TEST_CASE("Bernstein form: agrees with the long double sum for degrees 1..12 in 2D and 3D" * geolab::points(2) *
              geolab::hint("Σ_k B_k^n(t) P_k, with your bernstein(n, k, t).")) {
        Rng rng(3);
        for (int n = 1; n <= 12; ++n)
            for (int rep = 0; rep < 5; ++rep) {
                const Poly3 P = rng.poly(n);
                const double t = rng.uniform(0, 1);
                const glm::dvec3 want = ref_point(P, t), got = evaluate_bernstein(P, t);
                INFO("degree " << n << " at t = " << num(t) << ": expected " << str(want) << ", got " << str(got));
                CHECK(close3(got, want, 1e-12, scale_of(P)));
                Poly2 P2;
                for (const auto& p : P) P2.emplace_back(p.z, p.x);
                const glm::dvec2 g2 = evaluate_bernstein(P2, t);
                CHECK(std::abs(g2.x - want.z) <= 1e-12 * (1 + scale_of(P)));
                CHECK(std::abs(g2.y - want.x) <= 1e-12 * (1 + scale_of(P)));
            }
        CHECK_THROWS_AS(evaluate_bernstein(Poly3{}, 0.5), std::invalid_argument);
    }
}
