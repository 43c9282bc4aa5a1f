#pragma once
// Lab 04 test helpers: the kernels written out again in long double (polynomials expanded in r, not in s), sums of
// blobs, finite differences, lattices of analytic fields, and mesh measures (volume by the divergence theorem,
// lib's check_surface). No helper calls a function you write.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "geolab/blobby.hpp"
#include "geolab/grading/test.hpp"
#include "geolab/mc_tables.hpp"
#include "geolab/surface_checks.hpp"

namespace lab04 {

using namespace geolab::blobby;
using geolab::PolygonSoup;
using LD = long double;

inline std::string str(const glm::dvec3& v) {
    std::ostringstream s;
    s.precision(17);
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}
inline std::string str(Kernel k) { return k == Kernel::blinn ? "blinn" : k == Kernel::nishimura ? "nishimura" : "wyvill"; }
inline std::string str(const Blob& b) {
    std::ostringstream s;
    s.precision(17);
    s << "blob centre " << str(b.center) << " b=" << b.strength << " a=" << b.a << " R=" << b.radius;
    return s.str();
}
inline std::string str(const BlobScene& sc) {
    std::ostringstream s;
    s << str(sc.kernel) << " scene of " << sc.blobs.size() << " blobs, T=" << sc.threshold;
    if (sc.blobs.size() <= 3)
        for (const Blob& b : sc.blobs) s << "; " << str(b);
    return s.str();
}

inline bool close(double x, double y, double tol, double scale = 1.0) {
    return std::abs(x - y) <= tol * std::max(scale, std::abs(y));
}

struct Rng {
    std::mt19937_64 gen;
    explicit Rng(std::uint64_t seed) : gen(seed) {}
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(gen); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(gen); }
    glm::dvec3 point(double lo, double hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
};

// The kernels in long double, expanded in r (Wyvill's C(r/R) as a polynomial in r² with R's powers).
inline LD ref_density(Kernel k, const Blob& b, LD r) {
    const LD B = b.strength, R = b.radius;
    switch (k) {
        case Kernel::blinn: return B * std::exp(-LD(b.a) * r * r);
        case Kernel::nishimura:
            if (3 * r <= R) return B - 3 * B * r * r / (R * R);
            if (r <= R) return B * (LD(1.5) - 3 * r / R + LD(1.5) * r * r / (R * R));
            return 0;
        case Kernel::wyvill: {
            if (r > R) return 0;
            const LD r2 = r * r, R2 = R * R;
            return B * (1 - 22 * r2 / (9 * R2) + 17 * r2 * r2 / (9 * R2 * R2) - 4 * r2 * r2 * r2 / (9 * R2 * R2 * R2));
        }
    }
    return 0;
}
inline LD ref_derivative(Kernel k, const Blob& b, LD r) {
    const LD B = b.strength, R = b.radius;
    switch (k) {
        case Kernel::blinn: return -2 * LD(b.a) * r * B * std::exp(-LD(b.a) * r * r);
        case Kernel::nishimura:
            if (3 * r <= R) return -6 * B * r / (R * R);
            if (r <= R) return B * (-3 / R + 3 * r / (R * R));
            return 0;
        case Kernel::wyvill: {
            if (r > R) return 0;
            const LD R2 = R * R;
            return B * (-44 * r / (9 * R2) + 68 * r * r * r / (9 * R2 * R2) - 24 * r * r * r * r * r / (9 * R2 * R2 * R2));
        }
    }
    return 0;
}
inline double ref_support(Kernel k, const Blob& b) {
    return k == Kernel::blinn ? std::numeric_limits<double>::infinity() : b.radius;
}

// F = T − Σ D and its gradient, in long double.
inline LD ref_value(const BlobScene& s, const glm::dvec3& p) {
    LD v = s.threshold;
    for (const Blob& b : s.blobs) v -= ref_density(s.kernel, b, glm::length(p - b.center));
    return v;
}
inline glm::dvec3 ref_gradient(const BlobScene& s, const glm::dvec3& p) {
    LD g[3] = {0, 0, 0};
    for (const Blob& b : s.blobs) {
        const glm::dvec3 d = p - b.center;
        const LD r = glm::length(d);
        if (r == 0) continue;
        const LD c = ref_derivative(s.kernel, b, r) / r;
        for (int a = 0; a < 3; ++a) g[a] -= c * d[a];
    }
    return {double(g[0]), double(g[1]), double(g[2])};
}
// Σ |bᵢ| Dmax-scale: the scale of the field for relative tolerances.
inline double scale_of(const BlobScene& s) {
    double m = std::abs(s.threshold);
    for (const Blob& b : s.blobs) m += std::abs(b.strength);
    return m;
}

inline BlobScene random_scene(Rng& rng, Kernel k, int n, double box = 1.0, bool negatives = true) {
    BlobScene s;
    s.kernel = k;
    s.threshold = rng.uniform(0.2, 0.6);
    for (int i = 0; i < n; ++i) {
        Blob b;
        b.center = rng.point(-box, box);
        b.strength = rng.uniform(0.5, 1.5) * (negatives && i % 4 == 3 ? -0.7 : 1.0);
        b.a = rng.uniform(1.0, 6.0);
        b.radius = rng.uniform(0.3, 0.8);
        s.blobs.push_back(b);
    }
    return s;
}

// A lattice of an analytic field f with gradient g.
inline Lattice lattice_of(const std::function<double(const glm::dvec3&)>& f,
                          const std::function<glm::dvec3(const glm::dvec3&)>& g, glm::dvec3 origin, double h,
                          glm::ivec3 n) {
    Lattice L;
    L.origin = origin;
    L.h = h;
    L.n = n;
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) {
                const glm::dvec3 p = origin + h * glm::dvec3(i, j, k);
                L.values.push_back(f(p));
                L.gradients.push_back(g(p));
            }
    return L;
}
// A cubic lattice over [-half, half]³ with cells of size about h (n samples per axis, the box's corners on it).
inline Lattice centred_lattice(const std::function<double(const glm::dvec3&)>& f,
                               const std::function<glm::dvec3(const glm::dvec3&)>& g, double half, int cells) {
    return lattice_of(f, g, glm::dvec3(-half), 2 * half / cells, glm::ivec3(cells + 1));
}

