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
    throw geolab::NotImplemented(__func__);
}

double density_derivative(Kernel kernel, const Blob& blob, double r) {
    throw geolab::NotImplemented(__func__);
}

double support_radius(Kernel kernel, const Blob& blob) {
    throw geolab::NotImplemented(__func__);
}

double isolated_radius(Kernel kernel, const Blob& blob, double threshold) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::blobby
