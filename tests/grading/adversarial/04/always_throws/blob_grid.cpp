// ADVERSARIAL CASE always_throws: every function of lab 04 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
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
    throw std::invalid_argument(__func__);
}

FieldSample evaluate(const BlobScene& scene, const BlobGrid& grid, const glm::dvec3& p) {
    throw std::invalid_argument(__func__);
}

Lattice sample_lattice(const BlobScene& scene, const glm::dvec3& origin, double h, const glm::ivec3& n,
                       std::uint64_t& kernel_evaluations) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::blobby
