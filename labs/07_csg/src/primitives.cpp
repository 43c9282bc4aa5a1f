// Task 1: exact signed distances of the primitives (handout §2).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/csg.hpp"
#include "geolab/quadric.hpp"

namespace geolab::csg {

// Helper functions of your own can go here.

double primitive_distance(const Node& leaf, const glm::dvec3& p) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::csg
