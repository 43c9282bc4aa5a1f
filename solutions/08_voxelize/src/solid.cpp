// Task 4: solid voxelization (handout §5).
#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "geolab/predicates.hpp"
#include "geolab/voxels.hpp"

namespace geolab::voxels {

// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.
namespace {

// orient2d(a, b, q) for q moved by (δu, δv) with 0 < δv ≪ δu ≪ 1 (u the coordinate perturbed at lower order).
// The determinant is linear in q: its change is (a.v − b.v)·δu + (b.u − a.u)·δv.
int orient2d_sos(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& q) {
    const int o = orient2d(a, b, q);
    if (o != 0) return o;
    if (a.y != b.y) return a.y > b.y ? 1 : -1;
    return b.x > a.x ? 1 : -1;  // a ≠ b: the caller skips triangles whose projection has zero area
}

// The signs of the normal (b − a) × (c − a): each component is a 2D orientation (exact).
glm::ivec3 normal_signs(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    return {orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z}), orient2d({a.z, a.x}, {b.z, b.x}, {c.z, c.x}),
            orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y})};
}

// Sign of n·(p + (ε, ε², ε³) − a): which side of the triangle's plane the perturbed point lies on.
int side_sos(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::ivec3& ns, const glm::dvec3& p) {
    const int o = -orient3d(a, b, c, p);  // orient3d is +1 when p lies on the side the normal points away from
    if (o != 0) return o;
    if (ns.x != 0) return ns.x;
    if (ns.y != 0) return ns.y;
    return ns.z;
}

// Columns along `axis`: the other two coordinates, u perturbed at lower order than v.
constexpr int axis_u[3] = {1, 0, 0}, axis_v[3] = {2, 2, 1};

}  // namespace
// END SOLUTION

