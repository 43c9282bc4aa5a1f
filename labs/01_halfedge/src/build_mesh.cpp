// Task 1: build a half-edge mesh from a polygon soup (handout §3).
#include <algorithm>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "geolab/halfedge.hpp"

namespace geolab::halfedge {
namespace {
// Helper functions of your own can go here.
}  // namespace

Mesh build_mesh(const PolygonSoup& soup) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::halfedge
