#pragma once
// Lab 06 test helpers: profiles and paths built by construction, and expected values computed independently of the
// reference: closed forms (Pappus, frusta, polyhedral solids of revolution), long double sums, point sampling, and
// the rotation-minimizing frame's ODE integrated by RK4 in long double. No helper calls a function you write (the
// given functions of given.cpp are the course's).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "geolab/grading/test.hpp"
#include "geolab/predicates.hpp"
#include "geolab/surface_checks.hpp"
#include "geolab/sweeps.hpp"

namespace lab06 {

using namespace geolab::sweeps;
using geolab::PolygonSoup;
using LD = long double;
constexpr double pi = std::numbers::pi;

inline std::string str(const glm::dvec3& v) {
    std::ostringstream s;
    s.precision(12);
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}
inline std::string str(const glm::dvec2& v) {
    std::ostringstream s;
    s.precision(12);
    s << "(" << v.x << ", " << v.y << ")";
    return s.str();
}
inline std::string str(const Loop& l) {
    std::string s = "[";
    for (std::size_t i = 0; i < l.size() && i < 12; ++i) s += (i ? " " : "") + str(l[i]);
    if (l.size() > 12) s += " ... (" + std::to_string(l.size()) + " points)";
    return s + "]";
}
inline std::string str(const Profile& p) {
    std::string s = "outer " + str(p.outer);
    for (std::size_t h = 0; h < p.holes.size(); ++h) s += ", hole " + std::to_string(h) + " " + str(p.holes[h]);
    return s;
}
// |x - y| <= tol * max(scale, |y|)
inline bool close(double x, double y, double tol, double scale = 1.0) {
    return std::abs(x - y) <= tol * std::max(scale, std::abs(y));
}

struct Rng {
    std::mt19937_64 gen;
    explicit Rng(std::uint64_t seed) : gen(seed) {}
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(gen); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(gen); }
};

inline Loop reversed(Loop l) {
    std::reverse(l.begin(), l.end());
    return l;
}
inline Loop shifted(Loop l, glm::dvec2 d) {
    for (auto& q : l) q += d;
    return l;
}
// The 4×4 square with a centred 2×2 hole, its centre at c (the profile).
inline Profile square_with_hole(glm::dvec2 c = {0, 0}) {
    return {rectangle_loop(c.x - 2, c.y - 2, c.x + 2, c.y + 2), {reversed(rectangle_loop(c.x - 1, c.y - 1, c.x + 1, c.y + 1))}};
}
// A star-shaped polygon about c: n points at angles 2πi/n with radii in [r0, r1] (counter-clockwise).
inline Loop star(Rng& rng, int n, double r0, double r1, glm::dvec2 c = {0, 0}) {
    Loop l;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * pi * i / n, r = rng.uniform(r0, r1);
        l.push_back(c + r * glm::dvec2(std::cos(a), std::sin(a)));
    }
    return l;
}
// A star-shaped outer loop (radii in [2, 3]) with up to k small clockwise holes (polygons of radius ≤ 0.3) whose
// centres lie within 1.5 of the origin and at least 0.8 apart. With holes the outer loop gets at least 8 points, so
// that it holds the disk of radius 2 cos(π/8) > 1.8 where the holes are.
inline Profile star_with_holes(Rng& rng, int n, int k) {
    Profile p{star(rng, k > 0 ? std::max(n, 8) : n, 2.0, 3.0), {}};
    std::vector<glm::dvec2> centres;
    for (int tries = 0; tries < 200 && static_cast<int>(centres.size()) < k; ++tries) {
        const glm::dvec2 c{rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5)};
        if (glm::length(c) > 1.5) continue;
        bool ok = true;
        for (auto d : centres) ok = ok && glm::length(c - d) >= 0.8;
        if (!ok) continue;
        centres.push_back(c);
        p.holes.push_back(reversed(star(rng, rng.integer(3, 7), 0.15, 0.3, c)));
    }
    return p;
}

