// Task 3: point membership classification (handout §4).
#include <cmath>
#include <stdexcept>

#include "geolab/csg.hpp"

namespace geolab::csg {

// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.
namespace {
Membership by_value(double v, double tol) { return std::abs(v) <= tol ? Membership::on : v < 0 ? Membership::in : Membership::out; }

Membership node_class(const Tree& t, int i, const glm::dvec3& x, double tol) {
    const Node& d = t.nodes[i];
    using M = Membership;
    switch (d.op) {
        case Op::leaf: {
            const glm::dvec3 p = glm::dvec3(affine_inverse(d.M) * glm::dvec4(x, 1.0));
            return by_value(min_stretch(d.M) * primitive_distance(d, p), tol);
        }
        case Op::blend: {
            Tree sub = t;
            sub.root = i;
            return by_value(sdf(sub, x), tol);
        }
        default: break;
    }
    const M a = node_class(t, d.a, x, tol), b = node_class(t, d.b, x, tol);
    switch (d.op) {
        case Op::unite:
            if (a == M::in || b == M::in) return M::in;
            return a == M::out && b == M::out ? M::out : M::on;
        case Op::intersect:
            if (a == M::out || b == M::out) return M::out;
            return a == M::in && b == M::in ? M::in : M::on;
        case Op::subtract:
            if (a == M::out || b == M::in) return M::out;
            return a == M::in && b == M::out ? M::in : M::on;
        default: break;
    }
    throw std::invalid_argument("classify: unknown operation");
}
}  // namespace
// END SOLUTION

Membership classify(const Tree& t, const glm::dvec3& x, double rel_tol) {
    // BEGIN SOLUTION
    if (!(rel_tol >= 0)) throw std::invalid_argument("classify: rel_tol must be >= 0");
    check_tree(t);
    return node_class(t, t.root, x, rel_tol * scene_size(t));
    // END SOLUTION
}

}  // namespace geolab::csg
