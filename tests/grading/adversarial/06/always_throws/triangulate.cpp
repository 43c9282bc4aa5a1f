// ADVERSARIAL CASE always_throws: every function of lab 06 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 2: triangulation by ear clipping with hole bridging (handout §3).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/predicates.hpp"
#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

namespace {
// Helper functions of your own can go here.
}  // namespace

std::vector<std::array<std::uint32_t, 3>> triangulate(const Profile& p) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::sweeps
