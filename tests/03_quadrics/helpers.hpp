#pragma once
// Lab 03 test helpers: inputs built by construction (canonical quadrics whose type is known, random rigid motions and
// affine maps) and expected values computed independently of the reference: polynomial expansions and Eigen in long
// double, bisection in long double, numerical integrals. No helper calls a function you write.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "geolab/grading/test.hpp"
#include "geolab/quadrics.hpp"

namespace lab03 {

using namespace geolab::quadrics;
using geolab::PolygonSoup;
using LD = long double;
using Mat4L = Eigen::Matrix<LD, 4, 4>;
constexpr double pi = std::numbers::pi;

inline std::string str(const glm::dvec3& v) {
    std::ostringstream s;
    s.precision(17);
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}
inline std::string str(const glm::dmat4& Q) {
    std::ostringstream s;
    s.precision(10);
    s << "[";
    for (int r = 0; r < 4; ++r) {
        s << (r ? "; " : "");
        for (int c = 0; c < 4; ++c) s << (c ? " " : "") << Q[c][r];
    }
    s << "]";
    return s.str();
}
inline std::string str(const Coefficients& k) {
    std::ostringstream s;
    s.precision(17);
    s << "{a=" << k.a << " b=" << k.b << " c=" << k.c << " f=" << k.f << " g=" << k.g << " h=" << k.h << " p=" << k.p
      << " q=" << k.q << " r=" << k.r << " d=" << k.d << "}";
    return s.str();
}
inline std::string str(const Ray& r) { return "ray " + str(r.origin) + " + t " + str(r.direction); }
inline std::string str(const Superquadric& s) {
    std::ostringstream o;
    o.precision(17);
    o << "superquadric radii " << str(s.radii) << " e1=" << s.e1 << " e2=" << s.e2;
    return o.str();
}

// |x - y| <= tol * max(scale, |y|)
inline bool close(double x, double y, double tol, double scale = 1.0) {
    return std::abs(x - y) <= tol * std::max(scale, std::abs(y));
}
inline double max_abs(const glm::dmat4& Q) {
    double m = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) m = std::max(m, std::abs(Q[i][j]));
    return m;
}

inline Mat4L to_eigen(const glm::dmat4& Q) {
    Mat4L m;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m(r, c) = Q[c][r];
    return m;
}
inline glm::dmat4 to_glm(const Mat4L& m) {
    glm::dmat4 Q;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) Q[c][r] = double(m(r, c));
    return Q;
}

// The matrix of the coefficients, written out here (not by your to_matrix).
inline glm::dmat4 matrix_of(const Coefficients& k) {
    Mat4L m;
    m << k.a, k.h, k.g, k.p, k.h, k.b, k.f, k.q, k.g, k.f, k.c, k.r, k.p, k.q, k.r, k.d;
    return to_glm(m);
}

// The lecture's polynomial, expanded in long double.
inline LD poly(const Coefficients& k, const glm::dvec3& v) {
    const LD x = v.x, y = v.y, z = v.z;
    return k.a * x * x + k.b * y * y + k.c * z * z + 2 * k.f * y * z + 2 * k.g * z * x + 2 * k.h * x * y +
           2 * k.p * x + 2 * k.q * y + 2 * k.r * z + k.d;
}
// XᵀQX in long double (symmetric part of Q).
inline LD value_ld(const glm::dmat4& Q, const glm::dvec3& v) {
    const LD X[4] = {v.x, v.y, v.z, 1};
    LD s = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) s += X[i] * LD(Q[j][i]) * X[j];
    return s;
}

// ---- random inputs ---------------------------------------------------------------------------------------------
struct Rng {
    std::mt19937_64 gen;
    explicit Rng(std::uint64_t seed) : gen(seed) {}
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(gen); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(gen); }
    glm::dvec3 unit() {
        for (;;) {
            glm::dvec3 v{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
            const double l = glm::length(v);
            if (l > 0.1 && l <= 1) return v / l;
        }
    }
};

