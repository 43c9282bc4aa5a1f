// Task 6: sweeping a profile along a path (handout §7).
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/memory.hpp"
#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

namespace {
// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.
void check_samples(const Path& path, const char* fn) {
    const std::size_t need = path.closed ? 3 : 2;
    if (path.points.size() < need)
        throw std::invalid_argument(std::string(fn) + ": the path has " + std::to_string(path.points.size()) +
                                    " samples (at least " + std::to_string(need) + ")");
}
// v resized to `count` elements, allocated once; a large array gets 2 MiB pages (lib memory.hpp: a speed hint
// only, 12.8M triangles then cost about 200 page faults instead of 90,000).
template <class T>
void allocate(std::vector<T>& v, std::size_t count) {
    v.reserve(count);
    prefer_huge_pages(v);
    v.resize(count);
}
// END SOLUTION
}  // namespace

PolygonSoup sweep(const Profile& p, const Path& path, const std::vector<Frame>& frames) {
    // BEGIN SOLUTION
    validate_profile(p);
    check_samples(path, "sweep");
    if (frames.size() != path.points.size())
        throw std::invalid_argument("sweep: " + std::to_string(frames.size()) + " frames for " +
                                    std::to_string(path.points.size()) + " samples");
    const std::vector<glm::dvec2> pts = profile_points(p);
    const auto n = static_cast<std::uint32_t>(pts.size());
    const auto ns = static_cast<std::uint32_t>(path.points.size());
    const std::uint32_t steps = path.closed ? ns : ns - 1;  // wall strips between consecutive samples
    std::vector<std::array<std::uint32_t, 3>> caps;
    if (!path.closed) caps = triangulate(p);
    // The sizes are known up front: every array is allocated once and written in place.
    const std::size_t n_faces = 2 * std::size_t(n) * steps + 2 * caps.size();
    PolygonSoup m;
    allocate(m.positions, std::size_t(n) * ns);
    allocate(m.indices, 3 * n_faces);
    allocate(m.offsets, n_faces + 1);
    for (std::uint32_t i = 0; i < ns; ++i) {
        const glm::dvec3 c = path.points[i], N = frames[i].N, B = frames[i].B;
        glm::dvec3* out = m.positions.data() + std::size_t(i) * n;
        for (std::uint32_t k = 0; k < n; ++k) out[k] = c + pts[k].x * N + pts[k].y * B;
    }
    std::uint32_t* tri = m.indices.data();
    const auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        tri[0] = a, tri[1] = b, tri[2] = c;
        tri += 3;
    };
    // Side walls: for each sample step, each loop edge a → b (region on its left) gives (a₀, b₀, b₁), (a₀, b₁, a₁).
    std::uint32_t start = 0;
    const auto walls = [&](std::size_t size) {
        const auto len = static_cast<std::uint32_t>(size);
        for (std::uint32_t i = 0; i < steps; ++i) {
            const std::uint32_t l0 = i * n, l1 = ((i + 1) % ns) * n;
            for (std::uint32_t k = 0; k < len; ++k) {
                const std::uint32_t a = start + k, b = start + (k + 1) % len;
                add(l0 + a, l0 + b, l1 + b);
                add(l0 + a, l1 + b, l1 + a);
            }
        }
        start += len;
    };
    walls(p.outer.size());
    for (const Loop& h : p.holes) walls(h.size());
    const std::uint32_t last = (ns - 1) * n;
    for (const auto& t : caps) {
        add(t[0], t[2], t[1]);                       // start cap, facing −T₀
        add(last + t[0], last + t[1], last + t[2]);  // end cap, facing +T
    }
    for (std::size_t f = 0; f <= n_faces; ++f) m.offsets[f] = static_cast<std::uint32_t>(3 * f);
    return m;
    // END SOLUTION
}

SweepCheck check_sweep(const Profile& p, const Path& path) {
    // BEGIN SOLUTION
    validate_profile(p);
    check_samples(path, "check_sweep");
    SweepCheck c;
    for (const glm::dvec2& q : profile_points(p)) c.profile_radius = std::max(c.profile_radius, glm::length(q));
    c.min_radius_of_curvature = std::numeric_limits<double>::infinity();
    const std::size_t n = path.points.size();
    for (std::size_t i = 0; i < n; ++i) {
        if (!path.closed && (i == 0 || i + 1 == n)) continue;
        const glm::dvec3 a = path.points[(i + n - 1) % n], b = path.points[i], d = path.points[(i + 1) % n];
        // R = |b − a| |d − b| |d − a| / (2 |(b − a) × (d − a)|); collinear samples: +∞ (or NaN), never the smallest
        const double cr = glm::length(glm::cross(b - a, d - a));
        const double R = glm::length(b - a) * glm::length(d - b) * glm::length(d - a) / (2 * cr);
        if (R < c.min_radius_of_curvature) {
            c.min_radius_of_curvature = R;
            c.at_sample = static_cast<std::uint32_t>(i);
        }
    }
    c.self_intersects = c.profile_radius >= c.min_radius_of_curvature;
    return c;
    // END SOLUTION
}

}  // namespace geolab::sweeps
