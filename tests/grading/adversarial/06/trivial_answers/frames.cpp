// ADVERSARIAL CASE trivial_answers: every function of lab 06 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 5: Frenet frames and rotation-minimizing frames (handout §6).
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

namespace {
// Helper functions of your own can go here.
}  // namespace

std::vector<Frame> frenet_frames(const Path& path) {
    return {};
}

RmfResult rotation_minimizing_frames(const Path& path, const glm::dvec3& initial_normal) {
    return {};
}

}  // namespace geolab::sweeps
