// Lab 09 — Task 3: the Cartesian octree build (the octree structure itself is given, in octree_given.cpp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <string>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"

namespace geolab::dc {

// ---- Task 3: the Cartesian octree -----------------------------------------------------------------------------------

Octree build_octree(const ScalarField& f, const CartesianParams& params) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::dc
