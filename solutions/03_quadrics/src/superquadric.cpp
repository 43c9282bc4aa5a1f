// Task 5: superquadrics (handout §7).
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {
namespace {
// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.
void check(const Superquadric& s, const char* who) {
    if (!(s.radii.x > 0 && s.radii.y > 0 && s.radii.z > 0 && s.e1 > 0 && s.e2 > 0) || !std::isfinite(s.e1) ||
        !std::isfinite(s.e2) || !std::isfinite(s.radii.x) || !std::isfinite(s.radii.y) || !std::isfinite(s.radii.z))
        throw std::invalid_argument(std::string(who) + ": the radii and exponents must be finite and > 0");
}
// END SOLUTION
}  // namespace

double spow(double x, double e) {
    // BEGIN SOLUTION
    if (x == 0) return 0.0;
    return std::copysign(std::pow(std::abs(x), e), x);
    // END SOLUTION
}

double inside_outside(const Superquadric& s, const glm::dvec3& x) {
    // BEGIN SOLUTION
    check(s, "inside_outside");
    const double u = std::pow(std::abs(x.x / s.radii.x), 2 / s.e2) + std::pow(std::abs(x.y / s.radii.y), 2 / s.e2);
    return std::pow(u, s.e2 / s.e1) + std::pow(std::abs(x.z / s.radii.z), 2 / s.e1);
    // END SOLUTION
}

glm::dvec3 superquadric_point(const Superquadric& s, double eta, double omega) {
    // BEGIN SOLUTION
    const double ce = spow(std::cos(eta), s.e1);
    return {s.radii.x * ce * spow(std::cos(omega), s.e2), s.radii.y * ce * spow(std::sin(omega), s.e2),
            s.radii.z * spow(std::sin(eta), s.e1)};
    // END SOLUTION
}

glm::dvec3 superquadric_normal(const Superquadric& s, double eta, double omega) {
    // BEGIN SOLUTION
    const double ce = spow(std::cos(eta), 2 - s.e1);
    const glm::dvec3 n{ce * spow(std::cos(omega), 2 - s.e2) / s.radii.x,
                       ce * spow(std::sin(omega), 2 - s.e2) / s.radii.y, spow(std::sin(eta), 2 - s.e1) / s.radii.z};
    const double len = glm::length(n);
    return len > 0 ? n / len : glm::dvec3(0.0);
    // END SOLUTION
}

double superquadric_volume(const Superquadric& s) {
    // BEGIN SOLUTION
    check(s, "superquadric_volume");
    auto beta = [](double x, double y) { return std::exp(std::lgamma(x) + std::lgamma(y) - std::lgamma(x + y)); };
    return 2 * s.radii.x * s.radii.y * s.radii.z * s.e1 * s.e2 * beta(s.e1 / 2 + 1, s.e1) * beta(s.e2 / 2, s.e2 / 2);
    // END SOLUTION
}

std::optional<Hit> intersect_superquadric(const Superquadric& s, const Ray& ray, double t_min, double t_max) {
    // BEGIN SOLUTION
    check(s, "intersect_superquadric");
    if (ray.direction == glm::dvec3(0.0))
        throw std::invalid_argument("intersect_superquadric: the ray's direction is zero");
    if (!(t_min <= t_max)) throw std::invalid_argument("intersect_superquadric: t_min > t_max");
    // clip to the bounding box (slightly enlarged so that a crossing on its faces is bracketed)
    double t0 = t_min, t1 = t_max;
    for (int i = 0; i < 3; ++i) {
        const double h = s.radii[i] * (1 + 1e-9), o = ray.origin[i], d = ray.direction[i];
        if (d == 0) {
            if (std::abs(o) > h) return std::nullopt;
            continue;
        }
        double a = (-h - o) / d, b = (h - o) / d;
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
    }
    if (!(t0 <= t1)) return std::nullopt;
    // g = F − 1: < 0 inside, 0 on, > 0 outside. March from t0 to t1 in n steps; the first step whose ends differ in
    // sign brackets the first crossing, which bisection narrows to two neighbouring doubles (only signs matter).
    auto g = [&](double t) { return inside_outside(s, ray.origin + t * ray.direction) - 1; };
    const int n = 1024;
    double ta = t0, ga = g(t0);
    double root = std::numeric_limits<double>::quiet_NaN();
    if (ga == 0) root = t0;  // starting on the surface
    for (int k = 1; k <= n && std::isnan(root); ++k) {
        const double tb = k == n ? t1 : t0 + (t1 - t0) * k / n;
        const double gb = g(tb);
        if ((ga < 0) != (gb < 0)) {
            double lo = ta, hi = tb;  // g(lo) has ga's sign, g(hi) the other
            for (double mid = 0.5 * (lo + hi); mid > lo && mid < hi; mid = 0.5 * (lo + hi))
                ((g(mid) < 0) == (ga < 0) ? lo : hi) = mid;
            root = hi;
        }
        ta = tb;
        ga = gb;
    }
    if (std::isnan(root)) return std::nullopt;
    Hit h;
    h.t = root;
    h.point = ray.origin + root * ray.direction;
    // the gradient of F: ∂F/∂x = (2/ε₁) u^(ε₂/ε₁ − 1) spow(x/a1, 2/ε₂ − 1) / a1, ...
    const glm::dvec3 p = h.point / s.radii;
    const double u = std::pow(std::abs(p.x), 2 / s.e2) + std::pow(std::abs(p.y), 2 / s.e2);
    const double w = u > 0 ? std::pow(u, s.e2 / s.e1 - 1) : 0.0;
    glm::dvec3 n3{w * spow(p.x, 2 / s.e2 - 1) / s.radii.x, w * spow(p.y, 2 / s.e2 - 1) / s.radii.y,
                  spow(p.z, 2 / s.e1 - 1) / s.radii.z};
    const double len = glm::length(n3);
    h.normal = len > 0 && std::isfinite(len) ? n3 / len : glm::dvec3(0.0);
    return h;
    // END SOLUTION
}

}  // namespace geolab::quadrics
