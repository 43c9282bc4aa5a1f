// ADVERSARIAL CASE trivial_answers: every function of lab 07 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
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
    return;
}

bool line_meets_box(const Ray& line, const glm::dvec3& lo, const glm::dvec3& hi) {
    return {};
}

// Helper functions of your own can go here.

void ray_spans(const PreparedTree& t, const Ray& world, SpanLists& lists) {
    return;
}

std::vector<Span> ray_spans(const Tree& t, const Ray& world) {
    return {};
}

}  // namespace geolab::csg
