#pragma once
// Lab 08 test helpers: meshes built by construction (boxes, octahedra, spheres, with vertices on or between voxel
// planes) and expected values computed independently of the reference: the triangle–box overlap by clipping in
// long double, point-in-solid by the shapes' own equations, counts voxel by voxel. No helper calls a student
// function.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "geolab/grading/test.hpp"
#include "geolab/io.hpp"
#include "geolab/mesh_field.hpp"
#include "geolab/models.hpp"
#include "geolab/voxels.hpp"

namespace lab08 {

using namespace geolab::voxels;
using geolab::PolygonSoup;
using LD = long double;

inline std::string str(const glm::dvec3& v) {
    std::ostringstream s;
    s.precision(17);
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}
inline std::string str(const Dims& d) {
    return std::to_string(d.nx) + " x " + std::to_string(d.ny) + " x " + std::to_string(d.nz);
}

struct Rng {
    std::mt19937_64 g;
    explicit Rng(std::uint64_t seed) : g(seed) {}
    double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(g); }
    int integer(int a, int b) { return std::uniform_int_distribution<int>(a, b)(g); }
};

// ---- counting, voxel by voxel (not count_set) -----------------------------------------------------------------
inline std::uint64_t count_bits(const BitGrid& g) {
    std::uint64_t n = 0;
    for (std::int64_t k = 0; k < g.dims.nz; ++k)
        for (std::int64_t j = 0; j < g.dims.ny; ++j)
            for (std::int64_t i = 0; i < g.dims.nx; ++i) n += g.get(i, j, k);
    return n;
}
// The bits past the last voxel are 0, and the words have the right size.
inline bool tail_clean(const BitGrid& g) {
    const std::uint64_t n = std::uint64_t(g.dims.count());
    if (g.words.size() != (n + 63) / 64) return false;
    if (n % 64 == 0 || g.words.empty()) return true;
    return (g.words.back() >> (n % 64)) == 0;
}
// The first voxel where a and b differ, as text ("" when equal), plus the number of differing voxels.
inline std::string first_difference(const BitGrid& got, const BitGrid& want, std::uint64_t* count = nullptr) {
    if (!(got.dims == want.dims)) return "dims " + str(got.dims) + " instead of " + str(want.dims);
    if (got.words.size() != want.words.size()) return "words.size() " + std::to_string(got.words.size()) + " instead of " + std::to_string(want.words.size());
    std::string first;
    std::uint64_t n = 0;
    for (std::int64_t k = 0; k < want.dims.nz; ++k)
        for (std::int64_t j = 0; j < want.dims.ny; ++j)
            for (std::int64_t i = 0; i < want.dims.nx; ++i)
                if (got.get(i, j, k) != want.get(i, j, k)) {
                    if (first.empty())
                        first = "voxel (" + std::to_string(i) + ", " + std::to_string(j) + ", " + std::to_string(k) +
                                ") is " + (got.get(i, j, k) ? "set" : "unset") + ", expected " +
                                (want.get(i, j, k) ? "set" : "unset");
                    ++n;
                }
    if (count) *count = n;
    if (!first.empty()) first += " (" + std::to_string(n) + " voxels differ)";
    return first;
}
template <class F>
BitGrid grid_of(Dims d, F inside) {
    BitGrid g(d);
    for (std::int64_t k = 0; k < d.nz; ++k)
        for (std::int64_t j = 0; j < d.ny; ++j)
            for (std::int64_t i = 0; i < d.nx; ++i)
                if (inside(i, j, k)) g.set(i, j, k);
    return g;
}

// The layers [k0, k1) of g as a grid of their own (layer k0 first), voxel by voxel.
inline BitGrid layers_of(const BitGrid& g, std::int64_t k0, std::int64_t k1) {
    return grid_of(Dims{g.dims.nx, g.dims.ny, k1 - k0},
                   [&](std::int64_t i, std::int64_t j, std::int64_t k) { return g.get(i, j, k + k0); });
}

