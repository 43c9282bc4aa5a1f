// Task 1: build the half-face mesh from a cell list (handout §3).
#include <algorithm>
#include <cmath>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>

#include "geolab/halfface.hpp"

namespace geolab::halfface {

namespace {
// Helper functions of your own can go here.
}  // namespace

Mesh build_mesh(const CellList& cl) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::halfface
