// Task 5: uniform Laplacian smoothing (handout §7).
#include <stdexcept>
#include <string>
#include <vector>

#include "geolab/halfedge.hpp"

namespace geolab::halfedge {

void laplacian_smoothing(Mesh& mesh, double t, int iterations) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::halfedge