// ---- meshes by construction ---------------------------------------------------------------------------------
// The box [lo, hi], 12 triangles, normals outward (inward when `inward`).
inline PolygonSoup box_mesh(glm::dvec3 lo, glm::dvec3 hi, bool inward = false) {
    PolygonSoup s;
    for (int c = 0; c < 8; ++c) s.positions.push_back({c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z});
    const std::uint32_t q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : q) {
        if (inward) {
            s.add_face({f[0], f[2], f[1]});
            s.add_face({f[0], f[3], f[2]});
        } else {
            s.add_face({f[0], f[1], f[2]});
            s.add_face({f[0], f[2], f[3]});
        }
    }
    return s;
}
// The octahedron |x − c.x| + |y − c.y| + |z − c.z| = r, 8 triangles, outward.
inline PolygonSoup octahedron(glm::dvec3 c, double r) {
    PolygonSoup s;
    s.positions = {c + glm::dvec3(r, 0, 0), c - glm::dvec3(r, 0, 0), c + glm::dvec3(0, r, 0),
                   c - glm::dvec3(0, r, 0), c + glm::dvec3(0, 0, r), c - glm::dvec3(0, 0, r)};
    for (std::uint32_t xi : {0u, 1u})
        for (std::uint32_t yi : {2u, 3u})
            for (std::uint32_t zi : {4u, 5u}) {
                // orientation: outward iff the triple's sign product is +
                const double sx = xi == 0 ? 1 : -1, sy = yi == 2 ? 1 : -1, sz = zi == 4 ? 1 : -1;
                if (sx * sy * sz > 0) s.add_face({xi, yi, zi});
                else s.add_face({xi, zi, yi});
            }
    return s;
}
// An icosphere of radius r around c (subdivided `levels` times), outward.
inline PolygonSoup icosphere(glm::dvec3 c, double r, int levels) {
    const double t = (1 + std::sqrt(5.0)) / 2;
    std::vector<glm::dvec3> p = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                 {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (auto& q : p) q = glm::normalize(q);
    std::vector<std::array<std::uint32_t, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                                   {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                                   {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                                   {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int l = 0; l < levels; ++l) {
        std::vector<std::array<std::uint32_t, 3>> g;
        std::vector<std::pair<std::uint64_t, std::uint32_t>> mids;
        auto mid = [&](std::uint32_t a, std::uint32_t b) {
            const std::uint64_t key = std::uint64_t(std::min(a, b)) << 32 | std::max(a, b);
            for (auto& m : mids)
                if (m.first == key) return m.second;
            p.push_back(glm::normalize(p[a] + p[b]));
            mids.push_back({key, std::uint32_t(p.size() - 1)});
            return std::uint32_t(p.size() - 1);
        };
        for (auto& tri : f) {
            const auto a = mid(tri[0], tri[1]), b = mid(tri[1], tri[2]), cc = mid(tri[2], tri[0]);
            g.push_back({tri[0], a, cc});
            g.push_back({tri[1], b, a});
            g.push_back({tri[2], cc, b});
            g.push_back({a, b, cc});
        }
        f = g;
    }
    PolygonSoup s;
    for (auto& q : p) s.positions.push_back(c + r * q);
    for (auto& tri : f) s.add_face({tri[0], tri[1], tri[2]});
    return s;
}
// "Dust": one tiny triangle inside each voxel (i, j, k0) of an nx × ny layer, in row order, so that threads taking
// triangles in turn write neighbouring bits of the same 64-bit words at the same time (a race shows). Each triangle
// covers its column's centre (i + ½, j + ½), so along z it flips that column once (z within 0.05 of the given height).
// With `shuffle`, the triangles come in a random order (a fixed seed): whatever block of them a thread takes, the
// bits it sets lie in every word of the layer, written at any time of the run by any thread.
inline PolygonSoup dust(std::int64_t nx, std::int64_t ny, double z, bool shuffle = false) {
    std::vector<std::int64_t> order(std::size_t(nx * ny));
    for (std::size_t n = 0; n < order.size(); ++n) order[n] = std::int64_t(n);
    if (shuffle) std::shuffle(order.begin(), order.end(), std::mt19937_64(2024));
    PolygonSoup s;
    for (const std::int64_t n : order) {
        const auto b = std::uint32_t(s.positions.size());
        const double x = double(n % nx), y = double(n / nx);
        s.positions.push_back({x + 0.3, y + 0.3, z});
        s.positions.push_back({x + 0.8, y + 0.4, z + 0.05});
        s.positions.push_back({x + 0.4, y + 0.8, z - 0.05});
        s.add_face({b, b + 1, b + 2});
    }
    return s;
}

// The enclosed volume of a closed, outward mesh (divergence theorem, long double).
// The generalized winding number of a mesh at p: the signed solid angles of its fan triangles over 4π (lib's
// triangle_solid_angle). On a closed mesh it is an integer away from the surface, and odd exactly where parity sets
// the voxel whose centre p is. Independent of every student function.
// `distance`, when given, receives the distance from p to the mesh.
inline double winding_number(const PolygonSoup& m, const glm::dvec3& p, double* distance = nullptr) {
    double w = 0, d = std::numeric_limits<double>::infinity();
    for (std::size_t f = 0; f < m.n_faces(); ++f) {
        const auto vs = m.face(f);
        for (std::size_t k = 1; k + 1 < vs.size(); ++k) {
            const glm::dvec3 &a = m.positions[vs[0]], &b = m.positions[vs[k]], &c = m.positions[vs[k + 1]];
            w += geolab::triangle_solid_angle(p, a, b, c);
            if (distance) d = std::min(d, glm::length(geolab::closest_point_on_triangle(p, a, b, c) - p));
        }
    }
    if (distance) *distance = d;
    return w / (4 * M_PI);
}
// Parity at `samples` random voxel centres of a closed mesh (grid units; all of them when samples < 0), told by the
// winding number (a centre on the surface, where the perturbation decides, is skipped): the first voxel where `got`
// differs, or "". `checked` counts the voxels compared.
inline std::string parity_spot_check(const BitGrid& got, const PolygonSoup& m, Rng& rng, int samples, int* checked) {
    *checked = 0;
    const Dims d = got.dims;
    if (d.nx <= 0 || d.ny <= 0 || d.nz <= 0 || !tail_clean(got)) return "not a grid of its dims";
    const std::int64_t n = d.count();
    for (std::int64_t s = 0; s < (samples < 0 ? n : samples); ++s) {
        const std::int64_t v = samples < 0 ? s : std::int64_t(rng.uniform(0, double(n))) % n;
        const std::int64_t i = v % d.nx, j = (v / d.nx) % d.ny, k = v / (d.nx * d.ny);
        double distance = 0;
        const double w = winding_number(m, glm::dvec3(i + 0.5, j + 0.5, k + 0.5), &distance);
        if (distance < 1e-6 || std::abs(w - std::round(w)) > 1e-6) continue;  // on the surface: the perturbation decides
        ++*checked;
        const bool inside = std::llabs(std::llround(w)) % 2 == 1;
        if (got.get(i, j, k) != inside)
            return "voxel (" + std::to_string(i) + ", " + std::to_string(j) + ", " + std::to_string(k) + ") is " +
                   (inside ? "inside (winding number " + std::to_string(w) + ") but unset" : "outside but set");
    }
    return "";
}

inline double mesh_volume(const PolygonSoup& s) {
    LD v = 0;
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        const auto vs = s.face(f);
        for (std::size_t t = 1; t + 1 < vs.size(); ++t) {
            const glm::dvec3 &a = s.positions[vs[0]], &b = s.positions[vs[t]], &c = s.positions[vs[t + 1]];
            v += (LD(a.x) * (LD(b.y) * c.z - LD(b.z) * c.y) - LD(a.y) * (LD(b.x) * c.z - LD(b.z) * c.x) +
                  LD(a.z) * (LD(b.x) * c.y - LD(b.y) * c.x)) / 6;
        }
    }
    return double(v);
}

inline PolygonSoup load_model(const std::string& name) {
    auto path = geolab::model_path(name);
    REQUIRE_MESSAGE(path.has_value(), "model " << name << " not found: run tools/fetch_models.sh");
    return geolab::read_mesh(*path);
}
// A model in grid units of a res³ grid (fit_grid, one empty layer around).
inline PolygonSoup model_in_grid(const std::string& name, std::int64_t res) {
    const PolygonSoup m = load_model(name);
    return to_grid_units(m, fit_grid(m, res, 1));
}

// ---- the triangle–box rule, independently: clip the triangle to the closed box (long double) -----------------
// True when the triangle meets the open box (lo, hi): the clipped polygon's vertex centroid (in the polygon's
// relative interior) lies strictly inside.
inline bool clip_meets_open_box(const std::array<glm::dvec3, 3>& tri, glm::dvec3 lo, glm::dvec3 hi) {
    using P = std::array<LD, 3>;
    std::vector<P> poly;
    for (const auto& v : tri) poly.push_back({LD(v.x), LD(v.y), LD(v.z)});
    for (int d = 0; d < 3; ++d)
        for (int side = 0; side < 2; ++side) {
            const LD bound = side == 0 ? LD(lo[d]) : LD(hi[d]);
            auto inside = [&](const P& p) { return side == 0 ? p[d] >= bound : p[d] <= bound; };
            std::vector<P> out;
            for (std::size_t n = 0; n < poly.size(); ++n) {
                const P &a = poly[n], &b = poly[(n + 1) % poly.size()];
                const bool ia = inside(a), ib = inside(b);
                if (ia) out.push_back(a);
                if (ia != ib) {
                    const LD t = (bound - a[d]) / (b[d] - a[d]);
                    P x;
                    for (int e = 0; e < 3; ++e) x[e] = a[e] + t * (b[e] - a[e]);
                    x[d] = bound;
                    out.push_back(x);
                }
            }
            poly = out;
            if (poly.empty()) return false;
        }
    P c{0, 0, 0};
    for (const P& p : poly)
        for (int e = 0; e < 3; ++e) c[e] += p[e] / LD(poly.size());
    for (int d = 0; d < 3; ++d)
        if (!(c[d] > LD(lo[d]) + 1e-15L * (1 + std::abs(LD(lo[d]))) && c[d] < LD(hi[d]) - 1e-15L * (1 + std::abs(LD(hi[d])))))
            return false;
    return true;
}
// The handout's rule for voxel (i, j, k), computed by clipping.
inline bool expected_overlap(const std::array<glm::dvec3, 3>& t, std::int64_t i, std::int64_t j, std::int64_t k) {
    const glm::dvec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
    if (n == glm::dvec3(0.0)) return false;
    std::array<glm::dvec3, 3> u = t;
    for (int d = 0; d < 3; ++d)
        if (t[0][d] == t[1][d] && t[1][d] == t[2][d] && std::floor(t[0][d]) == t[0][d]) {
            for (auto& p : u) p[d] += n[d] > 0 ? -0.5 : 0.5;  // into the layer behind the plane
            break;
        }
    const glm::dvec3 lo{double(i), double(j), double(k)};
    return clip_meets_open_box(u, lo, lo + 1.0);
}

// Triangles near the voxel [0, 1]³ that neither the box's face normals nor the triangle's normal separate from it,
// but clipping says miss it: only one of the nine edge cross-product axes separates them (found by search).
inline std::vector<std::array<glm::dvec3, 3>> edge_axis_triangles(std::size_t count, std::uint64_t seed) {
    Rng rng(seed);
    std::vector<std::array<glm::dvec3, 3>> found;
    for (int n = 0; n < 400000 && found.size() < count; ++n) {
        std::array<glm::dvec3, 3> t;
        const glm::dvec3 c(rng.uniform(-0.3, 1.3), rng.uniform(-0.3, 1.3), rng.uniform(-0.3, 1.3));
        for (auto& p : t) p = c + glm::dvec3(rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2));
        bool separated = false;
        for (int d = 0; d < 3; ++d) {
            const double lo = std::min({t[0][d], t[1][d], t[2][d]}), hi = std::max({t[0][d], t[1][d], t[2][d]});
            separated |= lo >= 1 || hi <= 0;
        }
        const glm::dvec3 nrm = glm::cross(t[1] - t[0], t[2] - t[0]);
        double lo = 1e300, hi = -1e300;
        for (int c8 = 0; c8 < 8; ++c8) {
            const double p = glm::dot(nrm, glm::dvec3(c8 & 1, (c8 >> 1) & 1, (c8 >> 2) & 1));
            lo = std::min(lo, p);
            hi = std::max(hi, p);
        }
        const double p = glm::dot(nrm, t[0]);
        separated |= p <= lo || p >= hi;
        if (!separated && !expected_overlap(t, 0, 0, 0)) found.push_back(t);
    }
    return found;
}

// The surface voxels by the rule above, every voxel of every triangle's bounding box (slow; small grids).
inline BitGrid expected_surface(const PolygonSoup& s, Dims d) {
    BitGrid g(d);
    const std::int64_t n[3] = {d.nx, d.ny, d.nz};
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        const auto vs = s.face(f);
        for (std::size_t t = 1; t + 1 < vs.size(); ++t) {
            const std::array<glm::dvec3, 3> tri = {s.positions[vs[0]], s.positions[vs[t]], s.positions[vs[t + 1]]};
            std::int64_t lo[3], hi[3];
            for (int e = 0; e < 3; ++e) {
                const double mn = std::min({tri[0][e], tri[1][e], tri[2][e]}), mx = std::max({tri[0][e], tri[1][e], tri[2][e]});
                lo[e] = std::max<std::int64_t>(0, std::int64_t(std::floor(mn)) - 1);
                hi[e] = std::min<std::int64_t>(n[e] - 1, std::int64_t(std::ceil(mx)) + 1);
            }
            for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
                for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
                    for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
                        if (expected_overlap(tri, i, j, k)) g.set(i, j, k);
        }
    }
    return g;
}

