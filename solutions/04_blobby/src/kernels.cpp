// Task 1: the kernels (handout §2).
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "geolab/blobby.hpp"

namespace geolab::blobby {

namespace {
// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.

bool finite_blob(const Blob& b) {
    return std::isfinite(b.strength) && std::isfinite(b.a) && std::isfinite(b.radius) && std::isfinite(b.center.x) &&
           std::isfinite(b.center.y) && std::isfinite(b.center.z);
}

// Throws the error of an invalid blob (out of line: check_blob runs at every kernel evaluation).
[[noreturn, gnu::cold, gnu::noinline]] void invalid_blob(const std::string& why) {
    throw std::invalid_argument("blob: " + why);
}

void check_blob(Kernel kernel, const Blob& b) {
    if (!finite_blob(b)) invalid_blob("a parameter is not finite");
    if (kernel == Kernel::blinn && !(b.a > 0))
        invalid_blob("Blinn's falloff a must be > 0 (got " + std::to_string(b.a) + ")");
    if (kernel != Kernel::blinn && !(b.radius > 0))
        invalid_blob("the support radius R must be > 0 (got " + std::to_string(b.radius) + ")");
}

void check_r(double r) {
    if (!(r >= 0) || !std::isfinite(r)) throw std::invalid_argument("density: r must be finite and >= 0");
}

// C(s) of the soft objects and its derivative dC/ds.
double wyvill_c(double s) {
    const double u = s * s;
    return 1.0 + u * (-22.0 / 9.0 + u * (17.0 / 9.0 - u * 4.0 / 9.0));
}
double wyvill_dc(double s) {
    const double u = s * s;
    return s * (-44.0 / 9.0 + u * (68.0 / 9.0 - u * 24.0 / 9.0));
}

// END SOLUTION
}  // namespace

double density(Kernel kernel, const Blob& blob, double r) {
    // BEGIN SOLUTION
    check_blob(kernel, blob);
    check_r(r);
    const double b = blob.strength, R = blob.radius;
    switch (kernel) {
        case Kernel::blinn: return b * std::exp(-blob.a * r * r);
        case Kernel::nishimura:
            if (r <= R / 3) return b * (1.0 - 3.0 * r * r / (R * R));
            if (r <= R) return 1.5 * b * (1.0 - r / R) * (1.0 - r / R);
            return 0.0;
        case Kernel::wyvill: return r < R ? b * wyvill_c(r / R) : 0.0;  // C(1) rounds to −2^-52: D(R) = 0 exactly
    }
    throw std::invalid_argument("density: unknown kernel");
    // END SOLUTION
}

double density_derivative(Kernel kernel, const Blob& blob, double r) {
    // BEGIN SOLUTION
    check_blob(kernel, blob);
    check_r(r);
    const double b = blob.strength, R = blob.radius;
    switch (kernel) {
        case Kernel::blinn: return -2.0 * blob.a * r * b * std::exp(-blob.a * r * r);
        case Kernel::nishimura:
            if (r <= R / 3) return -6.0 * b * r / (R * R);
            if (r <= R) return -3.0 * b * (1.0 - r / R) / R;
            return 0.0;
        case Kernel::wyvill: return r <= R ? b * wyvill_dc(r / R) / R : 0.0;
    }
    throw std::invalid_argument("density_derivative: unknown kernel");
    // END SOLUTION
}

double support_radius(Kernel kernel, const Blob& blob) {
    // BEGIN SOLUTION
    check_blob(kernel, blob);
    return kernel == Kernel::blinn ? std::numeric_limits<double>::infinity() : blob.radius;
    // END SOLUTION
}

double isolated_radius(Kernel kernel, const Blob& blob, double threshold) {
    // BEGIN SOLUTION
    check_blob(kernel, blob);
    if (!(threshold > 0) || !std::isfinite(threshold))
        throw std::invalid_argument("isolated_radius: the threshold T must be finite and > 0");
    const double b = blob.strength, R = blob.radius;
    if (threshold >= b) return 0.0;
    const double tau = threshold / b;  // in (0, 1)
    switch (kernel) {
        case Kernel::blinn: return std::sqrt(std::log(1.0 / tau) / blob.a);
        case Kernel::nishimura:
            if (tau >= 2.0 / 3.0) return R * std::sqrt((1.0 - tau) / 3.0);
            return R * (1.0 - std::sqrt(2.0 * tau / 3.0));
        case Kernel::wyvill: {
            // C decreases from 1 to 0 on [0, 1]: bisection on s, keeping C(lo) > τ ≥ C(hi). Once lo and hi are
            // adjacent doubles the midpoint rounds to one of them and the step leaves both in place; τ < 1 puts s
            // above 2^-28, so that happens within 80 halvings: 100 steps reach the last bit for every τ.
            double lo = 0.0, hi = 1.0;
            for (int step = 0; step < 100; ++step) {
                const double mid = 0.5 * (lo + hi);
                (wyvill_c(mid) > tau ? lo : hi) = mid;
            }
            return R * 0.5 * (lo + hi);
        }
    }
    throw std::invalid_argument("isolated_radius: unknown kernel");
    // END SOLUTION
}

}  // namespace geolab::blobby
