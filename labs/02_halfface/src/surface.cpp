// Task 5: the boundary surface (handout §7).
#include "geolab/halfface.hpp"

namespace geolab::halfface {

PolygonSoup boundary_surface(const Mesh& mesh) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::halfface
