// ADVERSARIAL CASE always_throws: every function of lab 07 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 4: a ray's inside intervals in one primitive (handout §5).
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <glm/geometric.hpp>

#include "geolab/csg.hpp"

namespace geolab::csg {

// Helper functions of your own can go here.

void primitive_spans(const Node& leaf, const Ray& r, std::vector<Span>& out) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::csg
