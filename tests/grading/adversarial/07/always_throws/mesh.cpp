// ADVERSARIAL CASE always_throws: every function of lab 07 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 7: meshes of CSG trees and their volumes (handout §8).
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/csg.hpp"
#include "geolab/polygonize.hpp"

namespace geolab::csg {

// Helper functions of your own can go here.

PolygonSoup mesh_tree(const Tree& t, int resolution) {
    throw std::invalid_argument(__func__);
}

double volume(const PolygonSoup& mesh) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::csg