// A random rotation (Rodrigues, long double) as a 4×4 matrix.
inline Mat4L rotation(Rng& rng) {
    const glm::dvec3 u = rng.unit();
    const LD a = rng.uniform(0, 2 * pi);
    Eigen::Matrix<LD, 3, 1> k(u.x, u.y, u.z);
    k.normalize();
    Eigen::Matrix<LD, 3, 3> K;
    K << 0, -k(2), k(1), k(2), 0, -k(0), -k(1), k(0), 0;
    const Eigen::Matrix<LD, 3, 3> R = Eigen::Matrix<LD, 3, 3>::Identity() + std::sin(a) * K + (1 - std::cos(a)) * K * K;
    Mat4L M = Mat4L::Identity();
    M.block<3, 3>(0, 0) = R;
    return M;
}
// A random rigid motion times a uniform scaling s: x ↦ s R x + t.
inline Mat4L similarity(Rng& rng, double s, double max_shift) {
    Mat4L M = rotation(rng);
    M.block<3, 3>(0, 0) *= LD(s);
    for (int i = 0; i < 3; ++i) M(i, 3) = rng.uniform(-max_shift, max_shift);
    return M;
}
// A random affine map with a well-conditioned linear part.
inline Mat4L affine(Rng& rng) {
    for (;;) {
        Mat4L M = Mat4L::Identity();
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 3; ++c) M(r, c) = rng.uniform(-1, 1) + (r == c ? 1.5 : 0.0);
            M(r, 3) = rng.uniform(-2, 2);
        }
        const auto sv = Eigen::JacobiSVD<Eigen::Matrix<LD, 3, 3>>(M.block<3, 3>(0, 0)).singularValues();
        if (sv(2) > 0.3) return M;
    }
}
// M⁻ᵀ Q M⁻¹ in long double (Eigen), symmetrized: the test's own transform.
inline Mat4L moved(const Mat4L& Q, const Mat4L& M) {
    const Mat4L Mi = M.inverse();
    const Mat4L R = Mi.transpose() * Q * Mi;
    return (R + R.transpose()) / 2;
}
inline glm::dvec3 apply(const Mat4L& M, const glm::dvec3& p) {
    Eigen::Matrix<LD, 4, 1> X(p.x, p.y, p.z, 1);
    const auto Y = M * X;
    return {double(Y(0)), double(Y(1)), double(Y(2))};
}

// ---- the 17 types, by construction ------------------------------------------------------------------------------
// The canonical Q of each type with semi-axes (a, b, c) (diagonal in x, y, z plus the needed linear term).
inline Mat4L canonical(QuadricType t, double a, double b, double c) {
    const LD A = 1 / (LD(a) * a), B = 1 / (LD(b) * b), C = 1 / (LD(c) * c);
    Mat4L Q = Mat4L::Zero();
    auto diag = [&](LD x, LD y, LD z, LD w) {
        Q(0, 0) = x;
        Q(1, 1) = y;
        Q(2, 2) = z;
        Q(3, 3) = w;
    };
    using T = QuadricType;
    switch (t) {
        case T::real_ellipsoid: diag(A, B, C, -1); break;
        case T::imaginary_ellipsoid: diag(A, B, C, 1); break;
        case T::hyperboloid_one_sheet: diag(A, B, -C, -1); break;
        case T::hyperboloid_two_sheets: diag(A, B, -C, 1); break;
        case T::real_cone: diag(A, B, -C, 0); break;
        case T::imaginary_cone: diag(A, B, C, 0); break;
        case T::elliptic_paraboloid: diag(A, B, 0, 0); Q(2, 3) = Q(3, 2) = -0.5; break;
        case T::hyperbolic_paraboloid: diag(A, -B, 0, 0); Q(2, 3) = Q(3, 2) = -0.5; break;
        case T::real_elliptic_cylinder: diag(A, B, 0, -1); break;
        case T::imaginary_elliptic_cylinder: diag(A, B, 0, 1); break;
        case T::hyperbolic_cylinder: diag(A, -B, 0, -1); break;
        case T::parabolic_cylinder: diag(A, 0, 0, 0); Q(2, 3) = Q(3, 2) = -LD(c); break;
        case T::real_intersecting_planes: diag(A, -B, 0, 0); break;
        case T::imaginary_intersecting_planes: diag(A, B, 0, 0); break;
        case T::real_parallel_planes: diag(1, 0, 0, -LD(a) * a); break;
        case T::imaginary_parallel_planes: diag(1, 0, 0, LD(a) * a); break;
        case T::coincident_planes: diag(A, 0, 0, 0); break;
    }
    return Q;
}
inline constexpr int n_types = 17;
inline QuadricType type_at(int i) { return static_cast<QuadricType>(i); }

