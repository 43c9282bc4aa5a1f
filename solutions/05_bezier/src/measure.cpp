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

// Gauss–Legendre rules on [−1, 1]: the non-negative roots x_i of the Legendre polynomial P_N and their weights
// (the rule uses ±x_i, and x_0 = 0 once when N is odd). Computed by Newton on P_N in 60-digit arithmetic.
constexpr std::array<double, 3> x5{0.0, 0.5384693101056831, 0.906179845938664},
    w5{0.5688888888888889, 0.47862867049936647, 0.23692688505618908};
constexpr std::array<double, 5> x10{0.14887433898163122, 0.4333953941292472, 0.6794095682990244,
                                    0.8650633666889845, 0.9739065285171717},
    w10{0.29552422471475287, 0.26926671930999635, 0.21908636251598204, 0.1494513491505806, 0.06667134430868814};

// ∫_a^b |C'| by the rule (x, w) mapped to [a, b]; D is C's hodograph.
template <std::size_t N>
double gauss(const Poly3& D, double a, double b, const std::array<double, N>& x, const std::array<double, N>& w) {
    const double h = 0.5 * (b - a), m = 0.5 * (a + b);
    auto speed = [&](double t) { return glm::length(de_casteljau(D, t)); };
    double s = 0;
    for (std::size_t i = 0; i < N; ++i) s += w[i] * (x[i] == 0 ? speed(m) : speed(m + h * x[i]) + speed(m - h * x[i]));
    return s * h;
}

// The adaptive rule: the 10-point value where the 5- and 10-point rules agree within tol (this interval's share)
// or to rounding (1e-14 of the value), or where [a, b] cannot be halved in double; else the sum over the halves.
double adapt(const Poly3& D, double a, double b, double tol) {
    const double g5 = gauss(D, a, b, x5, w5), g10 = gauss(D, a, b, x10, w10), m = 0.5 * (a + b);
    if (std::abs(g10 - g5) <= std::max(tol, 1e-14 * g10) || m <= a || m >= b) return g10;
    return adapt(D, a, m, 0.5 * tol) + adapt(D, m, b, 0.5 * tol);
}

// Candidate parameters in [a, b] of the roots of the polynomial with Bernstein coefficients c on [a, b]: none
// where the coefficients do not change sign (convex hull); else the midpoint (a root exactly there would be lost
// by both halves) and the candidates of both halves, down to a width of 2^-40 (the midpoint is then within
// 2^-41 of the root: far below what changes C at a stationary point).
void roots(const std::vector<double>& c, double a, double b, std::vector<double>& out, int depth) {
    const auto [lo, hi] = std::minmax_element(c.begin(), c.end());
    if (*lo >= 0 || *hi <= 0) return;
    const double m = 0.5 * (a + b);
    out.push_back(m);
    if (depth == 40) return;
    // Split the Bernstein coefficients at 1/2 (de Casteljau): l on [a, m], r on [m, b].
    const std::size_t n = c.size() - 1;
    std::vector<double> l(n + 1), r(n + 1), w = c;
    l[0] = w[0];
    r[n] = w[n];
    for (std::size_t k = 1; k <= n; ++k) {
        for (std::size_t i = 0; i + k <= n; ++i) w[i] = 0.5 * (w[i] + w[i + 1]);
        l[k] = w[0];
        r[n - k] = w[n - k];
    }
    roots(l, a, m, out, depth + 1);
    roots(r, m, b, out, depth + 1);
}

double binomial(int n, int k) {
    double c = 1;
    for (int i = 1; i <= k; ++i) c = c * (n - k + i) / i;
    return c;
}

