// ADVERSARIAL CASE trivial_answers: every function of lab 06 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 7: volume, area and Pappus's theorems (handout §8).
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

double mesh_volume(const PolygonSoup& mesh) {
    return {};
}

double mesh_area(const PolygonSoup& mesh) {
    return {};
}

Pappus pappus(const Profile& p, double angle) {
    return {};
}

}  // namespace geolab::sweeps
