// Task 5: combining interval lists, Roth's ray casting of CSG trees (handout §6).
#include <limits>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "geolab/csg.hpp"

namespace geolab::csg {

std::vector<Span> combine(Op op, const std::vector<Span>& a, const std::vector<Span>& b) {
    // BEGIN SOLUTION
    if (op != Op::unite && op != Op::intersect && op != Op::subtract)
        throw std::invalid_argument("combine: op must be unite, intersect or subtract");
    const double inf = std::numeric_limits<double>::infinity();
    // Endpoint k of a list: span k/2's t0 (k even, entering) or t1 (k odd, leaving).
    auto at = [](const std::vector<Span>& v, std::size_t k) { return k % 2 == 0 ? v[k / 2].t0 : v[k / 2].t1; };
    auto normal = [](const std::vector<Span>& v, std::size_t k) { return k % 2 == 0 ? v[k / 2].n0 : v[k / 2].n1; };
    auto result = [op](bool x, bool y) {
        return op == Op::unite ? (x || y) : op == Op::intersect ? (x && y) : (x && !y);
    };
    std::vector<Span> out;
    std::size_t ka = 0, kb = 0;
    const std::size_t na = 2 * a.size(), nb = 2 * b.size();
    bool in_a = false, in_b = false, inside = false;
    Span cur;
    while (ka < na || kb < nb) {
        const double ta = ka < na ? at(a, ka) : inf, tb = kb < nb ? at(b, kb) : inf;
        const double t = std::min(ta, tb);
        bool has_a = false, has_b = false;
        glm::dvec3 n_a(0.0), n_b(0.0);
        while (ka < na && at(a, ka) == t) {  // every endpoint at t before deciding
            in_a = ka % 2 == 0;
            n_a = normal(a, ka);
            has_a = true;
            ++ka;
        }
        while (kb < nb && at(b, kb) == t) {
            in_b = kb % 2 == 0;
            n_b = normal(b, kb);
            has_b = true;
            ++kb;
        }
        const bool now = result(in_a, in_b);
        if (now == inside) continue;
        const glm::dvec3 n = has_a ? n_a : (op == Op::subtract ? -n_b : n_b);
        (void)has_b;
        if (now) {
            cur.t0 = t;
            cur.n0 = n;
        } else {
            cur.t1 = t;
            cur.n1 = n;
            if (cur.t0 < cur.t1) out.push_back(cur);
        }
        inside = now;
    }
    return out;
    // END SOLUTION
}

// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.
namespace {
std::vector<Span> node_spans(const Tree& t, int i, const Ray& r) {
    const Node& d = t.nodes[i];
    if (d.op == Op::blend) throw std::invalid_argument("ray_spans: a blend (node " + std::to_string(i) +
                                                       ") has no exact interval list");
    if (d.op != Op::leaf) return combine(d.op, node_spans(t, d.a, r), node_spans(t, d.b, r));
    const glm::dmat4 Mi = affine_inverse(d.M);
    const Ray local{glm::dvec3(Mi * glm::dvec4(r.origin, 1.0)), glm::dvec3(Mi * glm::dvec4(r.direction, 0.0))};
    std::vector<Span> s = primitive_spans(d, local);
    const glm::dmat3 N = glm::transpose(glm::dmat3(Mi));  // normals map by M⁻ᵀ
    auto map = [&N](const glm::dvec3& n) {
        const glm::dvec3 w = N * n;
        const double l = glm::length(w);
        return l > 0 ? w / l : glm::dvec3(0.0);
    };
    for (Span& x : s) {
        x.n0 = map(x.n0);
        x.n1 = map(x.n1);
    }
    return s;
}
}  // namespace
// END SOLUTION

std::vector<Span> ray_spans(const Tree& t, const Ray& world) {
    // BEGIN SOLUTION
    check_tree(t);
    if (world.direction == glm::dvec3(0.0)) throw std::invalid_argument("ray_spans: zero direction");
    return node_spans(t, t.root, world);
    // END SOLUTION
}

}  // namespace geolab::csg
