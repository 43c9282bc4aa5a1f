// Lab 09 — task 7: filling the holes around the polar axis with a ghost vertex.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"

namespace geolab::dc {

PoleFillResult fill_poles(PolygonSoup& soup, std::span<const PoleRing> rings, const ScalarField& f,
                          const glm::dvec3& origin, PoleFill::Method method) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::dc
