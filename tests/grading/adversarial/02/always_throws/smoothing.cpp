// ADVERSARIAL CASE always_throws: every function of lab 02 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 4: volume Laplacian smoothing (handout §6).
#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/halfface.hpp"

namespace geolab::halfface {

double volume_smoothing(Mesh& mesh, double t, int iterations) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::halfface
