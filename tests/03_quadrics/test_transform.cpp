// Lab 03, Task 2: transforms. Expected values: closed forms, and M⁻ᵀQM⁻¹ computed here with Eigen in long double.
#include "helpers.hpp"

using namespace lab03;

namespace {
// Checks that every point of the canonical surface, moved by M, lies on got = transform_quadric(Q, M).
void check_points_follow(QuadricType t, double a, double b, double c, const Mat4L& M, const glm::dmat4& got, Rng& rng,
                         const std::string& what) {
    const double qn = max_abs(got);
    // (every point lies on the zero matrix: the transformed quadric must be one)
    CHECK_MESSAGE(qn > 0, what << ": the transformed " << type_name(t) << " is the zero matrix");
    for (int n = 0; n < 12; ++n) {
        glm::dvec3 p;
        if (!canonical_point(t, a, b, c, rng.uniform(0, 1), rng.uniform(0, 1), p)) return;
        const glm::dvec3 y = apply(M, p);
        const double v = double(value_ld(got, y));
        const double scale = qn * std::max(1.0, glm::dot(y, y));
        CHECK_MESSAGE(std::abs(v) <= 1e-10 * scale, what << ": the point " << str(p) << " of the canonical "
                                                         << type_name(t) << " moves to " << str(y)
                                                         << ", where XᵀQ'X should be 0 but is " << v);
    }
}
}  // namespace

