// ADVERSARIAL CASE always_throws: every function of lab 06 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 4: surfaces of revolution (handout §5).
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

Profile clip_to_axis(const Profile& p) {
    throw std::invalid_argument(__func__);
}

PolygonSoup revolve(const Profile& p, const RevolveOptions& o) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::sweeps
