// ADVERSARIAL CASE always_throws: every function of lab 02 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 5: the boundary surface (handout §7).
#include "geolab/halfface.hpp"

namespace geolab::halfface {

PolygonSoup boundary_surface(const Mesh& mesh) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::halfface
