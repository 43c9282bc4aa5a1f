// ADVERSARIAL CASE hostile_soup: boundary_surface answers a soup whose last face claims 2^28 indices. Code in the
// judge that walks the answer
// (PolygonSoup::face() spans indices[offsets[f]..offsets[f+1]); render::Image::pixel() reads rgba at 4·(y·w + x))
// would read memory outside it: the judge refuses such an answer as malformed. Honest: 0.
// Task 5: the boundary surface (handout §7).
#include "geolab/halfface.hpp"

namespace geolab::halfface {

PolygonSoup boundary_surface(const Mesh& mesh) {
    // 3 positions, one honest triangle, then a face whose span runs 2^28 indices past the end
    PolygonSoup hostile;
    hostile.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    hostile.indices = {0, 1, 2};
    hostile.offsets = {0, 3, 1u << 28};
    return hostile;
}

}  // namespace geolab::halfface
