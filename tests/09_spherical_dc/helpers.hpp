#pragma once
// Lab 09 test helpers: the shapes (analytic fields with known volumes, fields with exact zeros on the lattice,
// fields whose QEF minimisers leave their cells), and checks computed independently of the lab's code (an edge
// map, boundary loops, the enclosed volume, spherical coordinates, a brute-force smallest enclosing sphere).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"
#include "geolab/field.hpp"
#include "geolab/fixtures.hpp"
#include "geolab/grading/test.hpp"
#include "geolab/implicits.hpp"
#include "geolab/io.hpp"
#include "geolab/mesh_field.hpp"
#include "geolab/models.hpp"
#include "geolab/soup.hpp"
#include "geolab/surface_checks.hpp"

namespace lab09 {

using namespace geolab::dc;
using geolab::Box;
using geolab::FieldPtr;
using geolab::PolygonSoup;
using geolab::ScalarField;

inline constexpr double kPi = 3.14159265358979323846;

inline std::string str(const glm::dvec3& p) {
    std::ostringstream os;
    os.precision(10);
    os << "(" << p.x << ", " << p.y << ", " << p.z << ")";
    return os.str();
}

// The QEF of vertex vi: tree.qefs[vi], which place_vertices and simplify keep beside tree.vertices. A tree whose
// arrays differ in length fails the test here (with the reason), not with an out-of-range read.
inline const Qef& qef_of(const Octree& t, std::uint32_t vi) {
    static const Qef none;
    if (t.qefs.size() != t.vertices.size() || vi >= t.qefs.size()) {
        FAIL_CHECK("tree.qefs must hold one QEF per dual vertex (tree.qefs[i] is the QEF of tree.vertices[i]): "
                   << t.qefs.size() << " QEFs for " << t.vertices.size() << " vertices, vertex " << vi);
        return none;
    }
    return t.qefs[vi];
}

// Whether two soups are the same to the bit: positions, indices and offsets, in the same order.
inline bool same_soup(const PolygonSoup& a, const PolygonSoup& b) {
    return a.positions == b.positions && a.indices == b.indices && a.offsets == b.offsets;
}
// Where two soups first differ, for a failure message.
inline std::string soup_difference(const PolygonSoup& a, const PolygonSoup& b) {
    std::ostringstream os;
    os << a.n_vertices() << " vs " << b.n_vertices() << " positions, " << a.n_faces() << " vs " << b.n_faces()
       << " faces";
    for (std::size_t i = 0; i < std::min(a.positions.size(), b.positions.size()); ++i)
        if (a.positions[i] != b.positions[i]) {
            os << "; position " << i << ": " << str(a.positions[i]) << " vs " << str(b.positions[i]);
            return os.str();
        }
    for (std::size_t i = 0; i < std::min(a.indices.size(), b.indices.size()); ++i)
        if (a.indices[i] != b.indices[i]) {
            os << "; index " << i << ": " << a.indices[i] << " vs " << b.indices[i];
            return os.str();
        }
    return os.str();
}

// ---- independent mesh checks ---------------------------------------------------------------------------------

// Undirected edges of a soup with how often each is traversed in each direction (lo→hi, hi→lo).
struct EdgeReport {
    std::size_t faces = 0, referenced_vertices = 0, edges = 0;
    std::size_t boundary = 0, non_manifold = 0, misoriented = 0, degenerate = 0, non_triangles = 0;
    std::size_t bad_indices = 0;
    bool closed_manifold() const {
        return faces > 0 && boundary == 0 && non_manifold == 0 && misoriented == 0 && degenerate == 0 &&
               bad_indices == 0;
    }
    long euler() const { return long(referenced_vertices) - long(edges) + long(faces); }
};

inline EdgeReport edge_report(const PolygonSoup& soup) {
    EdgeReport r;
    r.faces = soup.n_faces();
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<int, int>> uses;
    std::vector<char> used(soup.n_vertices(), 0);
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        auto vs = soup.face(f);
        if (vs.size() != 3) ++r.non_triangles;
        bool bad = false, degenerate = false;
        for (std::size_t i = 0; i < vs.size(); ++i) {
            if (vs[i] >= soup.n_vertices()) bad = true;
            for (std::size_t j = 0; j < i; ++j) degenerate |= vs[i] == vs[j];
        }
        if (bad) {
            ++r.bad_indices;
            continue;
        }
        r.degenerate += degenerate;
        for (std::size_t i = 0; i < vs.size(); ++i) {
            std::uint32_t a = vs[i], b = vs[(i + 1) % vs.size()];
            used[a] = 1;
            if (a == b) continue;
            auto& u = uses[{std::min(a, b), std::max(a, b)}];
            (a < b ? u.first : u.second) += 1;
        }
    }
    r.referenced_vertices = std::size_t(std::count(used.begin(), used.end(), 1));
    r.edges = uses.size();
    for (const auto& [e, u] : uses) {
        int n = u.first + u.second;
        if (n == 1) ++r.boundary;
        else if (n > 2) ++r.non_manifold;
        else if (u.first != 1) ++r.misoriented;
    }
    return r;
}

inline std::string describe(const EdgeReport& r) {
    std::ostringstream os;
    os << "faces " << r.faces << ", vertices used " << r.referenced_vertices << ", edges " << r.edges
       << ", boundary edges " << r.boundary << ", non-manifold edges " << r.non_manifold
       << ", misoriented edges " << r.misoriented << ", degenerate faces " << r.degenerate
       << ", non-triangles " << r.non_triangles << ", bad indices " << r.bad_indices << ", chi " << r.euler();
    return os.str();
}

// Number of boundary loops: connected components of the graph of boundary edges (edges used by one face).
inline std::size_t boundary_loops(const PolygonSoup& soup) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        auto vs = soup.face(f);
        for (std::size_t i = 0; i < vs.size(); ++i) {
            std::uint32_t a = vs[i], b = vs[(i + 1) % vs.size()];
            if (a != b) ++count[{std::min(a, b), std::max(a, b)}];
        }
    }
    std::map<std::uint32_t, std::uint32_t> parent;
    auto find = [&](std::uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    for (const auto& [e, n] : count) {
        if (n != 1) continue;
        for (std::uint32_t v : {e.first, e.second})
            if (!parent.count(v)) parent[v] = v;
        parent[find(e.first)] = find(e.second);
    }
    std::size_t loops = 0;
    for (const auto& [v, p] : parent) loops += find(v) == v;
    return loops;
}

// Connected components of the faces (sharing a vertex).
inline std::size_t components(const PolygonSoup& soup) {
    std::vector<std::uint32_t> parent(soup.n_vertices());
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](std::uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    std::vector<char> used(soup.n_vertices(), 0);
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        auto vs = soup.face(f);
        for (std::size_t i = 0; i < vs.size(); ++i) {
            if (vs[i] >= soup.n_vertices()) continue;
            used[vs[i]] = 1;
            if (i > 0 && vs[0] < soup.n_vertices()) parent[find(vs[i])] = find(vs[0]);
        }
    }
    std::size_t n = 0;
    for (std::uint32_t v = 0; v < soup.n_vertices(); ++v) n += used[v] && find(v) == v;
    return n;
}

