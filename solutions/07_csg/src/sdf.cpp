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
double node_sdf(const PreparedTree& t, int i, const glm::dvec3& x) {
    const PreparedNode& p = t.nodes[i];
    const Node& d = p.node;
    switch (d.op) {
        case Op::leaf: return p.stretch * primitive_distance(d, glm::dvec3(p.inverse * glm::dvec4(x, 1.0)));
        case Op::unite: return std::min(node_sdf(t, d.a, x), node_sdf(t, d.b, x));
        case Op::intersect: return std::max(node_sdf(t, d.a, x), node_sdf(t, d.b, x));
        case Op::subtract: return std::max(node_sdf(t, d.a, x), -node_sdf(t, d.b, x));
        case Op::blend: return smooth_min(node_sdf(t, d.a, x), node_sdf(t, d.b, x), d.k);
    }
    throw std::invalid_argument("sdf: unknown operation");
}
}  // namespace
// END SOLUTION

double sdf(const PreparedTree& t, const glm::dvec3& x) {
    // BEGIN SOLUTION
    return node_sdf(t, t.root, x);
    // END SOLUTION
}

double sdf(const Tree& t, const glm::dvec3& x) {
    // BEGIN SOLUTION
    return sdf(prepare(t), x);
    // END SOLUTION
}

}  // namespace geolab::csg
