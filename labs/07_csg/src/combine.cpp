// Task 5: combining interval lists, Roth's ray casting of CSG trees (handout §6).
#include <limits>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "geolab/csg.hpp"

namespace geolab::csg {

std::vector<Span> combine(Op op, const std::vector<Span>& a, const std::vector<Span>& b) {
    throw geolab::NotImplemented(__func__);
}

// Helper functions of your own can go here.

std::vector<Span> ray_spans(const Tree& t, const Ray& world) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::csg
