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

// Whether p lies in the closed triangle (a, b, c), which is counter-clockwise.
bool in_triangle(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, const glm::dvec2& p) {
    return orient2d(a, b, p) >= 0 && orient2d(b, c, p) >= 0 && orient2d(c, a, p) >= 0;
}

// Joins the hole (indices into pts, clockwise) into the polygon `poly` by a bridge from the hole's rightmost
// vertex M to a vertex P of poly that M sees (Eberly's choice): poly becomes ... P, M, hole..., M, P, ...
void bridge(std::vector<Index>& poly, const std::vector<Index>& hole, const std::vector<glm::dvec2>& pts) {
    std::size_t mi = 0;
    for (std::size_t i = 1; i < hole.size(); ++i)
        if (pts[hole[i]].x > pts[hole[mi]].x) mi = i;
    const glm::dvec2 M = pts[hole[mi]];
    // The nearest point I of poly's boundary on the ray M + t (1, 0), t > 0.
    double best = std::numeric_limits<double>::infinity();
    std::size_t edge = poly.size();
    const std::size_t n = poly.size();
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 a = pts[poly[i]], b = pts[poly[(i + 1) % n]];
        if ((a.y > M.y) == (b.y > M.y) && a.y != M.y && b.y != M.y) continue;
        if (a.y == b.y) continue;
        if (std::min(a.y, b.y) > M.y || std::max(a.y, b.y) < M.y) continue;
        const double x = a.x + (M.y - a.y) * (b.x - a.x) / (b.y - a.y);
        if (x < M.x) continue;
        if (x < best) {
            best = x;
            edge = i;
        }
    }
    if (edge == n) throw std::invalid_argument("triangulate: a hole is not inside the outer loop");
    const glm::dvec2 I{best, M.y};
    const glm::dvec2 ea = pts[poly[edge]], eb = pts[poly[(edge + 1) % n]];
    std::size_t pk = ea == I ? edge : eb == I ? (edge + 1) % n : (ea.x > eb.x ? edge : (edge + 1) % n);
    const glm::dvec2 P = pts[poly[pk]];
    if (P != I) {
        // A reflex vertex of poly inside the triangle (M, I, P) would block the view: take the one closest in angle.
        glm::dvec2 a = M, b = I, c = P;
        if (orient2d(a, b, c) < 0) std::swap(b, c);
        double best_angle = std::numeric_limits<double>::infinity(), best_dist = best_angle;
        for (std::size_t i = 0; i < n; ++i) {
            const glm::dvec2 v = pts[poly[i]];
            if (poly[i] == poly[pk]) continue;
            const glm::dvec2 u = pts[poly[(i + n - 1) % n]], w = pts[poly[(i + 1) % n]];
            if (orient2d(u, v, w) > 0) continue;  // convex: cannot block
            if (!in_triangle(a, b, c, v)) continue;
            const glm::dvec2 d = v - M;
            const double ang = std::atan2(std::abs(d.y), d.x), dist = glm::dot(d, d);
            if (ang < best_angle || (ang == best_angle && dist < best_dist)) {
                best_angle = ang;
                best_dist = dist;
                pk = i;
            }
        }
    }
    // Among copies of P (a vertex bridged before), take the one whose wedge holds M.
    for (std::size_t i = 0; i < n; ++i) {
        if (poly[i] != poly[pk]) continue;
        const glm::dvec2 u = pts[poly[(i + n - 1) % n]], v = pts[poly[i]], w = pts[poly[(i + 1) % n]];
        const bool convex = orient2d(u, v, w) >= 0;
        const bool in_wedge = convex ? (orient2d(u, v, M) > 0 && orient2d(v, w, M) > 0)
                                     : !(orient2d(u, v, M) <= 0 && orient2d(v, w, M) <= 0);
        if (in_wedge) {
            pk = i;
            break;
        }
    }
    std::vector<Index> out;
    out.reserve(n + hole.size() + 2);
    out.insert(out.end(), poly.begin(), poly.begin() + static_cast<std::ptrdiff_t>(pk) + 1);
    for (std::size_t k = 0; k <= hole.size(); ++k) out.push_back(hole[(mi + k) % hole.size()]);
    out.insert(out.end(), poly.begin() + static_cast<std::ptrdiff_t>(pk), poly.end());
    poly.swap(out);
}
// END SOLUTION
}  // namespace

std::vector<std::array<std::uint32_t, 3>> triangulate(const Profile& p) {
    // BEGIN SOLUTION
    validate_profile(p);
    const std::vector<glm::dvec2> pts = profile_points(p);
    std::vector<Index> poly(p.outer.size());
    std::iota(poly.begin(), poly.end(), Index{0});
    // Holes by decreasing rightmost x: a ray from a hole's rightmost vertex meets no hole not yet bridged.
    std::vector<std::vector<Index>> holes;
    Index next = static_cast<Index>(p.outer.size());
    for (const Loop& h : p.holes) {
        std::vector<Index> idx(h.size());
        std::iota(idx.begin(), idx.end(), next);
        next += static_cast<Index>(h.size());
        holes.push_back(std::move(idx));
    }
    auto max_x = [&](const std::vector<Index>& h) {
        double m = -std::numeric_limits<double>::infinity();
        for (Index i : h) m = std::max(m, pts[i].x);
        return m;
    };
    std::stable_sort(holes.begin(), holes.end(), [&](const auto& a, const auto& b) { return max_x(a) > max_x(b); });
    for (const auto& h : holes) bridge(poly, h, pts);

    std::vector<std::array<Index, 3>> tris;
    tris.reserve(poly.size());
    // Ear clipping: an ear is a strictly convex corner whose triangle holds no other vertex of the polygon.
    auto is_ear = [&](std::size_t i, bool strict) {
        const std::size_t n = poly.size();
        const Index ia = poly[(i + n - 1) % n], ib = poly[i], ic = poly[(i + 1) % n];
        const glm::dvec2 a = pts[ia], b = pts[ib], c = pts[ic];
        if (orient2d(a, b, c) <= 0) return false;
        for (std::size_t k = 0; k < n; ++k) {
            const Index iv = poly[k];
            if (iv == ia || iv == ib || iv == ic) continue;
            const glm::dvec2 v = pts[iv];
            if (strict ? in_triangle(a, b, c, v)
                       : (orient2d(a, b, v) > 0 && orient2d(b, c, v) > 0 && orient2d(c, a, v) > 0))
                return false;
        }
        return true;
    };
    std::size_t i = 0;
    while (poly.size() > 3) {
        const std::size_t n = poly.size();
        bool found = false;
        for (int pass = 0; pass < 2 && !found; ++pass) {
            for (std::size_t k = 0; k < n; ++k) {
                const std::size_t j = (i + k) % n;
                if (is_ear(j, pass == 0)) {
                    tris.push_back({poly[(j + n - 1) % n], poly[j], poly[(j + 1) % n]});
                    poly.erase(poly.begin() + static_cast<std::ptrdiff_t>(j));
                    i = j % poly.size();
                    found = true;
                    break;
                }
            }
        }
        if (!found)
            throw std::runtime_error("triangulate: no ear left among " + std::to_string(n) +
                                     " vertices (a degenerate profile)");
    }
    tris.push_back({poly[0], poly[1], poly[2]});
    return tris;
    // END SOLUTION
}

}  // namespace geolab::sweeps
