// ADVERSARIAL CASE always_throws: every function of lab 04 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 2: the field (handout §3).
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/blobby.hpp"

namespace geolab::blobby {

FieldValue field(const BlobScene& scene, const glm::dvec3& p) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::blobby