// Points on the real canonical surfaces (parameters u, v in [0, 1)); false for the types with no real points.
inline bool canonical_point(QuadricType t, double a, double b, double c, double u, double v, glm::dvec3& out) {
    const double th = 2 * pi * u, s = 2 * v - 1, ph = pi * (v - 0.5);
    using T = QuadricType;
    switch (t) {
        case T::real_ellipsoid:
            out = {a * std::cos(ph) * std::cos(th), b * std::cos(ph) * std::sin(th), c * std::sin(ph)};
            return true;
        case T::hyperboloid_one_sheet:
            out = {a * std::cosh(s) * std::cos(th), b * std::cosh(s) * std::sin(th), c * std::sinh(s)};
            return true;
        case T::hyperboloid_two_sheets:
            out = {a * std::sinh(s) * std::cos(th), b * std::sinh(s) * std::sin(th), c * std::cosh(s) * (v < 0.5 ? -1 : 1)};
            return true;
        case T::real_cone: out = {a * s * std::cos(th), b * s * std::sin(th), c * s}; return true;
        case T::elliptic_paraboloid:
            out = {a * s * std::cos(th), b * s * std::sin(th), s * s};
            return true;
        case T::hyperbolic_paraboloid: {
            const double x = 2 * u - 1, y = s;
            out = {a * x, b * y, x * x - y * y};
            return true;
        }
        case T::real_elliptic_cylinder: out = {a * std::cos(th), b * std::sin(th), 2 * s}; return true;
        case T::hyperbolic_cylinder:
            out = {a * std::cosh(s) * (u < 0.5 ? -1 : 1), b * std::sinh(s), 2 * (2 * u - 1)};
            return true;
        case T::parabolic_cylinder: out = {s, 2 * u - 1, s * s / (2 * c * a * a)}; return true;
        case T::real_intersecting_planes: out = {a * s, b * s * (u < 0.5 ? -1 : 1), 2 * (2 * u - 1)}; return true;
        case T::imaginary_intersecting_planes: out = {0, 0, 2 * s}; return true;
        case T::imaginary_cone: out = {0, 0, 0}; return true;
        case T::real_parallel_planes: out = {a * (u < 0.5 ? -1 : 1), s, 2 * v}; return true;
        case T::coincident_planes: out = {0, s, 2 * u - 1}; return true;
        default: return false;
    }
}

// Axes, shuffled and drawn in [0.3, 3].
inline void random_axes(Rng& rng, double& a, double& b, double& c) {
    a = rng.uniform(0.3, 3);
    b = rng.uniform(0.3, 3);
    c = rng.uniform(0.3, 3);
}

