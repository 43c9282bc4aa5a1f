// ADVERSARIAL CASE trivial_answers: every function of lab 03 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 7: images (handout §9).
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {

render::Image render_lambert(const Scene& scene, const PinholeCamera& camera, int width, int height) {
    return {};
}

}  // namespace geolab::quadrics
