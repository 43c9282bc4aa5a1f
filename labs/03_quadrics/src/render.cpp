// Task 7: images (handout §9).
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {

render::Image render_lambert(const Scene& scene, const PinholeCamera& camera, int width, int height) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::quadrics
