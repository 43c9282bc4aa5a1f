// ADVERSARIAL CASE always_throws: every function of lab 06 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
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
    throw std::invalid_argument(__func__);
}

SweepCheck check_sweep(const Profile& p, const Path& path) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::sweeps