// The loop started at its k-th point (the same loop: the start is free).
inline Loop rotated(Loop l, std::size_t k) {
    std::rotate(l.begin(), l.begin() + static_cast<std::ptrdiff_t>(k % l.size()), l.end());
    return l;
}
// The profile with every loop started at a random point.
inline Profile rotated_loops(Rng& rng, Profile p) {
    p.outer = rotated(p.outer, std::size_t(rng.integer(0, int(p.outer.size()) - 1)));
    for (auto& h : p.holes) h = rotated(h, std::size_t(rng.integer(0, int(h.size()) - 1)));
    return p;
}
// A loop with `extra` points inserted at random places along its edges (collinear points; integer coordinates stay
// integers when the edge's length allows).
inline Loop with_edge_points(Rng& rng, const Loop& l, int extra) {
    Loop out;
    for (std::size_t i = 0; i < l.size(); ++i) {
        const glm::dvec2 a = l[i], b = l[(i + 1) % l.size()];
        out.push_back(a);
        const int steps = int(std::max(std::abs(b.x - a.x), std::abs(b.y - a.y)));
        if (extra > 0 && steps >= 2 && rng.integer(0, 1)) {
            const int k = rng.integer(1, steps - 1);
            out.push_back(a + (b - a) * (double(k) / steps));
            --extra;
        }
    }
    return out;
}
// A profile on the integer grid, valid by construction, full of ties and collinear points: the outer loop is a
// skyline over `cols` columns of width 4 (bottom y = 0, column c of height 4·hᶜ), with points added along its edges;
// holes sit in 4×4 cells under the skyline, each a shape inside [4c + 1, 4c + 3] × [4r + 1, 4r + 3] (square, square
// with edge points, diamond, triangle, L, or a thin bar), clockwise; cells side by side give holes with equal
// rightmost x and vertices level with each other and with the outer loop's. Every loop starts at a random point.
inline Profile grid_profile(Rng& rng, int cols, int max_height, int max_holes) {
    std::vector<int> h(static_cast<std::size_t>(cols));
    for (auto& v : h) v = rng.integer(1, max_height);
    Loop outer{{0, 0}, {4.0 * cols, 0}};
    for (int c = cols - 1; c >= 0; --c) {
        const double x1 = 4.0 * (c + 1), x0 = 4.0 * c, y = 4.0 * h[std::size_t(c)];
        if (outer.back() != glm::dvec2(x1, y)) {
            if (outer.back().x != x1) outer.push_back({x1, outer.back().y});
            outer.push_back({x1, y});
        }
        outer.push_back({x0, y});
    }
    // the loop ends at (0, 4·h₀) and joins (0, 0); drop straight corners made by equal neighbouring heights
    Loop clean;
    for (std::size_t i = 0; i < outer.size(); ++i) {
        const glm::dvec2 a = outer[(i + outer.size() - 1) % outer.size()], b = outer[i], c = outer[(i + 1) % outer.size()];
        if (b == a) continue;
        if (geolab::orient2d(a, b, c) == 0 && glm::dot(b - a, c - b) > 0 && rng.integer(0, 2) > 0) continue;
        clean.push_back(b);
    }
    Profile p{with_edge_points(rng, clean, rng.integer(0, 6)), {}};
    std::vector<glm::ivec2> cells;
    for (int c = 0; c < cols; ++c)
        for (int r = 0; r < h[std::size_t(c)]; ++r) cells.push_back({c, r});
    std::shuffle(cells.begin(), cells.end(), rng.gen);
    const int k = std::min<int>(max_holes, int(cells.size()));
    for (int i = 0; i < k; ++i) {
        const glm::dvec2 o{4.0 * cells[std::size_t(i)].x + 1, 4.0 * cells[std::size_t(i)].y + 1};  // the cell's [o, o + 2]²
        Loop s;
        switch (rng.integer(0, 5)) {
            case 0: s = {{0, 0}, {2, 0}, {2, 2}, {0, 2}}; break;
            case 1: s = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}}; break;
            case 2: s = {{1, 0}, {2, 1}, {1, 2}, {0, 1}}; break;
            case 3: s = {{0, 0}, {2, 1}, {0, 2}}; break;
            case 4: s = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}; break;
            default: s = {{0, 1}, {2, 1}, {2, 1.5}, {0, 1.5}}; break;
        }
        p.holes.push_back(reversed(shifted(s, o)));
    }
    return rotated_loops(rng, p);
}

