// Task 3: surface voxelization (handout §4).
#include <algorithm>
#include <array>
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

// The voxel range [lo, hi] of coordinate d that a triangle's bounding box [mn, mx] can belong to in a grid of n.
void voxel_range(double mn, double mx, std::int64_t n, std::int64_t& lo, std::int64_t& hi) {
    // open boxes: a box touched only at its face x = floor(mx) + 1 ... is not met; a triangle in the plane x = m
    // (mn = mx = m) may belong to layer m − 1 or m
    double l = std::floor(mn), h = std::ceil(mx) - 1;
    if (mn == mx && std::floor(mn) == mn) {
        l = mn - 1;
        h = mn;
    }
    l = std::max(l, 0.0);
    h = std::min(h, double(n - 1));
    lo = std::int64_t(l);
    hi = h < l ? lo - 1 : std::int64_t(h);
}

}  // namespace
// END SOLUTION

BitGrid voxelize_surface(const PolygonSoup& mesh, const Dims& dims, int threads) {
    // BEGIN SOLUTION
    if (threads < 1) throw std::invalid_argument("voxelize_surface: threads must be >= 1");
    check_soup(mesh);
    BitGrid grid(dims);
    if (dims.count() == 0) return grid;
    // the fan triangles, listed once
    std::vector<std::array<std::uint32_t, 3>> tris;
    for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
        const auto vs = mesh.face(f);
        for (std::size_t t = 1; t + 1 < vs.size(); ++t) tris.push_back({vs[0], vs[t], vs[t + 1]});
    }
    const double nmax[3] = {double(dims.nx), double(dims.ny), double(dims.nz)};
    auto work = [&](std::size_t first, std::size_t step) {
        for (std::size_t t = first; t < tris.size(); t += step) {
            const glm::dvec3 &a = mesh.positions[tris[t][0]], &b = mesh.positions[tris[t][1]], &c = mesh.positions[tris[t][2]];
            std::int64_t lo[3], hi[3];
            bool empty = false;
            for (int d = 0; d < 3; ++d) {
                const double mn = std::min({a[d], b[d], c[d]}), mx = std::max({a[d], b[d], c[d]});
                if (mx < -1 || mn > nmax[d] + 1) {  // far outside (also keeps huge values away from int64)
                    empty = true;
                    break;
                }
                voxel_range(mn, mx, std::int64_t(nmax[d]), lo[d], hi[d]);
                if (hi[d] < lo[d]) empty = true;
            }
            if (empty) continue;
            for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
                for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
                    for (std::int64_t i = lo[0]; i <= hi[0]; ++i) {
                        if (!triangle_overlaps_voxel(a, b, c, i, j, k)) continue;
                        const std::uint64_t n = std::uint64_t(i) + std::uint64_t(dims.nx) * (std::uint64_t(j) + std::uint64_t(dims.ny) * std::uint64_t(k));
                        // threads share words: an atomic OR (the result does not depend on the order)
                        std::atomic_ref<std::uint64_t>(grid.words[n >> 6]).fetch_or(std::uint64_t(1) << (n & 63),
                                                                                   std::memory_order_relaxed);
                    }
        }
    };
    if (threads == 1) {
        work(0, 1);
    } else {
        std::vector<std::thread> pool;
        for (int w = 0; w < threads; ++w) pool.emplace_back(work, std::size_t(w), std::size_t(threads));
        for (std::thread& th : pool) th.join();
    }
    return grid;
    // END SOLUTION
}

}  // namespace geolab::voxels
