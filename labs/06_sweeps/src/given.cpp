// Given code of lab 06 (read it; do not change it): profile points, simple loops and paths.
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

std::vector<glm::dvec2> profile_points(const Profile& p) {
    std::vector<glm::dvec2> pts(p.outer);
    for (const Loop& h : p.holes) pts.insert(pts.end(), h.begin(), h.end());
    return pts;
}

Loop rectangle_loop(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

Loop circle_loop(glm::dvec2 c, double r, int n) {
    if (n < 3) throw std::invalid_argument("circle_loop: n = " + std::to_string(n) + " (at least 3 points)");
    Loop l(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        const double a = 2 * std::numbers::pi * i / n;
        l[static_cast<std::size_t>(i)] = c + r * glm::dvec2(std::cos(a), std::sin(a));
    }
    return l;
}

Path helix_path(double r, double h, double turns, int n) {
    if (n < 2) throw std::invalid_argument("helix_path: n = " + std::to_string(n) + " (at least 2 samples)");
    Path p;
    for (int i = 0; i < n; ++i) {
        const double t = i * turns * 2 * std::numbers::pi / (n - 1);
        p.points.push_back({r * std::cos(t), r * std::sin(t), h * t});
        p.tangents.push_back(glm::normalize(glm::dvec3(-r * std::sin(t), r * std::cos(t), h)));
    }
    return p;
}

Path trefoil_path(int n, double scale) {
    if (n < 3) throw std::invalid_argument("trefoil_path: n = " + std::to_string(n) + " (at least 3 samples)");
    Path p;
    p.closed = true;
    p.points.reserve(static_cast<std::size_t>(n));
    p.tangents.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        const double t = 2 * std::numbers::pi * i / n;
        p.points.push_back(scale * glm::dvec3(std::sin(t) + 2 * std::sin(2 * t), std::cos(t) - 2 * std::cos(2 * t),
                                              -std::sin(3 * t)));
        p.tangents.push_back(glm::normalize(glm::dvec3(std::cos(t) + 4 * std::cos(2 * t),
                                                       -std::sin(t) + 4 * std::sin(2 * t), -3 * std::cos(3 * t))));
    }
    return p;
}

Path polyline_path(const std::vector<glm::dvec3>& points, bool closed) {
    const std::size_t n = points.size();
    if (n < 2) throw std::invalid_argument("polyline_path: " + std::to_string(n) + " points (at least 2)");
    for (std::size_t i = 0; i + (closed ? 0 : 1) < n; ++i)
        if (points[i] == points[(i + 1) % n])
            throw std::invalid_argument("polyline_path: points " + std::to_string(i) + " and " +
                                        std::to_string((i + 1) % n) + " coincide");
    Path p{points, {}, closed};
    for (std::size_t i = 0; i < n; ++i) {
        const bool first = i == 0 && !closed, last = i + 1 == n && !closed;
        const glm::dvec3 a = first ? points[i] : points[(i + n - 1) % n];
        const glm::dvec3 b = last ? points[i] : points[(i + 1) % n];
        const glm::dvec3 d = b - a;
        if (glm::length(d) == 0)
            throw std::invalid_argument("polyline_path: no tangent at point " + std::to_string(i) +
                                        " (its neighbours coincide)");
        p.tangents.push_back(glm::normalize(d));
    }
    return p;
}

}  // namespace geolab::sweeps
