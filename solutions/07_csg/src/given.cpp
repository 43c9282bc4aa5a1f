// Given code of lab 07 (read it, do not write it): tree checks and builders, bounds, the stretch of a map, a
// polynomial root finder, OpenSCAD scenes to trees, the camera's rays.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "geolab/csg.hpp"

namespace geolab::csg {

namespace {
const double inf = std::numeric_limits<double>::infinity();

[[noreturn]] void bad(int i, const std::string& why) {
    throw std::invalid_argument("CSG tree: node " + std::to_string(i) + ": " + why);
}
bool finite(const glm::dmat4& M) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(M[c][r])) return false;
    return true;
}
}  // namespace

glm::dmat4 affine_inverse(const glm::dmat4& M) {
    const glm::dmat3 L(M);
    double norm = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) norm = std::max(norm, std::abs(L[i][j]));
    const double det = glm::determinant(L);
    if (!(std::abs(det) > 1e-12 * norm * norm * norm) || !std::isfinite(det))
        throw std::invalid_argument("affine_inverse: the linear part is singular or not finite");
    const glm::dmat3 Li = glm::inverse(L);
    glm::dmat4 R(Li);
    R[3] = glm::dvec4(-(Li * glm::dvec3(M[3])), 1.0);
    return R;
}

double min_stretch(const glm::dmat4& M) {
    // The smallest eigenvalue of LᵀL (symmetric 3×3, Jacobi rotations), square-rooted.
    const glm::dmat3 L(M);
    glm::dmat3 A = glm::transpose(L) * L;
    for (int sweep = 0; sweep < 50; ++sweep) {
        double off = std::abs(A[0][1]) + std::abs(A[0][2]) + std::abs(A[1][2]);
        if (off <= 1e-300) break;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (A[p][q] == 0) continue;
                const double theta = (A[q][q] - A[p][p]) / (2 * A[p][q]);
                const double t = (theta >= 0 ? 1 : -1) / (std::abs(theta) + std::sqrt(theta * theta + 1));
                const double c = 1 / std::sqrt(t * t + 1), s = t * c;
                glm::dmat3 J(1.0);
                J[p][p] = c;
                J[q][q] = c;
                J[q][p] = s;   // column q, row p
                J[p][q] = -s;  // column p, row q
                A = glm::transpose(J) * A * J;
            }
    }
    const double m = std::min({A[0][0], A[1][1], A[2][2]});
    return std::sqrt(std::max(m, 0.0));
}

void check_tree(const Tree& t) {
    const int n = int(t.nodes.size());
    if (t.root < 0 || t.root >= n)
        throw std::invalid_argument("CSG tree: root " + std::to_string(t.root) + " out of range (" +
                                    std::to_string(n) + " nodes)");
    for (int i = 0; i < n; ++i) {
        const Node& d = t.nodes[i];
        if (d.op == Op::leaf) {
            if (!finite(d.M) || d.M[0][3] != 0 || d.M[1][3] != 0 || d.M[2][3] != 0 || d.M[3][3] != 1)
                bad(i, "M is not a finite affine map (last row 0 0 0 1)");
            try {
                (void)affine_inverse(d.M);
            } catch (const std::invalid_argument&) {
                bad(i, "M is singular");
            }
            const glm::dvec3 s = d.size;
            if (!std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.z)) bad(i, "size is not finite");
            switch (d.shape) {
                case Shape::sphere:
                    if (!(s.x > 0)) bad(i, "sphere radius must be > 0");
                    break;
                case Shape::box:
                    if (!(s.x > 0 && s.y > 0 && s.z > 0)) bad(i, "box half extents must be > 0");
                    break;
                case Shape::cylinder:
                    if (!(s.x > 0 && s.z > 0)) bad(i, "cylinder radius and half height must be > 0");
                    break;
                case Shape::cone:
                    if (!(s.x >= 0 && s.y >= 0 && (s.x > 0 || s.y > 0) && s.z > 0))
                        bad(i, "cone radii must be >= 0, not both 0, half height > 0");
                    break;
                case Shape::torus:
                    if (!(s.y > 0 && s.y < s.x)) bad(i, "torus needs 0 < r < R");
                    break;
                case Shape::halfspace: break;
                case Shape::quadric:
                    if (!finite(d.Q)) bad(i, "Q is not finite");
                    break;
                default: bad(i, "unknown shape " + std::to_string(int(d.shape)));
            }
        } else {
            if (d.op != Op::unite && d.op != Op::intersect && d.op != Op::subtract && d.op != Op::blend)
                bad(i, "unknown operation " + std::to_string(int(d.op)));
            if (d.a < 0 || d.a >= i || d.b < 0 || d.b >= i)
                bad(i, "children " + std::to_string(d.a) + ", " + std::to_string(d.b) +
                           " must be earlier nodes (0 ≤ child < " + std::to_string(i) + ")");
            if (d.op == Op::blend && !(d.k > 0 && std::isfinite(d.k))) bad(i, "blend radius k must be > 0");
        }
    }
}

