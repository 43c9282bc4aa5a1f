// ADVERSARIAL CASE trivial_answers: every function of lab 04 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 3: fast evaluation through a uniform grid of the blobs (handout §4).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "geolab/blobby.hpp"

namespace geolab::blobby {

BlobGrid build_blob_grid(const BlobScene& scene, double cell) {
    return {};
}

FieldSample evaluate(const BlobScene& scene, const BlobGrid& grid, const glm::dvec3& p) {
    return {};
}

Lattice sample_lattice(const BlobScene& scene, const glm::dvec3& origin, double h, const glm::ivec3& n,
                       std::uint64_t& kernel_evaluations) {
    return {};
}

}  // namespace geolab::blobby
