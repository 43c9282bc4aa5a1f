#pragma once
// Lab 05 test helpers: expected values computed independently of the reference — the Bernstein form and its
// derivatives in long double from exact binomials (power of t and 1 − t), dense sampling refined by golden-section
// search in long double, shoelace areas of finely sampled outlines. No helper calls a function you write.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
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

//! The patch of degree (n, m) of the tensor polynomial S(u, v) = Σ c_ab u^a v^b (coeff(a, b) = c_ab): control
//! points P_ij = Σ_(a ≤ i, b ≤ j) [C(i, a) / C(n, a)] [C(j, b) / C(m, b)] c_ab (the power-to-Bernstein conversion).
template <class F>
BezierPatch patch_from_power(int n, int m, F coeff) {
    BezierPatch S{n, m, {}};
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= m; ++j) {
            V3L p{};
            for (int a = 0; a <= i; ++a)
                for (int b = 0; b <= j; ++b)
                    p = p + (binom(i, a) / binom(n, a) * binom(j, b) / binom(m, b)) * L(coeff(a, b));
            S.points.push_back(D(p));
        }
    return S;
}
//! The unit normal by the contract (bezier.hpp, patch_normal), in long double: unit(S_u × S_v) where
//! |S_u × S_v| > 1e-12 (|S_u| + |S_v|)²; otherwise the limit along the diagonal towards the centre (σ = +1 for a
//! parameter ≤ ½), found numerically — unit normals at δ = 1e-7 and 2e-7 extrapolated to δ = 0 (Richardson) —
//! so a test of the first-order formula does not use that formula. (Not for points where that limit is 0 to first
//! order too: the contract then moves by 1e-6; the tests state those cases apart.)
inline glm::dvec3 ref_normal(const BezierPatch& S, LD u, LD v) {
    const V3L su = ref_patch(S, u, v, 1, 0), sv = ref_patch(S, u, v, 0, 1), c = cross(su, sv);
    const LD scale = norm(su) + norm(sv);
    if (norm(c) > 1e-12L * scale * scale) return D((1 / norm(c)) * c);
    const LD ru = u <= 0.5L ? 1 : -1, rv = v <= 0.5L ? 1 : -1;
    auto unit_at = [&](LD d) {
        const V3L n = cross(ref_patch(S, u + ru * d, v + rv * d, 1, 0), ref_patch(S, u + ru * d, v + rv * d, 0, 1));
        return (1 / norm(n)) * n;
    };
    const V3L e = LD(2) * unit_at(1e-7L) - unit_at(2e-7L);
    return D((1 / norm(e)) * e);
}