Tree leaf(Shape s, glm::dvec3 size, const glm::dmat4& M) {
    Tree t;
    Node n;
    n.shape = s;
    n.size = size;
    n.M = M;
    t.nodes.push_back(n);
    t.root = 0;
    return t;
}

Tree quadric_leaf(const glm::dmat4& Q, const glm::dmat4& M) {
    Tree t = leaf(Shape::quadric, glm::dvec3(0.0), M);
    t.nodes[0].Q = Q;
    return t;
}

Tree combine_trees(Op op, const Tree& a, const Tree& b, double k) {
    Tree t = a;
    const int off = int(a.nodes.size());
    for (Node n : b.nodes) {
        if (n.op != Op::leaf) {
            n.a += off;
            n.b += off;
        }
        t.nodes.push_back(n);
    }
    Node n;
    n.op = op;
    n.a = a.root;
    n.b = b.root + off;
    n.k = k;
    t.nodes.push_back(n);
    t.root = int(t.nodes.size()) - 1;
    return t;
}

namespace {
Box hull(const Box& a, const Box& b) { return {glm::min(a.lo, b.lo), glm::max(a.hi, b.hi)}; }
bool is_finite(const Box& b) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(b.lo[i]) || !std::isfinite(b.hi[i])) return false;
    return true;
}
Box leaf_box(const Node& d) {
    glm::dvec3 h;
    const glm::dvec3 s = d.size;
    switch (d.shape) {
        case Shape::sphere: h = glm::dvec3(s.x); break;
        case Shape::box: h = s; break;
        case Shape::cylinder: h = {s.x, s.x, s.z}; break;
        case Shape::cone: h = {std::max(s.x, s.y), std::max(s.x, s.y), s.z}; break;
        case Shape::torus: h = {s.x + s.y, s.x + s.y, s.y}; break;
        default: return {glm::dvec3(-inf), glm::dvec3(inf)};
    }
    Box b{glm::dvec3(inf), glm::dvec3(-inf)};
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3 p((c & 1) ? h.x : -h.x, (c & 2) ? h.y : -h.y, (c & 4) ? h.z : -h.z);
        const glm::dvec3 w = glm::dvec3(d.M * glm::dvec4(p, 1.0));
        b.lo = glm::min(b.lo, w);
        b.hi = glm::max(b.hi, w);
    }
    return b;
}
// The box of an operation from its operands' boxes.
Box op_box(const Node& d, const Box& a, const Box& b) {
    switch (d.op) {
        case Op::unite: return hull(a, b);
        case Op::intersect: {
            Box r{glm::max(a.lo, b.lo), glm::min(a.hi, b.hi)};
            for (int k = 0; k < 3; ++k)
                if (r.lo[k] > r.hi[k]) r.lo[k] = r.hi[k] = 0.5 * (r.lo[k] + r.hi[k]);
            return r;
        }
        case Op::subtract: return a;
        case Op::blend: {
            Box r = hull(a, b);
            r.lo -= glm::dvec3(d.k / 4);
            r.hi += glm::dvec3(d.k / 4);
            return r;
        }
        case Op::leaf: break;
    }
    return {};
}
// Every node's box, children before parents (check_tree done).
std::vector<Box> node_boxes(const Tree& t) {
    std::vector<Box> box(t.nodes.size());
    for (std::size_t i = 0; i < t.nodes.size(); ++i) {
        const Node& d = t.nodes[i];
        box[i] = d.op == Op::leaf ? leaf_box(d) : op_box(d, box[d.a], box[d.b]);
    }
    return box;
}
}  // namespace

Box bounds(const Tree& t) {
    check_tree(t);
    return node_boxes(t)[t.root];
}

