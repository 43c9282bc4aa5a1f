// Task 2: triangulation by ear clipping with hole bridging (handout §3).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/predicates.hpp"
#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

namespace {
// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.
using Index = std::uint32_t;
using Chain = std::vector<Index>;  // a closed chain of indices into the profile's points

// Whether q lies on the closed segment [a, b], given that a, b, q are collinear.
bool on_segment(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& q) {
    return std::min(a.x, b.x) <= q.x && q.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= q.y &&
           q.y <= std::max(a.y, b.y);
}

// Whether the edge (u, w) is in the way of the segment from m to p: the two cross, or u or w (other than m and p)
// lies on the segment. (m and p never lie inside an edge: loops are simple and apart, and every bridge made
// before passed this test.)
bool blocks(const glm::dvec2& m, const glm::dvec2& p, const glm::dvec2& u, const glm::dvec2& w) {
    const int ou = orient2d(m, p, u), ow = orient2d(m, p, w);
    if (ou * ow < 0 && orient2d(u, w, m) * orient2d(u, w, p) < 0) return true;
    const auto on_mp = [&](const glm::dvec2& q, int o) { return o == 0 && q != m && q != p && on_segment(m, p, q); };
    return on_mp(u, ou) || on_mp(w, ow);
}

// Whether no edge of the chains is in the way of the segment m–p.
bool sees(const glm::dvec2& m, const glm::dvec2& p, const std::vector<const Chain*>& chains,
          const std::vector<glm::dvec2>& pts) {
    for (const Chain* c : chains)
        for (std::size_t i = 0; i < c->size(); ++i)
            if (blocks(m, p, pts[(*c)[i]], pts[(*c)[(i + 1) % c->size()]])) return false;
    return true;
}

// Whether the point q lies inside the corner of the polygon at v (u before v, w after it; the region is on the
// left of u→v and of v→w): strictly left of both edges at a convex corner, of either at a reflex or straight one.
bool in_corner(const glm::dvec2& u, const glm::dvec2& v, const glm::dvec2& w, const glm::dvec2& q) {
    const bool left_of_uv = orient2d(u, v, q) > 0, left_of_vw = orient2d(v, w, q) > 0;
    return orient2d(u, v, w) > 0 ? left_of_uv && left_of_vw : left_of_uv || left_of_vw;
}

// Joins `hole` into the polygon `poly` by a bridge from the hole's rightmost vertex M to the nearest place P of
// poly that M sees (no edge of poly, of the hole or of the holes still `waiting` is in the way) and whose corner opens towards M
// (a vertex joined before appears twice in poly: only one of its corners holds M). poly becomes
// ... P, M, (the hole from M around back to M), P, ...
void bridge(Chain& poly, const Chain& hole, const std::vector<Chain>& waiting, const std::vector<glm::dvec2>& pts) {
    std::size_t mi = 0;
    for (std::size_t i = 1; i < hole.size(); ++i)
        if (pts[hole[i]].x > pts[hole[mi]].x) mi = i;
    const glm::dvec2 M = pts[hole[mi]];
    std::vector<const Chain*> chains{&poly, &hole};
    for (const Chain& h : waiting) chains.push_back(&h);
    const std::size_t n = poly.size();
    std::size_t pk = n;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 P = pts[poly[i]];
        const double d = glm::dot(P - M, P - M);
        if (d < best && in_corner(pts[poly[(i + n - 1) % n]], P, pts[poly[(i + 1) % n]], M) && sees(M, P, chains, pts)) {
            best = d;
            pk = i;
        }
    }
    if (pk == n) throw std::runtime_error("triangulate: no vertex of the polygon is visible from a hole");
    Chain out(poly.begin(), poly.begin() + static_cast<std::ptrdiff_t>(pk) + 1);
    for (std::size_t k = 0; k <= hole.size(); ++k) out.push_back(hole[(mi + k) % hole.size()]);
    out.insert(out.end(), poly.begin() + static_cast<std::ptrdiff_t>(pk), poly.end());
    poly.swap(out);
}

// Whether p lies in the closed triangle (a, b, c), which is counter-clockwise.
bool in_triangle(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, const glm::dvec2& p) {
    return orient2d(a, b, p) >= 0 && orient2d(b, c, p) >= 0 && orient2d(c, a, p) >= 0;
}

// Whether the corner at position j of poly is an ear: strictly convex, and no other vertex of poly lies in its
// closed triangle (copies of its own three vertices, made by bridging, do not count).
bool is_ear(const Chain& poly, std::size_t j, const std::vector<glm::dvec2>& pts) {
    const std::size_t n = poly.size();
    const Index ia = poly[(j + n - 1) % n], ib = poly[j], ic = poly[(j + 1) % n];
    if (orient2d(pts[ia], pts[ib], pts[ic]) <= 0) return false;
    for (const Index iv : poly)
        if (iv != ia && iv != ib && iv != ic && in_triangle(pts[ia], pts[ib], pts[ic], pts[iv])) return false;
    return true;
}
// END SOLUTION
}  // namespace

std::vector<std::array<std::uint32_t, 3>> triangulate(const Profile& p) {
    // BEGIN SOLUTION
    validate_profile(p);
    const std::vector<glm::dvec2> pts = profile_points(p);
    Chain poly(p.outer.size());
    std::iota(poly.begin(), poly.end(), Index{0});
    // Holes by decreasing rightmost x: then a vertex visible from the next hole's rightmost vertex always exists.
    std::vector<Chain> holes;
    Index next = static_cast<Index>(p.outer.size());
    for (const Loop& h : p.holes) {
        Chain idx(h.size());
        std::iota(idx.begin(), idx.end(), next);
        next += static_cast<Index>(h.size());
        holes.push_back(std::move(idx));
    }
    const auto max_x = [&](const Chain& h) {
        double m = -std::numeric_limits<double>::infinity();
        for (Index i : h) m = std::max(m, pts[i].x);
        return m;
    };
    std::stable_sort(holes.begin(), holes.end(), [&](const Chain& a, const Chain& b) { return max_x(a) > max_x(b); });
    while (!holes.empty()) {
        const Chain hole = std::move(holes.front());
        holes.erase(holes.begin());
        bridge(poly, hole, holes, pts);
    }
    // Ear clipping, each search starting where the last ear was cut.
    std::vector<std::array<Index, 3>> tris;
    std::size_t i = 0;
    while (poly.size() > 3) {
        const std::size_t n = poly.size();
        std::size_t k = 0;
        while (k < n && !is_ear(poly, (i + k) % n, pts)) ++k;
        if (k == n) throw std::runtime_error("triangulate: no ear left among " + std::to_string(n) + " vertices");
        const std::size_t j = (i + k) % n;
        tris.push_back({poly[(j + n - 1) % n], poly[j], poly[(j + 1) % n]});
        poly.erase(poly.begin() + static_cast<std::ptrdiff_t>(j));
        i = j % poly.size();
    }
    tris.push_back({poly[0], poly[1], poly[2]});
    return tris;
    // END SOLUTION
}

}  // namespace geolab::sweeps
