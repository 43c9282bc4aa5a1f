// Task 7: volume, area and Pappus's theorems (handout §8).
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

double mesh_volume(const PolygonSoup& mesh) {
    // BEGIN SOLUTION
    if (mesh.positions.empty()) return 0.0;
    const glm::dvec3 o = mesh.positions[0];
    double v = 0;
    for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
        const auto face = mesh.face(f);
        const glm::dvec3 a = mesh.positions[face[0]] - o;
        for (std::size_t i = 1; i + 1 < face.size(); ++i)
            v += glm::dot(a, glm::cross(mesh.positions[face[i]] - o, mesh.positions[face[i + 1]] - o));
    }
    return v / 6;
    // END SOLUTION
}

double mesh_area(const PolygonSoup& mesh) {
    // BEGIN SOLUTION
    double s = 0;
    for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
        const auto face = mesh.face(f);
        const glm::dvec3 a = mesh.positions[face[0]];
        for (std::size_t i = 1; i + 1 < face.size(); ++i)
            s += glm::length(glm::cross(mesh.positions[face[i]] - a, mesh.positions[face[i + 1]] - a));
    }
    return s / 2;
    // END SOLUTION
}

Pappus pappus(const Profile& p, double angle) {
    // BEGIN SOLUTION
    validate_profile(p);
    if (!(angle > 0)) throw std::invalid_argument("pappus: angle = " + std::to_string(angle) + " (must be > 0)");
    Pappus r;
    double moment = 0;  // ∫∫ x dA = (1/6) Σ (xᵢ + xᵢ₊₁)(xᵢ yᵢ₊₁ − xᵢ₊₁ yᵢ)
    auto loop = [&](const Loop& l) {
        for (std::size_t i = 0; i < l.size(); ++i) {
            const glm::dvec2 a = l[i], b = l[(i + 1) % l.size()];
            if (a.x < 0)
                throw std::invalid_argument("pappus: a point has x = " + std::to_string(a.x) + " < 0 (clip it first)");
            moment += (a.x + b.x) * (a.x * b.y - b.x * a.y);
            r.lateral_area += glm::length(b - a) * 0.5 * (a.x + b.x);
        }
    };
    loop(p.outer);
    for (const Loop& h : p.holes) loop(h);
    r.volume = angle * moment / 6;
    r.lateral_area *= angle;
    return r;
    // END SOLUTION
}

}  // namespace geolab::sweeps
