#pragma once
// Lab 07 test helpers: trees built by construction and expected values computed independently of the reference:
// inside tests straight from each primitive's definition, distances by other formulas or by dense sampling of the
// surface in long double, spans by marching along the ray and bisecting. No helper calls a function you write.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>

#include "geolab/csg.hpp"
#include "geolab/grading/test.hpp"

namespace lab07 {

using namespace geolab::csg;
using geolab::PolygonSoup;
using LD = long double;
constexpr double pi = std::numbers::pi;
const double inf = std::numeric_limits<double>::infinity();

inline std::string str(const glm::dvec3& v) {
    std::ostringstream s;
    s.precision(12);
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}
inline std::string str(const Ray& r) { return "ray " + str(r.origin) + " + t " + str(r.direction); }
inline std::string str(const std::vector<Span>& v) {
    std::ostringstream s;
    s.precision(10);
    s << "{";
    for (const Span& x : v) s << " [" << x.t0 << ", " << x.t1 << "]";
    s << " }";
    return s.str();
}
inline const char* name(Shape s) {
    static const char* n[] = {"sphere", "box", "cylinder", "cone", "torus", "halfspace", "quadric"};
    return n[int(s)];
}
inline std::string str(Membership m) { return m == Membership::in ? "in" : m == Membership::on ? "on" : "out"; }
inline std::string str(const Node& d) {
    std::ostringstream s;
    s << name(d.shape) << " size " << str(d.size);
    return s.str();
}

struct Rng {
    std::mt19937_64 gen;
    explicit Rng(std::uint64_t seed) : gen(seed) {}
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(gen); }
    glm::dvec3 point(double r) { return {uniform(-r, r), uniform(-r, r), uniform(-r, r)}; }
    glm::dvec3 unit() {
        for (;;) {
            glm::dvec3 v = point(1);
            const double l = glm::length(v);
            if (l > 0.1 && l <= 1) return v / l;
        }
    }
};

inline glm::dmat4 translate(glm::dvec3 v) { return glm::translate(glm::dmat4(1.0), v); }
inline glm::dmat4 rotate(double deg, glm::dvec3 axis) { return glm::rotate(glm::dmat4(1.0), deg * pi / 180, axis); }
inline glm::dmat4 scale(glm::dvec3 s) { return glm::scale(glm::dmat4(1.0), s); }
// A random rigid motion (rotation and translation within ±t).
inline glm::dmat4 rigid(Rng& rng, double t = 1.0) {
    return translate(rng.point(t)) * rotate(rng.uniform(0, 360), rng.unit());
}

// The inverse of M computed in long double with Eigen (independent of the given affine_inverse).
inline glm::dvec3 to_local(const glm::dmat4& M, const glm::dvec3& x) {
    Eigen::Matrix<LD, 4, 4> m;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m(r, c) = M[c][r];
    const Eigen::Matrix<LD, 4, 1> y = m.inverse() * Eigen::Matrix<LD, 4, 1>(x.x, x.y, x.z, 1);
    return {double(y(0)), double(y(1)), double(y(2))};
}

// ---- definitions of the primitives: inside tests and exact distances computed another way ------------------

// Signed value whose sign is the definition of the primitive (not a distance except where noted).
inline LD ref_implicit(const Node& d, const glm::dvec3& p) {
    const LD x = p.x, y = p.y, z = p.z;
    const glm::dvec3 s = d.size;
    switch (d.shape) {
        case Shape::sphere: return std::sqrt(x * x + y * y + z * z) - s.x;
        case Shape::box: return std::max({std::abs(x) - s.x, std::abs(y) - s.y, std::abs(z) - s.z});
        case Shape::cylinder: return std::max<LD>(std::sqrt(x * x + y * y) - s.x, std::abs(z) - s.z);
        case Shape::cone: {
            const LD r = s.x + (LD(s.y) - s.x) * (z + s.z) / (2 * LD(s.z));
            return std::max<LD>(std::sqrt(x * x + y * y) - r, std::abs(z) - s.z);
        }
        case Shape::torus: {
            const LD a = std::sqrt(x * x + y * y) - s.x;
            return std::sqrt(a * a + z * z) - s.y;
        }
        case Shape::halfspace: return z;
        case Shape::quadric: {
            LD v = 0;
            const LD X[4] = {x, y, z, 1};
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j) v += X[i] * LD(d.Q[j][i]) * X[j];
            return v;
        }
    }
    return 0;
}