// Enclosed volume by the divergence theorem, fan triangles taken about the vertex centroid (less rounding than
// about the coordinate origin). Positive for outward orientation.
inline double enclosed_volume(const PolygonSoup& soup) {
    if (soup.n_vertices() == 0) return 0.0;
    glm::dvec3 c(0.0);
    for (const auto& p : soup.positions) c += p;
    c /= double(soup.n_vertices());
    double v = 0.0;
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        auto vs = soup.face(f);
        for (std::size_t i = 1; i + 1 < vs.size(); ++i)
            v += glm::dot(soup.positions[vs[0]] - c,
                          glm::cross(soup.positions[vs[i]] - c, soup.positions[vs[i + 1]] - c));
    }
    return v / 6.0;
}

inline double max_abs_f(const ScalarField& f, const PolygonSoup& soup) {
    double m = 0.0;
    for (const auto& p : soup.positions) m = std::max(m, std::abs(f.value(p)));
    return m;
}

// Vertices whose faces make more than one fan (lib's check_surface); 0 for a soup it cannot read (bad indices, faces
// of fewer than 3 vertices: the checks below report those).
inline std::size_t non_manifold_vertices(const PolygonSoup& soup) {
    geolab::CheckOptions o;
    o.self_intersections = false;
    try {
        return geolab::check_surface(soup, o).non_manifold_vertices;
    } catch (const std::invalid_argument&) {
        return 0;
    }
}

// Both the lab's given mesh check and the independent edge map must call the soup a closed oriented manifold, and
// lib's check_surface must find no vertex whose faces make more than one fan.
#define LAB09_CHECK_CLOSED_MANIFOLD(soup, label)                                                              \
    do {                                                                                                      \
        const ::lab09::EdgeReport er_ = ::lab09::edge_report(soup);                                           \
        const ::geolab::dc::MeshCheck mc_ = ::geolab::dc::check_mesh(soup);                                   \
        const std::size_t nmv_ = ::lab09::non_manifold_vertices(soup);                                        \
        const std::string label_ = std::string(label);                                                        \
        INFO(label_ << ": " << ::lab09::describe(er_));                                                       \
        CHECK_MESSAGE(er_.faces > 0, "the mesh has no faces");                                               \
        CHECK_MESSAGE(er_.boundary == 0, "boundary edges (holes, cracks): " << er_.boundary);                 \
        CHECK_MESSAGE(er_.non_manifold == 0, "edges in more than 2 faces: " << er_.non_manifold);             \
        CHECK_MESSAGE(er_.misoriented == 0, "edges traversed twice the same way: " << er_.misoriented);       \
        CHECK_MESSAGE(er_.degenerate == 0, "faces with a repeated vertex: " << er_.degenerate);               \
        CHECK_MESSAGE(er_.bad_indices == 0, "faces with an index >= n_vertices: " << er_.bad_indices);        \
        CHECK_MESSAGE(er_.non_triangles == 0, "faces that are not triangles: " << er_.non_triangles);         \
        CHECK_MESSAGE(mc_.closed_manifold(), "check_mesh disagrees: boundary " << mc_.boundary_edges          \
                                                 << ", non-manifold " << mc_.non_manifold_edges);             \
        CHECK_MESSAGE(nmv_ == 0, "vertices whose faces make more than one fan: " << nmv_);                    \
    } while (0)

// ---- spherical coordinates, computed here without the lab's functions ------------------------------------------

struct Sph {
    double r, theta, phi;  // phi in [0, 2π)
};
inline Sph sph_of(const glm::dvec3& p) {
    double rho = std::hypot(p.x, p.y);
    double r = std::hypot(rho, p.z);
    double th = std::atan2(rho, p.z);
    double ph = std::atan2(p.y, p.x);
    if (ph < 0) ph += 2 * kPi;
    if (ph >= 2 * kPi) ph -= 2 * kPi;
    return {r, th, ph};
}
inline glm::dvec3 cart_of(double r, double th, double ph) {
    return {r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph), r * std::cos(th)};
}
// Angular distance from phi to the interval [lo, lo + w] going around the circle (0 inside).
inline double phi_outside(double phi, double lo, double w) {
    double d = std::fmod(phi - lo + 4 * kPi, 2 * kPi);
    if (d <= w) return 0.0;
    return std::min(d - w, 2 * kPi - d);
}

// ---- octree helpers (the given data structure only) -----------------------------------------------------------

// The leaf containing a Cartesian point (Cartesian octree), by doubled lattice coordinates.
inline std::uint32_t leaf_at(const Octree& t, const glm::dvec3& p) {
    if (t.coordinates == Coordinates::cartesian) {
        glm::dvec3 q = (p - t.min_corner) * (2.0 * t.resolution() / t.size);
        return t.locate(glm::ivec3(glm::floor(q)));
    }
    Sph s = sph_of(p - t.origin);
    const double n2 = 2.0 * t.resolution();
    glm::dvec3 q((s.r - t.r_min) / (t.r_max - t.r_min) * n2, s.theta / kPi * n2, s.phi / (2 * kPi) * n2);
    glm::ivec3 qi(glm::floor(q));
    qi.y = std::clamp(qi.y, 0, int(n2) - 1);
    qi.z = std::clamp(qi.z, 0, int(n2) - 1);
    return t.locate(qi);
}

// Leaves (indices) reachable from the root; checks on the way that children follow the convention.
struct TreeShape {
    std::vector<std::uint32_t> leaves;
    std::size_t bad_children = 0;  // child cell index != 2 * parent + bits, or level != parent + 1
    std::size_t deeper_than_max = 0;
};
inline TreeShape tree_shape(const Octree& t) {
    TreeShape s;
    if (t.nodes.empty()) return s;
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty()) {
        std::uint32_t n = stack.back();
        stack.pop_back();
        const OctreeNode& nd = t.nodes[n];
        if (nd.level > t.max_level) ++s.deeper_than_max;
        if (nd.is_leaf()) {
            s.leaves.push_back(n);
            continue;
        }
        if (nd.first_child + 8 > t.nodes.size()) {
            ++s.bad_children;
            continue;
        }
        for (int c = 0; c < 8; ++c) {
            const OctreeNode& ch = t.nodes[nd.first_child + c];
            if (ch.level != nd.level + 1 || ch.x != 2 * nd.x + (c & 1) || ch.y != 2 * nd.y + ((c >> 1) & 1) ||
                ch.z != 2 * nd.z + ((c >> 2) & 1))
                ++s.bad_children;
            else
                stack.push_back(nd.first_child + c);
        }
    }
    return s;
}

// Corner c of a leaf is inside (by the lab's tie rule, f ≤ 0) — read through the given cache.
inline int inside_corners(const Octree& t, const OctreeNode& nd) {
    int n = 0;
    for (int c = 0; c < 8; ++c) n += t.value(t.corner(nd, c)) <= 0.0;
    return n;
}

// ---- shapes -----------------------------------------------------------------------------------------------------

inline double sphere_volume(double r) { return 4.0 / 3.0 * kPi * r * r * r; }
inline double torus_volume(double R, double r) { return 2.0 * kPi * kPi * R * r * r; }

