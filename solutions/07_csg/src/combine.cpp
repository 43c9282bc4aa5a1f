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
    out.clear();
    if (b.empty()) {  // A ∪ ∅ = A − ∅ = A, A ∩ ∅ = ∅
        if (op != Op::intersect) out = a;
        return;
    }
    if (a.empty()) {  // ∅ ∪ B = B, ∅ ∩ B = ∅ − B = ∅
        if (op == Op::unite) out = b;
        return;
    }
    std::size_t ka = 0, kb = 0;
    const std::size_t na = 2 * a.size(), nb = 2 * b.size();
    bool in_a = false, in_b = false, inside = false;
    Span cur;
    while (ka < na || kb < nb) {
        const double ta = ka < na ? at(a, ka) : inf, tb = kb < nb ? at(b, kb) : inf;
        const double t = std::min(ta, tb);
        bool has_a = false;
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
            ++kb;
        }
        const bool now = result(in_a, in_b);
        if (now == inside) continue;
        const glm::dvec3 n = has_a ? n_a : (op == Op::subtract ? -n_b : n_b);
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
    // END SOLUTION
}

bool line_meets_box(const Ray& line, const glm::dvec3& lo, const glm::dvec3& hi) {
    // BEGIN SOLUTION
    const double inf = std::numeric_limits<double>::infinity();
    double t0 = -inf, t1 = inf;  // the line's parameters inside every slab so far
    for (int k = 0; k < 3; ++k) {
        const double o = line.origin[k], d = line.direction[k];
        if (d == 0) {
            if (o < lo[k] || o > hi[k]) return false;  // parallel to the slab and outside it
            continue;
        }
        double ta = (lo[k] - o) / d, tb = (hi[k] - o) / d;
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    return t0 <= t1;
    // END SOLUTION
}

// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.
namespace {
// A leaf's spans along the world ray: the ray in the leaf's coordinates (M⁻¹, the same t), normals back by M⁻ᵀ.
void leaf_spans(const PreparedNode& p, const Ray& world, std::vector<Span>& out) {
    const Ray local{glm::dvec3(p.inverse * glm::dvec4(world.origin, 1.0)),
                    glm::dvec3(p.inverse * glm::dvec4(world.direction, 0.0))};
    primitive_spans(p.node, local, out);
    auto to_world = [&p](const glm::dvec3& n) {
        const glm::dvec3 w = p.normal_map * n;
        const double l = glm::length(w);
        return l > 0 ? w / l : glm::dvec3(0.0);
    };
    for (Span& s : out) {
        s.n0 = to_world(s.n0);
        s.n1 = to_world(s.n1);
    }
}

// Node i's spans into lists[i]: nothing where the line misses the node's box, a leaf's own, or its children's
// combined.
void node_spans(const PreparedTree& t, int i, const Ray& world, SpanLists& lists) {
    const PreparedNode& p = t.nodes[i];
    std::vector<Span>& out = lists[i];
    if (!line_meets_box(world, p.lo, p.hi)) {
        out.clear();
        return;
    }
    const Node& d = p.node;
    if (d.op == Op::leaf) {
        leaf_spans(p, world, out);
        return;
    }
    node_spans(t, d.a, world, lists);
    if (lists[d.a].empty() && d.op != Op::unite) {  // ∅ ∩ B = ∅ − B = ∅: B need not be cast
        out.clear();
        return;
    }
    node_spans(t, d.b, world, lists);
    combine(d.op, lists[d.a], lists[d.b], out);
}
}  // namespace
// END SOLUTION

void ray_spans(const PreparedTree& t, const Ray& world, SpanLists& lists) {
    // BEGIN SOLUTION
    if (t.has_blend) throw std::invalid_argument("ray_spans: a blend node has no exact interval list");
    if (world.direction == glm::dvec3(0.0)) throw std::invalid_argument("ray_spans: zero direction");
    lists.resize(t.nodes.size());
    node_spans(t, t.root, world, lists);
    // END SOLUTION
}

std::vector<Span> ray_spans(const Tree& t, const Ray& world) {
    // BEGIN SOLUTION
    const PreparedTree p = prepare(t);
    SpanLists lists;
    ray_spans(p, world, lists);
    return lists[p.root];
    // END SOLUTION
}

}  // namespace geolab::csg