// Everything wrong with a triangulation of p (empty when it is right). Exact: each triangle counter-clockwise
// (orient2d > 0), each loop edge a→b (region on its left) used by exactly one triangle as a→b and by none as b→a,
// every other directed edge used once and its reverse once. Then the triangles cover the region exactly once
// and nothing else (each point's count of triangles is the loops' winding number about it), whatever the choice
// of bridges and ears. Also the count n + 2h − 2.
inline std::string triangulation_problem(const Profile& p, const std::vector<std::array<std::uint32_t, 3>>& t) {
    const std::vector<glm::dvec2> pts = profile_points(p);
    std::ostringstream why;
    const std::size_t want = pts.size() + 2 * p.holes.size() - 2;
    if (t.size() != want)
        why << " expected " << want << " triangles (n + 2h − 2 with n = " << pts.size() << ", h = " << p.holes.size()
            << "), got " << t.size() << ";";
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> used;
    for (std::size_t k = 0; k < t.size(); ++k) {
        const auto& tr = t[k];
        if (tr[0] >= pts.size() || tr[1] >= pts.size() || tr[2] >= pts.size()) {
            why << " triangle " << k << " has an index >= " << pts.size() << " points;";
            return why.str();
        }
        if (geolab::orient2d(pts[tr[0]], pts[tr[1]], pts[tr[2]]) <= 0)
            why << " triangle " << k << " (" << tr[0] << ", " << tr[1] << ", " << tr[2] << ") "
                << str(pts[tr[0]]) << " " << str(pts[tr[1]]) << " " << str(pts[tr[2]])
                << " is not counter-clockwise (or has zero area);";
        for (int e = 0; e < 3; ++e) ++used[{tr[std::size_t(e)], tr[std::size_t((e + 1) % 3)]}];
    }
    std::map<std::pair<std::uint32_t, std::uint32_t>, bool> loop_edge;
    std::uint32_t start = 0;
    for (std::size_t l = 0; l <= p.holes.size(); ++l) {
        const auto len = std::uint32_t(l == 0 ? p.outer.size() : p.holes[l - 1].size());
        for (std::uint32_t i = 0; i < len; ++i) loop_edge[{start + i, start + (i + 1) % len}] = true;
        start += len;
    }
    int reported = 0;
    for (const auto& [e, on] : loop_edge) {
        const int fwd = used.count(e) ? used[e] : 0, back = used.count({e.second, e.first}) ? used[{e.second, e.first}] : 0;
        if ((fwd != 1 || back != 0) && reported++ < 3)
            why << " the loop edge " << e.first << "→" << e.second << " " << str(pts[e.first]) << " " << str(pts[e.second])
                << " is used " << fwd << " times as it runs (expected 1) and " << back << " times reversed (expected 0);";
    }
    for (const auto& [e, n] : used) {
        if (loop_edge.count(e) || loop_edge.count({e.second, e.first})) continue;
        const auto r = used.find({e.second, e.first});
        if ((n != 1 || r == used.end() || r->second != 1) && reported++ < 6)
            why << " the inner edge " << e.first << "→" << e.second << " " << str(pts[e.first]) << " " << str(pts[e.second])
                << " is used " << n << " times and reversed " << (r == used.end() ? 0 : r->second)
                << " times (a diagonal is shared by exactly two triangles, once each way);";
    }
    return why.str();
}

