// ADVERSARIAL CASE trivial_answers: every function of lab 07 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 5: combining interval lists, Roth's ray casting of CSG trees (handout §6).
#include <limits>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "geolab/csg.hpp"

namespace geolab::csg {

std::vector<Span> combine(Op op, const std::vector<Span>& a, const std::vector<Span>& b) {
    return {};
}

// Helper functions of your own can go here.

std::vector<Span> ray_spans(const Tree& t, const Ray& world) {
    return {};
}

}  // namespace geolab::csg
