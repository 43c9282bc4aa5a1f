// Task 4: volume Laplacian smoothing (handout §6).
#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/halfface.hpp"

namespace geolab::halfface {

double volume_smoothing(Mesh& mesh, double t, int iterations) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::halfface
