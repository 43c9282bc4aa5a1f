// ADVERSARIAL CASE trivial_answers: every function of lab 02 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
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
    return {};
}

}  // namespace geolab::halfface