PreparedTree prepare(const Tree& t) {
    check_tree(t);
    const std::vector<Box> box = node_boxes(t);
    PreparedTree p;
    p.root = t.root;
    p.nodes.resize(t.nodes.size());
    for (std::size_t i = 0; i < t.nodes.size(); ++i) {
        PreparedNode& q = p.nodes[i];
        q.node = t.nodes[i];
        if (q.node.op == Op::leaf) {
            q.inverse = affine_inverse(q.node.M);
            q.normal_map = glm::transpose(glm::dmat3(q.inverse));
            q.stretch = min_stretch(q.node.M);
        }
        p.has_blend = p.has_blend || q.node.op == Op::blend;
        // grow the box by 1e-9 of its extent and position (rounding in leaf_box, M⁻¹ and the slab test is far less)
        for (int k = 0; k < 3; ++k) {
            const double lo = box[i].lo[k], hi = box[i].hi[k];
            double scale = 0;
            if (std::isfinite(lo)) scale = std::abs(lo);
            if (std::isfinite(hi)) scale = std::max(scale, std::abs(hi));
            if (std::isfinite(hi - lo)) scale += hi - lo;
            q.lo[k] = lo - 1e-9 * scale;
            q.hi[k] = hi + 1e-9 * scale;
        }
    }
    return p;
}

double scene_size(const Tree& t) {
    const Box b = bounds(t);
    if (is_finite(b)) return glm::length(b.hi - b.lo);
    Box all{glm::dvec3(inf), glm::dvec3(-inf)};
    bool any = false;
    for (const Node& d : t.nodes)
        if (d.op == Op::leaf) {
            const Box lb = leaf_box(d);
            if (is_finite(lb)) {
                all = hull(all, lb);
                any = true;
            }
        }
    return any ? glm::length(all.hi - all.lo) : 1.0;
}

namespace {
double horner(const std::vector<double>& c, double t) {
    double v = 0;
    for (std::size_t i = c.size(); i-- > 0;) v = v * t + c[i];
    return v;
}
// Roots of c in [lo, hi] by the roots of its derivative: between consecutive critical points c is monotone,
// so each such piece holds at most one root, found by bisection.
std::vector<double> roots_rec(const std::vector<double>& c, double lo, double hi) {
    const int n = int(c.size()) - 1;
    if (n < 1) return {};
    if (n == 1) {
        const double r = -c[0] / c[1];
        return (r >= lo && r <= hi) ? std::vector<double>{r} : std::vector<double>{};
    }
    std::vector<double> d(n);
    for (int i = 1; i <= n; ++i) d[i - 1] = i * c[i];
    std::vector<double> cuts{lo};
    for (double x : roots_rec(d, lo, hi)) cuts.push_back(x);
    cuts.push_back(hi);
    std::vector<double> out;
    double scale = 0;
    for (double x : c) scale = std::max(scale, std::abs(x));
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        double a = cuts[i], b = cuts[i + 1];
        double fa = horner(c, a), fb = horner(c, b);
        if (i > 0 && std::abs(fa) <= 1e-14 * scale * std::max(1.0, std::pow(std::abs(a), n))) {
            // a touching (or exact) root at a critical point
            if (out.empty() || out.back() != a) out.push_back(a);
            continue;
        }
        if (fa == 0) {
            if (out.empty() || out.back() != a) out.push_back(a);
            continue;
        }
        if ((fa < 0) == (fb < 0)) continue;
        if (fb == 0) continue;  // the next piece reports it
        for (int it = 0; it < 200 && b - a > 1e-15 * std::max(1.0, std::abs(a)); ++it) {
            const double m = 0.5 * (a + b);
            const double fm = horner(c, m);
            if (fm == 0) {
                a = b = m;
                break;
            }
            if ((fm < 0) == (fa < 0)) {
                a = m;
                fa = fm;
            } else {
                b = m;
            }
        }
        out.push_back(0.5 * (a + b));
    }
    const double fh = horner(c, hi);
    if (fh == 0 && (out.empty() || out.back() != hi)) out.push_back(hi);
    return out;
}
}  // namespace

std::vector<double> real_roots(const std::vector<double>& coefficients, double lo, double hi) {
    std::vector<double> c = coefficients;
    double scale = 0;
    for (double x : c) scale = std::max(scale, std::abs(x));
    while (!c.empty() && std::abs(c.back()) <= 1e-15 * scale) c.pop_back();
    if (c.size() < 2 || !(lo <= hi)) return {};
    std::vector<double> r = roots_rec(c, lo, hi);
    std::sort(r.begin(), r.end());
    r.erase(std::unique(r.begin(), r.end()), r.end());
    return r;
}