// The meridian (ρ, z) outline of a solid of revolution as a polyline (cylinder, cone): the distance to it,
// minimised over a dense sampling and refined by golden-section search on each edge, in long double.
inline LD polyline_distance(LD rho, LD z, const std::vector<std::pair<LD, LD>>& pts) {
    LD best = std::numeric_limits<LD>::infinity();
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
        auto dist = [&](LD s) {
            const LD px = pts[i].first + s * (pts[i + 1].first - pts[i].first);
            const LD pz = pts[i].second + s * (pts[i + 1].second - pts[i].second);
            return std::sqrt((px - rho) * (px - rho) + (pz - z) * (pz - z));
        };
        LD a = 0, b = 1;  // the distance to a segment is convex in s: golden section finds its minimum
        for (int it = 0; it < 200; ++it) {
            const LD m1 = a + (b - a) * 0.381966011250105L, m2 = a + (b - a) * 0.618033988749895L;
            if (dist(m1) < dist(m2)) b = m2;
            else a = m1;
        }
        best = std::min({best, dist(a), dist(0), dist(1)});
    }
    return best;
}

// The exact signed distance, by formulas other than the reference's (box and cylinder through the nearest point
// of the clamped region, cone through a polyline search).
inline LD ref_distance(const Node& d, const glm::dvec3& p) {
    const glm::dvec3 s = d.size;
    const LD x = p.x, y = p.y, z = p.z;
    switch (d.shape) {
        case Shape::box: {
            const LD cx = std::clamp<LD>(x, -s.x, s.x), cy = std::clamp<LD>(y, -s.y, s.y),
                     cz = std::clamp<LD>(z, -s.z, s.z);
            const LD out = std::sqrt((x - cx) * (x - cx) + (y - cy) * (y - cy) + (z - cz) * (z - cz));
            if (out > 0) return out;
            return -std::min({s.x - std::abs(x), s.y - std::abs(y), s.z - std::abs(z)});
        }
        case Shape::cylinder:
        case Shape::cone: {
            const LD r1 = s.x, r2 = d.shape == Shape::cylinder ? s.x : s.y, h = s.z;
            const LD rho = std::sqrt(x * x + y * y);
            const LD dd = polyline_distance(rho, z, {{0, -h}, {r1, -h}, {r2, h}, {0, h}});
            return ref_implicit(d, p) <= 0 ? -dd : dd;
        }
        default: return ref_implicit(d, p);  // sphere, torus, halfspace: their implicit forms are distances
    }
}

// Inside test of a whole tree (closed sets; union/intersection/difference as sets; blend by its field is not
// supported here).
inline bool ref_inside(const Tree& t, int i, const glm::dvec3& x) {
    const Node& d = t.nodes[i];
    switch (d.op) {
        case Op::leaf: return ref_implicit(d, to_local(d.M, x)) <= 0;
        case Op::unite: return ref_inside(t, d.a, x) || ref_inside(t, d.b, x);
        case Op::intersect: return ref_inside(t, d.a, x) && ref_inside(t, d.b, x);
        case Op::subtract: return ref_inside(t, d.a, x) && !ref_inside(t, d.b, x);
        default: return false;
    }
}
inline bool ref_inside(const Tree& t, const glm::dvec3& x) { return ref_inside(t, t.root, x); }

// ---- checking span lists against the definition ------------------------------------------------------------

// Checks that `got` is a sorted list of disjoint positive-length spans whose interiors are inside (sampled) and whose
// gaps are outside, with every finite end where the inside test changes (within tol · scale of the ray parameter).
// `inside(t)` is the reference membership of the point at t. Returns an empty string or what went wrong.
template <class Inside>
std::string check_spans(const std::vector<Span>& got, Inside inside, double t_lo, double t_hi, double tol) {
    std::ostringstream err;
    err.precision(12);
    for (std::size_t i = 0; i < got.size(); ++i) {
        if (!(got[i].t0 < got[i].t1)) err << "span " << i << " has t0 >= t1; ";
        if (i > 0 && !(got[i - 1].t1 < got[i].t0)) err << "spans " << i - 1 << " and " << i << " overlap or touch; ";
    }
    if (!err.str().empty()) return err.str();
    // Sample the window: each sample inside a span (away from its ends) must be inside, each outside all spans
    // (away from the ends) outside.
    const int n = 2000;
    for (int k = 0; k < n; ++k) {
        const double t = t_lo + (t_hi - t_lo) * (k + 0.37) / n;  // off the round values where lists may touch
        bool in_span = false, near_end = false;
        for (const Span& s : got) {
            if (t > s.t0 && t < s.t1) in_span = true;
            if ((std::isfinite(s.t0) && std::abs(t - s.t0) <= tol) || (std::isfinite(s.t1) && std::abs(t - s.t1) <= tol))
                near_end = true;
        }
        if (near_end) continue;
        if (in_span != inside(t)) {
            err << "at t = " << t << " the reference says " << (inside(t) ? "inside" : "outside") << " but the spans "
                << str(got) << " say " << (in_span ? "inside" : "outside");
            return err.str();
        }
    }
    return "";
}