// −f: the same surface with inside and outside swapped (a closed surface then bounds the outside).
class Negated final : public ScalarField {
public:
    explicit Negated(FieldPtr f) : f_(std::move(f)) {}
    double value(const glm::dvec3& p) const override { return -f_->value(p); }
    glm::dvec3 gradient(const glm::dvec3& p) const override { return -f_->gradient(p); }
    Box bounds() const override { return f_->bounds(); }
    double lipschitz() const override { return f_->lipschitz(); }

private:
    FieldPtr f_;
};

// f with an unknown Lipschitz constant (lipschitz() == 0: the octrees estimate one from the gradient).
class NoLipschitz final : public ScalarField {
public:
    explicit NoLipschitz(FieldPtr f) : f_(std::move(f)) {}
    double value(const glm::dvec3& p) const override { return f_->value(p); }
    glm::dvec3 gradient(const glm::dvec3& p) const override { return f_->gradient(p); }
    Box bounds() const override { return f_->bounds(); }

private:
    FieldPtr f_;
};

// An axis-aligned box whose faces lie EXACTLY on lattice planes of the Cartesian octree of level L built over
// bounds() = [-1, 1]^3 with padding p: the planes lo + (side / N) * k, computed with the same formula as
// Octree::lattice_point. f = max over axes of max(a_lo − x, x − a_hi) is 0 at the lattice points on the faces.
class LatticeBox final : public ScalarField {
public:
    LatticeBox(int level, double padding, glm::ivec3 k_lo, glm::ivec3 k_hi) {
        const double side = 2.0 * (1.0 + 2.0 * padding);
        const glm::dvec3 lo = glm::dvec3(0.0) - glm::dvec3(0.5 * side);
        const double n = double(1 << level);
        lo_ = lo + (side / n) * glm::dvec3(k_lo);
        hi_ = lo + (side / n) * glm::dvec3(k_hi);
    }
    double value(const glm::dvec3& p) const override {
        double v = -1e300;
        for (int a = 0; a < 3; ++a) v = std::max({v, lo_[a] - p[a], p[a] - hi_[a]});
        return v;
    }
    glm::dvec3 gradient(const glm::dvec3& p) const override {
        double best = -1e300;
        glm::dvec3 g(0.0);
        for (int a = 0; a < 3; ++a)
            for (int s : {-1, 1}) {
                double v = s < 0 ? lo_[a] - p[a] : p[a] - hi_[a];
                if (v > best) best = v, g = glm::dvec3(0.0), g[a] = s;
            }
        return g;
    }
    Box bounds() const override { return {glm::dvec3(-1.0), glm::dvec3(1.0)}; }
    double lipschitz() const override { return 1.0; }
    glm::dvec3 lo_, hi_;
};

// f = |p - c|^2 - R^2 without a Lipschitz constant (lipschitz() == 0): |grad f| = 2 |p - c| grows with the distance,
// so the octrees' estimate (2 x the largest |grad f| on a 9^3 lattice) depends on exactly which lattice is sampled.
// bounds() are the ball's box, or a larger box given (then the domain is not centred on c, and the estimate depends
// on which end of each axis the lattice reaches).
class QuadraticBall final : public ScalarField {
public:
    QuadraticBall(glm::dvec3 c, double r) : c_(c), r_(r), box_{c - r, c + r} {}
    QuadraticBall(glm::dvec3 c, double r, Box box) : c_(c), r_(r), box_(box) {}
    double value(const glm::dvec3& p) const override { return glm::dot(p - c_, p - c_) - r_ * r_; }
    glm::dvec3 gradient(const glm::dvec3& p) const override { return 2.0 * (p - c_); }
    Box bounds() const override { return box_; }
    // the estimate build_octree / build_spherical_octree must make over the cube [lo, lo + side]^3
    double estimate(const glm::dvec3& lo, double side) const {
        double g = 0;
        for (int i = 0; i <= 8; ++i)
            for (int j = 0; j <= 8; ++j)
                for (int k = 0; k <= 8; ++k) g = std::max(g, glm::length(gradient(lo + side / 8.0 * glm::dvec3(i, j, k))));
        return 2.0 * g;
    }
    glm::dvec3 c_;
    double r_;
    Box box_;
};

// The distance to a sphere without a Lipschitz constant whose gradient is 1000 times too long within 1e-6 of one
// point (the spike): the octrees' estimate of Lf (2 x the largest |grad f| on a 9^3 lattice) is huge exactly when
// the lattice holds that point, and then nearly every cell is split. `scale` shrinks the gradient elsewhere (a
// field whose |grad f| stays below 1 when scale < 0.5).
class SpikyGradient final : public ScalarField {
public:
    SpikyGradient(glm::dvec3 c, double r, glm::dvec3 spike, double scale = 1.0) : c_(c), r_(r), spike_(spike), scale_(scale) {}
    double value(const glm::dvec3& p) const override { return scale_ * (glm::length(p - c_) - r_); }
    glm::dvec3 gradient(const glm::dvec3& p) const override {
        const glm::dvec3 g = scale_ * glm::normalize(p - c_ + glm::dvec3(1e-300));
        return glm::length(p - spike_) < 1e-6 ? 1000.0 * g : g;
    }
    Box bounds() const override { return {c_ - r_, c_ + r_}; }
    // 2 x the largest |grad f| over `points`: what the octree must estimate when they are its lattice
    double estimate(const std::vector<glm::dvec3>& points) const {
        double g = 0;
        for (const auto& q : points) g = std::max(g, glm::length(gradient(q)));
        return 2.0 * g;
    }

private:
    glm::dvec3 c_;
    double r_;
    glm::dvec3 spike_;
    double scale_;
};

// A sphere a few finest cells wide at level 10 inside large bounds ([-1, 1]^3): the octrees refine only around it,
// so max_level = 10 (the largest allowed) stays small and fast.
class TinySphere final : public ScalarField {
public:
    TinySphere(glm::dvec3 c, double r) : c_(c), r_(r) {}
    double value(const glm::dvec3& p) const override { return glm::length(p - c_) - r_; }
    glm::dvec3 gradient(const glm::dvec3& p) const override {
        const glm::dvec3 d = p - c_;
        const double len = glm::length(d);
        return len > 0 ? d / len : glm::dvec3(0.0);
    }
    Box bounds() const override { return {glm::dvec3(-1.0), glm::dvec3(1.0)}; }
    double lipschitz() const override { return 1.0; }

private:
    glm::dvec3 c_;
    double r_;
};

// The plane z = z0 (value exact), but with gradients that swing around wildly (∇f is NOT the plane's normal):
// the QEF planes then meet far away, so unclamped minimisers leave their cells.
class WobblyPlane final : public ScalarField {
public:
    explicit WobblyPlane(double z0) : z0_(z0) {}
    double value(const glm::dvec3& p) const override { return p.z - z0_; }
    glm::dvec3 gradient(const glm::dvec3& p) const override {
        return {std::sin(23.0 * p.x + 7.0 * p.y), std::cos(19.0 * p.y - 5.0 * p.x), 0.35};
    }
    Box bounds() const override { return {glm::dvec3(-1.0), glm::dvec3(1.0)}; }
    double lipschitz() const override { return 1.0; }

private:
    double z0_;
};

