// ADVERSARIAL CASE trivial_answers: every function of lab 04 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 1: the kernels (handout §2).
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "geolab/blobby.hpp"

namespace geolab::blobby {

namespace {
// Helper functions of your own can go here.
}  // namespace

double density(Kernel kernel, const Blob& blob, double r) {
    return {};
}

double density_derivative(Kernel kernel, const Blob& blob, double r) {
    return {};
}

double support_radius(Kernel kernel, const Blob& blob) {
    return {};
}

double isolated_radius(Kernel kernel, const Blob& blob, double threshold) {
    return {};
}

}  // namespace geolab::blobby
