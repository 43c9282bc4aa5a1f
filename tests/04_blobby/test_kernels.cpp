// Lab 04, Task 1: the kernels. Expected values from the formulas expanded in r, in long double (helpers.hpp).
#include "helpers.hpp"

using namespace lab04;

namespace {
const Kernel kernels[3] = {Kernel::blinn, Kernel::nishimura, Kernel::wyvill};
Blob blob(double b, double a, double R) {
    Blob x;
    x.strength = b;
    x.a = a;
    x.radius = R;
    return x;
}
void check_density(Kernel k, const Blob& b, double r) {
    const double want = double(ref_density(k, b, r)), got = density(k, b, r);
    CHECK_MESSAGE(close(got, want, 1e-12, std::abs(b.strength)),
                  str(k) << " " << str(b) << " at r = " << r << ": expected D = " << want << ", got " << got);
}
}  // namespace

TEST_SUITE("Task 1: the kernels") {
    TEST_CASE("kernels: Blinn's b·exp(−a r²) for several a; b and r" * geolab::points(3) *
              geolab::hint("D(r) = b * exp(-a * r * r): a is the falloff, b the strength (negative b subtracts).")) {
        for (double a : {0.5, 1.0, 3.0})
            for (double b : {1.0, 2.5, -0.7})
                for (double r : {0.0, 0.1, 0.5, 0.832555, 1.0, 2.0, 4.0}) check_density(Kernel::blinn, blob(b, a, 1), r);
        CHECK_MESSAGE(close(density(Kernel::blinn, blob(1, 1, 1), std::sqrt(std::log(2.0))), 0.5, 1e-14),
                      "a = b = 1: D(√ln2) must be exactly 1/2");
    }

    TEST_CASE("kernels: Nishimura's metaball: two pieces meeting at R/3; zero from R on" * geolab::points(3) *
              geolab::hint("b(1 − 3r²/R²) for r ≤ R/3, (3b/2)(1 − r/R)² for R/3 ≤ r ≤ R, 0 beyond R. Both pieces give "
                           "2b/3 at R/3.")) {
        for (double R : {0.5, 1.0, 2.0})
            for (double b : {1.0, 2.0, -1.0})
                for (double s : {0.0, 0.1, 0.2, 1.0 / 3.0, 0.4, 0.6, 0.9, 0.999, 1.0, 1.2, 3.0})
                    check_density(Kernel::nishimura, blob(b, 1, R), s * R);
        const Blob b = blob(1.5, 1, 0.9);
        CHECK_MESSAGE(close(density(Kernel::nishimura, b, 0.3), 1.0, 1e-12), "D(R/3) = 2b/3 = 1 for b = 1.5, R = 0.9");
    }

    TEST_CASE("kernels: Wyvill's soft object C(r/R); with C(R/2) = 1/2" * geolab::points(3) *
              geolab::hint("D(r) = b·C(r/R), C(s) = 1 − 22/9 s² + 17/9 s⁴ − 4/9 s⁶ for s ≤ 1, else 0.")) {
        for (double R : {0.25, 1.0, 3.0}) {
            const Blob b = blob(1, 1, R);
            CHECK_MESSAGE(close(density(Kernel::wyvill, b, R / 2), 0.5, 1e-14), "R = " << R << ": C(R/2) must be 1/2, got "
                                                                                      << density(Kernel::wyvill, b, R / 2));
            CHECK_MESSAGE(density(Kernel::wyvill, b, 0) == 1.0, "C(0) = 1");
            CHECK_MESSAGE(std::abs(density(Kernel::wyvill, b, R)) < 1e-14, "C(R) = 0, got " << density(Kernel::wyvill, b, R));
            for (double s : {0.05, 0.3, 0.7, 0.95, 1.5, 10.0}) check_density(Kernel::wyvill, blob(-2, 1, R), s * R);
        }
    }

    TEST_CASE("kernels: density_derivative is dD/dr (finite differences and the expanded formulas)" * geolab::points(3) *
              geolab::hint("Differentiate each piece; the derivative is 0 at r = 0 and beyond the support.")) {
        Rng rng(41);
        for (Kernel k : kernels)
            for (int n = 0; n < 60; ++n) {
                const Blob b = blob(rng.uniform(-2, 2), rng.uniform(0.5, 4), rng.uniform(0.3, 2));
                const double r = rng.uniform(0.0, 1.3 * (k == Kernel::blinn ? 1.5 : b.radius));
                const double want = double(ref_derivative(k, b, r)), got = density_derivative(k, b, r);
                const double h = 1e-6 * std::max(1.0, b.radius);
                const double fd = r > h ? (density(k, b, r + h) - density(k, b, r - h)) / (2 * h) : want;
                const double scale = std::abs(b.strength) / std::min(b.radius, 1.0) * (1 + b.a);
                CHECK_MESSAGE(close(got, want, 1e-10, scale), str(k) << " " << str(b) << " at r = " << r
                                                                       << ": expected dD/dr = " << want << ", got " << got);
                CHECK_MESSAGE(close(got, fd, 1e-5, scale), str(k) << " " << str(b) << " at r = " << r
                                                                    << ": finite differences of your density give " << fd
                                                                    << ", your derivative " << got);
            }
        for (Kernel k : kernels) CHECK_MESSAGE(density_derivative(k, blob(1, 2, 1), 0.0) == 0.0, str(k) << ": D'(0) = 0");
    }

    TEST_CASE("kernels: support_radius; and D is exactly zero beyond it" * geolab::points(2) *
              geolab::hint("R for nishimura and wyvill, +infinity for blinn. D(r) = 0 for every r ≥ R.")) {
        for (double R : {0.2, 1.0, 7.0}) {
            const Blob b = blob(1.3, 2, R);
            CHECK(std::isinf(support_radius(Kernel::blinn, b)));
            for (Kernel k : {Kernel::nishimura, Kernel::wyvill}) {
                CHECK_MESSAGE(support_radius(k, b) == R, str(k) << " R = " << R << ": support radius " << support_radius(k, b));
                CHECK_MESSAGE(density(k, b, R) == 0.0, str(k) << " R = " << R << ": D(R) must be exactly 0, got " << density(k, b, R));
                CHECK_MESSAGE(density_derivative(k, b, R) == 0.0, str(k) << " R = " << R << ": D'(R) must be exactly 0, got "
                                                                        << density_derivative(k, b, R));
                CHECK_MESSAGE(density(k, b, R * 1.0000001) == 0.0, str(k) << ": D just beyond R must be 0");
                CHECK_MESSAGE(density(k, b, 2 * R) == 0.0, str(k) << ": D(2R) must be 0");
                CHECK_MESSAGE(density(k, b, 0.99 * R) > 0.0, str(k) << ": D(0.99 R) must be > 0 (support too small?)");
                CHECK_MESSAGE(density_derivative(k, b, 0.99 * R) < 0.0, str(k) << ": D'(0.99 R) must be < 0");
                CHECK_MESSAGE(density_derivative(k, b, 1.01 * R) == 0.0, str(k) << ": D'(1.01 R) must be 0");
            }
        }
    }

    TEST_CASE("kernels: isolated_radius solves D(r) = T; Blinn a = b = 1; T = 0.5 gives √ln2 = 0.832555" *
              geolab::points(3) *
              geolab::hint("Blinn: √(ln(b/T)/a). Nishimura: pick the piece by comparing T with 2b/3. Wyvill: C is "
                           "decreasing on [0, 1], so bisection or Newton on s works. T ≥ b: 0.")) {
        const double r0 = isolated_radius(Kernel::blinn, blob(1, 1, 1), 0.5);
        CHECK_MESSAGE(std::abs(r0 - 0.832555) < 5e-7, "expected √ln2 = 0.832555, got " << r0);
        CHECK_MESSAGE(close(isolated_radius(Kernel::wyvill, blob(1, 1, 2), 0.5), 1.0, 1e-12), "wyvill R = 2, T = b/2: r = R/2 = 1");
        CHECK_MESSAGE(close(isolated_radius(Kernel::nishimura, blob(1.5, 1, 0.9), 1.0), 0.3, 1e-12), "nishimura T = 2b/3: r = R/3");
        Rng rng(42);
        for (Kernel k : kernels)
            for (int n = 0; n < 40; ++n) {
                const Blob b = blob(rng.uniform(0.5, 3), rng.uniform(0.5, 4), rng.uniform(0.3, 2));
                const double T = b.strength * rng.uniform(0.02, 0.98);
                const double r = isolated_radius(k, b, T);
                const double D = double(ref_density(k, b, r));
                const double slope = std::abs(double(ref_derivative(k, b, r))) + 1e-300;
                CHECK_MESSAGE(std::abs(D - T) / slope < 1e-9 * std::max(1.0, b.radius),
                              str(k) << " " << str(b) << " T = " << T << ": your r = " << r << " has D(r) = " << D
                                     << " (off by " << std::abs(D - T) / slope << " in r)");
            }
        for (Kernel k : kernels) CHECK_MESSAGE(isolated_radius(k, blob(1, 1, 1), 1.0) == 0.0, str(k) << ": T = b gives 0");
    }

    TEST_CASE("kernels: negative blobs have negative density and no surface of their own" * geolab::points(1)) {
        for (Kernel k : kernels) {
            const Blob b = blob(-1, 1, 1);
            CHECK_MESSAGE(density(k, b, 0.3) < 0, str(k) << ": a negative blob's D must be < 0 inside its support");
            CHECK_MESSAGE(isolated_radius(k, b, 0.5) == 0.0, str(k) << ": b < T has no surface: 0");
        }
    }

    TEST_CASE("kernels: invalid input throws std::invalid_argument" * geolab::points(2) *
              geolab::hint("Reject r < 0, NaN, a ≤ 0 (blinn), R ≤ 0 (nishimura, wyvill), T ≤ 0 in isolated_radius.")) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        for (Kernel k : kernels) {
            CHECK_THROWS_AS(density(k, blob(1, 1, 1), -0.1), std::invalid_argument);
            CHECK_THROWS_AS(density(k, blob(1, 1, 1), nan), std::invalid_argument);
            CHECK_THROWS_AS(density_derivative(k, blob(nan, 1, 1), 0.5), std::invalid_argument);
            CHECK_THROWS_AS(isolated_radius(k, blob(1, 1, 1), 0.0), std::invalid_argument);
            CHECK_THROWS_AS(isolated_radius(k, blob(1, 1, 1), -1.0), std::invalid_argument);
        }
        CHECK_THROWS_AS(density(Kernel::blinn, blob(1, 0, 1), 0.5), std::invalid_argument);
        CHECK_THROWS_AS(density(Kernel::wyvill, blob(1, 1, 0), 0.5), std::invalid_argument);
        CHECK_THROWS_AS(support_radius(Kernel::nishimura, blob(1, 1, -2)), std::invalid_argument);
        // valid input is no error ("reject everything" is not the contract)
        for (Kernel k : kernels) CHECK(std::isfinite(density(k, blob(1, 1, 1), 0.5)));
    }
}