// A sphere with the wobbly gradients of WobblyPlane tilted towards the true normal (spherical clamping tests).
class WobblySphere final : public ScalarField {
public:
    WobblySphere(glm::dvec3 c, double r) : c_(c), r_(r) {}
    double value(const glm::dvec3& p) const override { return glm::length(p - c_) - r_; }
    glm::dvec3 gradient(const glm::dvec3& p) const override {
        glm::dvec3 n = glm::normalize(p - c_);
        return n + 1.5 * glm::dvec3(std::sin(31.0 * p.x + 11.0 * p.y), std::cos(29.0 * p.y - 13.0 * p.z),
                                    std::sin(37.0 * p.z + 3.0 * p.x));
    }
    Box bounds() const override { return {c_ - r_, c_ + r_}; }
    double lipschitz() const override { return 1.0; }

private:
    glm::dvec3 c_;
    double r_;
};

// ---- models -----------------------------------------------------------------------------------------------------

// The model's soup; FAILS the test (REQUIRE) if it has not been fetched.
inline PolygonSoup load_model(const std::string& name) {
    auto path = geolab::model_path(name);
    INFO("model " << name << " not found: run tools/fetch_models.sh (the README's bootstrap fetches the models)");
    REQUIRE_MESSAGE(path.has_value(), "model " << name << " not found: run tools/fetch_models.sh");
    return geolab::read_mesh(*path);
}

// ---- smallest enclosing sphere, brute force -------------------------------------------------------------------

// Circumscribed / smallest sphere through a support set of 1-4 points (nullopt when degenerate).
inline std::optional<Sphere> support_sphere(const std::vector<glm::dvec3>& s) {
    if (s.size() == 1) return Sphere{s[0], 0.0};
    if (s.size() == 2) return Sphere{0.5 * (s[0] + s[1]), 0.5 * glm::length(s[1] - s[0])};
    if (s.size() == 3) {
        glm::dvec3 a = s[1] - s[0], b = s[2] - s[0], n = glm::cross(a, b);
        double n2 = glm::dot(n, n);
        if (n2 < 1e-20 * glm::dot(a, a) * glm::dot(b, b)) return std::nullopt;
        glm::dvec3 o = (glm::dot(b, b) * glm::cross(n, a) + glm::dot(a, a) * glm::cross(b, n)) / (2.0 * n2);
        return Sphere{s[0] + o, glm::length(o)};
    }
    // 4 points: solve 2 (p_i − p_0) · x = |p_i|² − |p_0|² by Cramer's rule
    glm::dvec3 r1 = 2.0 * (s[1] - s[0]), r2 = 2.0 * (s[2] - s[0]), r3 = 2.0 * (s[3] - s[0]);
    double b1 = glm::dot(s[1], s[1]) - glm::dot(s[0], s[0]), b2 = glm::dot(s[2], s[2]) - glm::dot(s[0], s[0]),
           b3 = glm::dot(s[3], s[3]) - glm::dot(s[0], s[0]);
    double det = glm::dot(r1, glm::cross(r2, r3));
    double scale = glm::length(r1) * glm::length(r2) * glm::length(r3);
    if (std::abs(det) < 1e-10 * scale) return std::nullopt;
    glm::dvec3 x = (b1 * glm::cross(r2, r3) + b2 * glm::cross(r3, r1) + b3 * glm::cross(r1, r2)) / det;
    return Sphere{x, glm::length(x - s[0])};
}

// The smallest sphere containing all points: the smallest support sphere (≤ 4 points) that contains them all.
inline Sphere brute_force_enclosing_sphere(const std::vector<glm::dvec3>& p, double eps) {
    Sphere best{glm::dvec3(0.0), 1e300};
    const std::size_t n = p.size();
    auto consider = [&](const std::vector<glm::dvec3>& s) {
        auto sp = support_sphere(s);
        if (!sp || sp->radius >= best.radius) return;
        for (const auto& q : p)
            if (glm::length(q - sp->center) > sp->radius + eps) return;
        best = *sp;
    };
    for (std::size_t i = 0; i < n; ++i) {
        consider({p[i]});
        for (std::size_t j = i + 1; j < n; ++j) {
            consider({p[i], p[j]});
            for (std::size_t k = j + 1; k < n; ++k) {
                consider({p[i], p[j], p[k]});
                for (std::size_t l = k + 1; l < n; ++l) consider({p[i], p[j], p[k], p[l]});
            }
        }
    }
    return best;
}

// A tiny deterministic generator (tests must not depend on the standard library's distributions).
struct Lcg {
    std::uint64_t s;
    explicit Lcg(std::uint64_t seed) : s(seed * 6364136223846793005ULL + 1442695040888963407ULL) {}
    double uniform() {  // [0, 1)
        s = s * 6364136223846793005ULL + 1442695040888963407ULL;
        return double(s >> 11) * (1.0 / 9007199254740992.0);
    }
    double uniform(double a, double b) { return a + (b - a) * uniform(); }
    glm::dvec3 unit_vector() {
        double z = uniform(-1.0, 1.0), t = uniform(0.0, 2 * kPi), r = std::sqrt(1 - z * z);
        return {r * std::cos(t), r * std::sin(t), z};
    }
};

// Points on the surface of a distance field near a dense grid (spacing `step`) over `box`: each grid point with
// |f| < step is projected onto the surface along ∇f (exact for the distance fields used here).
inline std::vector<glm::dvec3> surface_samples(const ScalarField& f, const Box& box, double step) {
    std::vector<glm::dvec3> out;
    glm::ivec3 n(glm::ceil((box.hi - box.lo) / step));
    for (int i = 0; i <= n.x; ++i)
        for (int j = 0; j <= n.y; ++j)
            for (int k = 0; k <= n.z; ++k) {
                glm::dvec3 p = box.lo + step * glm::dvec3(i, j, k);
                double v = f.value(p);
                if (std::abs(v) >= step) continue;
                glm::dvec3 g = f.gradient(p);
                double len = glm::length(g);
                if (!(len > 0)) continue;
                glm::dvec3 q = p - v * g / len;
                if (std::abs(f.value(q)) < 1e-9) out.push_back(q);
            }
    return out;
}

}  // namespace lab09

namespace lab09 {

// Sign-changing edges of the leaves at max_level, each counted once (key: lower lattice end and axis).
inline std::size_t sign_changing_finest_edges(const Octree& t) {
    std::vector<std::uint64_t> keys;
    for (std::uint32_t li : tree_shape(t).leaves) {
        const OctreeNode& nd = t.nodes[li];
        if (nd.level != t.max_level) continue;
        for (int a = 0; a < 3; ++a)
            for (int c = 0; c < 8; ++c) {
                if (c & (1 << a)) continue;
                const glm::ivec3 q0 = t.corner(nd, c), q1 = t.corner(nd, c | (1 << a));
                if ((t.value(q0) <= 0.0) == (t.value(q1) <= 0.0)) continue;
                keys.push_back((std::uint64_t(q0.x) << 44) | (std::uint64_t(q0.y) << 24) | (std::uint64_t(q0.z) << 4) |
                               std::uint64_t(a));
            }
    }
    std::sort(keys.begin(), keys.end());
    return std::size_t(std::unique(keys.begin(), keys.end()) - keys.begin());
}

// The sign configuration a leaf must carry: bit c set when corner c is inside (f <= 0).
inline int expected_signs(const Octree& t, const OctreeNode& nd) {
    int m = 0;
    for (int c = 0; c < 8; ++c) m |= int(t.value(t.corner(nd, c)) <= 0.0) << c;
    return m;
}

// Leaves whose OctreeNode::signs disagree with their corner samples; the first few described in `first`.
inline std::size_t wrong_signs(const Octree& t, std::ostringstream& first) {
    std::size_t wrong = 0;
    for (std::uint32_t li : tree_shape(t).leaves) {
        const OctreeNode& nd = t.nodes[li];
        const int want = expected_signs(t, nd);
        if (nd.signs != want && wrong++ < 3)
            first << "\n  leaf (" << nd.x << ", " << nd.y << ", " << nd.z << ") level " << int(nd.level)
                  << ": signs " << int(nd.signs) << ", its corners give " << want;
    }
    return wrong;
}

// Sign-changing edges of one leaf (12 edges, by the lab's tie rule).
inline int sign_changing_edges(const Octree& t, const OctreeNode& nd) {
    int n = 0;
    for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 8; ++c)
            if (!(c & (1 << a)) && (t.value(t.corner(nd, c)) <= 0.0) != (t.value(t.corner(nd, c | (1 << a))) <= 0.0)) ++n;
    return n;
}

