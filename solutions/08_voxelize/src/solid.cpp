// Task 4: solid voxelization (handout §5).
#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cstdint>
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

// ---- runs of bits anywhere in the packed grid (a row or a layer need not start at a word) --------------------
// The `len` bits (1..64) from bit `pos` on, as the low bits of a word.
std::uint64_t get_bits(const std::vector<std::uint64_t>& w, std::uint64_t pos, unsigned len) {
    const std::uint64_t word = pos >> 6;
    const unsigned shift = pos & 63;
    std::uint64_t bits = w[word] >> shift;
    if (shift + len > 64) bits |= w[word + 1] << (64 - shift);
    return len == 64 ? bits : bits & ((std::uint64_t(1) << len) - 1);
}
// Writes the low `len` bits of `bits` at bit `pos`; the other bits stay.
void put_bits(std::vector<std::uint64_t>& w, std::uint64_t pos, unsigned len, std::uint64_t bits) {
    const std::uint64_t word = pos >> 6;
    const unsigned shift = pos & 63;
    const std::uint64_t mask = len == 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << len) - 1;
    bits &= mask;
    w[word] = (w[word] & ~(mask << shift)) | (bits << shift);
    if (shift + len > 64) w[word + 1] = (w[word + 1] & ~(mask >> (64 - shift))) | (bits >> (64 - shift));
}
// Bit i of the result is the XOR of bits 0..i of x.
std::uint64_t prefix_xor(std::uint64_t x) {
    for (int s = 1; s < 64; s *= 2) x ^= x << s;
    return x;
}
// Prefix XOR along the `len` bits from `pos` (a row along x): each bit becomes the parity of the bits up to it.
void prefix_xor_run(std::vector<std::uint64_t>& w, std::uint64_t pos, std::uint64_t len) {
    std::uint64_t carry = 0;  // all ones when the bits so far have odd parity
    for (std::uint64_t off = 0; off < len; off += 64) {
        const auto n = unsigned(std::min<std::uint64_t>(64, len - off));
        const std::uint64_t x = prefix_xor(get_bits(w, pos + off, n)) ^ carry;
        put_bits(w, pos + off, n, x);
        carry = (x >> (n - 1)) & 1 ? ~std::uint64_t(0) : 0;
    }
}
// XOR the `len` bits from `src` into the `len` bits from `dst` (a row or a layer onto the next one).
void xor_run(std::vector<std::uint64_t>& w, std::uint64_t src, std::uint64_t dst, std::uint64_t len) {
    std::uint64_t off = 0;
    if (src % 64 == 0 && dst % 64 == 0)  // both start at a word (rows and layers of 64·m voxels): word by word
        for (; off + 64 <= len; off += 64) w[(dst + off) / 64] ^= w[(src + off) / 64];
    for (; off < len; off += 64) {
        const auto n = unsigned(std::min<std::uint64_t>(64, len - off));
        put_bits(w, dst + off, n, get_bits(w, dst + off, n) ^ get_bits(w, src + off, n));
    }
}

// A fan triangle of the mesh: its three vertices.
struct Triangle {
    std::uint32_t a, b, c;
};

// The layers [k0, k1) in slabs of about 16 layers that start at word boundaries (each word has one writer, so
// threads need no atomics, and a slab's words stay in the cache while its triangles flip them), with the triangles
// of each slab: those whose columns or flips can be there (the layers floor(zmin − ½) .. floor(zmax − ½) + 1); a
// triangle below all slabs goes to the first (along z it flips whole columns), one above all slabs nowhere.
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
            const double lo = std::floor(std::min({za, zb, zc}) - 0.5), hi = std::floor(std::max({za, zb, zc}) - 0.5) + 1;
            // the slabs s with b[s + 1] > lo (from the one holding lo on, or the first) and b[s] <= hi
            const auto above_lo = std::size_t(std::upper_bound(b.begin(), b.end(), lo) - b.begin());
            std::size_t s = above_lo == 0 ? 0 : above_lo - 1;
            if (s + 1 == b.size()) continue;  // above all slabs
            do slabs.triangles[s].push_back(t);
            while (++s + 1 < b.size() && double(b[s]) <= hi);
        }
    }
    return slabs;
}

