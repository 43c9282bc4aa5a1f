// ADVERSARIAL CASE always_throws: every function of lab 02 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 1: build the half-face mesh from a cell list (handout §3).
#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>

#include "geolab/halfface.hpp"

namespace geolab::halfface {

namespace {
// Helper functions of your own can go here.
}  // namespace

Mesh build_mesh(const CellList& cl) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::halfface
