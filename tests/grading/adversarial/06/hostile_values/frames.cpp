// ADVERSARIAL CASE hostile_values (see triangulate.cpp).
#include <limits>
#include <vector>

#include "geolab/sweeps.hpp"

namespace geolab::sweeps {
namespace {
Frame nan_frame() {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {glm::dvec3(nan), glm::dvec3(nan), glm::dvec3(nan)};
}
}  // namespace

std::vector<Frame> frenet_frames(const Path& path) { return std::vector<Frame>(path.points.size(), nan_frame()); }

RmfResult rotation_minimizing_frames(const Path& path, const glm::dvec3&) {
    RmfResult r;
    r.frames.assign(path.points.size(), nan_frame());
    r.mismatch = std::numeric_limits<double>::quiet_NaN();
    return r;
}

}  // namespace geolab::sweeps
