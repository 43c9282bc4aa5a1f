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
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::csg
