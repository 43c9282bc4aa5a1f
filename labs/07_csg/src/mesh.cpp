// Task 7: meshes of CSG trees and their volumes (handout §8).
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/csg.hpp"
#include "geolab/polygonize.hpp"

namespace geolab::csg {

// Helper functions of your own can go here.

PolygonSoup mesh_tree(const Tree& t, int resolution) {
    throw geolab::NotImplemented(__func__);
}

double volume(const PolygonSoup& mesh) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::csg