// An icosphere of radius 0.8 (3 subdivisions, 1280 faces) without the faces whose centroid has z > 0.5: a hole of
// radius about 0.6 around +Z. MeshField's winding-number sign spans the hole with a cap on which the field jumps
// from +d to −d, d up to about 0.3 (the distance to the hole's rim): a distance test alone sees no surface there.
inline PolygonSoup sphere_with_hole() {
    const PolygonSoup ico = geolab::fixtures::icosphere(3);
    PolygonSoup out;
    for (const auto& p : ico.positions) out.positions.push_back(0.8 * p);
    for (std::size_t f = 0; f < ico.n_faces(); ++f) {
        auto vs = ico.face(f);
        glm::dvec3 c(0.0);
        for (std::uint32_t v : vs) c += out.positions[v];
        if (c.z / double(vs.size()) > 0.5) continue;
        out.add_face(vs);
    }
    return out;
}

// What dual contouring needs of a tree whatever the field: no leaf above max_level has corners on both sides, and
// every leaf around a sign-changing edge of a finest leaf (the 4 sharing it; the ring of leaves around a radial
// edge on the polar axis) is a finest leaf. Checked through the given locate() and the cached samples.
struct ClosureReport {
    std::size_t coarse_with_sign_change = 0, coarse_around_edge = 0;
    std::string first;
};
inline ClosureReport closure_report(const Octree& t) {
    ClosureReport r;
    const std::int32_t n = t.resolution();
    auto note = [&](std::uint32_t l, const std::string& why) {
        if (!r.first.empty()) return;
        const OctreeNode& nd = t.nodes[l];
        std::ostringstream os;
        os << "leaf " << l << " (level " << int(nd.level) << ", cell " << nd.x << ", " << nd.y << ", " << nd.z
           << ") " << why;
        r.first = os.str();
    };
    auto check_at = [&](glm::ivec3 p2, const glm::ivec3& q0, int a) {
        const std::uint32_t l = t.locate(p2);
        if (l == invalid_index || t.nodes[l].level == t.max_level) return;
        ++r.coarse_around_edge;
        note(l, "is coarser than max_level but touches the sign-changing finest edge from lattice point (" +
                    std::to_string(q0.x) + ", " + std::to_string(q0.y) + ", " + std::to_string(q0.z) +
                    ") along axis " + std::to_string(a));
    };
    for (std::uint32_t li : tree_shape(t).leaves) {
        const OctreeNode& nd = t.nodes[li];
        const int n_in = inside_corners(t, nd);
        if (nd.level < t.max_level) {
            if (n_in != 0 && n_in != 8) ++r.coarse_with_sign_change, note(li, "is coarser than max_level but its "
                                                                              "corners are on both sides");
            continue;
        }
        for (int a = 0; a < 3; ++a)
            for (int c = 0; c < 8; ++c) {
                if (c & (1 << a)) continue;
                const glm::ivec3 q0 = t.corner(nd, c), q1 = t.corner(nd, c | (1 << a));
                if ((t.value(q0) <= 0.0) == (t.value(q1) <= 0.0)) continue;
                if (t.coordinates == Coordinates::spherical && a == 0 && (q0.y == 0 || q0.y == n)) {
                    for (std::int32_t k = 0; k < n; ++k) check_at({2 * q0.x + 1, q0.y == 0 ? 1 : 2 * n - 1, 2 * k + 1}, q0, a);
                    continue;
                }
                const int b = (a + 1) % 3, d = (a + 2) % 3;
                for (int k = 0; k < 4; ++k) {
                    glm::ivec3 p2 = 2 * q0;
                    p2[a] += 1;
                    p2[b] += (k & 1) ? 1 : -1;
                    p2[d] += (k & 2) ? 1 : -1;
                    check_at(p2, q0, a);
                }
            }
    }
    return r;
}

// CHECK that no leaf above max_level sits at a sign change (closure_report), naming the first that does.
inline void check_closure(const Octree& t) {
    const ClosureReport r = closure_report(t);
    CHECK_MESSAGE(r.coarse_with_sign_change + r.coarse_around_edge == 0,
                  r.coarse_with_sign_change << " coarse leaves with corners on both sides, " << r.coarse_around_edge
                                            << " coarse leaves around sign-changing finest edges; first: " << r.first);
}

// The Cartesian box of a leaf.
inline Box cell_box(const Octree& t, const OctreeNode& nd) {
    return {t.lattice_point(t.corner(nd, 0)), t.lattice_point(t.corner(nd, 7))};
}
inline double box_outside(const Box& b, const glm::dvec3& p) {
    glm::dvec3 d = glm::max(b.lo - p, p - b.hi);
    return std::max({d.x, d.y, d.z, 0.0});
}

// ---- Trees and vertices for the tests of Tasks 4-6 WITHOUT your build_octree (Task 3) or place_vertices (Task 4)
// DESIGN.md: a task's tests never depend on your answer to another task, so a bug in build_octree costs Task 3's
// points only. These use the given Octree code only (init_cartesian, split, refine_around_sign_changes).

// A Cartesian octree to `level` over cartesian_domain(f, padding): a cell of level l < L is split when
// |f(centre)| <= 2 Lf (half diagonal), Lf = f.lipschitz() -- twice Task 3's bound, so the tree may be finer than
// yours away from the surface, never coarser near it -- and every cell when the field has no Lipschitz constant
// or its sign may jump (a complete tree); then refine_around_sign_changes(). No vertices yet.
inline Octree given_octree(const ScalarField& f, int level, double padding = 0.05) {
    Octree t;
    const auto [lo, side] = cartesian_domain(f, padding);
    t.init_cartesian(f, level, lo, side);
    const double lf = f.lipschitz();
    const bool split_all = !(lf > 0.0) || f.sign_may_jump();
    const double h = side / t.resolution();
    std::vector<std::uint32_t> work{0};
    while (!work.empty()) {
        const std::uint32_t n = work.back();
        work.pop_back();
        const OctreeNode nd = t.nodes[n];
        if (nd.level >= level) continue;
        const std::int32_t s = t.cell_span(nd.level);  // >= 2 below the finest level: the centre is a lattice point
        const glm::ivec3 centre(nd.x * s + s / 2, nd.y * s + s / 2, nd.z * s + s / 2);
        if (split_all || std::abs(t.value(centre)) <= 2.0 * lf * 0.5 * std::sqrt(3.0) * s * h) {
            const std::uint32_t first = t.split(n);
            for (std::uint32_t c = 0; c < 8; ++c) work.push_back(first + c);
        }
    }
    t.refine_around_sign_changes();
    return t;
}

