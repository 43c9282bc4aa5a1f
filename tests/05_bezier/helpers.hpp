#pragma once
// Lab 05 test helpers: expected values computed independently of the reference — the Bernstein form and its
// derivatives in long double from exact binomials (power of t and 1 − t), dense sampling refined by golden-section
// search in long double, shoelace areas of finely sampled outlines. No helper calls a function you write.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "geolab/bezier.hpp"
#include "geolab/bezier_data.hpp"
#include "geolab/grading/test.hpp"

namespace lab05 {

using namespace geolab::bezier;
using geolab::BezierPatch;
using geolab::GlyphOutline;
using geolab::QuadSegment;
using LD = long double;
constexpr double pi = std::numbers::pi;

struct V3L {
    LD x = 0, y = 0, z = 0;
};
inline V3L operator+(V3L a, V3L b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3L operator-(V3L a, V3L b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3L operator*(LD s, V3L a) { return {s * a.x, s * a.y, s * a.z}; }
inline LD dot(V3L a, V3L b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V3L cross(V3L a, V3L b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline LD norm(V3L a) { return std::sqrt(dot(a, a)); }
inline V3L L(const glm::dvec3& v) { return {v.x, v.y, v.z}; }
inline glm::dvec3 D(V3L v) { return {double(v.x), double(v.y), double(v.z)}; }

inline std::string str(const glm::dvec3& v) {
    std::ostringstream s;
    s.precision(17);
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}
inline std::string str(const glm::dvec2& v) {
    std::ostringstream s;
    s.precision(17);
    s << "(" << v.x << ", " << v.y << ")";
    return s.str();
}
template <class P>
std::string str(const std::vector<P>& ps) {
    std::string s = "[";
    for (std::size_t i = 0; i < ps.size(); ++i) s += (i ? ", " : "") + str(ps[i]);
    return s + "]";
}
inline std::string num(double x) {
    std::ostringstream s;
    s.precision(17);
    s << x;
    return s.str();
}

struct Rng {
    std::mt19937_64 gen;
    explicit Rng(std::uint64_t seed) : gen(seed) {}
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(gen); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(gen); }
    //! A dyadic number k/8 with |k| ≤ 8·r: exact in every de Casteljau step of small degree at dyadic t.
    double dyadic(int r) { return integer(-8 * r, 8 * r) / 8.0; }
    Poly3 poly(int n, double r = 4) {
        Poly3 P(n + 1);
        for (auto& p : P) p = {uniform(-r, r), uniform(-r, r), uniform(-r, r)};
        return P;
    }
    Poly3 dyadic_poly(int n, int r = 4) {
        Poly3 P(n + 1);
        for (auto& p : P) p = {dyadic(r), dyadic(r), dyadic(r)};
        return P;
    }
};

//! C(n, k) exactly (long double holds integers up to 2^64).
inline LD binom(int n, int k) {
    LD c = 1;
    for (int i = 1; i <= k; ++i) c = c * (n - k + i) / i;
    return std::round(c);
}
//! B_k^n(t) in long double.
inline LD bern(int n, int k, LD t) {
    if (k < 0 || k > n) return 0;
    return binom(n, k) * std::pow(t, LD(k)) * std::pow(1 - t, LD(n - k));
}
//! The d-th derivative of the Bézier curve at t, from the Bernstein form in long double:
//! C^(d)(t) = n!/(n−d)! Σ_k Δ^d P_k B_k^(n−d)(t).
inline V3L ref_deriv(const Poly3& P, LD t, int d = 0) {
    const int n = int(P.size()) - 1;
    if (d > n) return {};
    std::vector<V3L> diff(P.size());
    for (std::size_t i = 0; i < P.size(); ++i) diff[i] = L(P[i]);
    LD f = 1;
    for (int r = 0; r < d; ++r) {
        for (std::size_t i = 0; i + 1 < diff.size(); ++i) diff[i] = diff[i + 1] - diff[i];
        diff.pop_back();
        f *= (n - r);
    }
    // Σ C(m, k) t^k (1 − t)^(m − k) diff[k], m = n − d, with the powers and binomials built incrementally
    const int m = n - d;
    std::vector<LD> tp(m + 1, 1), sp(m + 1, 1);
    for (int k = 1; k <= m; ++k) tp[k] = tp[k - 1] * t, sp[k] = sp[k - 1] * (1 - t);
    V3L c{};
    LD b = 1;
    for (int k = 0; k <= m; ++k) {
        c = c + (b * tp[k] * sp[m - k]) * diff[k];
        b = b * (m - k) / (k + 1);
    }
    return f * c;
}
inline glm::dvec3 ref_point(const Poly3& P, LD t) { return D(ref_deriv(P, t, 0)); }
inline Poly3 lift(const Poly2& P) {
    Poly3 Q;
    for (const auto& p : P) Q.emplace_back(p, 0.0);
    return Q;
}

//! |a − b| ≤ rel · (1 + scale): vectors.
inline bool close3(const glm::dvec3& a, const glm::dvec3& b, double rel, double scale = 1.0) {
    return glm::length(a - b) <= rel * (1.0 + scale);
}
//! The largest |P_k|: the scale of a control polygon.
inline double scale_of(const Poly3& P) {
    double s = 0;
    for (const auto& p : P) s = std::max(s, glm::length(p));
    return s;
}

//! The tensor-product surface point or derivative (du, dv derivative orders) in long double, P_ij =
//! points[i (m + 1) + j], i along u.
inline V3L ref_patch(const BezierPatch& S, LD u, LD v, int du = 0, int dv = 0) {
    const int n = S.degree_u, m = S.degree_v;
    // Row curves in v for each i, then the u-curve of their values.
    Poly3 ucurve(n + 1);
    std::vector<V3L> vals(n + 1);
    for (int i = 0; i <= n; ++i) {
        Poly3 row(S.points.begin() + i * (m + 1), S.points.begin() + (i + 1) * (m + 1));
        vals[i] = ref_deriv(row, v, dv);
    }
    // the u-derivative of Σ_i B_i^n(u) vals[i] in long double
    std::vector<V3L> diff = vals;
    LD f = 1;
    for (int r = 0; r < du; ++r) {
        for (std::size_t i = 0; i + 1 < diff.size(); ++i) diff[i] = diff[i + 1] - diff[i];
        diff.pop_back();
        f *= (n - r);
    }
    V3L c{};
    for (int k = 0; k + du <= n; ++k) c = c + bern(n - du, k, u) * diff[k];
    return f * c;
}
inline BezierPatch random_patch(Rng& rng, int du, int dv, double r = 3) {
    BezierPatch S{du, dv, {}};
    for (int k = 0; k < (du + 1) * (dv + 1); ++k) S.points.push_back({rng.uniform(-r, r), rng.uniform(-r, r), rng.uniform(-r, r)});
    return S;
}

//! The teapot's patches (lib's reader of data/teapot.bpt).
inline const std::vector<BezierPatch>& teapot() {
    static const std::vector<BezierPatch> t = geolab::read_bpt(geolab::teapot_path());
    return t;
}

//! A quadratic segment's point in long double.
inline glm::dvec2 quad_at(const QuadSegment& s, LD t) {
    const LD a = (1 - t) * (1 - t), b = 2 * t * (1 - t), c = t * t;
    return {double(a * s[0].x + b * s[1].x + c * s[2].x), double(a * s[0].y + b * s[1].y + c * s[2].y)};
}
//! The shoelace area of a contour sampled at `per_segment` uniform steps per segment (long double).
inline LD sampled_area(const std::vector<QuadSegment>& c, int per_segment) {
    LD a = 0;
    for (const auto& s : c)
        for (int k = 0; k < per_segment; ++k) {
            const LD t0 = LD(k) / per_segment, t1 = LD(k + 1) / per_segment;
            const LD x0 = (1 - t0) * (1 - t0) * s[0].x + 2 * t0 * (1 - t0) * s[1].x + t0 * t0 * s[2].x;
            const LD y0 = (1 - t0) * (1 - t0) * s[0].y + 2 * t0 * (1 - t0) * s[1].y + t0 * t0 * s[2].y;
            const LD x1 = (1 - t1) * (1 - t1) * s[0].x + 2 * t1 * (1 - t1) * s[1].x + t1 * t1 * s[2].x;
            const LD y1 = (1 - t1) * (1 - t1) * s[0].y + 2 * t1 * (1 - t1) * s[1].y + t1 * t1 * s[2].y;
            a += x0 * y1 - x1 * y0;
        }
    return a / 2;
}
//! Distance from point q to the segment ab.
inline double seg_dist(const glm::dvec2& q, const glm::dvec2& a, const glm::dvec2& b) {
    const glm::dvec2 ab = b - a;
    const double l2 = glm::dot(ab, ab);
    const double t = l2 > 0 ? std::clamp(glm::dot(q - a, ab) / l2, 0.0, 1.0) : 0.0;
    return glm::length(q - (a + t * ab));
}
inline const GlyphOutline& glyph(char32_t c) {
    static std::vector<std::pair<char32_t, GlyphOutline>> cache;
    for (const auto& [k, g] : cache)
        if (k == c) return g;
    cache.emplace_back(c, geolab::read_glyph(geolab::default_font_path(), c));
    return cache.back().second;
}

//! The global minimum of |C(t) − q| over [0, 1]: dense sampling then golden-section search, long double.
inline LD ref_closest_t(const Poly3& P, const glm::dvec3& q) {
    auto dist = [&](LD t) { return norm(ref_deriv(P, t) - L(q)); };
    const int N = 1000;
    int best = 0;
    LD bd = dist(0);
    for (int i = 1; i <= N; ++i)
        if (LD d = dist(LD(i) / N); d < bd) bd = d, best = i;
    LD a = std::max<LD>(0, LD(best - 1) / N), b = std::min<LD>(1, LD(best + 1) / N);
    const LD g = (std::sqrt(LD(5)) - 1) / 2;
    for (int it = 0; it < 120; ++it) {
        const LD c = b - g * (b - a), d = a + g * (b - a);
        if (dist(c) < dist(d)) b = d; else a = c;
    }
    return (a + b) / 2;
}

}  // namespace lab05
