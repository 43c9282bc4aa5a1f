// Task 2: signed distances of CSG trees and the smooth minimum (handout §3).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geolab/csg.hpp"

namespace geolab::csg {

double smooth_min(double a, double b, double k) {
    // BEGIN SOLUTION
    if (!(k > 0)) throw std::invalid_argument("smooth_min: k must be > 0");
    const double h = std::clamp(0.5 + (b - a) / (2 * k), 0.0, 1.0);
    return b * (1 - h) + a * h - k * h * (1 - h);
    // END SOLUTION
}

// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.
namespace {
double node_sdf(const Tree& t, int i, const glm::dvec3& x) {
    const Node& d = t.nodes[i];
    switch (d.op) {
        case Op::leaf: {
            const glm::dvec3 p = glm::dvec3(affine_inverse(d.M) * glm::dvec4(x, 1.0));
            return min_stretch(d.M) * primitive_distance(d, p);
        }
        case Op::unite: return std::min(node_sdf(t, d.a, x), node_sdf(t, d.b, x));
        case Op::intersect: return std::max(node_sdf(t, d.a, x), node_sdf(t, d.b, x));
        case Op::subtract: return std::max(node_sdf(t, d.a, x), -node_sdf(t, d.b, x));
        case Op::blend: return smooth_min(node_sdf(t, d.a, x), node_sdf(t, d.b, x), d.k);
    }
    throw std::invalid_argument("sdf: unknown operation");
}
}  // namespace
// END SOLUTION

double sdf(const Tree& t, const glm::dvec3& x) {
    // BEGIN SOLUTION
    check_tree(t);
    return node_sdf(t, t.root, x);
    // END SOLUTION
}

}  // namespace geolab::csg
