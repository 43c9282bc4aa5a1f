// Task 4: rays (handout §6).
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {

Roots solve_quadratic(double alpha, double beta, double gamma) {
    // BEGIN SOLUTION
    Roots r;
    if (alpha == 0) {
        if (beta == 0) return r;  // no root, or every t (α = β = γ = 0): none by convention
        r.count = 1;
        r.t0 = r.t1 = -gamma / beta;
        return r;
    }
    const double disc = beta * beta - 4 * alpha * gamma;
    // Δ within its own rounding error of 0 is a double root (a tangent ray, a ray through coincident planes)
    if (std::abs(disc) <= 1e-12 * (beta * beta + 4 * std::abs(alpha * gamma))) {
        r.count = 1;
        r.t0 = r.t1 = -beta / (2 * alpha);
        return r;
    }
    if (disc < 0) return r;
    // q has the sign of -β and the larger magnitude: no cancellation in β + sign(β)√Δ
    const double q = -0.5 * (beta + std::copysign(std::sqrt(disc), beta));
    double t0 = q / alpha, t1 = gamma / q;
    if (t0 > t1) std::swap(t0, t1);
    r.count = 2;
    r.t0 = t0;
    r.t1 = t1;
    return r;
    // END SOLUTION
}

std::vector<Hit> intersect(const glm::dmat4& Q, const Ray& ray, double t_min, double t_max) {
    // BEGIN SOLUTION
    if (ray.direction == glm::dvec3(0.0)) throw std::invalid_argument("intersect: the ray's direction is zero");
    if (!(t_min <= t_max)) throw std::invalid_argument("intersect: t_min > t_max");
    const glm::dvec4 X(ray.origin, 1.0), D(ray.direction, 0.0);
    const glm::dvec4 QD = Q * D;
    const Roots roots = solve_quadratic(glm::dot(D, QD), 2 * glm::dot(X, QD), glm::dot(X, Q * X));
    std::vector<Hit> hits;
    const double ts[2] = {roots.t0, roots.t1};
    for (int i = 0; i < roots.count; ++i) {
        const double t = ts[i];
        if (!(t >= t_min && t <= t_max)) continue;
        Hit h;
        h.t = t;
        h.point = ray.origin + t * ray.direction;
        const glm::dvec3 g = glm::dvec3(Q * glm::dvec4(h.point, 1.0));
        const double len = glm::length(g);
        h.normal = len > 0 ? g / len : glm::dvec3(0.0);
        hits.push_back(h);
    }
    return hits;
    // END SOLUTION
}

std::vector<Hit> intersect_in_box(const glm::dmat4& Q, const Ray& ray, const Box3& box) {
    // BEGIN SOLUTION
    double t0 = 0, t1 = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
        if (!(box.lo[i] <= box.hi[i])) throw std::invalid_argument("intersect_in_box: lo > hi on an axis");
        const double o = ray.origin[i], d = ray.direction[i];
        if (d == 0) {
            if (o < box.lo[i] || o > box.hi[i]) return {};
            continue;
        }
        double a = (box.lo[i] - o) / d, b = (box.hi[i] - o) / d;
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
    }
    if (t0 > t1) return {};
    return intersect(Q, ray, t0, t1);
    // END SOLUTION
}

}  // namespace geolab::quadrics
