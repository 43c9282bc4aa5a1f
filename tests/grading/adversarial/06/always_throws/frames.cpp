// ADVERSARIAL CASE always_throws: every function of lab 06 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
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
    throw std::invalid_argument(__func__);
}

RmfResult rotation_minimizing_frames(const Path& path, const glm::dvec3& initial_normal) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::sweeps