// ---- rays: the expected roots by bisection in long double ------------------------------------------------------
// The quadratic along the ray, from Q, origin and direction in long double: p(t) = X(t)ᵀ Q X(t).
struct RayPoly {
    LD alpha, beta, gamma;
    LD operator()(LD t) const { return (alpha * t + beta) * t + gamma; }
};
inline RayPoly ray_poly(const glm::dmat4& Q, const Ray& r) {
    const LD X[4] = {r.origin.x, r.origin.y, r.origin.z, 1}, D[4] = {r.direction.x, r.direction.y, r.direction.z, 0};
    RayPoly p{0, 0, 0};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const LD q = Q[j][i];
            p.alpha += D[i] * q * D[j];
            p.beta += 2 * X[i] * q * D[j];
            p.gamma += X[i] * q * X[j];
        }
    return p;
}
// A root of f in [lo, hi] where f(lo), f(hi) differ in sign, by bisection to the last bit of long double.
template <class F>
LD bisect(const F& f, LD lo, LD hi) {
    LD flo = f(lo);
    for (int i = 0; i < 20000; ++i) {
        const LD mid = (lo + hi) / 2;
        if (mid <= lo || mid >= hi) break;
        const LD fm = f(mid);
        if (fm == 0) return mid;
        if ((fm < 0) == (flo < 0)) {
            lo = mid;
            flo = fm;
        } else {
            hi = mid;
        }
    }
    return (lo + hi) / 2;
}
// The roots of the ray's quadratic in [lo, hi], found by bracketing at the critical point and bisection (no formula).
inline std::vector<LD> roots_by_bisection(const RayPoly& p, LD lo, LD hi) {
    std::vector<LD> cuts{lo};
    if (p.alpha != 0) {
        const LD tc = -p.beta / (2 * p.alpha);
        if (tc > lo && tc < hi) cuts.push_back(tc);
    }
    cuts.push_back(hi);
    std::vector<LD> out;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        const LD a = cuts[i], b = cuts[i + 1];
        const LD fa = p(a), fb = p(b);
        if (fa == 0) {
            if (out.empty() || out.back() != a) out.push_back(a);
        } else if ((fa < 0) != (fb < 0) && fb != 0) {
            out.push_back(bisect(p, a, b));
        }
        if (fb == 0 && i + 2 == cuts.size()) out.push_back(b);
    }
    return out;
}

// The textbook formula (−β ± √Δ)/(2α): what a stable solver must NOT do (used to show a case is hard).
inline double naive_near_root(double alpha, double beta, double gamma) {
    const double s = std::sqrt(beta * beta - 4 * alpha * gamma);
    const double r1 = (-beta + s) / (2 * alpha), r2 = (-beta - s) / (2 * alpha);
    return std::abs(r1) < std::abs(r2) ? r1 : r2;
}

// ---- superquadrics ----------------------------------------------------------------------------------------------
// Barr's F, written here in long double.
inline LD F_ld(const Superquadric& s, const glm::dvec3& p) {
    const LD u = std::pow(std::abs(LD(p.x) / s.radii.x), LD(2) / s.e2) + std::pow(std::abs(LD(p.y) / s.radii.y), LD(2) / s.e2);
    return std::pow(u, LD(s.e2) / s.e1) + std::pow(std::abs(LD(p.z) / s.radii.z), LD(2) / s.e1);
}
// Gauss–Legendre on [0, 1] with n points per panel and m panels, after the substitution x = (1 − cos πs)/2 which
// flattens the endpoint singularities of (1 − x^k)^m.
template <class F>
LD integrate01(const F& f, int panels = 400) {
    static const LD xg[5] = {0, -0.5384693101056830910363144L, 0.5384693101056830910363144L,
                             -0.9061798459386639927976269L, 0.9061798459386639927976269L};
    static const LD wg[5] = {0.5688888888888888888888889L, 0.4786286704993664680412915L, 0.4786286704993664680412915L,
                             0.2369268850561890875142640L, 0.2369268850561890875142640L};
    const LD PI = 3.14159265358979323846264338327950288L;
    LD sum = 0;
    for (int k = 0; k < panels; ++k) {
        const LD a = LD(k) / panels, b = LD(k + 1) / panels;
        for (int i = 0; i < 5; ++i) {
            const LD s = (a + b) / 2 + (b - a) / 2 * xg[i];
            const LD x = (1 - std::cos(PI * s)) / 2, dx = PI / 2 * std::sin(PI * s);
            sum += wg[i] * (b - a) / 2 * f(x) * dx;
        }
    }
    return sum;
}
// The volume by integrating cross-sections: V = 2 a3 ∫₀¹ area(z) dz with area(z) = a1 a2 ρ(z)² S(ε₂),
// ρ(z)² = (1 − z^(2/ε₁))^ε₁ and S(ε₂) = 4 ∫₀¹ (1 − x^(2/ε₂))^(ε₂/2) dx the unit superellipse's area.
inline LD volume_by_integral(const Superquadric& s) {
    const LD e1 = s.e1, e2 = s.e2;
    const LD S = 4 * integrate01([&](LD x) { return std::pow(std::max(LD(0), 1 - std::pow(x, 2 / e2)), e2 / 2); });
    const LD I = integrate01([&](LD z) { return std::pow(std::max(LD(0), 1 - std::pow(z, 2 / e1)), e1); });
    return 2 * LD(s.radii.z) * s.radii.x * s.radii.y * S * I;
}

