// ADVERSARIAL CASE always_throws: every function of lab 06 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 3: extrusion with twist and scale (handout §4).
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

PolygonSoup extrude(const Profile& p, const ExtrudeOptions& o) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::sweeps
