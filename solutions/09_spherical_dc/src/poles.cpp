// Lab 09 — task 7: filling the holes around the polar axis with a ghost vertex.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"

namespace geolab::dc {

PoleFillResult fill_poles(PolygonSoup& soup, std::span<const PoleRing> rings, const ScalarField& f,
                          const glm::dvec3& origin, PoleFill::Method method) {
    // BEGIN SOLUTION
    PoleFillResult out;
    out.first_face = soup.n_faces();
    if (method == PoleFill::none) return out;
    for (const PoleRing& pr : rings) {
        // a ring of 2 vertices bounds a hole whose two sides are the one edge {ring[0], ring[1]}, already shared by
        // two faces: the mesh is closed there, and a fan would put that edge into 4 faces
        if (pr.ring.size() < 3) continue;
        const glm::dvec3 axis(0.0, 0.0, pr.north ? 1.0 : -1.0);
        // vertical projection: the mean axial coordinate of the ring
        double s_vertical = 0.0;
        for (std::uint32_t v : pr.ring) s_vertical += glm::dot(axis, soup.positions[v] - origin);
        s_vertical /= double(pr.ring.size());
        double s = s_vertical;
        if (method == PoleFill::normal_projection) {
            // least-squares point of the axis on the ring's tangent planes: min Σ (nᵢ·(o + s a − vᵢ))²
            double num = 0.0, den = 0.0;
            for (std::uint32_t v : pr.ring) {
                glm::dvec3 g = f.gradient(soup.positions[v]);
                double len = glm::length(g);
                if (!(len > 0.0)) continue;
                glm::dvec3 n = g / len;
                double na = glm::dot(n, axis);
                num += na * glm::dot(n, soup.positions[v] - origin);
                den += na * na;
            }
            if (den >= 1e-12 * double(pr.ring.size())) s = num / den;
        }
        s = std::clamp(s, pr.r_lo, pr.r_hi);
        const std::uint32_t ghost = std::uint32_t(soup.positions.size());
        soup.positions.push_back(origin + s * axis);
        out.ghost_vertices.push_back(ghost);
        for (std::size_t i = 0; i < pr.ring.size(); ++i) {
            out.ring_vertices.push_back(pr.ring[i]);
            soup.add_face({ghost, pr.ring[i], pr.ring[(i + 1) % pr.ring.size()]});
        }
    }
    out.n_faces = soup.n_faces() - out.first_face;
    return out;
    // END SOLUTION
}

}  // namespace geolab::dc
