// ADVERSARIAL CASE always_throws: every function of lab 04 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
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
    throw std::invalid_argument(__func__);
}

double density_derivative(Kernel kernel, const Blob& blob, double r) {
    throw std::invalid_argument(__func__);
}

double support_radius(Kernel kernel, const Blob& blob) {
    throw std::invalid_argument(__func__);
}

double isolated_radius(Kernel kernel, const Blob& blob, double threshold) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::blobby