//! The mesh tessellate_patches must return (bezier.hpp), built independently: samples i-major per patch in
//! order, positions from the Bernstein form in long double; a border sample within tol of an earlier border
//! vertex is the earliest such one (a linear scan); triangles (a, b, c), (a, c, d) per cell, dropped when two
//! vertices are one, (x, z, y) when flipped. `sample` names each vertex's first sample (patch, i, j).
struct ExpectedMesh {
    std::vector<glm::dvec3> positions;
    std::vector<std::array<std::uint32_t, 3>> faces;
    struct Sample {
        int patch, i, j;
    };
    std::vector<Sample> sample;
};
inline ExpectedMesh expected_tessellation(const std::vector<BezierPatch>& patches, int n, double tol, bool flip) {
    ExpectedMesh m;
    std::vector<std::uint32_t> border;
    for (int p = 0; p < int(patches.size()); ++p) {
        std::vector<std::uint32_t> id;
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j) {
                const glm::dvec3 x = D(ref_patch(patches[p], LD(i) / n, LD(j) / n));
                const bool on_border = i == 0 || j == 0 || i == n || j == n;
                std::uint32_t v = std::uint32_t(m.positions.size());
                bool found = false;
                if (on_border)
                    for (std::uint32_t k : border)
                        if (glm::length(m.positions[k] - x) <= tol) {
                            v = k;
                            found = true;
                            break;
                        }
                if (!found) {
                    m.positions.push_back(x);
                    m.sample.push_back({p, i, j});
                    if (on_border) border.push_back(v);
                }
                id.push_back(v);
            }
        auto tri = [&](std::uint32_t x, std::uint32_t y, std::uint32_t z) {
            if (x == y || y == z || x == z) return;
            m.faces.push_back(flip ? std::array<std::uint32_t, 3>{x, z, y} : std::array<std::uint32_t, 3>{x, y, z});
        };
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const std::uint32_t a = id[i * (n + 1) + j], b = id[(i + 1) * (n + 1) + j],
                                    c = id[(i + 1) * (n + 1) + j + 1], d = id[i * (n + 1) + j + 1];
                tri(a, b, c);
                tri(a, c, d);
            }
    }
    return m;
}
//! Compares a PatchMesh with the expected one: the same vertices in the same order (within rel · (1 + scale)), the
//! same faces, and each normal the contract's normal at the vertex's first sample (negated when flipped), within
//! 1e-9. Returns "" or the first difference.
inline std::string compare_mesh(const PatchMesh& got, const ExpectedMesh& want, const std::vector<BezierPatch>& patches,
                                int n, bool flip, double rel = 1e-13, double scale = 4) {
    std::ostringstream out;
    if (got.soup.n_vertices() != want.positions.size() || got.normals.size() != want.positions.size())
        out << "expected " << want.positions.size() << " vertices (and as many normals), got " << got.soup.n_vertices()
            << " vertices and " << got.normals.size() << " normals";
    else if (got.soup.n_faces() != want.faces.size())
        out << "expected " << want.faces.size() << " triangles, got " << got.soup.n_faces();
    if (!out.str().empty()) return out.str();
    for (std::size_t k = 0; k < want.positions.size(); ++k) {
        const auto& smp = want.sample[k];
        if (!close3(got.soup.positions[k], want.positions[k], rel, scale))
            return "vertex " + std::to_string(k) + " (patch " + std::to_string(smp.patch) + ", sample (" +
                   std::to_string(smp.i) + ", " + std::to_string(smp.j) + ")): expected " + str(want.positions[k]) +
                   ", got " + str(got.soup.positions[k]);
        glm::dvec3 nrm = ref_normal(patches[smp.patch], LD(smp.i) / n, LD(smp.j) / n);
        if (flip) nrm = -nrm;
        if (!close3(got.normals[k], nrm, 1e-9))
            return "normal of vertex " + std::to_string(k) + " (patch " + std::to_string(smp.patch) + ", sample (" +
                   std::to_string(smp.i) + ", " + std::to_string(smp.j) + ")): expected " + str(nrm) + ", got " +
                   str(got.normals[k]);
    }
    for (std::size_t f = 0; f < want.faces.size(); ++f) {
        const auto t = got.soup.face(f);
        const auto& w = want.faces[f];
        if (t.size() != 3 || t[0] != w[0] || t[1] != w[1] || t[2] != w[2])
            return "triangle " + std::to_string(f) + ": expected (" + std::to_string(w[0]) + ", " +
                   std::to_string(w[1]) + ", " + std::to_string(w[2]) + "), got (" +
                   (t.size() == 3 ? std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2])
                                  : std::to_string(t.size()) + " vertices") +
                   ")";
    }
    return "";
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

//! ∫_a^b |C'(t)| dt by composite Simpson (2048 panels) in long double: for curves whose speed is smooth on [a, b]
//! (split a kinked curve at its cusp: ref_length(P, a, t0) + ref_length(P, t0, b)).
inline LD ref_length(const Poly3& P, LD a, LD b) {
    const int N = 2048;
    const LD h = (b - a) / N;
    LD s = 0;
    for (int i = 0; i <= N; ++i) {
        const LD w = (i == 0 || i == N) ? 1 : (i % 2 ? 4 : 2);
        s += w * norm(ref_deriv(P, a + i * h, 1));
    }
    return s * h / 3;
}
//! The length on [a, b] of a curve whose speed has one kink at t0 (a cusp), split there.
inline LD ref_length_kinked(const Poly3& P, LD a, LD b, LD t0) {
    if (t0 <= a || t0 >= b) return ref_length(P, a, b);
    return ref_length(P, a, t0) + ref_length(P, t0, b);
}

//! A cubic with a cusp at t0: C'(t) = (t − t0)(u0 + u1 t) = c0 + c1 t + c2 t², C(0) = p0. The hodograph's
//! Bernstein coefficients are D_0 = c0, D_1 = c0 + c1/2, D_2 = c0 + c1 + c2 and P_(k+1) = P_k + D_k / 3. (Rounding
//! of the control points leaves |C'| ~ 1e-16 at the cusp: its speed still has a kink there.)
inline Poly3 cusp_cubic(double t0, const glm::dvec3& u0, const glm::dvec3& u1, const glm::dvec3& p0 = {0, 0, 0}) {
    const glm::dvec3 c0 = -t0 * u0, c1 = u0 - t0 * u1, c2 = u1;
    const glm::dvec3 D0 = c0, D1 = c0 + 0.5 * c1, D2 = c0 + c1 + c2;
    return {p0, p0 + D0 / 3.0, p0 + (D0 + D1) / 3.0, p0 + (D0 + D1 + D2) / 3.0};
}

