// Lab 09 — task 2: spherical coordinates, root finding and edge crossings.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"

namespace geolab::dc {

Spherical to_spherical(const glm::dvec3& p) {
    // BEGIN SOLUTION
    double rho = std::hypot(p.x, p.y);
    double r = std::hypot(rho, p.z);
    if (r == 0.0) return {0.0, 0.0, 0.0};
    double theta = std::atan2(rho, p.z);
    double phi = rho == 0.0 ? 0.0 : std::atan2(p.y, p.x);
    if (phi < 0.0) phi += 2.0 * pi;
    if (phi >= 2.0 * pi) phi = 0.0;  // rounding of −0 + 2π
    return {r, theta, phi};
    // END SOLUTION
}

glm::dvec3 to_cartesian(const Spherical& s) {
    // BEGIN SOLUTION
    double st = std::sin(s.theta), ct = std::cos(s.theta);
    if (s.theta == 0.0) st = 0.0, ct = 1.0;
    if (s.theta == pi) st = 0.0, ct = -1.0;
    return {s.r * st * std::cos(s.phi), s.r * st * std::sin(s.phi), s.r * ct};
    // END SOLUTION
}

double find_root(FunctionRef g, double g0, double g1, double tolerance) {
    // BEGIN SOLUTION
    // Regula falsi on [t0, t1] with inside(g(t0)) == inside(g0). When the same end moves twice in a row, the other
    // end's value is scaled by m = 1 − g(t)/g(old end) (Anderson–Björck), but never by less than 0.5 (Illinois, which
    // always halves). On the nearly linear g of a small cell m ≈ 1: the iterates close in from one side without the
    // overshoot that halving causes (3 evaluations where Illinois takes 4). On a flat-then-steep g, g(t) ≈ g(old end)
    // gives m ≈ 0, which would throw the next iterate onto the far end: there the 0.5 floor keeps Illinois' pace.
    const bool in0 = inside(g0);
    double t0 = 0.0, t1 = 1.0, f0 = g0, f1 = g1;
    double t = 0.5, prev = -1.0;
    int side = 0;
    for (int it = 0; it < 100; ++it) {
        double denom = f1 - f0;
        t = denom != 0.0 ? (t0 * f1 - t1 * f0) / denom : 0.5 * (t0 + t1);
        if (!(t > t0)) return t0;  // f0 ≈ 0: the bracket's end is the root
        if (!(t < t1)) return t1;
        if (std::abs(t - prev) < 0.125 * tolerance) break;  // converged: g(t) would only move the bracket
        double ft = g(t);
        if (inside(ft) == in0) {
            if (side == -1) {
                const double m = 1.0 - ft / f0;
                f1 *= m > 0.5 ? m : 0.5;
            }
            t0 = t, f0 = ft;
            side = -1;
        } else {
            if (side == +1) {
                const double m = 1.0 - ft / f1;
                f0 *= m > 0.5 ? m : 0.5;
            }
            t1 = t, f1 = ft;
            side = +1;
        }
        if (t1 - t0 < tolerance) break;
        prev = t;
    }
    return t;
    // END SOLUTION
}

Crossing find_crossing(const ScalarField& f, const glm::dvec3& a, const glm::dvec3& b, double fa, double fb,
                       double tolerance) {
    // BEGIN SOLUTION
    const glm::dvec3 d = b - a;
    double t = find_root([&](double s) { return f.value(a + s * d); }, fa, fb, tolerance);
    Crossing c;
    c.point = a + t * d;
    glm::dvec3 g = f.gradient(c.point);
    double len = glm::length(g);
    c.normal = len > 0.0 ? g / len : glm::normalize(inside(fa) ? d : -d);
    return c;
    // END SOLUTION
}

Crossing find_crossing_arc(const ScalarField& f, const glm::dvec3& origin, const Spherical& a, const Spherical& b,
                           double fa, double fb, double tolerance) {
    // BEGIN SOLUTION
    auto at = [&](double s) {
        return origin + to_cartesian({a.r + s * (b.r - a.r), a.theta + s * (b.theta - a.theta),
                                      a.phi + s * (b.phi - a.phi)});
    };
    double t = find_root([&](double s) { return f.value(at(s)); }, fa, fb, tolerance);
    Crossing c;
    c.point = at(t);
    glm::dvec3 g = f.gradient(c.point);
    double len = glm::length(g);
    if (len > 0.0) {
        c.normal = g / len;
    } else {  // the path's direction at t, from the inside end to the outside end
        glm::dvec3 d = at(std::min(1.0, t + 1e-6)) - at(std::max(0.0, t - 1e-6));
        c.normal = glm::normalize(inside(fa) ? d : -d);
    }
    return c;
    // END SOLUTION
}

}  // namespace geolab::dc
