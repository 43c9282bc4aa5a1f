// Task 5: combining interval lists, Roth's ray casting of CSG trees (handout §6).
#include <limits>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/csg.hpp"

namespace geolab::csg {

void combine(Op op, const std::vector<Span>& a, const std::vector<Span>& b, std::vector<Span>& out) {
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