//! The N-point Gauss–Legendre nodes and weights on [−1, 1] in long double: Newton on the Legendre polynomial P_N
//! (three-term recurrence) from cos(π (i + 3/4) / (N + 1/2)).
struct GaussRule {
    std::vector<LD> x, w;
};
inline GaussRule gauss_legendre(int N) {
    GaussRule r;
    for (int i = 0; i < N; ++i) {
        LD z = std::cos(std::numbers::pi_v<LD> * (i + 0.75L) / (N + 0.5L)), dp = 0;
        for (int it = 0; it < 100; ++it) {
            LD p0 = 1, p1 = z;
            for (int k = 2; k <= N; ++k) {
                const LD p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = N * (z * p1 - p0) / (z * z - 1);
            const LD dz = p1 / dp;
            z -= dz;
            if (std::abs(dz) < 1e-19L) break;
        }
        r.x.push_back(z);
        r.w.push_back(2 / ((1 - z * z) * dp * dp));
    }
    return r;
}
//! The parameters in (a, b) where the speed |C'| is stationary: sign changes of C'(t) · C''(t) on 4096 samples
//! (and exact zeros), refined by bisection in long double.
inline std::vector<LD> speed_stationary(const Poly3& P, LD a, LD b) {
    auto g = [&](LD t) { return dot(ref_deriv(P, t, 1), ref_deriv(P, t, 2)); };
    std::vector<LD> out;
    const int N = 4096;
    LD t0 = a, g0 = g(a);
    for (int i = 1; i <= N; ++i) {
        const LD t1 = a + (b - a) * i / N, g1 = g(t1);
        if (g1 == 0 && i < N) out.push_back(t1);
        if ((g0 < 0 && g1 > 0) || (g0 > 0 && g1 < 0)) {
            LD lo = t0, hi = t1;
            for (int it = 0; it < 80; ++it) {
                const LD m = (lo + hi) / 2;
                ((g(m) < 0) == (g0 < 0) ? lo : hi) = m;
            }
            out.push_back((lo + hi) / 2);
        }
        t0 = t1;
        g0 = g1;
    }
    return out;
}
//! The contract's arc length (bezier.hpp) computed independently in long double: [a, b] cut at the speed's
//! stationary points; on each piece the 10-point value where the 5- and 10-point values differ by at most the
//! interval's share of T (T · its length / (b − a), T = max(tol, 1e-14 (b − a) max_k |n ΔP_k|)), else the two
//! halves. `margin` is the smallest relative distance of a decision from its threshold: a test uses inputs where no
//! decision is close to a tie (the student's rounding cannot flip one).
struct AdaptiveLength {
    LD value = 0, margin = 1e30L;
    int leaves = 0;
};
inline AdaptiveLength adaptive_length(const Poly3& P, double a, double b, double tol) {
    static const GaussRule g5 = gauss_legendre(5), g10 = gauss_legendre(10);
    const int n = int(P.size()) - 1;
    LD dmax = 0;
    for (int k = 0; k < n; ++k) dmax = std::max(dmax, norm(LD(n) * (L(P[k + 1]) - L(P[k]))));
    const LD T = std::max<LD>(tol, 1e-14L * (LD(b) - a) * dmax);
    AdaptiveLength out;
    auto rule = [&](const GaussRule& g, LD lo, LD hi) {
        const LD h = (hi - lo) / 2, m = (lo + hi) / 2;
        LD s = 0;
        for (std::size_t i = 0; i < g.x.size(); ++i) s += g.w[i] * norm(ref_deriv(P, m + h * g.x[i], 1));
        return s * h;
    };
    auto adapt = [&](auto&& self, LD lo, LD hi) -> void {
        const LD v5 = rule(g5, lo, hi), v10 = rule(g10, lo, hi), share = T * (hi - lo) / (LD(b) - a);
        const LD diff = std::abs(v10 - v5);
        out.margin = std::min(out.margin, std::abs(diff - share) / share);
        if (diff <= share) {
            out.value += v10;
            ++out.leaves;
            return;
        }
        self(self, lo, (lo + hi) / 2);
        self(self, (lo + hi) / 2, hi);
    };
    std::vector<LD> ends{LD(a)};
    for (LD t : speed_stationary(P, 0, 1))
        if (t > a && t < b) ends.push_back(t);
    ends.push_back(b);
    for (std::size_t k = 0; k + 1 < ends.size(); ++k) adapt(adapt, ends[k], ends[k + 1]);
    return out;
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
