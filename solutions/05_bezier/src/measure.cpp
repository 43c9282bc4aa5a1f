// Task 3: measures — arc length, its inverse, the tight bounding box, the closest point (handout §4).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/bezier.hpp"

namespace geolab::bezier {

namespace {
// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.

// Gauss–Legendre nodes and weights on [−1, 1] for N points: Newton on the Legendre polynomial P_N.
template <int N>
struct GaussLegendre {
    std::array<double, N> x{}, w{};
    GaussLegendre() {
        for (int i = 0; i < N; ++i) {
            double z = std::cos(std::numbers::pi * (i + 0.75) / (N + 0.5)), dp = 0;
            for (int it = 0; it < 100; ++it) {
                double p0 = 1, p1 = z;  // P_0, P_1; recurrence up to P_N
                for (int k = 2; k <= N; ++k) {
                    const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
                    p0 = p1;
                    p1 = p2;
                }
                dp = N * (z * p1 - p0) / (z * z - 1);
                const double dz = p1 / dp;
                z -= dz;
                if (std::abs(dz) < 1e-16) break;
            }
            x[i] = z;
            w[i] = 2 / ((1 - z * z) * dp * dp);
        }
    }
};

template <int N>
double gauss(const Poly3& D, double a, double b) {
    static const GaussLegendre<N> g;
    const double h = 0.5 * (b - a), m = 0.5 * (a + b);
    double s = 0;
    for (int i = 0; i < N; ++i) s += g.w[i] * glm::length(de_casteljau(D, m + h * g.x[i]));
    return s * h;
}

double adapt(const Poly3& D, double a, double b, double tol, int depth) {
    const double g5 = gauss<5>(D, a, b), g10 = gauss<10>(D, a, b);
    // Done when the rules agree to tol, or to rounding (a tol below rounding would otherwise split to depth 50
    // everywhere).
    if (std::abs(g10 - g5) <= std::max(tol, 1e-14 * std::abs(g10)) || depth >= 50) return g10;
    const double m = 0.5 * (a + b);
    return adapt(D, a, m, 0.5 * tol, depth + 1) + adapt(D, m, b, 0.5 * tol, depth + 1);
}

// Candidate parameters of extremes of the polynomial with Bernstein coefficients c on [a, b]: where its
// derivative (coefficients d) changes sign.
void derivative_roots(const std::vector<double>& d, double a, double b, std::vector<double>& out, int depth) {
    const auto [lo, hi] = std::minmax_element(d.begin(), d.end());
    if (*lo >= 0 || *hi <= 0) return;  // no sign change of the derivative inside (convex hull)
    if (depth > 40) {  // the interval is 2^-41 wide: its midpoint is the root to far below rounding of C
        out.push_back(0.5 * (a + b));
        return;
    }
    // Split the Bernstein coefficients at 1/2 (de Casteljau).
    const std::size_t n = d.size() - 1;
    std::vector<double> l(n + 1), r(n + 1), w = d;
    l[0] = w[0];
    r[n] = w[n];
    for (std::size_t k = 1; k <= n; ++k) {
        for (std::size_t i = 0; i + k <= n; ++i) w[i] = 0.5 * (w[i] + w[i + 1]);
        l[k] = w[0];
        r[n - k] = w[n - k];
    }
    const double m = 0.5 * (a + b);
    out.push_back(m);  // a root exactly at the split point would be lost by both halves (a curve point: harmless)
    derivative_roots(l, a, m, out, depth + 1);
    derivative_roots(r, m, b, out, depth + 1);
}

// END SOLUTION
}  // namespace

double arc_length(const Poly3& P, double a, double b, double tol) {
    // BEGIN SOLUTION
    if (P.empty()) throw std::invalid_argument("arc_length: no control points");
    if (!(tol > 0)) throw std::invalid_argument("arc_length: tol must be > 0");
    if (!(0 <= a && a <= b && b <= 1)) throw std::invalid_argument("arc_length: need 0 <= a <= b <= 1");
    if (a == b || P.size() == 1) return 0.0;
    return adapt(hodograph(P), a, b, 0.5 * tol, 0);
    // END SOLUTION
}

double parameter_at_length(const Poly3& P, double s, double tol) {
    // BEGIN SOLUTION
    const double total = arc_length(P, 0, 1, 0.25 * tol);
    if (s < 0 || s > total + tol)
        throw std::invalid_argument("parameter_at_length: s = " + std::to_string(s) + " is outside [0, " +
                                    std::to_string(total) + "]");
    const Poly3 D = hodograph(P);
    double lo = 0, hi = 1, t = total > 0 ? std::clamp(s / total, 0.0, 1.0) : 0.0;
    for (int it = 0; it < 200; ++it) {
        const double f = arc_length(P, 0, t, 0.25 * tol) - s;
        if (std::abs(f) <= 0.5 * tol) return t;
        if (f > 0) hi = t; else lo = t;
        const double speed = glm::length(de_casteljau(D, t));
        double next = speed > 0 ? t - f / speed : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket: bisect
        t = next;
    }
    return t;
    // END SOLUTION
}

Box bounding_box(const Poly3& P) {
    // BEGIN SOLUTION
    if (P.empty()) throw std::invalid_argument("bounding_box: no control points");
    Box box{P.front(), P.front()};
    auto grow = [&](const glm::dvec3& p) {
        box.lo = glm::min(box.lo, p);
        box.hi = glm::max(box.hi, p);
    };
    grow(P.back());
    if (P.size() < 3) return box;  // a point or a segment: the ends
    const Poly3 D = hodograph(P);
    for (int axis = 0; axis < 3; ++axis) {
        std::vector<double> d(D.size());
        for (std::size_t k = 0; k < D.size(); ++k) d[k] = D[k][axis];
        std::vector<double> roots;
        derivative_roots(d, 0.0, 1.0, roots, 0);
        for (double t : roots) {
            const glm::dvec3 p = de_casteljau(P, t);
            box.lo[axis] = std::min(box.lo[axis], p[axis]);
            box.hi[axis] = std::max(box.hi[axis], p[axis]);
        }
    }
    return box;
    // END SOLUTION
}

Closest closest_point(const Poly3& P, const glm::dvec3& q) {
    // BEGIN SOLUTION
    if (P.empty()) throw std::invalid_argument("closest_point: no control points");
    const Poly3 D = hodograph(P), DD = hodograph(D);
    const int samples = 64 * int(P.size());
    std::vector<double> dist(samples + 1);
    for (int i = 0; i <= samples; ++i) dist[i] = glm::length(de_casteljau(P, double(i) / samples) - q);
    Closest best{0.0, P.front(), glm::length(P.front() - q)};
    auto consider = [&](double t) {
        const glm::dvec3 p = de_casteljau(P, t);
        const double d = glm::length(p - q);
        if (d < best.distance) best = Closest{t, p, d};
    };
    consider(1.0);
    for (int i = 0; i <= samples; ++i) {
        const bool local_min = (i == 0 || dist[i] <= dist[i - 1]) && (i == samples || dist[i] <= dist[i + 1]);
        if (!local_min) continue;
        double t = double(i) / samples;
        for (int it = 0; it < 30; ++it) {
            const glm::dvec3 r = de_casteljau(P, t) - q, d1 = de_casteljau(D, t), d2 = de_casteljau(DD, t);
            const double f = glm::dot(r, d1), fp = glm::dot(d1, d1) + glm::dot(r, d2);
            if (fp <= 0) break;
            const double next = std::clamp(t - f / fp, 0.0, 1.0);
            if (std::abs(next - t) < 1e-16) break;
            t = next;
        }
        consider(t);
        consider(double(i) / samples);
    }
    return best;
    // END SOLUTION
}

}  // namespace geolab::bezier