// Shoelace in long double.
inline LD area_ld(const Loop& l) {
    LD s = 0;
    for (std::size_t i = 0; i < l.size(); ++i) {
        const auto a = l[i], b = l[(i + 1) % l.size()];
        s += (LD)a.x * b.y - (LD)b.x * a.y;
    }
    return s / 2;
}
inline LD region_area(const Profile& p) {
    LD s = area_ld(p.outer);
    for (const auto& h : p.holes) s += area_ld(h);  // holes are clockwise: negative
    return s;
}
// ∫∫ x dA over the region (long double).
inline LD region_moment_x(const Profile& p) {
    auto m = [](const Loop& l) {
        LD s = 0;
        for (std::size_t i = 0; i < l.size(); ++i) {
            const auto a = l[i], b = l[(i + 1) % l.size()];
            s += ((LD)a.x + b.x) * ((LD)a.x * b.y - (LD)b.x * a.y);
        }
        return s / 6;
    };
    LD s = m(p.outer);
    for (const auto& h : p.holes) s += m(h);
    return s;
}
// Crossing-number point-in-polygon (the point must not lie on the loop).
inline bool in_loop(const Loop& l, glm::dvec2 q) {
    bool in = false;
    for (std::size_t i = 0, j = l.size() - 1; i < l.size(); j = i++) {
        const auto a = l[i], b = l[j];
        if ((a.y > q.y) != (b.y > q.y) && q.x < (b.x - a.x) * (q.y - a.y) / (b.y - a.y) + a.x) in = !in;
    }
    return in;
}
inline bool in_region(const Profile& p, glm::dvec2 q) {
    if (!in_loop(p.outer, q)) return false;
    for (const auto& h : p.holes)
        if (in_loop(h, q)) return false;
    return true;
}
inline double cross2(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Volume and area of a mesh, in long double (fan triangulation of polygons), about the first vertex.
inline LD volume_ld(const PolygonSoup& m) {
    if (m.positions.empty()) return 0;
    const glm::dvec3 o = m.positions[0];
    LD v = 0;
    for (std::size_t f = 0; f < m.n_faces(); ++f) {
        const auto fc = m.face(f);
        for (std::size_t i = 1; i + 1 < fc.size(); ++i) {
            const glm::dvec3 a = m.positions[fc[0]] - o, b = m.positions[fc[i]] - o, c = m.positions[fc[i + 1]] - o;
            v += (LD)a.x * ((LD)b.y * c.z - (LD)b.z * c.y) - (LD)a.y * ((LD)b.x * c.z - (LD)b.z * c.x) +
                 (LD)a.z * ((LD)b.x * c.y - (LD)b.y * c.x);
        }
    }
    return v / 6;
}
inline glm::dvec3 tri_normal(const PolygonSoup& m, std::size_t f) {
    const auto fc = m.face(f);
    return glm::cross(m.positions[fc[1]] - m.positions[fc[0]], m.positions[fc[2]] - m.positions[fc[0]]);
}

// A closed, consistently oriented, self-intersection-free 2-manifold with the given χ and component count.
inline std::string surface_problem(const PolygonSoup& m, long chi, std::size_t components, bool self_x = true) {
    geolab::CheckOptions o;
    o.self_intersections = self_x;
    const geolab::SurfaceCheck c = geolab::check_surface(m, o);
    std::string why;
    if (c.boundary_edges) why += " boundary edges (holes in the surface; a seam not shared?);";
    if (c.non_manifold_edges || c.non_manifold_vertices) why += " non-manifold edges or vertices;";
    if (c.misoriented_edges) why += " misoriented edges (a face, e.g. a cap, wound the wrong way);";
    if (c.repeated_index_faces || c.zero_area_faces) why += " degenerate faces;";
    if (c.coincident_vertices) why += " coincident vertices (a duplicated seam or pole?);";
    if (self_x && c.self_intersecting_pairs()) why += " self-intersecting face pairs;";
    if (c.euler_characteristic != chi) why += " χ " + std::to_string(c.euler_characteristic) + " instead of " + std::to_string(chi) + ";";
    if (c.components != components)
        why += " " + std::to_string(c.components) + " components instead of " + std::to_string(components) + ";";
    return why.empty() ? "" : why + " [" + c.summary() + "]";
}

// ---- the rotation-minimizing frame as an ODE: r' = −(r · T') T along a parametric curve, RK4 in long double ----
struct V3L {
    LD x = 0, y = 0, z = 0;
};
inline V3L operator+(V3L a, V3L b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3L operator*(LD s, V3L a) { return {s * a.x, s * a.y, s * a.z}; }
inline LD dot(V3L a, V3L b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V3L cross(V3L a, V3L b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
// c'(t) and c''(t) of a curve.
using Deriv = std::function<void(LD t, V3L& d1, V3L& d2)>;
inline V3L unit_tangent(const Deriv& c, LD t) {
    V3L d1, d2;
    c(t, d1, d2);
    return (1 / std::sqrt(dot(d1, d1))) * d1;
}
// The normal carried from r0 at t0 to t1 without rotation about T, in `steps` RK4 steps.
inline V3L rmf_ode(const Deriv& c, LD t0, LD t1, V3L r0, int steps) {
    auto f = [&](LD t, V3L r) {
        V3L d1, d2;
        c(t, d1, d2);
        const LD s = std::sqrt(dot(d1, d1));
        const V3L T = (1 / s) * d1;
        const V3L Tp = (1 / s) * (d2 + (-dot(d2, T)) * T);  // dT/dt
        return (-dot(r, Tp)) * T;
    };
    const LD h = (t1 - t0) / steps;
    V3L r = r0;
    for (int i = 0; i < steps; ++i) {
        const LD t = t0 + i * h;
        const V3L k1 = f(t, r), k2 = f(t + h / 2, r + (h / 2) * k1), k3 = f(t + h / 2, r + (h / 2) * k2),
                  k4 = f(t + h, r + h * k3);
        r = r + (h / 6) * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    return r;
}
inline Deriv trefoil_deriv(LD scale = 1) {
    return [scale](LD t, V3L& d1, V3L& d2) {
        d1 = scale * V3L{std::cos(t) + 4 * std::cos(2 * t), -std::sin(t) + 4 * std::sin(2 * t), -3 * std::cos(3 * t)};
        d2 = scale * V3L{-std::sin(t) - 8 * std::sin(2 * t), -std::cos(t) + 8 * std::cos(2 * t), 9 * std::sin(3 * t)};
    };
}
inline glm::dvec3 to_glm(V3L v) { return {double(v.x), double(v.y), double(v.z)}; }
inline V3L to_ld(glm::dvec3 v) { return {v.x, v.y, v.z}; }

// The signed angle from a to b about the unit axis t.
inline double angle_about(glm::dvec3 a, glm::dvec3 b, glm::dvec3 t) {
    return std::atan2(glm::dot(glm::cross(a, b), t), glm::dot(a, b));
}
inline double wrap(double a) {  // to (−π, π]
    while (a <= -pi) a += 2 * pi;
    while (a > pi) a -= 2 * pi;
    return a;
}

// One double reflection step, written here from Wang et al. (2008) (for checks of the closing step).
inline glm::dvec3 reflect_step(glm::dvec3 x0, glm::dvec3 t0, glm::dvec3 r0, glm::dvec3 x1, glm::dvec3 t1) {
    const glm::dvec3 v1 = x1 - x0;
    const double c1 = glm::dot(v1, v1);
    const glm::dvec3 rl = r0 - (2 / c1) * glm::dot(v1, r0) * v1, tl = t0 - (2 / c1) * glm::dot(v1, t0) * v1;
    const glm::dvec3 v2 = t1 - tl;
    const double c2 = glm::dot(v2, v2);
    return c2 == 0 ? rl : rl - (2 / c2) * glm::dot(v2, rl) * v2;
}

// Rotation-minimizing frames made here, for the sweep tests (Task 6 must not depend on your Task 5): double
// reflection from N₀ = initial_normal made orthogonal to T₀; a closed path's closing angle is then spread along the
// arc length, frame i turned about Tᵢ by −mismatch·sᵢ/L, as the contract of rotation_minimizing_frames says.
inline std::vector<Frame> rmf_frames(const Path& p, glm::dvec3 initial_normal) {
    const std::size_t n = p.points.size();
    std::vector<Frame> f(n);
    glm::dvec3 r = initial_normal - glm::dot(initial_normal, p.tangents[0]) * p.tangents[0];
    r = glm::normalize(r);
    for (std::size_t i = 0; i < n; ++i) {
        if (i > 0) r = glm::normalize(reflect_step(p.points[i - 1], p.tangents[i - 1], r, p.points[i], p.tangents[i]));
        f[i] = {p.tangents[i], r, glm::cross(p.tangents[i], r)};
    }
    if (!p.closed) return f;
    const glm::dvec3 back = reflect_step(p.points[n - 1], p.tangents[n - 1], f[n - 1].N, p.points[0], p.tangents[0]);
    const double mismatch = angle_about(f[0].N, back, p.tangents[0]);
    std::vector<double> s(n, 0.0);
    for (std::size_t i = 1; i < n; ++i) s[i] = s[i - 1] + glm::length(p.points[i] - p.points[i - 1]);
    const double L = s[n - 1] + glm::length(p.points[0] - p.points[n - 1]);
    for (std::size_t i = 0; i < n; ++i) {
        const double a = -mismatch * s[i] / L;
        const glm::dvec3 N = std::cos(a) * f[i].N + std::sin(a) * f[i].B;
        f[i] = {f[i].T, N, glm::cross(f[i].T, N)};
    }
    return f;
}

// A frame's problems: not orthonormal or not right-handed (tolerance tol).
inline std::string frame_problem(const Frame& f, double tol = 1e-9) {
    std::string w;
    if (std::abs(glm::length(f.T) - 1) > tol || std::abs(glm::length(f.N) - 1) > tol || std::abs(glm::length(f.B) - 1) > tol)
        w += " not unit;";
    if (std::abs(glm::dot(f.T, f.N)) > tol || std::abs(glm::dot(f.T, f.B)) > tol || std::abs(glm::dot(f.N, f.B)) > tol)
        w += " not orthogonal;";
    if (glm::length(glm::cross(f.T, f.N) - f.B) > tol) w += " B ≠ T × N;";
    return w.empty() ? "" : w + " T " + str(f.T) + " N " + str(f.N) + " B " + str(f.B);
}

// A closed random smooth curve c(t) = Σ aₖ cos(k t) + bₖ sin(k t), k = 1..3, with its derivatives.
struct Fourier {
    glm::dvec3 a[3], b[3];
    explicit Fourier(Rng& rng) {
        for (int k = 0; k < 3; ++k) {
            a[k] = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
            b[k] = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
            if (k == 0) a[k] *= 3, b[k] *= 3;  // keep the speed away from zero most of the time
        }
    }
    V3L d(LD t, int order) const {
        V3L s;
        for (int k = 1; k <= 3; ++k) {
            const LD c = std::cos(k * t), sn = std::sin(k * t);
            const LD kk = order == 0 ? 1 : order == 1 ? k : (LD)k * k;
            V3L A = to_ld(a[k - 1]), B = to_ld(b[k - 1]);
            if (order == 0) s = s + (c * A + sn * B);
            else if (order == 1) s = s + kk * ((-sn) * A + c * B);
            else s = s + kk * ((-c) * A + (-sn) * B);
        }
        return s;
    }
    Deriv deriv() const {
        return [this](LD t, V3L& d1, V3L& d2) { d1 = d(t, 1), d2 = d(t, 2); };
    }
    // The point (order 0) or a derivative in double: the inputs the tests pass are computed in double only, so that
    // the program that runs your code and the judge build bit-identical inputs.
    glm::dvec3 dd(double t, int order) const {
        glm::dvec3 s(0.0);
        for (int k = 1; k <= 3; ++k) {
            const double c = std::cos(k * t), sn = std::sin(k * t);
            if (order == 0) s += c * a[k - 1] + sn * b[k - 1];
            else s += double(k) * (-sn * a[k - 1] + c * b[k - 1]);
        }
        return s;
    }
    // n samples over [0, 2π) (closed) or [0, π] (open), with exact unit tangents.
    Path path(int n, bool closed) const {
        Path p;
        p.closed = closed;
        for (int i = 0; i < n; ++i) {
            const double t = closed ? 2 * pi * i / n : pi * i / (n - 1);
            p.points.push_back(dd(t, 0));
            p.tangents.push_back(glm::normalize(dd(t, 1)));
        }
        return p;
    }
    double min_speed() const {
        double m = 1e300;
        for (int i = 0; i < 2000; ++i) m = std::min(m, glm::length(dd(2 * pi * i / 2000, 1)));
        return m;
    }
};

}  // namespace lab06
