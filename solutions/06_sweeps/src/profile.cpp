// Task 1: profiles (handout §2).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/predicates.hpp"
#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

double signed_area(const Loop& loop) {
    // BEGIN SOLUTION
    const std::size_t n = loop.size();
    double s = 0;  // fewer than 3 points: the terms cancel exactly, s = 0
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2& a = loop[i];
        const glm::dvec2& b = loop[(i + 1) % n];
        s += a.x * b.y - b.x * a.y;
    }
    return 0.5 * s;
    // END SOLUTION
}

namespace {
// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.
// Whether c lies on the closed segment [a, b], given that a, b, c are collinear.
bool on_segment(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
           c.y <= std::max(a.y, b.y);
}
// Whether the closed segments [a, b] and [c, d] have a point in common (exact): on one line, when their extents
// overlap; else when neither segment lies strictly on one side of the other's line.
bool segments_meet(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, const glm::dvec2& d) {
    const int o1 = orient2d(a, b, c), o2 = orient2d(a, b, d);
    if (o1 == 0 && o2 == 0) return on_segment(a, b, c) || on_segment(a, b, d) || on_segment(c, d, a) || on_segment(c, d, b);
    return o1 * o2 <= 0 && orient2d(c, d, a) * orient2d(c, d, b) <= 0;
}
// Crossing-number test; p must not lie on the loop.
bool inside(const Loop& loop, const glm::dvec2& p) {
    bool in = false;
    for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
        const glm::dvec2 &a = loop[i], &b = loop[j];
        if ((a.y > p.y) != (b.y > p.y)) {
            const int o = orient2d(a, b, p);
            // p left of the upward edge counts as a crossing to the right
            if ((b.y > a.y) ? o > 0 : o < 0) in = !in;
        }
    }
    return in;
}
std::string loop_name(int k) { return k < 0 ? "outer loop" : "hole " + std::to_string(k); }

void check_loop(const Loop& l, int k) {
    const std::string name = "validate_profile: " + loop_name(k);
    const std::size_t n = l.size();
    if (n < 3) throw std::invalid_argument(name + " has " + std::to_string(n) + " vertices (at least 3)");
    for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(l[i].x) || !std::isfinite(l[i].y))
            throw std::invalid_argument(name + ": vertex " + std::to_string(i) + " is not finite");
        if (l[i] == l[(i + 1) % n])
            throw std::invalid_argument(name + ": vertices " + std::to_string(i) + " and " +
                                        std::to_string((i + 1) % n) + " are equal");
    }
    // Every two edges that are not neighbours (an edge that folds back onto its neighbour meets another edge too).
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1) continue;  // neighbours through the wrap
            if (segments_meet(l[i], l[(i + 1) % n], l[j], l[(j + 1) % n]))
                throw std::invalid_argument(name + " intersects itself: edges " + std::to_string(i) + " and " +
                                            std::to_string(j) + " meet");
        }
    const double area = signed_area(l);
    if (area == 0) throw std::invalid_argument(name + " has zero area");
    if ((k < 0) != (area > 0))
        throw std::invalid_argument(name + " has the wrong orientation (signed area " + std::to_string(area) +
                                    "; the outer loop must be counter-clockwise, a hole clockwise)");
}
bool loops_meet(const Loop& p, const Loop& q) {
    for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t j = 0; j < q.size(); ++j)
            if (segments_meet(p[i], p[(i + 1) % p.size()], q[j], q[(j + 1) % q.size()])) return true;
    return false;
}
// END SOLUTION
}  // namespace

void validate_profile(const Profile& p) {
    // BEGIN SOLUTION
    check_loop(p.outer, -1);
    for (std::size_t h = 0; h < p.holes.size(); ++h) check_loop(p.holes[h], static_cast<int>(h));
    for (std::size_t h = 0; h < p.holes.size(); ++h) {
        const std::string name = "validate_profile: hole " + std::to_string(h);
        if (loops_meet(p.outer, p.holes[h])) throw std::invalid_argument(name + " touches or crosses the outer loop");
        if (!inside(p.outer, p.holes[h][0])) throw std::invalid_argument(name + " is not inside the outer loop");
        for (std::size_t g = 0; g < h; ++g) {
            if (loops_meet(p.holes[g], p.holes[h]))
                throw std::invalid_argument(name + " touches or crosses hole " + std::to_string(g));
            if (inside(p.holes[g], p.holes[h][0]) || inside(p.holes[h], p.holes[g][0]))
                throw std::invalid_argument(name + " and hole " + std::to_string(g) + " are nested");
        }
    }
    // END SOLUTION
}

}  // namespace geolab::sweeps