// What contour (Task 6) needs from place_vertices (Task 4), made here: every leaf's signs (bit c set when corner c
// is inside, f <= 0) and, in each leaf whose corners are not all on one side, its vertices as DualVertex's layout
// says: a finest leaf one per piece of cell_surface(signs, face_joins) (given code), any other leaf one; each at the
// mean of the crossings of its piece's edges by linear interpolation of the corner values (inside the cell; no QEF,
// so no sharp corners). contour must work with any vertex inside its cell.
inline void given_vertices(Octree& t) {
    t.vertices.clear();
    t.qefs.clear();
    for (std::uint32_t li : t.leaves()) {
        OctreeNode& nd = t.nodes[li];
        nd.vertex = invalid_index;
        double v[8];
        int signs = 0;
        for (int c = 0; c < 8; ++c) v[c] = t.value(t.corner(nd, c)), signs |= int(inside(v[c])) << c;
        nd.signs = std::uint8_t(signs);
        if (signs == 0 || signs == 0xff) continue;
        CellSurface pieces;
        if (nd.level == t.max_level) {
            pieces = cell_surface(nd.signs, face_joins(t, nd));
        } else {
            pieces.count = 1;
            for (int e = 0; e < 12; ++e)
                if (inside(v[cell_edge_corners[e][0]]) != inside(v[cell_edge_corners[e][1]]))
                    pieces.edges[0] |= std::uint16_t(1u << e);
        }
        nd.vertex = std::uint32_t(t.vertices.size());
        for (int k = 0; k < pieces.count; ++k) {
            glm::dvec3 sum(0.0);
            int n = 0;
            for (int e = 0; e < 12; ++e) {
                if (!((pieces.edges[k] >> e) & 1)) continue;
                const int c = cell_edge_corners[e][0], d = cell_edge_corners[e][1];
                const double s = v[c] / (v[c] - v[d]);
                sum += t.lattice_point(t.corner(nd, c)) + s * (t.lattice_point(t.corner(nd, d)) -
                                                               t.lattice_point(t.corner(nd, c)));
                ++n;
            }
            t.vertices.push_back(DualVertex{sum / double(n), pieces.edges[k], std::uint8_t(pieces.count)});
            t.qefs.push_back(Qef{});  // contour reads no QEF
        }
    }
}

// An adaptive Cartesian tree without your simplify (Task 5): bottom-up, a node of level >= min_level whose 8 children
// are leaves becomes a leaf when every child's corners form one sheet and Ju et al.'s sign tests pass (its corners
// form one sheet; every edge midpoint, face centre and the centre has the sign of a corner of its feature), computed
// here from the samples; its vertex is the mean of the children's vertices (in the cell), or none when they have
// none. After given_vertices (the children's signs).
inline std::size_t given_collapse(Octree& t, int min_level) {
    auto connected = [](int mask) {
        if (mask == 0) return true;
        int seen = mask & -mask, todo = seen;
        while (todo) {
            int next = 0;
            for (int c = 0; c < 8; ++c)
                if (todo & (1 << c))
                    for (int a = 0; a < 3; ++a) next |= 1 << (c ^ (1 << a));
            todo = next & mask & ~seen;
            seen |= todo;
        }
        return seen == mask;
    };
    std::size_t collapses = 0;
    for (std::size_t ni = t.nodes.size(); ni-- > 0;) {
        const OctreeNode nd = t.nodes[ni];
        if (nd.is_leaf() || nd.level < min_level) continue;
        bool leaves = true;
        for (int c = 0; c < 8; ++c) leaves = leaves && t.nodes[nd.first_child + c].is_leaf();
        if (!leaves) continue;
        const std::int32_t half = t.cell_span(nd.level) / 2;
        const glm::ivec3 base = t.corner(nd, 0);
        int mask = 0;
        for (int c = 0; c < 8; ++c) mask |= int(t.value(t.corner(nd, c)) <= 0.0) << c;
        if (!connected(mask) || !connected(~mask & 0xff)) continue;
        bool children_sheet = true;  // every child's own corners one sheet: one piece each, no ambiguous face
        for (int c = 0; c < 8; ++c) {
            const int cs = t.nodes[nd.first_child + c].signs;
            children_sheet = children_sheet && connected(cs) && connected(~cs & 0xff);
        }
        if (!children_sheet) continue;
        bool agree = true;
        for (int i = 0; i < 3 && agree; ++i)
            for (int j = 0; j < 3 && agree; ++j)
                for (int k = 0; k < 3 && agree; ++k) {
                    const bool in = t.value(base + half * glm::ivec3(i, j, k)) <= 0.0;
                    bool some = false;
                    for (int c = 0; c < 8; ++c) {
                        const int ci[3] = {c & 1, (c >> 1) & 1, c >> 2}, p[3] = {i, j, k};
                        bool on = true;
                        for (int a = 0; a < 3; ++a) on = on && (p[a] == 1 || p[a] == 2 * ci[a]);
                        if (on && ((mask >> c) & 1) == int(in)) some = true;
                    }
                    agree = some;
                }
        if (!agree) continue;
        glm::dvec3 sum(0.0);
        int n = 0;
        for (int c = 0; c < 8; ++c) {
            const std::uint32_t v = t.nodes[nd.first_child + c].vertex;
            if (v != invalid_index) sum += t.vertices[v].position, ++n;
        }
        if ((n > 0) != (mask != 0 && mask != 0xff)) continue;
        OctreeNode& parent = t.nodes[ni];
        parent.first_child = invalid_index;
        parent.signs = std::uint8_t(mask);
        parent.vertex = invalid_index;
        if (n > 0) {
            parent.vertex = std::uint32_t(t.vertices.size());
            t.vertices.push_back(DualVertex{sum / double(n)});
            t.qefs.push_back(Qef{});
        }
        ++collapses;
    }
    return collapses;
}

