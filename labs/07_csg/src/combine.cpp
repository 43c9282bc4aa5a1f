// Task 5: combining interval lists, Roth's ray casting of CSG trees (handout §6).
#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include <glm/geometric.hpp>

#include "geolab/csg.hpp"

namespace geolab::csg {

void combine(Op op, const std::vector<Span>& a, const std::vector<Span>& b, std::vector<Span>& out) {
    throw geolab::NotImplemented(__func__);
}

bool line_meets_box(const Ray& line, const glm::dvec3& lo, const glm::dvec3& hi) {
    throw geolab::NotImplemented(__func__);
}

// Helper functions of your own can go here.

void ray_spans(const PreparedTree& t, const Ray& world, SpanLists& lists) {
    throw geolab::NotImplemented(__func__);
}

std::vector<Span> ray_spans(const Tree& t, const Ray& world) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::csg