// Runs work(s) for every slab s, on `threads` threads that take the slabs in turn.
template <class Work>
void for_each_slab(const Slabs& slabs, int threads, Work work) {
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        for (std::size_t s; (s = next++) < slabs.triangles.size();) work(s);
    };
    std::vector<std::thread> pool;
    for (int w = 1; w < threads; ++w) pool.emplace_back(worker);
    worker();
    for (std::thread& th : pool) th.join();
}

// Step 1 for one triangle (a, b, c) and the slab [s0, s1) of a grid whose first layer is k0: in every column along
// `axis` whose perturbed centre line crosses the triangle, flip the first voxel whose centre lies above it (along
// z, below layer k0 means layer k0; nothing when no centre is above). `ns`: the signs of the triangle's normal.
void flip_columns(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::ivec3& ns, int axis,
                  const Dims& dims, std::int64_t k0, std::int64_t s0, std::int64_t s1, std::vector<std::uint64_t>& words) {
    const int nd = ns[axis];
    if (nd == 0) return;  // its projection has zero area: no perturbed ray crosses it
    const int du = axis_u[axis], dv = axis_v[axis];
    const std::int64_t n[3] = {dims.nx, dims.ny, dims.nz};
    const glm::dvec2 pa(a[du], a[dv]), pb(b[du], b[dv]), pc(c[du], c[dv]);
    // the columns whose centre (iu + ½, iv + ½) can lie in the projection; along x and y only this slab's rows
    const double umin = std::min({pa.x, pb.x, pc.x}), umax = std::max({pa.x, pb.x, pc.x});
    const double vmin = std::min({pa.y, pb.y, pc.y}), vmax = std::max({pa.y, pb.y, pc.y});
    const double vlo = axis == 2 ? 0.0 : double(s0), vhi = axis == 2 ? double(n[dv] - 1) : double(s1 - 1);
    const double iu0 = std::max(0.0, std::ceil(umin - 0.5)), iu1 = std::min(double(n[du] - 1), std::floor(umax - 0.5));
    const double iv0 = std::max(vlo, std::ceil(vmin - 0.5)), iv1 = std::min(vhi, std::floor(vmax - 0.5));
    if (iu0 > iu1 || iv0 > iv1) return;
    const std::int64_t lowest = axis == 2 ? k0 : 0;  // the first voxel a flip can land on
    const glm::dvec3 nrm = glm::cross(b - a, c - a);
    for (auto iv = std::int64_t(iv0); iv <= std::int64_t(iv1); ++iv)
        for (auto iu = std::int64_t(iu0); iu <= std::int64_t(iu1); ++iu) {
            const glm::dvec2 q(double(iu) + 0.5, double(iv) + 0.5);
            const int o0 = orient2d_sos(pa, pb, q), o1 = orient2d_sos(pb, pc, q), o2 = orient2d_sos(pc, pa, q);
            if (o0 != o1 || o1 != o2) continue;
            glm::dvec3 p;
            p[du] = q.x;
            p[dv] = q.y;
            auto above = [&](std::int64_t k) {
                p[axis] = double(k) + 0.5;
                return side_sos(a, b, c, ns, p) * nd > 0;
            };
            // an estimate from the plane's equation, then corrected with the exact test
            const double pd = a[axis] - (nrm[du] * (q.x - a[du]) + nrm[dv] * (q.y - a[dv])) / nrm[axis];
            std::int64_t f = lowest;
            if (std::isfinite(pd)) f = std::int64_t(std::clamp(std::floor(pd - 0.5) + 1, double(lowest), double(n[axis])));
            while (f > lowest && above(f - 1)) --f;
            while (f < n[axis] && !above(f)) ++f;
            std::int64_t ijk[3];
            ijk[du] = iu;
            ijk[dv] = iv;
            ijk[axis] = f;
            if (f == n[axis] || ijk[2] < s0 || ijk[2] >= s1) continue;  // no centre above, or another slab's voxel
            const std::uint64_t idx = std::uint64_t(ijk[0]) + std::uint64_t(dims.nx) * (std::uint64_t(ijk[1]) + std::uint64_t(dims.ny) * std::uint64_t(ijk[2] - k0));
            words[idx >> 6] ^= std::uint64_t(1) << (idx & 63);
        }
}

