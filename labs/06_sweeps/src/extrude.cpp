// Task 3: extrusion with twist and scale (handout §4).
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

PolygonSoup extrude(const Profile& p, const ExtrudeOptions& o) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::sweeps
