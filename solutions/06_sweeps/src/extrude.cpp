// Task 3: extrusion with twist and scale (handout §4).
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

PolygonSoup extrude(const Profile& p, const ExtrudeOptions& o) {
    // BEGIN SOLUTION
    validate_profile(p);
    if (o.steps < 1) throw std::invalid_argument("extrude: steps = " + std::to_string(o.steps) + " (at least 1)");
    if (!std::isfinite(o.direction.x) || !std::isfinite(o.direction.y) || !std::isfinite(o.direction.z) ||
        !std::isfinite(o.twist) || !std::isfinite(o.scale))
        throw std::invalid_argument("extrude: an option is not finite");
    if (!(o.direction.z > 0))
        throw std::invalid_argument("extrude: direction.z = " + std::to_string(o.direction.z) + " (must be > 0)");
    if (!(o.scale > 0)) throw std::invalid_argument("extrude: scale = " + std::to_string(o.scale) + " (must be > 0)");
    const double per_step = std::abs(o.twist) / o.steps;
    if (per_step >= std::numbers::pi / 2)
        throw std::invalid_argument("extrude: twist per step " + std::to_string(per_step) +
                                    " rad is a quarter turn or more (use more steps)");
    const std::vector<glm::dvec2> pts = profile_points(p);
    const auto n = static_cast<std::uint32_t>(pts.size());
    PolygonSoup m;
    for (int k = 0; k <= o.steps; ++k) {
        const double s = static_cast<double>(k) / o.steps;
        const double sc = 1 + s * (o.scale - 1), c = std::cos(s * o.twist), si = std::sin(s * o.twist);
        for (const glm::dvec2& q : pts)
            m.positions.push_back(glm::dvec3(sc * (c * q.x - si * q.y), sc * (si * q.x + c * q.y), 0.0) +
                                  s * o.direction);
    }
    // Side walls: for each loop edge a -> b (region on its left) and each step.
    std::uint32_t start = 0;
    auto walls = [&](std::size_t size) {
        const auto len = static_cast<std::uint32_t>(size);
        for (std::uint32_t i = 0; i < len; ++i) {
            const std::uint32_t a = start + i, b = start + (i + 1) % len;
            for (std::uint32_t k = 0; k < static_cast<std::uint32_t>(o.steps); ++k) {
                const std::uint32_t a0 = k * n + a, b0 = k * n + b, a1 = a0 + n, b1 = b0 + n;
                m.add_face({a0, b0, b1});
                m.add_face({a0, b1, a1});
            }
        }
        start += len;
    };
    walls(p.outer.size());
    for (const Loop& h : p.holes) walls(h.size());
    const std::uint32_t top = static_cast<std::uint32_t>(o.steps) * n;
    for (const auto& t : triangulate(p)) {
        m.add_face({t[0], t[2], t[1]});                    // bottom: facing -z
        m.add_face({top + t[0], top + t[1], top + t[2]});  // top: facing away
    }
    return m;
    // END SOLUTION
}

}  // namespace geolab::sweeps