// Step 1 for slab s along each axis d with words[d] set, into grids whose first layer is k0.
void slab_flips(const PolygonSoup& mesh, const Slabs& slabs, std::size_t s, const Dims& dims, std::int64_t k0,
                std::vector<std::uint64_t>* const words[3]) {
    for (const Triangle& t : slabs.triangles[s]) {
        const glm::dvec3 &a = mesh.positions[t.a], &b = mesh.positions[t.b], &c = mesh.positions[t.c];
        const glm::ivec3 ns = normal_signs(a, b, c);
        for (int d = 0; d < 3; ++d)
            if (words[d]) flip_columns(a, b, c, ns, d, dims, k0, slabs.bounds[s], slabs.bounds[s + 1], *words[d]);
    }
}

// Step 2 along x (axis 0) or y (axis 1) for the layers [l0, l1) of a grid: a prefix XOR along each row or column.
void prefix_rows(std::vector<std::uint64_t>& words, const Dims& dims, int axis, std::int64_t l0, std::int64_t l1) {
    const std::uint64_t nx = std::uint64_t(dims.nx);
    for (std::int64_t k = l0; k < l1; ++k)
        for (std::int64_t j = 0; j < dims.ny; ++j) {
            const std::uint64_t row = nx * (std::uint64_t(j) + std::uint64_t(dims.ny) * std::uint64_t(k));
            if (axis == 0) prefix_xor_run(words, row, nx);
            if (axis == 1 && j > 0) xor_run(words, row - nx, row, nx);
        }
}

// parity_fill_layers without the checks, on slabs already made for [k0, k1).
BitGrid parity(const PolygonSoup& mesh, const Slabs& slabs, const Dims& dims, int axis, std::int64_t k0,
               std::int64_t k1, int threads) {
    BitGrid grid(Dims{dims.nx, dims.ny, k1 - k0});
    std::vector<std::uint64_t>* words[3] = {};
    words[axis] = &grid.words;
    for_each_slab(slabs, threads, [&](std::size_t s) {
        slab_flips(mesh, slabs, s, dims, k0, words);
        if (axis != 2) prefix_rows(grid.words, dims, axis, slabs.bounds[s] - k0, slabs.bounds[s + 1] - k0);
    });
    // Along z the prefix crosses the slabs: layer after layer, once all flips are in (each layer's words once).
    const std::uint64_t nxy = std::uint64_t(dims.nx) * std::uint64_t(dims.ny);
    if (axis == 2)
        for (std::int64_t k = 1; k < k1 - k0; ++k) xor_run(grid.words, nxy * std::uint64_t(k - 1), nxy * std::uint64_t(k), nxy);
    return grid;
}

}  // namespace
// END SOLUTION

BitGrid parity_fill_layers(const PolygonSoup& mesh, const Dims& dims, int axis, std::int64_t k0, std::int64_t k1,
                           int threads) {
    // BEGIN SOLUTION
    if (axis < 0 || axis > 2) throw std::invalid_argument("parity_fill_layers: axis must be 0, 1 or 2");
    if (threads < 1) throw std::invalid_argument("parity_fill_layers: threads must be >= 1");
    if (k0 < 0 || k0 > k1 || k1 > dims.nz)
        throw std::invalid_argument("parity_fill_layers: layers [" + std::to_string(k0) + ", " + std::to_string(k1) +
                                    ") are not within [0, " + std::to_string(dims.nz) + ")");
    check_soup(mesh);
    if (dims.nx * dims.ny * (k1 - k0) == 0) return BitGrid(Dims{dims.nx, dims.ny, k1 - k0});
    return parity(mesh, make_slabs(mesh, dims, k0, k1, threads), dims, axis, k0, k1, threads);
    // END SOLUTION
}

