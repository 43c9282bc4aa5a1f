// ADVERSARIAL CASE always_throws: every function of lab 06 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
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
    throw std::invalid_argument(__func__);
}

namespace {
// Helper functions of your own can go here.
}  // namespace

void validate_profile(const Profile& p) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::sweeps
