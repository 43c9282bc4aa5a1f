// ADVERSARIAL CASE always_throws: every function of lab 07 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
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
    throw std::invalid_argument(__func__);
}

bool line_meets_box(const Ray& line, const glm::dvec3& lo, const glm::dvec3& hi) {
    throw std::invalid_argument(__func__);
}

// Helper functions of your own can go here.

void ray_spans(const PreparedTree& t, const Ray& world, SpanLists& lists) {
    throw std::invalid_argument(__func__);
}

std::vector<Span> ray_spans(const Tree& t, const Ray& world) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::csg
