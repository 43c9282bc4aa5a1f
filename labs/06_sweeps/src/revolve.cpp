// Task 4: surfaces of revolution (handout §5).
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

Profile clip_to_axis(const Profile& p) {
    throw geolab::NotImplemented(__func__);
}

PolygonSoup revolve(const Profile& p, const RevolveOptions& o) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::sweeps