// ---- the calls with out-lists, in one expression --------------------------------------------------------------

// A list that was used before: reused lists hold stale spans, which the call must replace.
inline std::vector<Span> stale_list() { return {Span{-7e7, -6e7, glm::dvec3(0, 0, 1), glm::dvec3(0, 0, 1)}}; }

// primitive_spans into a reused (stale) list; returns what the call left in it.
inline std::vector<Span> spans_of(const Node& d, const Ray& r) {
    std::vector<Span> out = stale_list();
    primitive_spans(d, r, out);
    return out;
}
// combine into a reused (stale) list; returns what the call left in it.
inline std::vector<Span> combined(Op o, const std::vector<Span>& a, const std::vector<Span>& b) {
    std::vector<Span> out = stale_list();
    combine(o, a, b, out);
    return out;
}
// ray_spans on the tree prepared by the given prepare(), with the caller's lists: the tree's spans (lists[root]).
inline std::vector<Span> tree_spans(const PreparedTree& p, const Ray& r, SpanLists& lists) {
    ray_spans(p, r, lists);
    REQUIRE_MESSAGE(lists.size() == p.nodes.size(), "ray_spans must resize lists to one list per node ("
                                                         << p.nodes.size() << "), got " << lists.size() << " lists");
    return lists[p.root];
}
inline std::vector<Span> tree_spans(const Tree& t, const Ray& r) {
    SpanLists lists;
    return tree_spans(prepare(t), r, lists);
}
// first_hit on the tree prepared by prepare(), with fresh lists.
inline std::optional<Hit> hit_of(const Tree& t, const Ray& r, double t_min) {
    SpanLists lists;
    return first_hit(prepare(t), r, t_min, lists);
}

// Whether p lies on the surface of some leaf of t (within tol): an independent check that a point is on the
// boundary of the tree's solid.
inline bool on_some_leaf(const Tree& t, const glm::dvec3& p, double tol) {
    for (const Node& d : t.nodes)
        if (d.op == Op::leaf && std::abs(double(ref_distance(d, to_local(d.M, p)))) <= tol) return true;
    return false;
}

// A tree from leaves in one line: op(a, b).
inline Tree op(Op o, const Tree& a, const Tree& b, double k = 0) { return combine_trees(o, a, b, k); }
inline Tree unit_cube_at(glm::dvec3 lo) { return leaf(Shape::box, glm::dvec3(0.5), translate(lo + glm::dvec3(0.5))); }

// The CSG logo: (cube ∩ sphere) − three cylinders along x, y, z.
inline Tree logo() {
    const Tree body = op(Op::intersect, leaf(Shape::box, glm::dvec3(1.0)), leaf(Shape::sphere, {1.3, 0, 0}));
    const Tree cz = leaf(Shape::cylinder, {0.55, 0.55, 1.6});
    const Tree cx = leaf(Shape::cylinder, {0.55, 0.55, 1.6}, rotate(90, {0, 1, 0}));
    const Tree cy = leaf(Shape::cylinder, {0.55, 0.55, 1.6}, rotate(90, {1, 0, 0}));
    return op(Op::subtract, body, op(Op::unite, op(Op::unite, cx, cy), cz));
}

// The octahedron |x| + |y| + |z| ≤ r as the intersection of 8 half-spaces.
inline Tree octahedron(double r) {
    Tree t;
    bool first = true;
    for (int sx = -1; sx <= 1; sx += 2)
        for (int sy = -1; sy <= 1; sy += 2)
            for (int sz = -1; sz <= 1; sz += 2) {
                const glm::dvec3 n = glm::normalize(glm::dvec3(sx, sy, sz));
                // local z ≤ 0 moved so that its normal is n and its plane is n·x = r/√3
                const glm::dvec3 zax(0, 0, 1);
                const glm::dvec3 axis = glm::cross(zax, n);
                const double ang = std::acos(glm::dot(zax, n)) * 180 / pi;
                const glm::dmat4 M = translate(n * (r / std::sqrt(3.0))) * rotate(ang, axis);
                const Tree h = leaf(Shape::halfspace, glm::dvec3(0), M);
                t = first ? h : op(Op::intersect, t, h);
                first = false;
            }
    return t;
}

// |x − y| <= tol · max(scale, |y|)
inline bool close(double x, double y, double tol, double scale = 1.0) {
    return std::abs(x - y) <= tol * std::max(scale, std::abs(y));
}

}  // namespace lab07
