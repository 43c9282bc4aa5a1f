// Task 4: marching cubes (handout §5).
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/blobby.hpp"
#include "geolab/mc_tables.hpp"

namespace geolab::blobby {

int cube_index(const std::array<double, 8>& f, double iso) {
    // BEGIN SOLUTION
    int index = 0;
    for (int c = 0; c < 8; ++c)
        if (f[c] < iso) index |= 1 << c;
    return index;
    // END SOLUTION
}

glm::dvec3 edge_crossing(const glm::dvec3& p0, const glm::dvec3& p1, double f0, double f1, double iso) {
    // BEGIN SOLUTION
    if ((f0 < iso) == (f1 < iso))
        throw std::invalid_argument("edge_crossing: both ends are on the same side of the iso-value (f0 " +
                                    std::to_string(f0) + ", f1 " + std::to_string(f1) + ", iso " +
                                    std::to_string(iso) + ")");
    const double t = (iso - f0) / (f1 - f0);
    return p0 + t * (p1 - p0);
    // END SOLUTION
}

McMesh marching_cubes(const Lattice& L, double iso) {
    // BEGIN SOLUTION
    const glm::ivec3 n = L.n;
    if (n.x < 2 || n.y < 2 || n.z < 2) throw std::invalid_argument("marching_cubes: n must be >= 2 on every axis");
    const std::size_t N = std::size_t(n.x) * n.y * n.z;
    if (L.values.size() != N)
        throw std::invalid_argument("marching_cubes: " + std::to_string(L.values.size()) + " values for " +
                                    std::to_string(N) + " samples");
    if (L.gradients.size() != N)
        throw std::invalid_argument("marching_cubes: " + std::to_string(L.gradients.size()) +
                                    " gradients for " + std::to_string(N) + " samples");
    if (!(L.h > 0) || !std::isfinite(L.h)) throw std::invalid_argument("marching_cubes: h must be finite and > 0");
    for (std::size_t s = 0; s < N; ++s)
        if (!std::isfinite(L.values[s]))
            throw std::invalid_argument("marching_cubes: sample " + std::to_string(s) + " is not finite");
    if (!std::isfinite(iso)) throw std::invalid_argument("marching_cubes: iso is not finite");

    McMesh mesh;
    const std::size_t sx = 1, sy = std::size_t(n.x), sz = std::size_t(n.x) * n.y;
    const std::size_t stride[3] = {sx, sy, sz};
    std::vector<std::uint32_t> vertex_of(3 * N, UINT32_MAX);  // lattice edge (sample, axis) → vertex
    auto position = [&](std::size_t s) {
        const std::size_t i = s % sy, j = (s / sy) % std::size_t(n.y), k = s / sz;
        return L.origin + L.h * glm::dvec3(double(i), double(j), double(k));
    };
    auto vertex = [&](std::size_t s0, int axis) {
        std::uint32_t& v = vertex_of[3 * s0 + axis];
        if (v != UINT32_MAX) return v;
        const std::size_t s1 = s0 + stride[axis];
        const double f0 = L.values[s0], f1 = L.values[s1];
        const glm::dvec3 p0 = position(s0), p1 = position(s1);
        const glm::dvec3 p = edge_crossing(p0, p1, f0, f1, iso);
        const double t = (iso - f0) / (f1 - f0);
        glm::dvec3 g = L.gradients[s0] + t * (L.gradients[s1] - L.gradients[s0]);
        const double len = glm::length(g);
        v = std::uint32_t(mesh.soup.positions.size());
        mesh.soup.positions.push_back(p);
        mesh.normals.push_back(len > 0 ? g / len : glm::dvec3(0.0));
        return v;
    };
    for (int k = 0; k + 1 < n.z; ++k)
        for (int j = 0; j + 1 < n.y; ++j)
            for (int i = 0; i + 1 < n.x; ++i) {
                const std::size_t s = i * sx + j * sy + k * sz;
                std::array<double, 8> f;
                std::size_t cs[8];
                for (int c = 0; c < 8; ++c) {
                    cs[c] = s + (c & 1) * sx + ((c >> 1) & 1) * sy + ((c >> 2) & 1) * sz;
                    f[c] = L.values[cs[c]];
                }
                const int index = cube_index(f, iso);
                const int nt = geolab::mc_tables.n_triangles[index];
                for (int t = 0; t < nt; ++t) {
                    std::uint32_t tri[3];
                    for (int m = 0; m < 3; ++m) {
                        const int e = geolab::mc_tables.triangles[index][3 * t + m];
                        tri[m] = vertex(cs[mc_edge_corners[e][0]], e / 4);
                    }
                    mesh.soup.add_face({tri[0], tri[1], tri[2]});
                }
            }
    return mesh;
    // END SOLUTION
}

}  // namespace geolab::blobby
