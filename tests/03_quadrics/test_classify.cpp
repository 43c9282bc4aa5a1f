// Lab 03, Task 3: classification. Every input is built from a canonical form, so its type is known by construction.
#include "helpers.hpp"

using namespace lab03;

namespace {
std::string name(QuadricType t) { return type_name(t); }  // given code

void expect_type(const glm::dmat4& Q, QuadricType want, const std::string& what) {
    QuadricType got{};
    try {
        got = classify(Q);
    } catch (const geolab::NotImplemented&) {
        throw;
    } catch (const std::exception& e) {
        FAIL_CHECK(what << ": Q = " << str(Q) << ": expected " << name(want) << ", but classify threw: " << e.what());
        return;
    }
    CHECK_MESSAGE(got == want, what << ": Q = " << str(Q) << ": expected " << name(want) << ", got " << name(got));
}
}  // namespace

TEST_SUITE("Task 3: classification") {
    TEST_CASE("classify: the canonical form of each of the 17 types" * geolab::points(3) *
              geolab::hint("Decide by r3 = rank A, r4 = rank Q, whether A's non-zero eigenvalues agree in sign, and the "
                           "signs of Q's eigenvalues (handout §5's decision tree).")) {
        for (int i = 0; i < n_types; ++i) {
            expect_type(to_glm(canonical(type_at(i), 1, 1, 1)), type_at(i), "canonical, unit axes");
            expect_type(to_glm(canonical(type_at(i), 0.5, 2, 1.5)), type_at(i), "canonical, axes 0.5 2 1.5");
        }
    }

    TEST_CASE("classify: the type does not change under random rigid motions" * geolab::points(4) *
              geolab::hint("Ranks and eigenvalue signs are what survive a change of coordinates; entries of Q and the "
                           "sign of single entries do not. Judge zero eigenvalues relative to the largest one.")) {
        Rng rng(31);
        for (int i = 0; i < n_types; ++i)
            for (int n = 0; n < 20; ++n) {
                double a, b, c;
                random_axes(rng, a, b, c);
                const Mat4L M = similarity(rng, 1.0, 2.0);
                expect_type(to_glm(moved(canonical(type_at(i), a, b, c), M)), type_at(i),
                            "canonical moved by a rigid motion");
            }
    }

    TEST_CASE("classify: multiplying Q by a negative (or positive) number keeps the type" * geolab::points(2) *
              geolab::hint("−Q has the same surface: compare sign PATTERNS (do A's eigenvalues agree? how many of Q's are "
                           "positive vs negative, up to swapping), never a sign itself.")) {
        Rng rng(32);
        for (int i = 0; i < n_types; ++i)
            for (double k : {-1.0, -3.5, -0.01, 250.0, -1e4, 1e-15, -1e15}) {
                const Mat4L M = similarity(rng, 1.0, 1.0);
                const Mat4L Q = moved(canonical(type_at(i), 1.2, 0.7, 1.9), M) * LD(k);
                expect_type(to_glm(Q), type_at(i), "canonical moved and multiplied by " + std::to_string(k));
            }
    }

    TEST_CASE("classify: real and imaginary ellipsoids; elliptic cylinders and parallel planes are told apart" *
              geolab::points(3) *
              geolab::hint("Ranks and A's signs are the same for x² + y² = 1 and x² + y² = −1 (and for x² = 1 and x² = "
                           "−1): only the signs of the 4×4's eigenvalues differ. Both signs of Q must be handled.")) {
        Rng rng(33);
        using T = QuadricType;
        const std::pair<T, T> pairs[] = {{T::real_ellipsoid, T::imaginary_ellipsoid},
                                         {T::real_elliptic_cylinder, T::imaginary_elliptic_cylinder},
                                         {T::real_parallel_planes, T::imaginary_parallel_planes},
                                         {T::real_intersecting_planes, T::imaginary_intersecting_planes},
                                         {T::real_cone, T::imaginary_cone}};
        for (auto [re, im] : pairs)
            for (int n = 0; n < 15; ++n) {
                double a, b, c;
                random_axes(rng, a, b, c);
                const double s = rng.uniform(0.3, 3);
                const LD sign = n % 2 ? -1 : 1;
                const Mat4L M = similarity(rng, s, 2.0);
                expect_type(to_glm(sign * moved(canonical(re, a, b, c), M)), re, "moved and scaled by " + std::to_string(s));
                expect_type(to_glm(sign * moved(canonical(im, a, b, c), M)), im, "moved and scaled by " + std::to_string(s));
            }
    }

    TEST_CASE("classify: a zero quadratic part or a non-finite entry is rejected" * geolab::points(1) *
              geolab::hint("2x + 1 = 0 is a plane, not a quadric: throw std::invalid_argument; also for NaN entries.")) {
        glm::dmat4 plane(0.0);
        plane[0][3] = plane[3][0] = 1;
        plane[3][3] = 1;
        CHECK_THROWS_AS(classify(plane), std::invalid_argument);
        CHECK_THROWS_AS(classify(glm::dmat4(0.0)), std::invalid_argument);
        glm::dmat4 nan = to_glm(canonical(QuadricType::real_ellipsoid, 1, 1, 1));
        nan[1][1] = std::nan("");
        CHECK_THROWS_AS(classify(nan), std::invalid_argument);
        for (auto [c, r] : {std::pair{3, 0}, std::pair{0, 3}, std::pair{3, 3}, std::pair{2, 3}}) {
            glm::dmat4 bad = to_glm(canonical(QuadricType::real_ellipsoid, 1, 1, 1));
            bad[c][r] = INFINITY;
            INFO("an infinite entry at [" << c << "][" << r << "] must be rejected");
            CHECK_THROWS_AS(classify(bad), std::invalid_argument);
        }
        expect_type(to_glm(canonical(QuadricType::real_ellipsoid, 1, 1, 1)), QuadricType::real_ellipsoid,
                    "unit sphere after the rejected inputs");
        for (int c = 0; c < 4; ++c)  // a NaN at every position
            for (int r = 0; r < 4; ++r) {
                glm::dmat4 bad = to_glm(canonical(QuadricType::hyperboloid_one_sheet, 1, 2, 3));
                bad[c][r] = std::nan("");
                INFO("a NaN at [" << c << "][" << r << "] must be rejected");
                CHECK_THROWS_AS(classify(bad), std::invalid_argument);
            }
    }

    TEST_CASE("classify: the rank tolerance is 1e-9 of the largest |eigenvalue|; exactly" * geolab::points(1) *
              geolab::hint("An eigenvalue counts as zero when |λ| <= 1e-9 · max |λ| of the same matrix (A for r3, Q for "
                           "r4): 1.5e-9 counts, 0.5e-9 does not, at any overall scale of Q.")) {
        using T = QuadricType;
        for (double k : {1.0, 1e-12, 1e9}) {
            glm::dmat4 Q(0.0);  // x² + y² + λ z² = 1, scaled by k
            Q[0][0] = Q[1][1] = k;
            Q[3][3] = -k;
            Q[2][2] = 1.5e-9 * k;
            expect_type(Q, T::real_ellipsoid, "x² + y² + 1.5e-9 z² = 1 (times " + std::to_string(k) + ")");
            Q[2][2] = 0.5e-9 * k;
            expect_type(Q, T::real_elliptic_cylinder, "x² + y² + 0.5e-9 z² = 1 (times " + std::to_string(k) + ")");
            Q[2][2] = -1.5e-9 * k;
            expect_type(Q, T::hyperboloid_one_sheet, "x² + y² − 1.5e-9 z² = 1 (times " + std::to_string(k) + ")");
        }
    }
}  // TEST_SUITE