// The enclosed volume by the divergence theorem: Σ over triangles of (a · (b × c)) / 6. Positive for outward
// orientation.
inline double volume(const PolygonSoup& s) {
    LD v = 0;
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        const auto t = s.face(f);
        const glm::dvec3 a = s.positions[t[0]], b = s.positions[t[1]], c = s.positions[t[2]];
        v += LD(glm::dot(a, glm::cross(b, c)));
    }
    return double(v / 6);
}

// Edge pairing: every undirected edge in exactly two triangles, traversed once each way. Returns "" when so,
// else a description of the first bad edge.
inline std::string pairing_defect(const PolygonSoup& s) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        const auto t = s.face(f);
        if (t.size() != 3) return "face " + std::to_string(f) + " is not a triangle";
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = t[e], b = t[(e + 1) % 3];
            if (a == b) return "face " + std::to_string(f) + " repeats vertex " + std::to_string(a);
            ++directed[{a, b}];
        }
    }
    for (const auto& [e, c] : directed) {
        const auto it = directed.find({e.second, e.first});
        const int back = it == directed.end() ? 0 : it->second;
        if (c != 1 || back != 1)
            return "edge " + std::to_string(e.first) + "->" + std::to_string(e.second) + " used " + std::to_string(c) +
                   " time(s) in this direction and " + std::to_string(back) +
                   " in the other (a closed, consistently oriented surface has 1 and 1)";
    }
    return "";
}
inline long euler(const PolygonSoup& s) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    std::vector<bool> used(s.n_vertices(), false);
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        const auto t = s.face(f);
        for (std::size_t e = 0; e < t.size(); ++e) {
            used[t[e]] = true;
            std::uint32_t a = t[e], b = t[(e + 1) % t.size()];
            if (a > b) std::swap(a, b);
            edges[{a, b}] = 1;
        }
    }
    const long v = long(std::count(used.begin(), used.end(), true));
    return v - long(edges.size()) + long(s.n_faces());
}
// Connected components through shared vertices.
inline int components(const PolygonSoup& s) {
    std::vector<std::uint32_t> parent(s.n_vertices());
    for (std::uint32_t i = 0; i < parent.size(); ++i) parent[i] = i;
    std::function<std::uint32_t(std::uint32_t)> find = [&](std::uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    std::vector<bool> used(s.n_vertices(), false);
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        const auto t = s.face(f);
        for (std::size_t e = 0; e < t.size(); ++e) {
            used[t[e]] = true;
            parent[find(t[e])] = find(t[(e + 1) % t.size()]);
        }
    }
    int c = 0;
    for (std::uint32_t i = 0; i < parent.size(); ++i)
        if (used[i] && find(i) == i) ++c;
    return c;
}

