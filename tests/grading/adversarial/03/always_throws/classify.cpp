// ADVERSARIAL CASE always_throws: every function of lab 03 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 3: classification (handout §5).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {
namespace {
// Helper functions of your own can go here (symmetric_eigen is given).
}  // namespace

QuadricType classify(const glm::dmat4& Q) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::quadrics
