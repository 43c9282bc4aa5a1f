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
    throw geolab::NotImplemented(__func__);
}

RmfResult rotation_minimizing_frames(const Path& path, const glm::dvec3& initial_normal) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::sweeps
