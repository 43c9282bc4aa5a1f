// Task 4: surfaces of revolution (handout §5).
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

Profile clip_to_axis(const Profile& p) {
    // BEGIN SOLUTION
    validate_profile(p);
    for (std::size_t h = 0; h < p.holes.size(); ++h)
        for (const glm::dvec2& q : p.holes[h])
            if (q.x <= 0)
                throw std::invalid_argument("clip_to_axis: hole " + std::to_string(h) +
                                            " reaches the axis (x <= 0); only the outer loop may be clipped");
    Loop out;
    const std::size_t n = p.outer.size();
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 a = p.outer[(i + n - 1) % n], b = p.outer[i];  // the edge into point i: keeps the order
        const bool ain = a.x >= 0, bin = b.x >= 0;
        if (ain != bin) out.push_back({0.0, a.y + (b.y - a.y) * (0.0 - a.x) / (b.x - a.x)});
        if (bin) out.push_back(b);
    }
    Loop clean;  // without repeated points (a point on the axis and the crossing point there)
    for (const glm::dvec2& q : out)
        if (clean.empty() || clean.back() != q) clean.push_back(q);
    if (!clean.empty() && clean.front() == clean.back()) clean.pop_back();
    if (signed_area(clean) <= 0)  // also fewer than 3 points: area 0
        throw std::invalid_argument("clip_to_axis: nothing of the profile lies at x >= 0");
    return {clean, p.holes};
    // END SOLUTION
}

PolygonSoup revolve(const Profile& p, const RevolveOptions& o) {
    // BEGIN SOLUTION
    if (o.segments < 3)
        throw std::invalid_argument("revolve: segments = " + std::to_string(o.segments) + " (at least 3)");
    const double two_pi = 2 * std::numbers::pi;
    const bool full = std::abs(o.angle - two_pi) <= 1e-12;
    if (!full && !(o.angle > 0 && o.angle < two_pi))
        throw std::invalid_argument("revolve: angle = " + std::to_string(o.angle) + " (must be in (0, 2π])");
    const Profile c = clip_to_axis(p);
    const std::vector<glm::dvec2> pts = profile_points(c);
    const auto segs = static_cast<std::uint32_t>(o.segments);
    const std::uint32_t ring = full ? segs : segs + 1;
    PolygonSoup m;
    std::vector<std::uint32_t> base(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
        base[i] = static_cast<std::uint32_t>(m.positions.size());
        if (pts[i].x == 0) {
            m.positions.push_back({0.0, 0.0, pts[i].y});
            continue;
        }
        for (std::uint32_t j = 0; j < ring; ++j) {
            const double phi = full ? two_pi * j / segs : o.angle * j / segs;
            m.positions.push_back({pts[i].x * std::cos(phi), pts[i].x * std::sin(phi), pts[i].y});
        }
    }
    auto vert = [&](std::size_t i, std::uint32_t j) { return pts[i].x == 0 ? base[i] : base[i] + (full ? j % segs : j); };
    std::size_t start = 0;
    auto strips = [&](std::size_t len) {
        for (std::size_t k = 0; k < len; ++k) {
            const std::size_t a = start + k, b = start + (k + 1) % len;
            const bool pa = pts[a].x == 0, pb = pts[b].x == 0;  // both: an edge on the axis, no surface
            for (std::uint32_t j = 0; j < segs; ++j) {
                if (!pa) m.add_face({vert(a, j), vert(a, j + 1), vert(b, j + 1)});
                if (!pb) m.add_face({vert(a, j), vert(b, j + 1), vert(b, j)});
            }
        }
        start += len;
    };
    strips(c.outer.size());
    for (const Loop& h : c.holes) strips(h.size());
    if (!full) {
        for (const auto& t : triangulate(c)) {
            m.add_face({vert(t[0], 0), vert(t[1], 0), vert(t[2], 0)});
            m.add_face({vert(t[0], segs), vert(t[2], segs), vert(t[1], segs)});
        }
    }
    return m;
    // END SOLUTION
}

}  // namespace geolab::sweeps
