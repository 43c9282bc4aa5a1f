// ADVERSARIAL CASE always_throws: every function of lab 03 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 7: images (handout §9).
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {

render::Image render_lambert(const Scene& scene, const PinholeCamera& camera, int width, int height) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::quadrics
