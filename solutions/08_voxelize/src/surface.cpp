// Task 3: surface voxelization (handout §4).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>

#include "geolab/voxels.hpp"

namespace geolab::voxels {

// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.
namespace {

// One separating axis prepared for one triangle: the triangle projects onto `a` as [t0, t1], a voxel as its
// centre's projection ± r. Separated when the two only touch or are disjoint (the voxel is open).
struct Axis {
    glm::dvec3 a;
    double t0, t1, r;
    bool separates(const glm::dvec3& centre) const {
        const double s = glm::dot(a, centre);
        return t0 - s >= r || t1 - s <= -r;
    }
};

// A triangle prepared for Task 2's 13-axis test against every voxel of its box (Schwarz & Seidel's observation:
// what does not depend on the voxel is computed once). The 3 box normals become the voxel ranges lo..hi. The
// other 10 axes (its normal, the 9 edge cross products) are split by their x component: an axis with a.x = 0 gives
// the same answer for a whole row of voxels (j, k), the others are tested voxel by voxel. Coordinates are relative
// to the corner `o` of the triangle's first voxel in the grid: exact (differences of nearby doubles) and small, as
// Task 2's.
struct PreparedTriangle {
    std::int64_t lo[3], hi[3];
    glm::dvec3 o;
    Axis row[10], voxel[10];
    int n_row = 0, n_voxel = 0;
};

// False when the triangle belongs to no voxel of the grid (zero area, or its box misses the grid).
bool prepare(glm::dvec3 v0, glm::dvec3 v1, glm::dvec3 v2, const std::int64_t n[3], PreparedTriangle& t) {
    const glm::dvec3 normal = glm::cross(v1 - v0, v2 - v0);
    if (normal == glm::dvec3(0.0)) return false;
    // the tie rule: a triangle in the voxel plane x = m moves half a voxel into the layer behind its normal
    for (int d = 0; d < 3; ++d)
        if (v0[d] == v1[d] && v1[d] == v2[d] && std::floor(v0[d]) == v0[d]) {
            const double shift = normal[d] > 0 ? -0.5 : 0.5;
            v0[d] += shift;
            v1[d] += shift;
            v2[d] += shift;
            break;
        }
    // the box normals: voxel i's open interval (i, i+1) meets [min, max] for floor(min) <= i <= ceil(max) − 1
    for (int d = 0; d < 3; ++d) {
        const double mn = std::min({v0[d], v1[d], v2[d]}), mx = std::max({v0[d], v1[d], v2[d]});
        const double lo = std::max(0.0, std::floor(mn)), hi = std::min(double(n[d] - 1), std::ceil(mx) - 1);
        if (hi < lo) return false;  // (in double: a far-away triangle never reaches int64)
        t.lo[d] = std::int64_t(lo);
        t.hi[d] = std::int64_t(hi);
        t.o[d] = lo;
    }
    const glm::dvec3 p[3] = {v0 - t.o, v1 - t.o, v2 - t.o};
    t.n_row = t.n_voxel = 0;
    auto add = [&](const glm::dvec3& a) {
        if (a == glm::dvec3(0.0)) return;  // an edge parallel to a box edge: no axis
        const double s0 = glm::dot(a, p[0]), s1 = glm::dot(a, p[1]), s2 = glm::dot(a, p[2]);
        const Axis axis{a, std::min({s0, s1, s2}), std::max({s0, s1, s2}), 0.5 * (std::abs(a.x) + std::abs(a.y) + std::abs(a.z))};
        if (a.x == 0) t.row[t.n_row++] = axis;
        else t.voxel[t.n_voxel++] = axis;
    };
    // the normal (Task 2 projects only v0 on it: the three projections are equal up to rounding)
    const double s = glm::dot(normal, p[0]);
    const Axis plane{normal, s, s, 0.5 * (std::abs(normal.x) + std::abs(normal.y) + std::abs(normal.z))};
    if (normal.x == 0) t.row[t.n_row++] = plane;
    else t.voxel[t.n_voxel++] = plane;
    const glm::dvec3 e[3] = {p[1] - p[0], p[2] - p[1], p[0] - p[2]};
    for (const glm::dvec3& ed : e) {
        add({0.0, -ed.z, ed.y});  // e_x × edge
        add({ed.z, 0.0, -ed.x});  // e_y × edge
        add({-ed.y, ed.x, 0.0});  // e_z × edge
    }
    return true;
}

bool separated(const Axis* axes, int count, const glm::dvec3& centre) {
    for (int a = 0; a < count; ++a)
        if (axes[a].separates(centre)) return true;
    return false;
}

// A fan triangle of the mesh: its three vertices.
struct Triangle {
    std::uint32_t a, b, c;
};

// The layers [k0, k1) in slabs of about 16 layers that start at word boundaries (each word has one writer, so
// threads need no atomics, and a slab's words stay in the cache while its triangles set them), with the triangles
// of each slab: those that may have voxels there (the layers floor(zmin) − 1 .. floor(zmax) + 1).
struct Slabs {
    std::vector<std::int64_t> bounds;              // slab s is the layers [bounds[s], bounds[s + 1])
    std::vector<std::vector<Triangle>> triangles;  // slab s's triangles
};

Slabs make_slabs(const PolygonSoup& mesh, const Dims& dims, std::int64_t k0, std::int64_t k1, int threads) {
    Slabs slabs;
    slabs.bounds = word_aligned_slabs(dims, k0, k1, int(std::max<std::int64_t>(2 * threads, (k1 - k0) / 16)));
    slabs.triangles.resize(slabs.bounds.size() - 1);
    const std::vector<std::int64_t>& b = slabs.bounds;
    for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
        const auto vs = mesh.face(f);
        for (std::size_t v = 1; v + 1 < vs.size(); ++v) {
            const Triangle t{vs[0], vs[v], vs[v + 1]};
            const double za = mesh.positions[t.a].z, zb = mesh.positions[t.b].z, zc = mesh.positions[t.c].z;
            const double lo = std::floor(std::min({za, zb, zc})) - 1, hi = std::floor(std::max({za, zb, zc})) + 1;
            // the slabs s with b[s + 1] > lo (from the one holding lo on) and b[s] <= hi
            const auto above_lo = std::size_t(std::upper_bound(b.begin(), b.end(), lo) - b.begin());
            for (std::size_t s = above_lo == 0 ? 0 : above_lo - 1; s + 1 < b.size() && double(b[s]) <= hi; ++s)
                slabs.triangles[s].push_back(t);
        }
    }
    return slabs;
}

}  // namespace
// END SOLUTION

