// ADVERSARIAL CASE forbidden_wrapper: lab 07 forbids lib's implicits in Tasks 1 and 2. primitive_distance answers
// spheres with lib's geolab::sphere through a helper in sdf.cpp (Task 2's file, left a stub), which reaches it
// through an alias. Honest: what the code earns with no list, less its Task 1 points (the check zeroes Task 1).
// Task 1: exact signed distances of the primitives (handout §2).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/csg.hpp"
#include "geolab/quadric.hpp"

namespace geolab::csg {
namespace helpers {
double lib_distance(double radius, const glm::dvec3& p);
}

// Helper functions of your own can go here.

double primitive_distance(const Node& leaf, const glm::dvec3& p) {
    if (leaf.shape == Shape::sphere) return helpers::lib_distance(leaf.size.x, p);
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::csg