// ---- the polygons of contour (Task 6), computed here leaf by leaf from the contract -------------------------------
// For every sign-changing minimal edge (no leaf around it is smaller than the leaf it was found in), the leaves in
// the 4 quadrants around it (locate at the edge's midpoint +- half a finest cell along the other two axes; (b, c) =
// (a + 1, a + 2) mod 3, quadrants (-,-), (+,-), (+,+), (-,+)), in that order when the edge's lower end is inside and
// reversed otherwise, repeats dropped; from each leaf the vertex of the piece crossing the edge (a leaf with several
// vertices: the one whose DualVertex::edges holds a cell edge of the leaf with the edge's two ends); a triangle, or a
// quad split along the diagonal whose two triangles both face the edge's outward direction when only one does (the
// chord from the edge's lower to its upper lattice end, negated when the lower end is outside), else along its
// shorter diagonal (equal diagonals: either split). Spherical trees: radial edges on the polar axis give pole rings
// instead (each leaf the piece crossing the axis edge), edges on the inner sphere are skipped. Not for spherical
// trees of level 1 (their quads at phi = 0 and pi join the same 4 vertices; the contract splits them apart). Slow
// and simple: for checking contour's output exactly.
struct ReferenceContour {
    using Tri = std::array<glm::dvec3, 3>;
    std::vector<Tri> triangles;                         // from triangles and quads with a decided diagonal
    std::vector<std::array<glm::dvec3, 4>> tie_quads;   // quads whose diagonals are equally long
    struct Ring {
        bool north = true;
        double r_lo = 0.0, r_hi = 0.0;
        std::vector<glm::dvec3> ring;
    };
    std::vector<Ring> rings;
    std::size_t edges = 0;   // sign-changing minimal edges that gave a polygon
    std::string no_vertex;   // a leaf around a sign-changing minimal edge without a vertex (contour must throw)
};