BitGrid parity_fill(const PolygonSoup& mesh, const Dims& dims, int axis, int threads) {
    // BEGIN SOLUTION
    return parity_fill_layers(mesh, dims, axis, 0, dims.nz, threads);
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
    // the edges (x, y), x < y, bucketed by x (a counting sort): bucket x holds the y of its edges
    std::vector<std::uint32_t> first(std::size_t(next) + 3, 0), partner;  // ids 0..next
    auto each_edge = [&](auto&& use) {
        for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
            const auto vs = mesh.face(f);
            for (std::size_t t = 1; t + 1 < vs.size(); ++t)
                for (auto [p, q] : {std::pair{vs[0], vs[t]}, std::pair{vs[t], vs[t + 1]}, std::pair{vs[t + 1], vs[0]}}) {
                    const std::uint32_t x = id[p], y = id[q];
                    if (x != y) use(std::min(x, y), std::max(x, y));  // from a vertex to itself: no edge
                }
        }
    };
    each_edge([&](std::uint32_t x, std::uint32_t) { ++first[x + 2]; });
    for (std::size_t x = 2; x < first.size(); ++x) first[x] += first[x - 1];
    partner.resize(first.back());
    each_edge([&](std::uint32_t x, std::uint32_t y) { partner[first[x + 1]++] = y; });
    // now bucket x is partner[first[x] .. first[x + 1]): an edge used an odd number of times is a run of odd length
    std::uint64_t odd = 0;
    for (std::size_t x = 0; x + 1 < first.size(); ++x) {
        const auto b = partner.begin() + first[x], e = partner.begin() + first[x + 1];
        std::sort(b, e);
        for (auto r = b; r != e;) {
            const auto s = std::find_if(r, e, [&](std::uint32_t y) { return y != *r; });
            odd += (s - r) % 2;
            r = s;
        }
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
    if (threads < 1) throw std::invalid_argument("voxelize_solid: threads must be >= 1");
    SolidResult r;
    r.boundary_edges = count_boundary_edges(mesh);
    if (r.boundary_edges == 0) {
        r.method = SolidMethod::parity;
        if (dims.count() == 0) {
            r.grid = BitGrid(dims);
            return r;
        }
        // the z parity over the whole grid (its prefix crosses the slabs), then slab by slab the x and y parities in
        // two grids of the slab's size, ANDed into it (a slab starts at a word: word w of the slab's grids is word
        // first + w of the whole grid)
        const Slabs slabs = make_slabs(mesh, dims, 0, dims.nz, threads);
        r.grid = parity(mesh, slabs, dims, 2, 0, dims.nz, threads);
        std::vector<std::uint64_t> disagreements(slabs.triangles.size(), 0);
        for_each_slab(slabs, threads, [&](std::size_t s) {
            const std::int64_t s0 = slabs.bounds[s], s1 = slabs.bounds[s + 1];
            BitGrid x(Dims{dims.nx, dims.ny, s1 - s0}), y(x.dims);
            std::vector<std::uint64_t>* const words[3] = {&x.words, &y.words, nullptr};
            slab_flips(mesh, slabs, s, dims, s0, words);
            prefix_rows(x.words, dims, 0, 0, s1 - s0);
            prefix_rows(y.words, dims, 1, 0, s1 - s0);
            const std::size_t first = std::size_t(std::uint64_t(dims.nx) * std::uint64_t(dims.ny) * std::uint64_t(s0) / 64);
            for (std::size_t w = 0; w < x.words.size(); ++w) {
                std::uint64_t& z = r.grid.words[first + w];
                const std::uint64_t all = x.words[w] & y.words[w] & z, any = x.words[w] | y.words[w] | z;
                z = all;
                if (any != all) disagreements[s] += std::uint64_t(std::popcount(any & ~all));
            }
        });
        for (std::uint64_t d : disagreements) r.axis_disagreements += d;
    } else {
        r.method = SolidMethod::flood_fill;
        r.grid = flood_fill_solid(voxelize_surface(mesh, dims, threads));
    }
    return r;
    // END SOLUTION
}

}  // namespace geolab::voxels
