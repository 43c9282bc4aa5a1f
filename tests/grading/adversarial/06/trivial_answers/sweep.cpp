// ADVERSARIAL CASE trivial_answers: every function of lab 06 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 6: sweeping a profile along a path (handout §7).
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

namespace {
// Helper functions of your own can go here.
}  // namespace

PolygonSoup sweep(const Profile& p, const Path& path, const std::vector<Frame>& frames) {
    return {};
}

SweepCheck check_sweep(const Profile& p, const Path& path) {
    return {};
}

}  // namespace geolab::sweeps
