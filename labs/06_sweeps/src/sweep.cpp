// Task 6: sweeping a profile along a path (handout §7).
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/memory.hpp"
#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

namespace {
// Helper functions of your own can go here.
}  // namespace

PolygonSoup sweep(const Profile& p, const Path& path, const std::vector<Frame>& frames) {
    throw geolab::NotImplemented(__func__);
}

SweepCheck check_sweep(const Profile& p, const Path& path) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::sweeps
