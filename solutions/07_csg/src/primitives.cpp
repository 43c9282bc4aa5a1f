// Task 1: exact signed distances of the primitives (handout §2).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/csg.hpp"
#include "geolab/quadric.hpp"

namespace geolab::csg {

// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.
namespace {
// Distance from q to the segment [a, b] in the plane.
double segment_distance(glm::dvec2 q, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 ab = b - a;
    const double l2 = glm::dot(ab, ab);
    const double s = l2 > 0 ? std::clamp(glm::dot(q - a, ab) / l2, 0.0, 1.0) : 0.0;
    return glm::length(q - (a + s * ab));
}
// A solid of revolution about z whose meridian section is the trapezoid (0, −h) (r1, −h) (r2, h) (0, h): the
// distance is the 2-D distance in the meridian half-plane to the three real edges (the axis is not a boundary).
double trapezoid_distance(double rho, double z, double r1, double r2, double h) {
    const glm::dvec2 q(rho, z);
    const double d = std::min({segment_distance(q, {0, -h}, {r1, -h}), segment_distance(q, {r1, -h}, {r2, h}),
                               segment_distance(q, {r2, h}, {0, h})});
    const double radius = r1 + (r2 - r1) * (z + h) / (2 * h);
    const bool inside = std::abs(z) <= h && rho <= radius;
    return inside ? -d : d;
}
}  // namespace
// END SOLUTION

double primitive_distance(const Node& leaf, const glm::dvec3& p) {
    // BEGIN SOLUTION
    if (leaf.op != Op::leaf) throw std::invalid_argument("primitive_distance: the node is not a leaf");
    const glm::dvec3 s = leaf.size;
    switch (leaf.shape) {
        case Shape::sphere: return glm::length(p) - s.x;
        case Shape::box: {
            const glm::dvec3 q = glm::abs(p) - s;
            return glm::length(glm::max(q, 0.0)) + std::min(std::max({q.x, q.y, q.z}), 0.0);
        }
        case Shape::cylinder: {
            const glm::dvec2 q(std::sqrt(p.x * p.x + p.y * p.y) - s.x, std::abs(p.z) - s.z);
            return glm::length(glm::max(q, 0.0)) + std::min(std::max(q.x, q.y), 0.0);
        }
        case Shape::cone: return trapezoid_distance(std::sqrt(p.x * p.x + p.y * p.y), p.z, s.x, s.y, s.z);
        case Shape::torus: {
            const double a = std::sqrt(p.x * p.x + p.y * p.y) - s.x;
            return std::sqrt(a * a + p.z * p.z) - s.y;
        }
        case Shape::halfspace: return p.z;
        case Shape::quadric: {
            const double q = Quadric{leaf.Q}.value(p);
            const glm::dvec3 g = 2.0 * glm::dvec3(leaf.Q * glm::dvec4(p, 1.0));
            const double gl = glm::length(g);
            return gl > 0 ? q / gl : q;
        }
    }
    throw std::invalid_argument("primitive_distance: unknown shape");
    // END SOLUTION
}

}  // namespace geolab::csg
