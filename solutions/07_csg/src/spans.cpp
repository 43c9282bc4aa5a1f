// Task 4: a ray's inside intervals in one primitive (handout §5).
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <glm/geometric.hpp>

#include "geolab/csg.hpp"

namespace geolab::csg {

// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.
namespace {
const double inf = std::numeric_limits<double>::infinity();

glm::dvec3 unit_or_zero(const glm::dvec3& v) {
    const double l = glm::length(v);
    return l > 0 ? v / l : glm::dvec3(0.0);
}

// Clip a span to the slab lo < o + t d < hi along one axis (normals ∓axis at the two planes). A ray parallel to
// the slab keeps the span only when strictly between the planes (a ray in a face only touches the solid).
void clip_slab(Span& s, double o, double d, double lo, double hi, const glm::dvec3& axis) {
    if (d == 0) {
        if (!(o > lo && o < hi)) s.t1 = s.t0 = 0;  // empty
        return;
    }
    double ta = (lo - o) / d, tb = (hi - o) / d;
    glm::dvec3 na = -axis, nb = axis;
    if (ta > tb) {
        std::swap(ta, tb);
        std::swap(na, nb);
    }
    if (ta > s.t0) {
        s.t0 = ta;
        s.n0 = na;
    }
    if (tb < s.t1) {
        s.t1 = tb;
        s.n1 = nb;
    }
}

// Appends to out the spans where α t² + β t + γ ≤ 0 (touching roots give nothing); normals from `grad` at the
// finite ends.
template <class Grad>
void quadratic_spans(double al, double be, double ga, const Ray& r, Grad grad, std::vector<Span>& out) {
    auto normal = [&](double t) { return unit_or_zero(grad(r.origin + t * r.direction)); };
    auto span = [&](double t0, double t1) {
        Span s;
        s.t0 = t0;
        s.t1 = t1;
        if (std::isfinite(t0)) s.n0 = normal(t0);
        if (std::isfinite(t1)) s.n1 = normal(t1);
        out.push_back(s);
    };
    if (al == 0) {
        if (be == 0) {
            if (ga < 0) span(-inf, inf);
        } else if (be > 0) {
            span(-inf, -ga / be);
        } else {
            span(-ga / be, inf);
        }
        return;
    }
    const double disc = be * be - 4 * al * ga;
    if (!(disc > 0)) {
        if (al < 0) span(-inf, inf);
        return;
    }
    const double q = -0.5 * (be + std::copysign(std::sqrt(disc), be));  // never 0: Δ > 0
    double t0 = q / al, t1 = ga / q;
    if (t0 > t1) std::swap(t0, t1);
    if (al > 0) {
        span(t0, t1);
    } else {
        span(-inf, t0);
        span(t1, inf);
    }
}

// Removes the spans that clipping left empty (t0 ≥ t1).
void keep_positive(std::vector<Span>& v) {
    std::erase_if(v, [](const Span& s) { return !(s.t0 < s.t1); });
}

void torus_spans(const Node& leaf, const Ray& r, std::vector<Span>& out) {
    const double R = leaf.size.x, rr = leaf.size.y;
    // Well-conditioned quartic: from the point of the line nearest the centre, along the unit direction u, in
    // s = (t − t_c)·|d| (a far origin or a very long or short direction would otherwise lose the roots).
    const double L = glm::length(r.direction);
    const glm::dvec3 u = r.direction / L;
    const double t_c = -glm::dot(r.origin, r.direction) / (L * L);
    const glm::dvec3 o = r.origin + t_c * r.direction;
    const double bound = 1.01 * (R + rr);
    const double oo = glm::dot(o, o);
    if (oo >= bound * bound) return;
    const double hi = std::sqrt(bound * bound - oo), lo = -hi;
    // |p|² = s² + |o|² (o ⟂ u), so (|p|² + R² − r²)² − 4R²(x² + y²) = (s² + C)² − 4R²(ρ-terms) with no odd |p|² terms
    const double C = oo + R * R - rr * rr;
    const double dxy = u.x * u.x + u.y * u.y, odxy = o.x * u.x + o.y * u.y, oxy = o.x * o.x + o.y * o.y;
    const std::vector<double> c = {C * C - 4 * R * R * oxy, -8 * R * R * odxy, 2 * C - 4 * R * R * dxy, 0.0, 1.0};
    std::vector<double> ends = real_roots(c, lo, hi);
    ends.push_back(hi);
    auto inside = [&](double s) {
        const glm::dvec3 p = o + s * u;
        return std::hypot(std::hypot(p.x, p.y) - R, p.z) < rr;
    };
    auto grad = [&](double s) {
        const glm::dvec3 p = o + s * u;
        const double rho = std::hypot(p.x, p.y);
        // ∇ of the distance |(ρ − R, z)| − r: the direction from the tube's centre circle to p
        const glm::dvec3 c = rho > 0 ? glm::dvec3(R * p.x / rho, R * p.y / rho, 0.0) : glm::dvec3(R, 0, 0);
        return unit_or_zero(p - c);
    };
    // The pieces between lo, the roots and hi: inside or outside throughout, read off their midpoints.
    double a = lo;
    for (const double b : ends) {
        const double s0 = std::exchange(a, b);  // the piece [s0, b]
        if (!(s0 < b) || !inside(0.5 * (s0 + b))) continue;
        const double t0 = t_c + s0 / L, t1 = t_c + b / L;
        if (!out.empty() && out.back().t1 == t0) {  // a touching root inside: one span
            out.back().t1 = t1;
            out.back().n1 = grad(b);
            continue;
        }
        out.push_back(Span{t0, t1, grad(s0), grad(b)});
    }
}
}  // namespace
// END SOLUTION

void primitive_spans(const Node& leaf, const Ray& r, std::vector<Span>& out) {
    // BEGIN SOLUTION
    if (leaf.op != Op::leaf) throw std::invalid_argument("primitive_spans: the node is not a leaf");
    const glm::dvec3 o = r.origin, d = r.direction;
    if (d == glm::dvec3(0.0)) throw std::invalid_argument("primitive_spans: zero direction");
    out.clear();
    const glm::dvec3 s = leaf.size;
    switch (leaf.shape) {
        case Shape::sphere:
            quadratic_spans(glm::dot(d, d), 2 * glm::dot(o, d), glm::dot(o, o) - s.x * s.x, r,
                            [](glm::dvec3 p) { return p; }, out);
            keep_positive(out);
            return;
        case Shape::box: {
            Span sp{-inf, inf, glm::dvec3(0), glm::dvec3(0)};
            clip_slab(sp, o.x, d.x, -s.x, s.x, {1, 0, 0});
            clip_slab(sp, o.y, d.y, -s.y, s.y, {0, 1, 0});
            clip_slab(sp, o.z, d.z, -s.z, s.z, {0, 0, 1});
            if (sp.t0 < sp.t1) out.push_back(sp);
            return;
        }
        case Shape::cylinder:
        case Shape::cone: {
            // radius(z) = a z + b; the region x² + y² ≤ radius(z)² (both nappes of a cone), then the slab |z| ≤ h
            const double h = s.z;
            const double r1 = s.x, r2 = leaf.shape == Shape::cylinder ? s.x : s.y;
            const double a = (r2 - r1) / (2 * h), b = 0.5 * (r1 + r2);
            const double rz = a * o.z + b;
            const double al = d.x * d.x + d.y * d.y - a * a * d.z * d.z;
            const double be = 2 * (o.x * d.x + o.y * d.y - a * d.z * rz);
            const double ga = o.x * o.x + o.y * o.y - rz * rz;
            quadratic_spans(al, be, ga, r, [a, b](glm::dvec3 p) { return glm::dvec3(p.x, p.y, -a * (a * p.z + b)); },
                            out);
            for (Span& sp : out) clip_slab(sp, o.z, d.z, -h, h, {0, 0, 1});
            keep_positive(out);
            return;
        }
        case Shape::torus: torus_spans(leaf, r, out); return;
        case Shape::halfspace: {
            Span sp{-inf, inf, glm::dvec3(0), glm::dvec3(0)};
            if (d.z == 0) {
                if (o.z < 0) out.push_back(sp);
                return;
            }
            const double t = -o.z / d.z;
            if (d.z > 0) {
                sp.t1 = t;
                sp.n1 = {0, 0, 1};
            } else {
                sp.t0 = t;
                sp.n0 = {0, 0, 1};
            }
            out.push_back(sp);
            return;
        }
        case Shape::quadric: {
            const glm::dmat4& Q = leaf.Q;
            const glm::dvec4 X(o, 1.0), D(d, 0.0);
            const glm::dvec4 QX = Q * X, QD = Q * D;
            quadratic_spans(glm::dot(D, QD), 2 * glm::dot(X, QD), glm::dot(X, QX), r,
                            [&Q](glm::dvec3 p) { return glm::dvec3(Q * glm::dvec4(p, 1.0)); }, out);
            keep_positive(out);
            return;
        }
    }
    throw std::invalid_argument("primitive_spans: unknown shape");
    // END SOLUTION
}

}  // namespace geolab::csg