BitGrid parity_fill(const PolygonSoup& mesh, const Dims& dims, int axis, int threads) {
    // BEGIN SOLUTION
    if (axis < 0 || axis > 2) throw std::invalid_argument("parity_fill: axis must be 0, 1 or 2");
    if (threads < 1) throw std::invalid_argument("parity_fill: threads must be >= 1");
    check_soup(mesh);
    BitGrid grid(dims);
    if (dims.count() == 0) return grid;
    const int du = axis_u[axis], dv = axis_v[axis];
    const std::int64_t n[3] = {dims.nx, dims.ny, dims.nz};
    std::vector<std::array<std::uint32_t, 3>> tris;
    for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
        const auto vs = mesh.face(f);
        for (std::size_t t = 1; t + 1 < vs.size(); ++t) tris.push_back({vs[0], vs[t], vs[t + 1]});
    }
    // Step 1: every triangle flips, in each column it covers, the voxels from the first centre above it on.
    auto work = [&](std::size_t first, std::size_t step) {
        for (std::size_t t = first; t < tris.size(); t += step) {
            const glm::dvec3 &a = mesh.positions[tris[t][0]], &b = mesh.positions[tris[t][1]], &c = mesh.positions[tris[t][2]];
            const glm::ivec3 ns = normal_signs(a, b, c);
            const int nd = ns[axis];
            if (nd == 0) continue;  // its projection has zero area: no perturbed ray crosses it
            const glm::dvec2 pa(a[du], a[dv]), pb(b[du], b[dv]), pc(c[du], c[dv]);
            const double umin = std::min({pa.x, pb.x, pc.x}), umax = std::max({pa.x, pb.x, pc.x});
            const double vmin = std::min({pa.y, pb.y, pc.y}), vmax = std::max({pa.y, pb.y, pc.y});
            const double iu0 = std::max(0.0, std::ceil(umin - 0.5)), iu1 = std::min(double(n[du] - 1), std::floor(umax - 0.5));
            const double iv0 = std::max(0.0, std::ceil(vmin - 0.5)), iv1 = std::min(double(n[dv] - 1), std::floor(vmax - 0.5));
            if (iu0 > iu1 || iv0 > iv1) continue;
            const glm::dvec3 nrm = glm::cross(b - a, c - a);
            for (std::int64_t iv = std::int64_t(iv0); iv <= std::int64_t(iv1); ++iv)
                for (std::int64_t iu = std::int64_t(iu0); iu <= std::int64_t(iu1); ++iu) {
                    const glm::dvec2 q(double(iu) + 0.5, double(iv) + 0.5);
                    const int s0 = orient2d_sos(pa, pb, q), s1 = orient2d_sos(pb, pc, q), s2 = orient2d_sos(pc, pa, q);
                    if (s0 != s1 || s1 != s2) continue;
                    glm::dvec3 p;
                    p[du] = q.x;
                    p[dv] = q.y;
                    auto above = [&](std::int64_t k) {
                        p[axis] = double(k) + 0.5;
                        return side_sos(a, b, c, ns, p) * nd > 0;
                    };
                    // an estimate from the plane's equation, then corrected with the exact test
                    const double pd = a[axis] - (nrm[du] * (q.x - a[du]) + nrm[dv] * (q.y - a[dv])) / nrm[axis];
                    std::int64_t f = 0;
                    if (std::isfinite(pd)) f = std::int64_t(std::clamp(std::floor(pd - 0.5) + 1, 0.0, double(n[axis])));
                    while (f > 0 && above(f - 1)) --f;
                    while (f < n[axis] && !above(f)) ++f;
                    if (f == n[axis]) continue;
                    std::int64_t ijk[3];
                    ijk[du] = iu;
                    ijk[dv] = iv;
                    ijk[axis] = f;
                    const std::uint64_t idx = std::uint64_t(ijk[0]) + std::uint64_t(dims.nx) * (std::uint64_t(ijk[1]) + std::uint64_t(dims.ny) * std::uint64_t(ijk[2]));
                    // threads share words: an atomic XOR (the result does not depend on the order)
                    std::atomic_ref<std::uint64_t>(grid.words[idx >> 6]).fetch_xor(std::uint64_t(1) << (idx & 63),
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
    // Step 2: prefix XOR along the axis turns the flips into the parity.
    const std::uint64_t stride = axis == 0 ? 1 : axis == 1 ? std::uint64_t(dims.nx) : std::uint64_t(dims.nx * dims.ny);
    for (std::int64_t iv = 0; iv < n[dv]; ++iv)
        for (std::int64_t iu = 0; iu < n[du]; ++iu) {
            std::int64_t ijk[3];
            ijk[du] = iu;
            ijk[dv] = iv;
            ijk[axis] = 0;
            std::uint64_t idx = std::uint64_t(ijk[0]) + std::uint64_t(dims.nx) * (std::uint64_t(ijk[1]) + std::uint64_t(dims.ny) * std::uint64_t(ijk[2]));
            bool parity = false;
            for (std::int64_t k = 0; k < n[axis]; ++k, idx += stride) {
                parity ^= (grid.words[idx >> 6] >> (idx & 63)) & 1u;
                if (parity) grid.words[idx >> 6] |= std::uint64_t(1) << (idx & 63);
                else grid.words[idx >> 6] &= ~(std::uint64_t(1) << (idx & 63));
            }
        }
    return grid;
    // END SOLUTION
}

std::uint64_t count_boundary_edges(const PolygonSoup& mesh) {
    // BEGIN SOLUTION
    check_soup(mesh);
    // one id per distinct position
    std::vector<std::uint32_t> order(mesh.positions.size());
    for (std::uint32_t v = 0; v < order.size(); ++v) order[v] = v;
    auto less = [&](std::uint32_t x, std::uint32_t y) {
        const glm::dvec3 &p = mesh.positions[x], &q = mesh.positions[y];
        return p.x != q.x ? p.x < q.x : p.y != q.y ? p.y < q.y : p.z < q.z;
    };
    std::sort(order.begin(), order.end(), less);
    std::vector<std::uint32_t> id(order.size());
    std::uint32_t next = 0;
    for (std::size_t r = 0; r < order.size(); ++r) {
        if (r > 0 && less(order[r - 1], order[r])) ++next;
        id[order[r]] = next;
    }
    std::vector<std::uint64_t> edges;
    auto add = [&](std::uint32_t x, std::uint32_t y) {
        x = id[x];
        y = id[y];
        if (x == y) return;  // from a vertex to itself: no edge
        edges.push_back(std::uint64_t(std::min(x, y)) << 32 | std::max(x, y));
    };
    for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
        const auto vs = mesh.face(f);
        for (std::size_t t = 1; t + 1 < vs.size(); ++t) {
            add(vs[0], vs[t]);
            add(vs[t], vs[t + 1]);
            add(vs[t + 1], vs[0]);
        }
    }
    std::sort(edges.begin(), edges.end());
    std::uint64_t odd = 0;
    for (std::size_t r = 0; r < edges.size();) {
        std::size_t s = r;
        while (s < edges.size() && edges[s] == edges[r]) ++s;
        if ((s - r) % 2 == 1) ++odd;
        r = s;
    }
    return odd;
    // END SOLUTION
}

BitGrid flood_fill_solid(const BitGrid& surface) {
    // BEGIN SOLUTION
    const Dims d = surface.dims;
    BitGrid outside(d);
    if (surface.words.size() != outside.words.size()) throw std::invalid_argument("flood_fill_solid: wrong words size");
    std::vector<std::uint64_t> stack;
    auto visit = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
        if (i < 0 || j < 0 || k < 0 || i >= d.nx || j >= d.ny || k >= d.nz) return;
        if (surface.get(i, j, k) || outside.get(i, j, k)) return;
        outside.set(i, j, k);
        stack.push_back(std::uint64_t(i) + std::uint64_t(d.nx) * (std::uint64_t(j) + std::uint64_t(d.ny) * std::uint64_t(k)));
    };
    for (std::int64_t k = 0; k < d.nz; ++k)
        for (std::int64_t j = 0; j < d.ny; ++j)
            for (std::int64_t i = 0; i < d.nx; ++i)
                if (i == 0 || j == 0 || k == 0 || i == d.nx - 1 || j == d.ny - 1 || k == d.nz - 1) visit(i, j, k);
    const std::uint64_t nx = std::uint64_t(d.nx), nxy = nx * std::uint64_t(d.ny);
    while (!stack.empty()) {
        const std::uint64_t idx = stack.back();
        stack.pop_back();
        const auto k = std::int64_t(idx / nxy), j = std::int64_t(idx % nxy / nx), i = std::int64_t(idx % nx);
        visit(i - 1, j, k);
        visit(i + 1, j, k);
        visit(i, j - 1, k);
        visit(i, j + 1, k);
        visit(i, j, k - 1);
        visit(i, j, k + 1);
    }
    BitGrid solid(d);
    const std::uint64_t total = std::uint64_t(d.count());
    for (std::size_t w = 0; w < solid.words.size(); ++w) {
        std::uint64_t bits = ~outside.words[w];
        const std::uint64_t end = std::min<std::uint64_t>(64, total - 64 * w);
        if (end < 64) bits &= (std::uint64_t(1) << end) - 1;
        solid.words[w] = bits;
    }
    return solid;
    // END SOLUTION
}

SolidResult voxelize_solid(const PolygonSoup& mesh, const Dims& dims, int threads) {
    // BEGIN SOLUTION
    SolidResult r;
    r.boundary_edges = count_boundary_edges(mesh);
    if (r.boundary_edges == 0) {
        r.method = SolidMethod::parity;
        const BitGrid x = parity_fill(mesh, dims, 0, threads), y = parity_fill(mesh, dims, 1, threads),
                      z = parity_fill(mesh, dims, 2, threads);
        r.grid = BitGrid(dims);
        for (std::size_t w = 0; w < r.grid.words.size(); ++w) {
            const std::uint64_t all = x.words[w] & y.words[w] & z.words[w], any = x.words[w] | y.words[w] | z.words[w];
            r.grid.words[w] = all;
            r.axis_disagreements += std::uint64_t(std::popcount(any & ~all));
        }
    } else {
        r.method = SolidMethod::flood_fill;
        r.grid = flood_fill_solid(voxelize_surface(mesh, dims, threads));
    }
    return r;
    // END SOLUTION
}

}  // namespace geolab::voxels
