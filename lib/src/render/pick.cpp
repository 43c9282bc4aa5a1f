#include "geolab/render/pick.hpp"

#include <cmath>
#include <glm/geometric.hpp>

namespace geolab::render {
namespace {

// Möller–Trumbore: the t ≥ 0 where the ray meets triangle abc (either side), or a negative value.
double hit_triangle(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a, const glm::dvec3& b,
                    const glm::dvec3& c) {
    const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-300) return -1.0;
    const glm::dvec3 s = o - a;
    const double u = glm::dot(s, p) / det;
    if (u < 0.0 || u > 1.0) return -1.0;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(d, q) / det;
    if (v < 0.0 || u + v > 1.0) return -1.0;
    return glm::dot(e2, q) / det;
}

}  // namespace

std::optional<PickHit> pick(const PolygonSoup& soup, const Ray& ray) {
    const glm::dvec3 o(ray.origin), d(ray.direction);
    std::optional<PickHit> best;
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        auto vs = soup.face(f);
        for (std::size_t i = 1; i + 1 < vs.size(); ++i) {
            double t = hit_triangle(o, d, soup.positions[vs[0]], soup.positions[vs[i]], soup.positions[vs[i + 1]]);
            if (t >= 0.0 && (!best || t < best->t)) best = PickHit{f, 0, glm::vec3(o + t * d), float(t)};
        }
    }
    if (!best) return best;
    // the face's vertex nearest to the hit point
    double nearest = INFINITY;
    for (std::uint32_t v : soup.face(best->face)) {
        double dist = glm::length(soup.positions[v] - glm::dvec3(best->point));
        if (dist < nearest) nearest = dist, best->vertex = v;
    }
    return best;
}

}  // namespace geolab::render
