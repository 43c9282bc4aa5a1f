// ADVERSARIAL CASE trivial_answers: every function of lab 03 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
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
    return {};
}

}  // namespace geolab::quadrics
