// ADVERSARIAL CASE always_throws: every function of lab 06 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 7: volume, area and Pappus's theorems (handout §8).
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

double mesh_volume(const PolygonSoup& mesh) {
    throw std::invalid_argument(__func__);
}

double mesh_area(const PolygonSoup& mesh) {
    throw std::invalid_argument(__func__);
}

Pappus pappus(const Profile& p, double angle) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::sweeps
