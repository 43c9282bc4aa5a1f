// ADVERSARIAL CASE trivial_answers: every function of lab 06 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 1: profiles (handout §2).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/predicates.hpp"
#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

double signed_area(const Loop& loop) {
    return {};
}

namespace {
// Helper functions of your own can go here.
}  // namespace

void validate_profile(const Profile& p) {
    return;
}

}  // namespace geolab::sweeps
