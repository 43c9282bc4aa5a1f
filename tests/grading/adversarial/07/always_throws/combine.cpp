// ADVERSARIAL CASE always_throws: every function of lab 07 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 5: combining interval lists, Roth's ray casting of CSG trees (handout §6).
#include <limits>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "geolab/csg.hpp"

namespace geolab::csg {

std::vector<Span> combine(Op op, const std::vector<Span>& a, const std::vector<Span>& b) {
    throw std::invalid_argument(__func__);
}

// Helper functions of your own can go here.

std::vector<Span> ray_spans(const Tree& t, const Ray& world) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::csg
