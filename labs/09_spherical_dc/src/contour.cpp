// Lab 09 — task 4: dual vertices, simplification and polygons; the Cartesian one-shot function.
#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <queue>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"

namespace geolab::dc {



std::size_t place_vertices(Octree& tree, const VertexParams& params) {
    throw geolab::NotImplemented(__func__);
}

std::size_t simplify(Octree& tree, double tolerance, double tau) {
    throw geolab::NotImplemented(__func__);
}


PolygonSoup contour(const Octree& tree, std::vector<PoleRing>* poles) {
    throw geolab::NotImplemented(__func__);
}

PolygonSoup dual_contour_cartesian(const ScalarField& f, const CartesianParams& params, DcStats* stats) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::dc
