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

// Gauss–Legendre rules on [−1, 1]: the non-negative roots x of the Legendre polynomial P_N and their weights w
// (the rule uses ±x, and x = 0 once when N is odd). Computed by Newton on P_N in 60-digit arithmetic.
struct Node {
    double x, w;
};
constexpr std::array<Node, 3> gl5{{{0.0, 0.5688888888888889},
                                   {0.5384693101056831, 0.47862867049936647},
                                   {0.906179845938664, 0.23692688505618908}}};
constexpr std::array<Node, 5> gl10{{{0.14887433898163122, 0.29552422471475287},
                                    {0.4333953941292472, 0.26926671930999635},
                                    {0.6794095682990244, 0.21908636251598204},
                                    {0.8650633666889845, 0.1494513491505806},
                                    {0.9739065285171717, 0.06667134430868814}}};

// ∫_a^b |C'| by the rule mapped to [a, b]; D is C's hodograph.
template <std::size_t N>
double gauss(const Poly3& D, double a, double b, const std::array<Node, N>& rule) {
    const double h = 0.5 * (b - a), m = 0.5 * (a + b);
    auto speed = [&](double t) { return glm::length(de_casteljau(D, t)); };
    double s = 0;
    for (const Node& q : rule) s += q.w * (q.x == 0 ? speed(m) : speed(m + h * q.x) + speed(m - h * q.x));
    return s * h;
}

// ∫_a^b |C'| by the adaptive rule: the 10-point value where the 5- and 10-point values differ by at most this
// interval's share of tol, tol · (b − a) / whole (compared without the division: whole may be 0), or where [a, b]
// cannot be halved in double; otherwise the sum over the two halves.
double adapt(const Poly3& D, double a, double b, double tol, double whole) {
    const double g5 = gauss(D, a, b, gl5), g10 = gauss(D, a, b, gl10), m = 0.5 * (a + b);
    if (std::abs(g10 - g5) * whole <= tol * (b - a) || m <= a || m >= b) return g10;
    return adapt(D, a, m, tol, whole) + adapt(D, m, b, tol, whole);
}

// The roots in (a, b) of the polynomial with Bernstein coefficients c on [a, b], in increasing order: none where
// the coefficients do not change sign (convex hull); otherwise both halves (split by de Casteljau at ½), the split
// point itself when the polynomial is exactly 0 there, and at width 2^-40 the midpoint (within 2^-41 of the root:
// far below what moves C at a stationary point).
void roots(const std::vector<double>& c, double a, double b, std::vector<double>& out, int depth) {
    const auto [lo, hi] = std::minmax_element(c.begin(), c.end());
    if (*lo >= 0 || *hi <= 0) return;
    const double m = 0.5 * (a + b);
    if (depth == 40) {
        out.push_back(m);
        return;
    }
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
    if (l[n] == 0) out.push_back(m);  // the value at m: a root there is lost by both halves
    roots(r, m, b, out, depth + 1);
}

double binomial(int n, int k) {
    double c = 1;
    for (int i = 1; i <= k; ++i) c = c * (n - k + i) / i;
    return c;
}

// The Bernstein coefficients (degree p + q) of A(t) · B(t) for Bézier curves A (degree p) and B (degree q):
// c_k = Σ_(i+j=k) C(p, i) C(q, j) / C(p + q, k) A_i · B_j.
std::vector<double> dot_product(const Poly3& A, const Poly3& B) {
    const int p = int(A.size()) - 1, q = int(B.size()) - 1;
    std::vector<double> c(p + q + 1, 0.0);
    for (int i = 0; i <= p; ++i)
        for (int j = 0; j <= q; ++j)
            c[i + j] += binomial(p, i) * binomial(q, j) / binomial(p + q, i + j) * glm::dot(A[i], B[j]);
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
    double dmax = 0;  // |C'| ≤ dmax (convex hull); its rounding is about 1e-16 dmax
    for (const auto& d : D) {
        const double len = glm::length(d);
        if (!std::isfinite(len))
            throw std::invalid_argument("arc_length: |C'| is not finite (a control point too large or not finite)");
        dmax = std::max(dmax, len);
    }
    // Pieces between the stationary points of the speed (roots of C' · C''): |C'| is smooth on each, a cusp (where
    // it has a kink) is the end of a piece.
    std::vector<double> ends{a};
    std::vector<double> cuts;
    roots(dot_product(D, hodograph(D)), 0.0, 1.0, cuts, 0);
    for (double t : cuts)
        if (t > a && t < b) ends.push_back(t);
    ends.push_back(b);
    const double rounding_tol = 1e-14 * dmax * (b - a);
    double length = 0;
    for (std::size_t k = 0; k + 1 < ends.size(); ++k)
        length += adapt(D, ends[k], ends[k + 1], std::max(tol, rounding_tol), b - a);
    return length;
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
    // increasing t (t = 0 first, as the start), so the first of equally near points (the smallest t) is kept.
    Poly3 R = P;  // C − q
    for (auto& r : R) r -= q;
    std::vector<double> candidates;
    roots(dot_product(R, hodograph(P)), 0.0, 1.0, candidates, 0);
    candidates.push_back(1.0);
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