// The Bernstein coefficients (degree 2n − 1) of f(t) = (C(t) − q) · C'(t), whose roots are the stationary points
// of |C(t) − q|: the product of C − q (coefficients P_i − q, degree n) and C' (D_j, degree n − 1),
// c_k = Σ_(i+j=k) C(n, i) C(n − 1, j) / C(2n − 1, k) (P_i − q) · D_j.
std::vector<double> distance_slope(const Poly3& P, const Poly3& D, const glm::dvec3& q) {
    const int n = int(P.size()) - 1;
    std::vector<double> c(2 * n, 0.0);
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j < n; ++j)
            c[i + j] += binomial(n, i) * binomial(n - 1, j) / binomial(2 * n - 1, i + j) * glm::dot(P[i] - q, D[j]);
    return c;
}

// END SOLUTION
}  // namespace

double arc_length(const Poly3& P, double a, double b, double tol) {
    // BEGIN SOLUTION
    if (P.empty()) throw std::invalid_argument("arc_length: no control points");
    if (!(tol > 0)) throw std::invalid_argument("arc_length: tol must be > 0");
    if (!(0 <= a && a <= b && b <= 1)) throw std::invalid_argument("arc_length: need 0 <= a <= b <= 1");
    const Poly3 D = hodograph(P);
    for (const auto& d : D)
        if (!std::isfinite(glm::length(d)))
            throw std::invalid_argument("arc_length: |C'| is not finite (a control point too large or not finite)");
    return adapt(D, a, b, tol);
    // END SOLUTION
}

double parameter_at_length(const Poly3& P, double s, double tol) {
    // BEGIN SOLUTION
    const double total = arc_length(P, 0, 1, 0.5 * tol);
    if (s < 0 || s > total + tol)
        throw std::invalid_argument("parameter_at_length: s = " + std::to_string(s) + " is outside [0, " +
                                    std::to_string(total) + "]");
    // Bisection on length(0, t) − s (increasing in t): lengths within tol/2, stop within tol/2 (or when the
    // bracket is two neighbouring doubles).
    double lo = 0, hi = 1;
    for (;;) {
        const double t = 0.5 * (lo + hi);
        const double f = arc_length(P, 0, t, 0.5 * tol) - s;
        if (std::abs(f) <= 0.5 * tol || t <= lo || t >= hi) return t;
        (f > 0 ? hi : lo) = t;
    }
    // END SOLUTION
}

Box bounding_box(const Poly3& P) {
    // BEGIN SOLUTION
    if (P.empty()) throw std::invalid_argument("bounding_box: no control points");
    Box box{glm::min(P.front(), P.back()), glm::max(P.front(), P.back())};
    const Poly3 D = hodograph(P);
    // Per axis: C at the candidate roots of that coordinate of C' (a polynomial with D's coordinates as its
    // Bernstein coefficients).
    auto extend = [&](int axis) {
        std::vector<double> d(D.size()), candidates;
        for (std::size_t k = 0; k < D.size(); ++k) d[k] = D[k][axis];
        roots(d, 0.0, 1.0, candidates, 0);
        for (double t : candidates) {
            const double x = de_casteljau(P, t)[axis];
            box.lo[axis] = std::min(box.lo[axis], x);
            box.hi[axis] = std::max(box.hi[axis], x);
        }
    };
    extend(0);
    extend(1);
    extend(2);
    return box;
    // END SOLUTION
}

Closest closest_point(const Poly3& P, const glm::dvec3& q) {
    // BEGIN SOLUTION
    if (P.empty()) throw std::invalid_argument("closest_point: no control points");
    // The nearest point is an end or a stationary point of |C(t) − q|: a root of (C − q) · C'. Candidates in
    // increasing t, so the first of equally near points (the smallest t) is kept.
    std::vector<double> candidates{1.0};
    if (P.size() > 1) roots(distance_slope(P, hodograph(P), q), 0.0, 1.0, candidates, 0);
    std::sort(candidates.begin(), candidates.end());
    Closest best{0.0, P.front(), glm::length(P.front() - q)};
    for (double t : candidates) {
        const glm::dvec3 p = de_casteljau(P, t);
        const double d = glm::length(p - q);
        if (d < best.distance) best = Closest{t, p, d};
    }
    return best;
    // END SOLUTION
}

}  // namespace geolab::bezier