BitGrid voxelize_surface_layers(const PolygonSoup& mesh, const Dims& dims, std::int64_t k0, std::int64_t k1,
                                int threads) {
    // BEGIN SOLUTION
    if (threads < 1) throw std::invalid_argument("voxelize_surface_layers: threads must be >= 1");
    if (k0 < 0 || k0 > k1 || k1 > dims.nz)
        throw std::invalid_argument("voxelize_surface_layers: layers [" + std::to_string(k0) + ", " + std::to_string(k1) +
                                    ") are not within [0, " + std::to_string(dims.nz) + ")");
    check_soup(mesh);
    BitGrid grid(Dims{dims.nx, dims.ny, k1 - k0});
    if (grid.dims.count() == 0) return grid;
    const std::int64_t n[3] = {dims.nx, dims.ny, dims.nz};
    const Slabs slabs = make_slabs(mesh, dims, k0, k1, threads);
    std::atomic<std::size_t> next_slab{0};  // the threads take the slabs in turn
    auto work = [&] {
        PreparedTriangle t;
        for (std::size_t s; (s = next_slab++) < slabs.triangles.size();)
            for (const Triangle& tri : slabs.triangles[s]) {
                if (!prepare(mesh.positions[tri.a], mesh.positions[tri.b], mesh.positions[tri.c], n, t)) continue;
                for (std::int64_t k = std::max(t.lo[2], slabs.bounds[s]); k <= std::min(t.hi[2], slabs.bounds[s + 1] - 1); ++k)
                    for (std::int64_t j = t.lo[1]; j <= t.hi[1]; ++j) {
                        glm::dvec3 centre(0.0, double(j) - t.o.y + 0.5, double(k) - t.o.z + 0.5);
                        if (separated(t.row, t.n_row, centre)) continue;
                        for (std::int64_t i = t.lo[0]; i <= t.hi[0]; ++i) {
                            centre.x = double(i) - t.o.x + 0.5;
                            if (separated(t.voxel, t.n_voxel, centre)) continue;
                            const std::uint64_t idx = std::uint64_t(i) + std::uint64_t(dims.nx) * (std::uint64_t(j) + std::uint64_t(dims.ny) * std::uint64_t(k - k0));
                            grid.words[idx >> 6] |= std::uint64_t(1) << (idx & 63);
                        }
                    }
            }
    };
    std::vector<std::thread> pool;
    for (int w = 1; w < threads; ++w) pool.emplace_back(work);
    work();
    for (std::thread& th : pool) th.join();
    return grid;
    // END SOLUTION
}

BitGrid voxelize_surface(const PolygonSoup& mesh, const Dims& dims, int threads) {
    // BEGIN SOLUTION
    return voxelize_surface_layers(mesh, dims, 0, dims.nz, threads);
    // END SOLUTION
}

}  // namespace geolab::voxels
