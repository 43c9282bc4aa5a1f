// Lab 03, Task 1: the matrix form. Expected values from the lecture's polynomial written out in long double.
#include "helpers.hpp"

using namespace lab03;

namespace {
Coefficients random_coefficients(Rng& rng) {
    Coefficients k;
    double* v[10] = {&k.a, &k.b, &k.c, &k.f, &k.g, &k.h, &k.p, &k.q, &k.r, &k.d};
    for (double* x : v) *x = rng.uniform(-3, 3);
    return k;
}
}  // namespace

TEST_SUITE("Task 1: the matrix form") {
    TEST_CASE("matrix form: to_matrix puts each coefficient where XᵀQX gives the lecture's term" * geolab::points(3) *
              geolab::hint("Off-diagonal entries are HALF the cross coefficients' factors: the equation has 2f yz, and "
                           "XᵀQX counts Q[1][2] twice (Q[1][2] yz + Q[2][1] zy). So Q[1][2] = Q[2][1] = f, not 2f.")) {
        const char* names[10] = {"a", "b", "c", "f", "g", "h", "p", "q", "r", "d"};
        for (int i = 0; i < 10; ++i) {
            Coefficients k;
            double* v[10] = {&k.a, &k.b, &k.c, &k.f, &k.g, &k.h, &k.p, &k.q, &k.r, &k.d};
            *v[i] = 1.5;
            const glm::dmat4 expected = matrix_of(k), got = to_matrix(k);
            INFO("only " << names[i] << " = 1.5: expected Q = " << str(expected) << ", got " << str(got));
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) CHECK(got[c][r] == expected[c][r]);
        }
        Rng rng(11);
        for (int n = 0; n < 20; ++n) {
            const Coefficients k = random_coefficients(rng);
            const glm::dmat4 got = to_matrix(k);
            for (int m = 0; m < 5; ++m) {
                const glm::dvec3 x{rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2)};
                const double want = double(poly(k, x)), have = double(value_ld(got, x));
                CHECK_MESSAGE(close(have, want, 1e-12, 10), "coefficients " << str(k) << " at " << str(x)
                                                                             << ": the polynomial is " << want
                                                                             << " but XᵀQX of to_matrix is " << have);
            }
        }
    }

    TEST_CASE("matrix form: to_coefficients inverts to_matrix and reads a non-symmetric M by its symmetric part" *
              geolab::points(2) *
              geolab::hint("h = (Q[0][1] + Q[1][0]) / 2 and so on; a, b, c, d are the diagonal. Reject NaN and inf "
                           "entries with std::invalid_argument.")) {
        Rng rng(12);
        for (int n = 0; n < 20; ++n) {
            const Coefficients k = random_coefficients(rng);
            const Coefficients got = to_coefficients(matrix_of(k));
            INFO("Q = " << str(matrix_of(k)) << ": expected " << str(k) << ", got " << str(got));
            CHECK(got.a == k.a);
            CHECK(got.b == k.b);
            CHECK(got.c == k.c);
            CHECK(got.d == k.d);
            CHECK(got.f == k.f);
            CHECK(got.g == k.g);
            CHECK(got.h == k.h);
            CHECK(got.p == k.p);
            CHECK(got.q == k.q);
            CHECK(got.r == k.r);
        }
        glm::dmat4 M(0.0);  // x² + 4xy written as Q[0][1] = 4, Q[1][0] = 0: h = 2
        M[0][0] = 1;
        M[1][0] = 4;  // column 1, row 0
        M[2][3] = 6;  // column 2, row 3: 6 z, r = 3
        const Coefficients got = to_coefficients(M);
        INFO("non-symmetric M = " << str(M) << " (x² + 4xy + 6z): got " << str(got));
        CHECK(got.a == 1);
        CHECK(got.h == 2);
        CHECK(got.r == 3);
        CHECK(got.g == 0);
        CHECK(got.p == 0);
        for (int c = 0; c < 4; ++c)  // a NaN or an infinity at every position, diagonal and off-diagonal
            for (int r = 0; r < 4; ++r)
                for (double v : {std::nan(""), double(INFINITY), -double(INFINITY)}) {
                    glm::dmat4 bad = matrix_of(random_coefficients(rng));
                    bad[c][r] = v;
                    INFO("Q[" << c << "][" << r << "] = " << v << " must be rejected with std::invalid_argument");
                    CHECK_THROWS_AS(to_coefficients(bad), std::invalid_argument);
                }
    }

    TEST_CASE("matrix form: evaluate is the lecture's polynomial at any point" * geolab::points(2) *
              geolab::hint("X = (x, y, z, 1); the value is X · (Q X). The linear terms and d come from the last row and "
                           "column: do not drop them.")) {
        Rng rng(13);
        for (int n = 0; n < 50; ++n) {
            const Coefficients k = random_coefficients(rng);
            const glm::dmat4 Q = matrix_of(k);
            const glm::dvec3 x{rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)};
            const double want = double(poly(k, x)), got = evaluate(Q, x);
            CHECK_MESSAGE(close(got, want, 1e-12, 100), "coefficients " << str(k) << " at " << str(x) << ": expected "
                                                                          << want << ", got " << got);
        }
        const Coefficients sphere{1, 1, 1, 0, 0, 0, 0, 0, 0, -1};
        CHECK_MESSAGE(std::abs(evaluate(matrix_of(sphere), {0.6, 0.0, 0.8})) <= 1e-15,
                      "the unit sphere at (0.6, 0, 0.8) is on the surface");
        CHECK(evaluate(matrix_of(sphere), {0, 0, 0}) == -1.0);
    }

    TEST_CASE("matrix form: gradient is 2·(Q X) without its last entry; linear terms included" * geolab::points(3) *
              geolab::hint("∂/∂x of the polynomial is 2ax + 2hy + 2gz + 2p: the first entry of 2·Q·X with X = (x, y, z, "
                           "1). Forgetting the factor 2 or the p, q, r column fails here.")) {
        Rng rng(14);
        for (int n = 0; n < 50; ++n) {
            const Coefficients k = random_coefficients(rng);
            const glm::dvec3 x{rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)};
            const glm::dvec3 want{2 * (k.a * x.x + k.h * x.y + k.g * x.z + k.p), 2 * (k.h * x.x + k.b * x.y + k.f * x.z + k.q),
                                  2 * (k.g * x.x + k.f * x.y + k.c * x.z + k.r)};
            const glm::dvec3 got = gradient(matrix_of(k), x);
            const double scale = std::max(1.0, glm::length(want));
            CHECK_MESSAGE(glm::length(got - want) <= 1e-12 * scale,
                          "coefficients " << str(k) << " at " << str(x) << ": expected " << str(want) << ", got " << str(got));
        }
    }
}  // TEST_SUITE
