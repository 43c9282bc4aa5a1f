#pragma once
// Lab 08, Task 7 test helpers: expected solids computed without the student's CPU tasks (Task 4) — by the shapes'
// own equations with the perturbation c + (ε, ε², ε³), by half-spaces of convex meshes, or by an exact per-column
// parity (hidden tests only) — and the distance from a voxel centre to a mesh, which bounds where the GPU, working
// in float on a 1/256-pixel lattice, may decide a voxel differently (handout §9).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "helpers.hpp"

namespace lab08 {

// Where the GPU may differ from the exact rule: voxel centres closer to the mesh than this (in voxels): the
// rasterizer snaps corners to 1/256 of a pixel (half a step, 2⁻⁹, per coordinate: √2·2⁻⁹ ≈ 0.0028) and the
// slab test rounds to float (about 10⁻⁵ at 256 voxels).
constexpr double gl_band = 1.0 / 256;

// The fan triangles of a soup.
inline std::vector<std::array<glm::dvec3, 3>> triangles_of(const PolygonSoup& s) {
    std::vector<std::array<glm::dvec3, 3>> out;
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        const auto vs = s.face(f);
        for (std::size_t t = 1; t + 1 < vs.size(); ++t) out.push_back({s.positions[vs[0]], s.positions[vs[t]], s.positions[vs[t + 1]]});
    }
    return out;
}

// The distance from p to the triangle: to its plane when p projects inside it, else to the nearest edge.
inline double distance_to_triangle(const glm::dvec3& p, const std::array<glm::dvec3, 3>& t) {
    const glm::dvec3 &a = t[0], &b = t[1], &c = t[2];
    auto seg = [&](const glm::dvec3& x, const glm::dvec3& y) {
        const glm::dvec3 e = y - x;
        const double l2 = glm::dot(e, e);
        const double s = l2 > 0 ? std::clamp(glm::dot(p - x, e) / l2, 0.0, 1.0) : 0.0;
        return glm::length(p - (x + s * e));
    };
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double n2 = glm::dot(n, n);
    if (n2 > 0) {
        // the projection onto the plane, inside the triangle when its three edge signs agree
        const glm::dvec3 q = p - glm::dot(p - a, n) / n2 * n;
        const double s0 = glm::dot(glm::cross(b - a, q - a), n), s1 = glm::dot(glm::cross(c - b, q - b), n),
                     s2 = glm::dot(glm::cross(a - c, q - c), n);
        if (s0 >= 0 && s1 >= 0 && s2 >= 0) return std::abs(glm::dot(p - a, n)) / std::sqrt(n2);
    }
    return std::min({seg(a, b), seg(b, c), seg(c, a)});
}

// The distance from p to the nearest triangle.
inline double distance_to_mesh(const glm::dvec3& p, const std::vector<std::array<glm::dvec3, 3>>& tris) {
    double d = std::numeric_limits<double>::infinity();
    for (const auto& t : tris) d = std::min(d, distance_to_triangle(p, t));
    return d;
}

// Compares the GPU's grid with the expected one: they may differ only at voxels whose centre lies within gl_band
// of the mesh. Returns "" when that holds, else a message naming the first voxel beyond the band (at most 2000
// differing voxels are measured; more fail at once). `differ` receives the number of differing voxels.
inline std::string differences_beyond_band(const BitGrid& got, const BitGrid& want, const PolygonSoup& mesh,
                                           std::uint64_t* differ = nullptr) {
    if (!(got.dims == want.dims)) return "dims " + str(got.dims) + " instead of " + str(want.dims);
    if (!tail_clean(got)) return "the words have the wrong size or bits past the last voxel are set";
    std::vector<std::array<std::int64_t, 3>> diff;
    for (std::int64_t k = 0; k < want.dims.nz; ++k)
        for (std::int64_t j = 0; j < want.dims.ny; ++j)
            for (std::int64_t i = 0; i < want.dims.nx; ++i)
                if (got.get(i, j, k) != want.get(i, j, k)) diff.push_back({i, j, k});
    if (differ) *differ = diff.size();
    if (diff.empty()) return "";
    auto name = [&](const std::array<std::int64_t, 3>& v) {
        return "voxel (" + std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " + std::to_string(v[2]) + ") is " +
               (got.get(v[0], v[1], v[2]) ? "set" : "unset") + ", expected " + (want.get(v[0], v[1], v[2]) ? "set" : "unset");
    };
    if (diff.size() > 2000) return std::to_string(diff.size()) + " voxels differ, e.g. " + name(diff[0]);
    const auto tris = triangles_of(mesh);
    for (const auto& v : diff) {
        const double d = distance_to_mesh({v[0] + 0.5, v[1] + 0.5, v[2] + 0.5}, tris);
        if (d > gl_band)
            return name(v) + "; its centre is " + std::to_string(d) + " voxels from the mesh, beyond the " +
                   std::to_string(gl_band) + " where float rounding may decide (" + std::to_string(diff.size()) +
                   " voxels differ in all)";
    }
    return "";
}

// ---- expected solids ----------------------------------------------------------------------------------------
// The box [lo, hi] (any orientation of its faces): with the perturbation, a centre on the face x = lo is inside and
// one on x = hi outside, so inside means lo ≤ c < hi in each coordinate.
inline BitGrid box_solid(Dims d, glm::dvec3 lo, glm::dvec3 hi) {
    return grid_of(d, [&](std::int64_t i, std::int64_t j, std::int64_t k) {
        const glm::dvec3 c(i + 0.5, j + 0.5, k + 0.5);
        return lo.x <= c.x && c.x < hi.x && lo.y <= c.y && c.y < hi.y && lo.z <= c.z && c.z < hi.z;
    });
}
// The octahedron |x − c.x| + |y − c.y| + |z − c.z| ≤ r: on the surface, moving by (ε, ε², ε³) changes f by
// sign(x − c.x)·ε (+ε when x = c.x), so a centre on the surface is inside exactly when x < c.x.
inline BitGrid octahedron_solid(Dims d, glm::dvec3 c, double r) {
    return grid_of(d, [&](std::int64_t i, std::int64_t j, std::int64_t k) {
        const glm::dvec3 p(i + 0.5, j + 0.5, k + 0.5);
        const double f = std::abs(p.x - c.x) + std::abs(p.y - c.y) + std::abs(p.z - c.z);
        return f < r || (f == r && p.x < c.x);
    });
}
// A convex mesh with outward faces: inside = below every face plane (long double). Centres within gl_band of a
// plane are left to differences_beyond_band.
inline BitGrid convex_solid(Dims d, const PolygonSoup& s) {
    const auto tris = triangles_of(s);
    return grid_of(d, [&](std::int64_t i, std::int64_t j, std::int64_t k) {
        const glm::dvec3 p(i + 0.5, j + 0.5, k + 0.5);
        for (const auto& t : tris) {
            const glm::dvec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
            const LD side = LD(n.x) * (LD(p.x) - t[0].x) + LD(n.y) * (LD(p.y) - t[0].y) + LD(n.z) * (LD(p.z) - t[0].z);
            if (side >= 0) return false;
        }
        return true;
    });
}

// Corners of a mesh moved by an affine map (rotations by 90°, mirrors, translations keep ties ties).
inline PolygonSoup transformed(PolygonSoup s, const glm::dmat3& m, glm::dvec3 t) {
    for (auto& p : s.positions) p = m * p + t;
    return s;
}

}  // namespace lab08