// The solid of a surface with holes, by a breadth-first search from the border (6-connected).
inline BitGrid expected_flood_fill(const BitGrid& surface) {
    const Dims d = surface.dims;
    BitGrid out(d);
    std::vector<std::array<std::int64_t, 3>> st;
    auto push = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
        if (i < 0 || j < 0 || k < 0 || i >= d.nx || j >= d.ny || k >= d.nz || surface.get(i, j, k) || out.get(i, j, k)) return;
        out.set(i, j, k);
        st.push_back({i, j, k});
    };
    for (std::int64_t k = 0; k < d.nz; ++k)
        for (std::int64_t j = 0; j < d.ny; ++j)
            for (std::int64_t i = 0; i < d.nx; ++i)
                if (i == 0 || j == 0 || k == 0 || i == d.nx - 1 || j == d.ny - 1 || k == d.nz - 1) push(i, j, k);
    while (!st.empty()) {
        const auto [i, j, k] = st.back();
        st.pop_back();
        push(i - 1, j, k);
        push(i + 1, j, k);
        push(i, j - 1, k);
        push(i, j + 1, k);
        push(i, j, k - 1);
        push(i, j, k + 1);
    }
    return grid_of(d, [&](std::int64_t i, std::int64_t j, std::int64_t k) { return !out.get(i, j, k); });
}

// Boundary edges by another method: a map of canonical position pairs (exact positions), counted mod 2.
inline std::uint64_t boundary_edges_by_map(const PolygonSoup& s) {
    std::map<std::array<double, 6>, int> m;
    auto add = [&](const glm::dvec3& a, const glm::dvec3& b) {
        std::array<double, 3> x{a.x, a.y, a.z}, y{b.x, b.y, b.z};
        if (x == y) return;
        if (y < x) std::swap(x, y);
        m[{x[0], x[1], x[2], y[0], y[1], y[2]}] ^= 1;
    };
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        const auto vs = s.face(f);
        for (std::size_t t = 1; t + 1 < vs.size(); ++t) {
            add(s.positions[vs[0]], s.positions[vs[t]]);
            add(s.positions[vs[t]], s.positions[vs[t + 1]]);
            add(s.positions[vs[t + 1]], s.positions[vs[0]]);
        }
    }
    std::uint64_t n = 0;
    for (auto& [k, v] : m) n += v;
    return n;
}

}  // namespace lab08
