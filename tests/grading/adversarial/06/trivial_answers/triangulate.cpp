// ADVERSARIAL CASE trivial_answers: every function of lab 06 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
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
    return {};
}

}  // namespace geolab::sweeps
