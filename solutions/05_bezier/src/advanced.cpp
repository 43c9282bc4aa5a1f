// Task 8 (advanced): rational Bézier curves and the exact circle; B-splines by de Boor, knot insertion (handout §9).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/vec4.hpp>

#include "geolab/bezier.hpp"

namespace geolab::bezier {

namespace {
// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.
// Validates s and returns the span k (t_k ≤ t < t_(k+1), or the last non-empty span at the domain's end).
int span_of(const BSpline& s, double t, const char* who, bool allow_end) {
    const int p = s.degree, n = int(s.points.size()) - 1;
    if (p < 1) throw std::invalid_argument(std::string(who) + ": degree must be >= 1");
    if (n < p) throw std::invalid_argument(std::string(who) + ": need at least degree + 1 control points");
    if (s.knots.size() != s.points.size() + std::size_t(p) + 1)
        throw std::invalid_argument(std::string(who) + ": " + std::to_string(s.knots.size()) + " knots for " +
                                    std::to_string(s.points.size()) + " points of degree " + std::to_string(p) +
                                    " (need points + degree + 1)");
    for (std::size_t i = 0; i < s.knots.size(); ++i) {
        if (!std::isfinite(s.knots[i])) throw std::invalid_argument(std::string(who) + ": a knot is not finite");
        if (i > 0 && s.knots[i] < s.knots[i - 1])
            throw std::invalid_argument(std::string(who) + ": knots decrease at index " + std::to_string(i));
    }
    const double lo = s.knots[p], hi = s.knots[n + 1];
    if (!(lo < hi)) throw std::invalid_argument(std::string(who) + ": empty domain");
    if (!(t >= lo && (t < hi || (allow_end && t == hi))))
        throw std::invalid_argument(std::string(who) + ": t = " + std::to_string(t) + " is outside the domain [" +
                                    std::to_string(lo) + ", " + std::to_string(hi) + "]");
    // The largest non-empty span starting at or before t: t_k ≤ t < t_(k+1) inside the domain, the last non-empty
    // span at its end (t_p ≤ t, and a non-empty span starts at or after p, so k stops at p or above).
    int k = n;
    while (s.knots[k] > t || s.knots[k] == s.knots[k + 1]) --k;
    return k;
}
// END SOLUTION
}  // namespace

glm::dvec3 rational_point(const RationalCurve& c, double t) {
    // BEGIN SOLUTION
    if (c.points.empty()) throw std::invalid_argument("rational_point: no control points");
    if (c.points.size() != c.weights.size())
        throw std::invalid_argument("rational_point: " + std::to_string(c.points.size()) + " points but " +
                                    std::to_string(c.weights.size()) + " weights");
    std::vector<glm::dvec4> h(c.points.size());
    for (std::size_t k = 0; k < h.size(); ++k) {
        if (!(c.weights[k] > 0)) throw std::invalid_argument("rational_point: weight " + std::to_string(k) + " <= 0");
        h[k] = glm::dvec4(c.weights[k] * c.points[k], c.weights[k]);
    }
    const std::size_t n = h.size() - 1;  // de Casteljau in place from the back (basics.cpp): h[n] = the point
    for (std::size_t r = 1; r <= n; ++r)
        for (std::size_t k = n; k >= r; --k) h[k] = (1.0 - t) * h[k - 1] + t * h[k];
    return glm::dvec3(h[n]) / h[n].w;
    // END SOLUTION
}

RationalCurve circle_arc(const glm::dvec3& center, double r, double a0, double a1) {
    // BEGIN SOLUTION
    if (!(r > 0) || !std::isfinite(r)) throw std::invalid_argument("circle_arc: radius must be > 0");
    const double h = 0.5 * (a1 - a0);
    if (!(h > 0 && 2 * h < 3.141592653589793))
        throw std::invalid_argument("circle_arc: need 0 < a1 - a0 < pi");
    const double m = 0.5 * (a0 + a1);
    RationalCurve c;
    c.points = {center + r * glm::dvec3(std::cos(a0), std::sin(a0), 0.0),
                center + (r / std::cos(h)) * glm::dvec3(std::cos(m), std::sin(m), 0.0),
                center + r * glm::dvec3(std::cos(a1), std::sin(a1), 0.0)};
    c.weights = {1.0, std::cos(h), 1.0};
    return c;
    // END SOLUTION
}

glm::dvec3 de_boor(const BSpline& s, double t) {
    // BEGIN SOLUTION
    const int k = span_of(s, t, "de_boor", true), p = s.degree;
    std::vector<glm::dvec3> d(p + 1);
    for (int j = 0; j <= p; ++j) d[j] = s.points[j + k - p];
    for (int r = 1; r <= p; ++r)
        for (int j = p; j >= r; --j) {
            const double lo = s.knots[j + k - p], hi = s.knots[j + 1 + k - r];
            const double a = (t - lo) / (hi - lo);
            d[j] = (1.0 - a) * d[j - 1] + a * d[j];
        }
    return d[p];
    // END SOLUTION
}

BSpline insert_knot(const BSpline& s, double t) {
    // BEGIN SOLUTION
    const int k = span_of(s, t, "insert_knot", false), p = s.degree;
    BSpline out;
    out.degree = p;
    out.knots = s.knots;
    out.knots.insert(out.knots.begin() + k + 1, t);
    const int n = int(s.points.size()) - 1;
    out.points.resize(n + 2);
    for (int i = 0; i <= n + 1; ++i) {
        if (i <= k - p) {
            out.points[i] = s.points[i];
        } else if (i <= k) {
            const double a = (t - s.knots[i]) / (s.knots[i + p] - s.knots[i]);
            out.points[i] = (1.0 - a) * s.points[i - 1] + a * s.points[i];
        } else {
            out.points[i] = s.points[i - 1];
        }
    }
    return out;
    // END SOLUTION
}

}  // namespace geolab::bezier