namespace {
glm::dmat4 translation(glm::dvec3 v) {
    glm::dmat4 T(1.0);
    T[3] = glm::dvec4(v, 1.0);
    return T;
}
}  // namespace

Tree from_scad(const scad::Scene& s) {
    // Scene nodes come children first, each used once: append each one's tree to t, remembering its root.
    Tree t;
    std::vector<int> at(s.nodes.size(), -1);
    auto push_leaf = [&](Shape shape, glm::dvec3 size, const glm::dmat4& M) {
        Node d;
        d.shape = shape;
        d.size = size;
        d.M = M;
        t.nodes.push_back(d);
        return int(t.nodes.size()) - 1;
    };
    for (std::size_t i = 0; i < s.nodes.size(); ++i) {
        const scad::Node& n = s.nodes[i];
        switch (n.kind) {
            case scad::Kind::cube:
                at[i] = push_leaf(Shape::box, n.size / 2.0, n.M * translation(n.center ? glm::dvec3(0) : n.size / 2.0));
                break;
            case scad::Kind::sphere: at[i] = push_leaf(Shape::sphere, glm::dvec3(n.r, 0, 0), n.M); break;
            case scad::Kind::cylinder: {
                const glm::dmat4 M = n.M * translation({0, 0, n.center ? 0.0 : n.h / 2});
                at[i] = n.r1 == n.r2 ? push_leaf(Shape::cylinder, {n.r1, n.r1, n.h / 2}, M)
                                     : push_leaf(Shape::cone, {n.r1, n.r2, n.h / 2}, M);
                break;
            }
            default: {
                const Op op = n.kind == scad::Kind::unite ? Op::unite
                              : n.kind == scad::Kind::intersection ? Op::intersect
                                                                    : Op::subtract;
                if (n.children.empty()) throw std::invalid_argument("from_scad: a boolean without children");
                std::vector<int> kids;
                for (int c : n.children) {
                    if (c < 0 || std::size_t(c) >= i || at[c] < 0)
                        throw std::invalid_argument("from_scad: node " + std::to_string(i) + " has a bad child");
                    kids.push_back(at[c]);
                }
                // Balanced, not a chain: a union of 100,000 spheres made a tree 100,000 deep, and the recursive
                // walks (bounds, hits) overflowed the stack. a − b − c − ... = a − (b ∪ c ∪ ...).
                auto combine = [&](Op o, std::vector<int> list) {
                    while (list.size() > 1) {
                        std::vector<int> next;
                        for (std::size_t k = 0; k + 1 < list.size(); k += 2) {
                            Node d;
                            d.op = o;
                            d.a = list[k];
                            d.b = list[k + 1];
                            t.nodes.push_back(d);
                            next.push_back(int(t.nodes.size()) - 1);
                        }
                        if (list.size() % 2 == 1) next.push_back(list.back());
                        list = std::move(next);
                    }
                    return list[0];
                };
                if (op != Op::subtract || kids.size() == 1) {
                    at[i] = combine(op, kids);
                } else {
                    Node d;
                    d.op = Op::subtract;
                    d.a = kids[0];
                    d.b = combine(Op::unite, std::vector<int>(kids.begin() + 1, kids.end()));
                    t.nodes.push_back(d);
                    at[i] = int(t.nodes.size()) - 1;
                }
            }
        }
    }
    if (s.root < 0 || std::size_t(s.root) >= s.nodes.size()) throw std::invalid_argument("from_scad: no root");
    t.root = at[s.root];
    check_tree(t);
    return t;
}

Ray PinholeCamera::ray(int x, int y, int width, int height) const {
    const glm::dvec3 forward = glm::normalize(target - eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, up));
    const glm::dvec3 upv = glm::cross(right, forward);
    const double h = std::tan(fov_deg * std::numbers::pi / 360.0);
    const double aspect = double(width) / double(height);
    const double px = (2.0 * (x + 0.5) / width - 1.0) * h * aspect;
    const double py = (1.0 - 2.0 * (y + 0.5) / height) * h;
    return Ray{eye, glm::normalize(forward + px * right + py * upv)};
}

}  // namespace geolab::csg