inline ReferenceContour reference_contour(const Octree& t) {
    ReferenceContour out;
    const bool spherical = t.coordinates == Coordinates::spherical;
    const std::int32_t n = t.resolution();
    const int qb[4] = {-1, +1, +1, -1}, qc[4] = {-1, -1, +1, +1};
    std::set<std::array<int, 6>> seen;  // edges by their canonical ends
    // the vertex of `leaf` for the piece crossing the edge from q0 to q1 (along axis a)
    auto position = [&](std::uint32_t leaf, const glm::ivec3& q0, const glm::ivec3& q1, int a) -> std::optional<glm::dvec3> {
        const OctreeNode& nd = t.nodes[leaf];
        if (nd.vertex != invalid_index && nd.vertex < t.vertices.size()) {
            const std::size_t n_pieces = t.vertices[nd.vertex].pieces;
            if (n_pieces <= 1) return t.vertices[nd.vertex].position;
            const glm::ivec3 k0 = t.canonical(q0), k1 = t.canonical(q1);
            for (std::size_t k = 0; k < n_pieces && nd.vertex + k < t.vertices.size(); ++k)
                for (int e = 0; e < 12; ++e)
                    if ((t.vertices[nd.vertex + k].edges >> e) & 1 &&
                        t.canonical(t.corner(nd, cell_edge_corners[e][0])) == k0 &&
                        t.canonical(t.corner(nd, cell_edge_corners[e][1])) == k1)
                        return t.vertices[nd.vertex + k].position;
        }
        if (out.no_vertex.empty())
            out.no_vertex = "leaf " + std::to_string(leaf) + " (level " + std::to_string(int(nd.level)) + ", cell " +
                            std::to_string(nd.x) + ", " + std::to_string(nd.y) + ", " + std::to_string(nd.z) +
                            ") around the sign-changing edge from lattice point (" + std::to_string(q0.x) + ", " +
                            std::to_string(q0.y) + ", " + std::to_string(q0.z) + ") along axis " + std::to_string(a) +
                            (nd.vertex == invalid_index ? ": no vertex" : ": no vertex whose piece crosses the edge");
        return std::nullopt;
    };
    for (std::uint32_t li : tree_shape(t).leaves) {
        const OctreeNode& nd = t.nodes[li];
        const std::int32_t span = t.cell_span(nd.level);
        for (int a = 0; a < 3; ++a)
            for (int c = 0; c < 8; ++c) {
                if (c & (1 << a)) continue;
                const glm::ivec3 q0 = t.corner(nd, c), q1 = t.corner(nd, c | (1 << a));
                const glm::ivec3 k0 = t.canonical(q0), k1 = t.canonical(q1);
                if (!seen.insert({k0.x, k0.y, k0.z, k1.x, k1.y, k1.z}).second) continue;
                const bool in0 = t.value(q0) <= 0.0;
                if (in0 == (t.value(q1) <= 0.0)) continue;
                if (spherical && a == 0 && (q0.y == 0 || q0.y == n)) continue;  // a pole ring (below)
                if (spherical && a != 0 && q0.x == 0) continue;                 // on the inner sphere
                glm::ivec3 m2 = 2 * q0;
                m2[a] += span;
                const int b = (a + 1) % 3, cx = (a + 2) % 3;
                std::uint32_t around[4];
                bool inside_domain = true, minimal = true;
                for (int k = 0; k < 4; ++k) {
                    glm::ivec3 p2 = m2;
                    p2[b] += qb[k];
                    p2[cx] += qc[k];
                    around[k] = t.locate(p2);
                    if (around[k] == invalid_index) inside_domain = false;
                    else if (t.nodes[around[k]].level > nd.level) minimal = false;
                }
                if (!inside_domain) continue;
                if (!minimal) {  // a smaller leaf's edges subdivide it: found again from that leaf
                    seen.erase({k0.x, k0.y, k0.z, k1.x, k1.y, k1.z});
                    continue;
                }
                std::vector<std::uint32_t> poly;
                for (int k = 0; k < 4; ++k) {
                    const std::uint32_t l = around[in0 ? k : 3 - k];
                    if (poly.empty() || poly.back() != l) poly.push_back(l);
                }
                if (poly.size() > 1 && poly.back() == poly.front()) poly.pop_back();
                if (poly.size() < 3) continue;
                std::vector<glm::dvec3> P;
                for (std::uint32_t l : poly)
                    if (auto p = position(l, q0, q1, a)) P.push_back(*p);
                if (P.size() != poly.size()) continue;
                ++out.edges;
                if (P.size() == 3) {
                    out.triangles.push_back({P[0], P[1], P[2]});
                    continue;
                }
                const glm::dvec3 outward = (in0 ? 1.0 : -1.0) * (t.lattice_point(q1) - t.lattice_point(q0));
                auto faces_out = [&](int i, int j, int k) {
                    return glm::dot(glm::cross(P[j] - P[i], P[k] - P[i]), outward) > 0.0;
                };
                const bool out02 = faces_out(0, 1, 2) && faces_out(0, 2, 3), out13 = faces_out(0, 1, 3) && faces_out(1, 2, 3);
                const double d02 = glm::dot(P[2] - P[0], P[2] - P[0]), d13 = glm::dot(P[3] - P[1], P[3] - P[1]);
                if (out02 != out13 ? out02 : d02 < d13 * (1.0 - 1e-12)) {
                    out.triangles.push_back({P[0], P[1], P[2]});
                    out.triangles.push_back({P[0], P[2], P[3]});
                } else if (out02 != out13 || d13 < d02 * (1.0 - 1e-12)) {
                    out.triangles.push_back({P[0], P[1], P[3]});
                    out.triangles.push_back({P[1], P[2], P[3]});
                } else {
                    out.tie_quads.push_back({P[0], P[1], P[2], P[3]});
                }
            }
        // pole rings: the radial edge on the axis, found from the leaf at phi index 0
        if (!spherical || nd.z != 0) continue;
        for (int pole = 0; pole < 2; ++pole) {
            const bool north = pole == 0;
            if (north ? nd.y != 0 : (std::int32_t(nd.y) + 1) * span != n) continue;
            const int c0 = north ? 0 : 2, c1 = c0 | 1;
            const glm::ivec3 q0 = t.corner(nd, c0), q1 = t.corner(nd, c1);
            const bool in0 = t.value(q0) <= 0.0;
            if (in0 == (t.value(q1) <= 0.0)) continue;
            std::vector<std::uint32_t> ring;
            bool minimal = true;
            for (std::int32_t k = 0; k < n; ++k) {
                const std::uint32_t l = t.locate({2 * q0.x + span, north ? 1 : 2 * n - 1, 2 * k + 1});
                if (l == invalid_index || t.nodes[l].level > nd.level) minimal = false;
                else if (ring.empty() || ring.back() != l) ring.push_back(l);
            }
            if (!minimal) continue;
            if (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
            if (in0 != north) std::reverse(ring.begin(), ring.end());  // counter-clockwise seen from outside
            ReferenceContour::Ring r;
            r.north = north;
            r.r_lo = t.lattice_spherical(q0).r;
            r.r_hi = t.lattice_spherical(q1).r;
            for (std::uint32_t l : ring)
                if (auto p = position(l, q0, q1, 0)) r.ring.push_back(*p);
            out.rings.push_back(std::move(r));
        }
    }
    return out;
}

// contour's triangles against the reference: the same oriented triangles (by their vertex positions, whatever the
// order of the faces and of their first vertex); "" or what differs.
inline std::string compare_polygons(const PolygonSoup& s, const ReferenceContour& ref) {
    using Key = std::array<double, 9>;
    auto key = [](glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {  // rotated so that the smallest point comes first
        auto less = [](const glm::dvec3& u, const glm::dvec3& v) {
            return u.x != v.x ? u.x < v.x : u.y != v.y ? u.y < v.y : u.z < v.z;
        };
        while (less(b, a) || less(c, a)) std::tie(a, b, c) = std::make_tuple(b, c, a);
        return Key{a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z};
    };
    std::map<Key, int> got;
    std::size_t bad = 0;
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        auto vs = s.face(f);
        if (vs.size() != 3 || vs[0] >= s.n_vertices() || vs[1] >= s.n_vertices() || vs[2] >= s.n_vertices()) {
            ++bad;
            continue;
        }
        ++got[key(s.positions[vs[0]], s.positions[vs[1]], s.positions[vs[2]])];
    }
    std::ostringstream os;
    if (bad) os << bad << " faces are not triangles of valid indices; ";
    std::size_t missing = 0;
    std::ostringstream first;
    auto take = [&](const Key& k) {
        auto it = got.find(k);
        if (it == got.end() || it->second == 0) return false;
        --it->second;
        return true;
    };
    auto show = [](const Key& k) {
        std::ostringstream o;
        o.precision(6);
        o << "(" << k[0] << ", " << k[1] << ", " << k[2] << ") (" << k[3] << ", " << k[4] << ", " << k[5] << ") ("
          << k[6] << ", " << k[7] << ", " << k[8] << ")";
        return o.str();
    };
    for (const auto& t : ref.triangles) {
        const Key k = key(t[0], t[1], t[2]);
        if (!take(k) && missing++ < 2) first << "\n  missing triangle " << show(k);
    }
    for (const auto& q : ref.tie_quads) {
        const Key a = key(q[0], q[1], q[2]), b = key(q[0], q[2], q[3]), c = key(q[0], q[1], q[3]), d = key(q[1], q[2], q[3]);
        if (got[a] > 0 && got[b] > 0) take(a), take(b);
        else if (got[c] > 0 && got[d] > 0) take(c), take(d);
        else if (missing++ < 2) first << "\n  missing quad (equal diagonals) " << show(a) << " + " << q[3].x << ", " << q[3].y << ", " << q[3].z;
    }
    std::size_t extra = 0;
    for (const auto& [k, count] : got)
        for (int i = 0; i < count; ++i)
            if (extra++ < 2) first << "\n  unexpected triangle " << show(k);
    if (!missing && !extra && !bad) return "";
    os << missing << " expected triangles missing (or wound the other way, split along the other diagonal, or from another piece's vertex), "
       << extra << " unexpected triangles; expected " << ref.triangles.size() + 2 * ref.tie_quads.size()
       << " triangles from " << ref.edges << " sign-changing minimal edges, got " << s.n_faces() << first.str();
    return os.str();
}

// contour's pole rings against the reference: the same rings (as cycles of positions, any starting vertex, the
// same direction), north/south and radial extent; "" or what differs.
inline std::string compare_rings(const PolygonSoup& s, const std::vector<PoleRing>& rings, const ReferenceContour& ref) {
    std::vector<bool> used(ref.rings.size(), false);
    std::ostringstream os;
    std::size_t unmatched = 0;
    for (const PoleRing& r : rings) {
        std::vector<glm::dvec3> P;
        for (std::uint32_t v : r.ring) P.push_back(v < s.n_vertices() ? s.positions[v] : glm::dvec3(1e300));
        bool found = false;
        for (std::size_t j = 0; j < ref.rings.size() && !found; ++j) {
            const auto& q = ref.rings[j];
            if (used[j] || q.north != r.north || q.ring.size() != P.size() || std::abs(q.r_lo - r.r_lo) > 1e-12 * (1 + q.r_hi) ||
                std::abs(q.r_hi - r.r_hi) > 1e-12 * (1 + q.r_hi))
                continue;
            for (std::size_t shift = 0; shift < P.size() && !found; ++shift) {
                bool same = true;
                for (std::size_t i = 0; i < P.size() && same; ++i) same = P[(i + shift) % P.size()] == q.ring[i];
                if (same) found = used[j] = true;
            }
        }
        if (!found && unmatched++ < 2)
            os << "\n  ring " << (r.north ? "north" : "south") << " r in [" << r.r_lo << ", " << r.r_hi << "] of "
               << r.ring.size() << " vertices matches no expected ring (leaves around the axis edge by increasing phi, "
               << "reversed when the axis edge's inner end is outside (north) / inside (south))";
    }
    if (!unmatched && rings.size() == ref.rings.size()) return "";
    std::ostringstream out;
    out << rings.size() << " pole rings, expected " << ref.rings.size() << ", " << unmatched << " of them wrong" << os.str();
    return out.str();
}

// given_octree + given_vertices + your contour: Task 6 alone.
inline PolygonSoup given_pipeline(const ScalarField& f, int level, Octree* out = nullptr) {
    Octree t = given_octree(f, level);
    given_vertices(t);
    PolygonSoup s = contour(t);
    if (out) *out = std::move(t);
    return s;
}

// The Cartesian pipeline on a given tree: given_octree, your place_vertices (QEF vertices), your simplify when the
// tolerance (in finest cells h) is > 0, your contour. For the tests of Tasks 5 and 6 that need QEF vertices.
inline PolygonSoup cartesian_pipeline(const ScalarField& f, int level, double simplify_tolerance_in_h = 0.0,
                                      Octree* out = nullptr) {
    CartesianParams p;
    p.max_level = level;
    Octree t = given_octree(f, level, p.padding);
    place_vertices(t, {p.tau, p.crossing_tolerance});
    if (simplify_tolerance_in_h > 0.0) simplify(t, simplify_tolerance_in_h * t.size / t.resolution(), p.tau);
    PolygonSoup s = contour(t);
    if (out) *out = std::move(t);
    return s;
}

}  // namespace lab09
