// Procedural volume meshes (see volume_fixtures.hpp); tests/lib/test_volume_fixtures.cpp checks each documented
// count and invariant.
#include "geolab/volume_fixtures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <string>

namespace geolab::volume_fixtures {
namespace {

void require_size(int n, int lo, int hi, const char* what) {
    if (n < lo || n > hi)
        throw std::invalid_argument(std::string(what) + ": n = " + std::to_string(n) + " is outside " +
                                    std::to_string(lo) + ".." + std::to_string(hi));
}

// The (n+1)³ lattice points (i, j, k)/n · size + origin, numbered (k(n+1) + j)(n+1) + i.
void add_lattice(VolumeMesh& m, int n, const glm::dvec3& origin, double size) {
    m.positions.reserve(std::size_t(n + 1) * (n + 1) * (n + 1));
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) m.positions.push_back(origin + size * glm::dvec3(i, j, k) / double(n));
}

// The 8 lattice corners of cube (i, j, k) in binary order: corner t = (i + (t & 1), j + (t >> 1 & 1), k + (t >> 2 &
// 1)).
std::array<std::uint32_t, 8> cube_corners(int n, int i, int j, int k) {
    std::array<std::uint32_t, 8> b{};
    for (int t = 0; t < 8; ++t)
        b[t] = std::uint32_t(((k + (t >> 2 & 1)) * (n + 1) + j + (t >> 1 & 1)) * (n + 1) + i + (t & 1));
    return b;
}

// The 6 Kuhn tetrahedra of the cube with binary-ordered corners b: the paths 0 → e_p → e_p + e_q → 7 over the
// orders (p, q, r) of the axes; odd orders swap two corners so that every tetrahedron is positive.
void add_kuhn(VolumeMesh& m, const std::array<std::uint32_t, 8>& b, std::int32_t label) {
    static const int orders[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 2}, {2, 1}, {1, 0}};  // even, then odd
    for (int o = 0; o < 6; ++o) {
        const int i1 = 1 << orders[o][0], i2 = i1 | (1 << orders[o][1]);
        const std::array<std::uint32_t, 4> t = o < 3 ? std::array<std::uint32_t, 4>{b[0], b[i1], b[i2], b[7]}
                                                     : std::array<std::uint32_t, 4>{b[0], b[i2], b[i1], b[7]};
        m.add_cell(VolumeCell::tetrahedron, t, label);
    }
}

}  // namespace

VolumeMesh kuhn_cube() { return tet_grid(1); }

VolumeMesh tet_grid(int n) {
    require_size(n, 1, 256, "tet_grid");
    VolumeMesh m;
    add_lattice(m, n, glm::dvec3(0.0), 1.0);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) add_kuhn(m, cube_corners(n, i, j, k), 0);
    return m;
}

VolumeMesh hex_grid(int n) {
    require_size(n, 1, 256, "hex_grid");
    VolumeMesh m;
    add_lattice(m, n, glm::dvec3(0.0), 1.0);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const auto b = cube_corners(n, i, j, k);
                const std::array<std::uint32_t, 8> v{b[0], b[1], b[3], b[2], b[4], b[5], b[7], b[6]};
                m.add_cell(VolumeCell::hexahedron, v);
            }
    return m;
}

VolumeMesh ball_with_torus(int n) {
    require_size(n, 5, 256, "ball_with_torus");
    VolumeMesh m;
    add_lattice(m, n, glm::dvec3(-1.0), 2.0);
    // cube (i, j, k) has its centre at m/n with m = 2(i, j, k) + 1 − n: the ring test in integers, exactly symmetric
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const int mx = std::abs(2 * i + 1 - n), my = std::abs(2 * j + 1 - n), mz = std::abs(2 * k + 1 - n);
                const int ring = 10 * std::max(mx, my);
                const bool torus = ring >= 3 * n && ring <= 6 * n && 10 * mz <= 3 * n;
                add_kuhn(m, cube_corners(n, i, j, k), torus ? 1 : 0);
            }
    // onto the ball: p ↦ p·‖p‖∞/‖p‖₂ (the centre stays)
    for (glm::dvec3& p : m.positions) {
        const double len = glm::length(p);
        if (len > 0) p *= std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) / len;
    }
    return m;
}

}  // namespace geolab::volume_fixtures
