// ADVERSARIAL CASE trivial_answers: every function of lab 06 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 4: surfaces of revolution (handout §5).
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

Profile clip_to_axis(const Profile& p) {
    return {};
}

PolygonSoup revolve(const Profile& p, const RevolveOptions& o) {
    return {};
}

}  // namespace geolab::sweeps