// ---- meshes -----------------------------------------------------------------------------------------------------
// Checks that the triangle soup is closed and consistently oriented (every directed edge once, with its reverse);
// returns an empty string or what is wrong.
inline std::string closed_oriented(const PolygonSoup& s) {
    std::vector<std::pair<std::uint64_t, int>> dir;
    const auto key = [](std::uint32_t a, std::uint32_t b) { return (std::uint64_t(a) << 32) | b; };
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        const auto fv = s.face(f);
        for (std::size_t i = 0; i < fv.size(); ++i) {
            if (fv[i] >= s.n_vertices()) return "face " + std::to_string(f) + " has an index out of range";
            dir.push_back({key(fv[i], fv[(i + 1) % fv.size()]), int(f)});
        }
    }
    std::sort(dir.begin(), dir.end());
    for (std::size_t i = 0; i + 1 < dir.size(); ++i)
        if (dir[i].first == dir[i + 1].first)
            return "faces " + std::to_string(dir[i].second) + " and " + std::to_string(dir[i + 1].second) +
                   " use the same directed edge " + std::to_string(dir[i].first >> 32) + "->" +
                   std::to_string(dir[i].first & 0xffffffffu) + " (inconsistent orientation or a repeated face)";
    for (const auto& [k, f] : dir) {
        const std::uint64_t rev = ((k & 0xffffffffu) << 32) | (k >> 32);
        if (!std::binary_search(dir.begin(), dir.end(), std::pair{rev, -1},
                                [](const auto& x, const auto& y) { return x.first < y.first; }))
            return "the edge " + std::to_string(k >> 32) + "->" + std::to_string(k & 0xffffffffu) + " of face " +
                   std::to_string(f) + " has no twin: the mesh is not closed";
    }
    return "";
}
// The signed volume enclosed (divergence theorem, fan triangulation of each face), long double.
inline LD signed_volume(const PolygonSoup& s) {
    LD v = 0;
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        const auto fv = s.face(f);
        const glm::dvec3 p0 = s.positions[fv[0]];
        for (std::size_t i = 1; i + 1 < fv.size(); ++i) {
            const glm::dvec3 p1 = s.positions[fv[i]], p2 = s.positions[fv[i + 1]];
            v += (LD(p0.x) * (LD(p1.y) * p2.z - LD(p1.z) * p2.y) - LD(p0.y) * (LD(p1.x) * p2.z - LD(p1.z) * p2.x) +
                  LD(p0.z) * (LD(p1.x) * p2.y - LD(p1.y) * p2.x)) /
                 6;
        }
    }
    return v;
}
// χ = V − E + F of a closed soup.
inline long euler(const PolygonSoup& s) {
    std::vector<std::uint64_t> edges;
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        const auto fv = s.face(f);
        for (std::size_t i = 0; i < fv.size(); ++i) {
            const std::uint32_t a = fv[i], b = fv[(i + 1) % fv.size()];
            edges.push_back((std::uint64_t(std::min(a, b)) << 32) | std::max(a, b));
        }
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    return long(s.n_vertices()) - long(edges.size()) + long(s.n_faces());
}

}  // namespace lab03