TEST_SUITE("Task 2: transforms") {
    TEST_CASE("transform: moving and scaling the unit sphere gives the sphere's equation about its new centre" *
              geolab::points(2) *
              geolab::hint("Q' = M⁻ᵀ Q M⁻¹ (x on Q ⇔ M x on Q'): use the INVERSE of M. For x ↦ s x + t the unit sphere "
                           "becomes |x − t|² = s²: a = 1/s², p = −t_x/s², d = |t|²/s² − 1.")) {
        const glm::dmat4 S = matrix_of({1, 1, 1, 0, 0, 0, 0, 0, 0, -1});
        for (auto [s, t] : {std::pair{1.0, glm::dvec3{2, 0, 0}}, std::pair{2.0, glm::dvec3{0, 0, 0}},
                            std::pair{0.5, glm::dvec3{1, -2, 3}}, std::pair{3.0, glm::dvec3{-1, 0.5, 0.25}}}) {
            glm::dmat4 M(s);
            M[3] = glm::dvec4(t, 1.0);
            const glm::dmat4 got = transform_quadric(S, M);
            const double is2 = 1 / (s * s);
            const glm::dmat4 want = matrix_of({is2, is2, is2, 0, 0, 0, -t.x * is2, -t.y * is2, -t.z * is2,
                                               glm::dot(t, t) * is2 - 1});
            INFO("unit sphere moved by x -> " << s << " x + " << str(t) << ": expected Q' = " << str(want) << ", got "
                                              << str(got));
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) CHECK(close(got[c][r], want[c][r], 1e-12, 1.0));
        }
    }

    TEST_CASE("transform: points on a surface map to points on the transformed surface; for random affine maps" *
              geolab::points(4) *
              geolab::hint("Check on paper with M a pure translation first; then make sure you invert the whole affine "
                           "map (linear part AND translation), not just transpose it.")) {
        Rng rng(21);
        for (int i = 0; i < n_types; ++i) {
            for (int n = 0; n < 4; ++n) {
                double a, b, c;
                random_axes(rng, a, b, c);
                const QuadricType t = type_at(i);
                const Mat4L M = affine(rng);
                const glm::dmat4 got = transform_quadric(to_glm(canonical(t, a, b, c)), to_glm(M));
                check_points_follow(t, a, b, c, M, got, rng, "affine map " + str(to_glm(M)));
            }
        }
    }

    TEST_CASE("transform: the result equals M⁻ᵀ Q M⁻¹ entry by entry and is symmetric" * geolab::points(3) *
              geolab::hint("Symmetrize the product ((R + Rᵀ)/2): rounding makes it slightly asymmetric, and classify "
                           "and to_coefficients expect a symmetric Q.")) {
        Rng rng(22);
        for (int n = 0; n < 40; ++n) {
            Mat4L Q;
            for (int r = 0; r < 4; ++r)
                for (int c = r; c < 4; ++c) Q(r, c) = Q(c, r) = rng.uniform(-2, 2);
            const Mat4L M = affine(rng);
            const glm::dmat4 want = to_glm(moved(Q, M)), got = transform_quadric(to_glm(Q), to_glm(M));
            const double scale = max_abs(want);
            INFO("Q = " << str(to_glm(Q)) << ", M = " << str(to_glm(M)) << ": expected " << str(want) << ", got "
                        << str(got));
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) {
                    CHECK(std::abs(got[c][r] - want[c][r]) <= 1e-11 * scale);
                    CHECK(got[c][r] == got[r][c]);
                }
        }
    }

    TEST_CASE("transform: a map that is not affine or not invertible is rejected" * geolab::points(1) *
              geolab::hint("Check the last row (0, 0, 0, 1) and the determinant of the 3×3 part relative to its size; "
                           "throw std::invalid_argument.")) {
        const glm::dmat4 S = matrix_of({1, 1, 1, 0, 0, 0, 0, 0, 0, -1});
        glm::dmat4 P(1.0);
        P[2][3] = 0.5;  // a projective row
        CHECK_THROWS_AS(transform_quadric(S, P), std::invalid_argument);
        glm::dmat4 Z(1.0);
        Z[1] = glm::dvec4(2, 0, 0, 0);  // column 1 = 2 × column 0: singular
        Z[0] = glm::dvec4(1, 0, 0, 0);
        CHECK_THROWS_AS(transform_quadric(S, Z), std::invalid_argument);
        for (int c = 0; c < 4; ++c) {  // any entry of the last row off (0, 0, 0, 1)
            glm::dmat4 B(1.0);
            B[c][3] = c == 3 ? 2.0 : 0.25;
            INFO("M with last row entry [" << c << "][3] = " << B[c][3] << " is not affine");
            CHECK_THROWS_AS(transform_quadric(S, B), std::invalid_argument);
        }
        // singular relative to its size: |det| <= 1e-12 * (largest |entry|)^3, wherever the largest entry is
        for (int big = 0; big < 3; ++big)
            for (bool in_row : {false, true}) {
                glm::dmat4 L(1.0);
                L[big][big] = 100;  // on the diagonal: its row and its column
                if (in_row) {      // or off the diagonal, in row `big` (column (big + 1) % 3)
                    L[big][big] = 1;
                    L[(big + 1) % 3][big] = 100;
                }
                L[(big + 2) % 3][(big + 2) % 3] = 5e-10;  // det = 5e-8 <= 1e-12 * 100³ = 1e-6: singular
                INFO("M = " << str(L) << " has det " << glm::determinant(glm::dmat3(L))
                            << " <= 1e-12 * 100^3: singular for its size");
                CHECK_THROWS_AS(transform_quadric(S, L), std::invalid_argument);
            }
        glm::dmat4 edge(1.0);  // det exactly 1e-12 * 1^3: singular (<=); 1.5e-12: invertible
        edge[2][2] = 1e-12;
        CHECK_THROWS_AS(transform_quadric(S, edge), std::invalid_argument);
        edge[2][2] = 1.5e-12;
        CHECK_NOTHROW(transform_quadric(S, edge));
        for (double sc : {1e-3, 1e-5, 1e4}) {  // uniform scalings are invertible at every size
            glm::dmat4 U(sc);
            U[3][3] = 1;
            INFO("x -> " << sc << " x is invertible");
            CHECK_NOTHROW(transform_quadric(S, U));
        }
        glm::dmat4 tiny(1e-3);  // a uniform scaling by 1e-3 is invertible (det relative to the scale)
        tiny[3][3] = 1;
        const glm::dmat4 got = transform_quadric(S, tiny);
        CHECK_MESSAGE(close(got[0][0], 1e6, 1e-12), "x -> 1e-3 x maps the unit sphere to x² + y² + z² = 1e-6: a = 1e6, got "
                                                         << got[0][0]);
    }
}  // TEST_SUITE
