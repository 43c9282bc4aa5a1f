#pragma once
// Lab 09 test helpers for the manifold checks (handout §1.1): lib's check_surface (non-manifold vertices, exact
// self-intersections), the expected vertex layout of a leaf, and fields whose finest cells hold two surface pieces.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <sstream>
#include <string>

#include "geolab/surface_checks.hpp"
#include "helpers.hpp"

namespace lab09 {

// lib's full count: boundary, non-manifold and misoriented edges, non-manifold vertices (more than one fan),
// repeated indices, components, χ, and (when asked) self-intersecting face pairs by exact predicates.
inline geolab::SurfaceCheck surface_check(const PolygonSoup& soup, bool self_intersections) {
    geolab::CheckOptions o;
    o.self_intersections = self_intersections;
    return geolab::check_surface(soup, o);
}

// CHECK that the soup is a closed, oriented 2-manifold: no boundary, non-manifold or misoriented edge, no
// non-manifold vertex, no repeated index; and no self-intersecting face pair when `self_intersections`.
#define LAB09_CHECK_2_MANIFOLD(soup, label, self_intersections)                                                     \
    do {                                                                                                            \
        const ::geolab::SurfaceCheck sc_ = ::lab09::surface_check(soup, self_intersections);                        \
        INFO(std::string(label) << ": " << sc_.summary());                                                          \
        CHECK_MESSAGE(sc_.faces > 0, "the mesh has no faces");                                                      \
        CHECK_MESSAGE(sc_.boundary_edges == 0, "boundary edges (holes, cracks): " << sc_.boundary_edges);           \
        CHECK_MESSAGE(sc_.non_manifold_edges == 0, "edges in more than 2 faces: " << sc_.non_manifold_edges);       \
        CHECK_MESSAGE(sc_.non_manifold_vertices == 0,                                                               \
                      "vertices whose faces make more than one fan: " << sc_.non_manifold_vertices);                \
        CHECK_MESSAGE(sc_.misoriented_edges == 0, "edges traversed twice the same way: " << sc_.misoriented_edges); \
        CHECK_MESSAGE(sc_.repeated_index_faces == 0, "faces with a repeated vertex: " << sc_.repeated_index_faces); \
        if (self_intersections)                                                                                     \
            CHECK_MESSAGE(sc_.self_intersecting_pairs() == 0,                                                       \
                          "self-intersecting face pairs (exact): " << sc_.self_intersecting_pairs());               \
    } while (0)

// The pieces a leaf must have vertices for (DualVertex's layout): a finest leaf's cell_surface with face_joins,
// any other leaf one piece holding all its sign-changing edges (given code and the leaf's corner samples only).
inline CellSurface expected_pieces(const Octree& t, const OctreeNode& nd) {
    const std::uint8_t signs = std::uint8_t(expected_signs(t, nd));
    if (signs == 0 || signs == 0xff) return {};
    if (nd.level == t.max_level) return cell_surface(signs, face_joins(t, nd));
    CellSurface one;
    one.count = 1;
    for (int e = 0; e < 12; ++e)
        if (((signs >> cell_edge_corners[e][0]) ^ (signs >> cell_edge_corners[e][1])) & 1)
            one.edges[0] |= std::uint16_t(1u << e);
    return one;
}

// The crossings a piece with cell edges `edges` of leaf nd has: its edges counted once per distinct pair of canonical
// ends (the radial edge on the polar axis is two cell edges of a spherical cell there, one crossing).
inline int distinct_crossings(const Octree& t, const OctreeNode& nd, std::uint16_t edges) {
    std::vector<std::array<int, 6>> seen;
    for (int e = 0; e < 12; ++e) {
        if (!((edges >> e) & 1)) continue;
        const glm::ivec3 k0 = t.canonical(t.corner(nd, cell_edge_corners[e][0])),
                         k1 = t.canonical(t.corner(nd, cell_edge_corners[e][1]));
        const std::array<int, 6> key{k0.x, k0.y, k0.z, k1.x, k1.y, k1.z};
        if (std::find(seen.begin(), seen.end(), key) == seen.end()) seen.push_back(key);
    }
    return int(seen.size());
}

// Leaves whose vertices do not follow DualVertex's layout for expected_pieces (count, order, edges, pieces, index
// range); when `qef_counts`, also a vertex whose Qef does not hold one plane per crossing of its piece (each
// sign-changing edge once: distinct_crossings). The first few described in `first`.
inline std::size_t wrong_layouts(const Octree& t, std::ostringstream& first, bool qef_counts) {
    std::size_t wrong = 0;
    for (std::uint32_t li : tree_shape(t).leaves) {
        const OctreeNode& nd = t.nodes[li];
        const CellSurface want = expected_pieces(t, nd);
        std::ostringstream why;
        if (want.count == 0) {
            if (nd.vertex != invalid_index) why << "has a vertex but no sign change";
        } else if (nd.vertex == invalid_index) {
            why << "has no vertex but " << want.count << " piece(s)";
        } else if (std::size_t(nd.vertex) + std::size_t(want.count) > t.vertices.size()) {
            why << "vertices " << nd.vertex << " .. " << nd.vertex + want.count - 1 << " run past tree.vertices ("
                << t.vertices.size() << ")";
        } else {
            for (int k = 0; k < want.count && why.str().empty(); ++k) {
                const DualVertex& v = t.vertices[nd.vertex + k];
                if (v.pieces != want.count)
                    why << "vertex " << k << " says pieces = " << int(v.pieces) << ", the leaf has " << want.count;
                else if (v.edges != want.edges[k])
                    why << "vertex " << k << " has edges 0x" << std::hex << v.edges << ", piece " << std::dec << k
                        << " of cell_surface crosses 0x" << std::hex << want.edges[k] << std::dec;
                else if (qef_counts && qef_of(t, nd.vertex + k).count != distinct_crossings(t, nd, want.edges[k]))
                    why << "vertex " << k << " has " << qef_of(t, nd.vertex + k).count << " QEF planes for "
                        << distinct_crossings(t, nd, want.edges[k]) << " crossed edges";
            }
        }
        if (!why.str().empty() && wrong++ < 3)
            first << "\n  leaf (" << nd.x << ", " << nd.y << ", " << nd.z << ") level " << int(nd.level) << ", signs 0x"
                  << std::hex << int(expected_signs(t, nd)) << std::dec << ": " << why.str();
    }
    return wrong;
}

// Leaves with at least `n` pieces, and finest leaves with a joined ambiguous face.
inline std::size_t leaves_with_pieces(const Octree& t, int n) {
    std::size_t count = 0;
    for (std::uint32_t li : tree_shape(t).leaves) count += expected_pieces(t, t.nodes[li]).count >= n;
    return count;
}
inline std::size_t leaves_with_joins(const Octree& t) {
    std::size_t count = 0;
    for (std::uint32_t li : tree_shape(t).leaves) {
        const OctreeNode& nd = t.nodes[li];
        OctreeNode probe = nd;
        probe.signs = std::uint8_t(expected_signs(t, nd));
        count += nd.level == t.max_level && face_joins(t, probe) != 0;
    }
    return count;
}

// Two balls of radius r that nearly touch across the diagonal of a finest cell's z-faces: the cell of the Cartesian
// octree of `level` over bounds() = [-1, 1]^3 (padding 0.05) whose centre is `centre_cell` + (1/2, 1/2, 1/2) has two
// corners (one z-edge) in each ball and the other four in the gap between them, so its surface has two pieces.
// f = distance to the union of the balls (Lipschitz 1).
class DiagonalBalls final : public ScalarField {
public:
    DiagonalBalls(int level, glm::ivec3 centre_cell, double r, double gap_in_h) : r_(r) {
        const double h = 2.2 / double(1 << level);
        centre_ = glm::dvec3(-1.1) + h * (glm::dvec3(centre_cell) + 0.5);
        const glm::dvec3 u = glm::normalize(glm::dvec3(1.0, 1.0, 0.0));
        c1_ = centre_ - (r + 0.5 * gap_in_h * h) * u;
        c2_ = centre_ + (r + 0.5 * gap_in_h * h) * u;
    }
    double value(const glm::dvec3& p) const override {
        return std::min(glm::length(p - c1_), glm::length(p - c2_)) - r_;
    }
    glm::dvec3 gradient(const glm::dvec3& p) const override {
        const glm::dvec3 d = glm::length(p - c1_) <= glm::length(p - c2_) ? p - c1_ : p - c2_;
        const double len = glm::length(d);
        return len > 0 ? d / len : glm::dvec3(0.0);
    }
    Box bounds() const override { return {glm::dvec3(-1.0), glm::dvec3(1.0)}; }
    double lipschitz() const override { return 1.0; }
    glm::dvec3 centre_, c1_, c2_;
    double r_;
};

// The trilinear interpolant of values given at the lattice points of the Cartesian octree of `level` over
// bounds() = [-1, 1]^3 (padding 0.05): -1 inside the block [lo, hi]^3 of lattice points, +1 elsewhere, except the
// `holes` (lattice points set to +1) and the `islands` (set to -1). Its samples at the octree's lattice points are
// exactly these values. lipschitz() == 0: the given octree is then complete.
class LatticeBlock final : public ScalarField {
public:
    LatticeBlock(int level, int lo, int hi, std::vector<glm::ivec3> holes, std::vector<glm::ivec3> islands = {})
        : n_(1 << level), lo_(lo), hi_(hi), holes_(std::move(holes)), islands_(std::move(islands)) {}
    double value(const glm::dvec3& p) const override {
        glm::dvec3 t;
        const glm::ivec3 q = cell_of(p, t);
        double v = 0.0;
        for (int c = 0; c < 8; ++c) {
            const glm::ivec3 d(c & 1, (c >> 1) & 1, c >> 2);
            double w = 1.0;
            for (int a = 0; a < 3; ++a) w *= d[a] ? t[a] : 1.0 - t[a];
            v += w * at(q + d);
        }
        return v;
    }
    glm::dvec3 gradient(const glm::dvec3& p) const override {
        glm::dvec3 t;
        const glm::ivec3 q = cell_of(p, t);
        glm::dvec3 g(0.0);
        for (int c = 0; c < 8; ++c) {
            const glm::ivec3 d(c & 1, (c >> 1) & 1, c >> 2);
            for (int a = 0; a < 3; ++a) {
                double w = d[a] ? 1.0 : -1.0;
                for (int b = 0; b < 3; ++b)
                    if (b != a) w *= d[b] ? t[b] : 1.0 - t[b];
                g[a] += w * at(q + d);
            }
        }
        return g / h();
    }
    Box bounds() const override { return {glm::dvec3(-1.0), glm::dvec3(1.0)}; }
    double at(glm::ivec3 q) const {
        for (const glm::ivec3& hole : holes_)
            if (q == hole) return 1.0;
        for (const glm::ivec3& island : islands_)
            if (q == island) return -1.0;
        const bool in = q.x >= lo_ && q.y >= lo_ && q.z >= lo_ && q.x <= hi_ && q.y <= hi_ && q.z <= hi_;
        return in ? -1.0 : 1.0;
    }

private:
    double h() const { return 2.2 / double(n_); }
    // the lattice cell holding p and p's coordinates in it, rounded to a lattice point when within 1e-9 of one
    glm::ivec3 cell_of(const glm::dvec3& p, glm::dvec3& t) const {
        glm::ivec3 q;
        for (int a = 0; a < 3; ++a) {
            double x = (p[a] + 1.1) / h();
            if (std::abs(x - std::round(x)) < 1e-9) x = std::round(x);
            q[a] = std::clamp(int(std::floor(x)), 0, n_ - 1);
            t[a] = std::clamp(x - q[a], 0.0, 1.0);
        }
        return q;
    }
    int n_, lo_, hi_;
    std::vector<glm::ivec3> holes_, islands_;
};

// The lattice block [2, 6]^3 at level 3 with two outside points on one diagonal of the face z = 4 of the cells
// (3, 3, 3) and (3, 3, 4): the face's two inside corners (3, 3, 4), (4, 4, 4) are connected through inside points
// on both sides, so face_joins joins them and each outside point is a cavity of its own.
inline LatticeBlock two_cavities() { return LatticeBlock(3, 2, 6, {{4, 3, 4}, {3, 4, 4}}); }
// The same across a face normal to x (x = 4) and to y (y = 4).
inline LatticeBlock two_cavities_x() { return LatticeBlock(3, 2, 6, {{4, 4, 3}, {4, 3, 4}}); }
inline LatticeBlock two_cavities_y() { return LatticeBlock(3, 2, 6, {{4, 4, 3}, {3, 4, 4}}); }
// Four inside lattice points, no two on one cell edge, at corners 0, 3, 5 and 6 of the level-3 cell (3, 3, 3): that
// cell's surface has 4 pieces (each corner cut off; every face is ambiguous and none is joined).
inline LatticeBlock four_pieces() { return LatticeBlock(3, 1, 0, {}, {{3, 3, 3}, {4, 4, 3}, {4, 3, 4}, {3, 4, 4}}); }

// A field on the spherical lattice of a tree of `level` about the origin, shell [0, r_max]: the trilinear interpolant
// in (r, theta, phi) lattice units of -1 at the `inside` lattice points (i, j, k) (j = 0 or 2^level: a point on the
// polar axis, whatever k) and +1 elsewhere. Its samples at the tree's lattice points are exactly these values.
class SphericalLatticePoints final : public ScalarField {
public:
    SphericalLatticePoints(int level, double r_max, std::vector<glm::ivec3> inside)
        : n_(1 << level), r_max_(r_max), inside_(std::move(inside)) {}
    double value(const glm::dvec3& p) const override {
        const double r = glm::length(p);
        const double theta = r > 0 ? std::acos(std::clamp(p.z / r, -1.0, 1.0)) : 0.0;
        double phi = std::atan2(p.y, p.x);
        if (phi < 0) phi += 2 * kPi;
        const double u[3] = {r / r_max_ * n_, theta / kPi * n_, phi / (2 * kPi) * n_};
        glm::ivec3 q;
        double t[3];
        for (int a = 0; a < 3; ++a) {
            double x = u[a];
            if (std::abs(x - std::round(x)) < 1e-9) x = std::round(x);
            q[a] = std::clamp(int(std::floor(x)), 0, n_ - 1);
            t[a] = std::clamp(x - q[a], 0.0, 1.0);
        }
        double v = 0.0;
        for (int c = 0; c < 8; ++c) {
            const glm::ivec3 d(c & 1, (c >> 1) & 1, c >> 2);
            double w = 1.0;
            for (int a = 0; a < 3; ++a) w *= d[a] ? t[a] : 1.0 - t[a];
            v += w * at(q + d);
        }
        return v;
    }
    Box bounds() const override { return {glm::dvec3(-r_max_), glm::dvec3(r_max_)}; }
    double at(glm::ivec3 q) const {
        q.z %= n_;
        for (const glm::ivec3& in : inside_) {
            const bool axis = in.y == 0 || in.y == n_;
            if (q.x == in.x && q.y == in.y && (axis || q.z == in.z % n_)) return -1.0;
        }
        return 1.0;
    }

private:
    int n_;
    double r_max_;
    std::vector<glm::ivec3> inside_;
};

}  // namespace lab09
