// ADVERSARIAL CASE trivial_answers: every function of lab 04 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 2: the field (handout §3).
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/blobby.hpp"

namespace geolab::blobby {

FieldValue field(const BlobScene& scene, const glm::dvec3& p) {
    return {};
}

}  // namespace geolab::blobby
