// ADVERSARIAL CASE trivial_answers: every function of lab 02 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 4: volume Laplacian smoothing (handout §6).
#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/halfface.hpp"

namespace geolab::halfface {

double volume_smoothing(Mesh& mesh, double t, int iterations) {
    return {};
}

}  // namespace geolab::halfface
