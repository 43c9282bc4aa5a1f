// ADVERSARIAL CASE trivial_answers: every function of lab 07 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 7: meshes of CSG trees and their volumes (handout §8).
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/csg.hpp"
#include "geolab/polygonize.hpp"

namespace geolab::csg {

// Helper functions of your own can go here.

PolygonSoup mesh_tree(const Tree& t, int resolution) {
    return {};
}

double volume(const PolygonSoup& mesh) {
    return {};
}

}  // namespace geolab::csg
