// Lab 09 — task 5: the origin of the spherical octree (smallest enclosing sphere, eq. 6 correction).
#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"

namespace geolab::dc {

Sphere minimal_enclosing_sphere(std::span<const glm::dvec3> points) {
    // BEGIN SOLUTION
    if (points.empty()) return {};
    std::vector<glm::dvec3> p(points.begin(), points.end());
    std::mt19937_64 rng(0x9e3779b97f4a7c15ULL);
    std::shuffle(p.begin(), p.end(), rng);
    double scale = 0.0;
    for (const auto& q : p) scale = std::max(scale, glm::length(q - p[0]));
    const double eps = 1e-12 * std::max(scale, 1e-300);
    auto contains = [&](const Sphere& s, const glm::dvec3& q) { return glm::length(q - s.center) <= s.radius + eps; };
    auto two = [](const glm::dvec3& a, const glm::dvec3& b) -> Sphere {
        return {0.5 * (a + b), 0.5 * glm::length(b - a)};
    };
    // circumsphere of a triangle (centre in its plane); degenerate (collinear) → the widest pair's sphere
    auto three = [&](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) -> Sphere {
        glm::dvec3 ab = b - a, ac = c - a, n = glm::cross(ab, ac);
        double n2 = glm::dot(n, n);
        if (n2 <= 1e-24 * glm::dot(ab, ab) * glm::dot(ac, ac)) {
            Sphere s = two(a, b), t = two(a, c), u = two(b, c);
            if (t.radius > s.radius) s = t;
            if (u.radius > s.radius) s = u;
            return s;
        }
        glm::dvec3 off = (glm::dot(ac, ac) * glm::cross(n, ab) + glm::dot(ab, ab) * glm::cross(ac, n)) / (2.0 * n2);
        return {a + off, glm::length(off)};
    };
    // circumsphere of a tetrahedron; degenerate (coplanar) → the smallest sphere of three of them holding the 4th
    auto four = [&](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) -> Sphere {
        glm::dvec3 u = b - a, v = c - a, w = d - a;
        double det = glm::dot(u, glm::cross(v, w));
        double sc = glm::length(u) * glm::length(v) * glm::length(w);
        if (std::abs(det) <= 1e-12 * sc) {
            Sphere best{{0, 0, 0}, -1};
            const glm::dvec3 q[4] = {a, b, c, d};
            for (int skip = 0; skip < 4; ++skip) {
                glm::dvec3 t[3];
                for (int i = 0, k = 0; i < 4; ++i)
                    if (i != skip) t[k++] = q[i];
                Sphere s = three(t[0], t[1], t[2]);
                if (contains(s, q[skip]) && (best.radius < 0 || s.radius < best.radius)) best = s;
            }
            return best.radius >= 0 ? best : three(a, b, c);
        }
        glm::dvec3 off = (glm::dot(u, u) * glm::cross(v, w) + glm::dot(v, v) * glm::cross(w, u) +
                          glm::dot(w, w) * glm::cross(u, v)) /
                         (2.0 * det);
        return {a + off, glm::length(off)};
    };
    // Welzl in move-to-front loop form: point i outside → it is on the boundary of the sphere of p[0..i]
    Sphere s{p[0], 0.0};
    for (std::size_t i = 1; i < p.size(); ++i) {
        if (contains(s, p[i])) continue;
        s = {p[i], 0.0};
        for (std::size_t j = 0; j < i; ++j) {
            if (contains(s, p[j])) continue;
            s = two(p[i], p[j]);
            for (std::size_t k = 0; k < j; ++k) {
                if (contains(s, p[k])) continue;
                s = three(p[i], p[j], p[k]);
                for (std::size_t l = 0; l < k; ++l)
                    if (!contains(s, p[l])) s = four(p[i], p[j], p[k], p[l]);
            }
        }
    }
    return s;
    // END SOLUTION
}

std::vector<glm::dvec3> correct_origin(const ScalarField& f, const glm::dvec3& x0, const OriginParams& params) {
    if (!(params.unit > 0.0)) throw std::invalid_argument("correct_origin: params.unit must be > 0");
    // BEGIN SOLUTION
    const double step = params.delta * params.unit, margin = params.margin * params.unit;
    std::vector<glm::dvec3> path{x0};
    double fx = f.value(x0);
    if (std::abs(fx) >= margin) return path;
    // the unit direction of ∇f, or the axis probe where s·f grows most when ∇f vanishes
    auto direction = [&](const glm::dvec3& x, double s) {
        glm::dvec3 g = f.gradient(x);
        double len = glm::length(g);
        if (len >= 1e-12) return g / len;
        glm::dvec3 best(0, 0, 1);
        double best_v = -1e300;
        for (int a = 0; a < 3; ++a)
            for (double sg : {1.0, -1.0}) {
                glm::dvec3 e(0.0);
                e[a] = sg;
                double v = s * f.value(x + s * step * e);
                if (v > best_v) best_v = v, best = e;
            }
        return best;  // the step is s · best: along ∇f/|∇f| outward (s = 1), against it inward (s = -1)
    };
    // the side: the one we are on; exactly on the surface, the side whose probe is farther from it
    double s = fx > 0.0 ? 1.0 : -1.0;
    if (fx == 0.0) {
        glm::dvec3 n = direction(x0, 1.0);
        double out = std::abs(f.value(x0 + step * n)), in = std::abs(f.value(x0 - step * n));
        s = out > in ? 1.0 : -1.0;
    }
    glm::dvec3 x = x0;
    for (int k = 0; k < params.max_steps; ++k) {
        x += s * step * direction(x, s);
        path.push_back(x);
        fx = f.value(x);
        if (s * fx >= margin) break;
    }
    return path;
    // END SOLUTION
}

}  // namespace geolab::dc