// The number of lattice edges with one end inside (f < iso) and one outside.
inline std::size_t crossed_edges(const Lattice& L, double iso) {
    std::size_t n = 0;
    const glm::ivec3 d = L.n;
    auto at = [&](int i, int j, int k) { return L.values[i + std::size_t(d.x) * (j + std::size_t(d.y) * k)]; };
    for (int k = 0; k < d.z; ++k)
        for (int j = 0; j < d.y; ++j)
            for (int i = 0; i < d.x; ++i) {
                const bool in = at(i, j, k) < iso;
                if (i + 1 < d.x && in != (at(i + 1, j, k) < iso)) ++n;
                if (j + 1 < d.y && in != (at(i, j + 1, k) < iso)) ++n;
                if (k + 1 < d.z && in != (at(i, j, k + 1) < iso)) ++n;
            }
    return n;
}

// The tie rule's promises, checked exactly (lib's check_surface: zero-area faces by exact collinearity,
// coincident vertices, edge pairing, self-intersections by exact predicates): closed, 2-manifold, outward, one
// vertex per crossed edge, every vertex strictly inside its lattice edge (exactly two of its coordinates are
// lattice coordinates origin + h·i). components 0: components and χ not checked.
inline void check_tie_output(const McMesh& m, const Lattice& L, double iso, const std::string& what,
                             std::size_t components, long chi) {
    const geolab::SurfaceCheck sc = geolab::check_surface(m.soup);
    CHECK_MESSAGE(sc.zero_area_faces == 0, what << ": " << sc.zero_area_faces << " zero-area triangle(s) (two vertices on "
                                                "one point, or three on a line); " << sc.summary());
    CHECK_MESSAGE(sc.coincident_vertices == 0, what << ": " << sc.coincident_vertices << " vertices at the position of "
                                                    "another (vertices placed on a tie sample?); " << sc.summary());
    CHECK_MESSAGE(sc.closed_manifold(), what << ": " << sc.summary());
    CHECK_MESSAGE(m.soup.n_vertices() == crossed_edges(L, iso), what << ": " << crossed_edges(L, iso)
                                                                   << " crossed edges, so as many vertices; got " << m.soup.n_vertices());
    if (components > 0) {
        CHECK_MESSAGE(sc.components == components, what << ": " << components << " component(s) expected; " << sc.summary());
        CHECK_MESSAGE(sc.euler_characteristic == chi, what << ": χ = " << sc.euler_characteristic << ", expected " << chi);
    }
    for (std::size_t v = 0; v < m.soup.n_vertices(); ++v) {
        const glm::dvec3 p = m.soup.positions[v];
        int on_planes = 0;
        for (int a = 0; a < 3; ++a) {
            const double i0 = std::floor((p[a] - L.origin[a]) / L.h);
            bool on = false;
            for (double i = i0 - 1; i <= i0 + 2; ++i) on |= p[a] == L.origin[a] + L.h * i;
            on_planes += on;
        }
        if (on_planes != 2) {
            CHECK_MESSAGE(on_planes == 2, what << ": vertex " << str(p) << " is not strictly inside a lattice edge ("
                                               << on_planes << " of its coordinates are lattice coordinates, 2 expected)");
            break;
        }
    }
}

// Fields used by several tests.
inline double sphere_f(const glm::dvec3& p, glm::dvec3 c, double r) { return glm::length(p - c) - r; }
inline glm::dvec3 sphere_g(const glm::dvec3& p, glm::dvec3 c) {
    const double l = glm::length(p - c);
    return l > 0 ? (p - c) / l : glm::dvec3(0.0);
}
// Torus around z, major radius R, minor r.
inline double torus_f(const glm::dvec3& p, double R, double r) {
    const double q = std::hypot(p.x, p.y) - R;
    return std::hypot(q, p.z) - r;
}
inline glm::dvec3 torus_g(const glm::dvec3& p, double R, double r) {
    const double rho = std::hypot(p.x, p.y);
    const double q = rho - R, l = std::hypot(q, p.z);
    if (rho == 0 || l == 0) return glm::dvec3(0.0);
    return {q / l * p.x / rho, q / l * p.y / rho, p.z / l};
}

}  // namespace lab04
