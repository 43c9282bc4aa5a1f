// Task 2: the triangle–box test (handout §3).
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "geolab/voxels.hpp"

namespace geolab::voxels {

// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.
namespace {

// True when some axis of the 13 separates the triangle (vertices relative to the box centre) from the open box of
// half-size h: a projection that only touches the box's projection separates too.
bool separated(const glm::dvec3 v[3], double h) {
    // the box's three face normals
    for (int d = 0; d < 3; ++d) {
        const double lo = std::min({v[0][d], v[1][d], v[2][d]}), hi = std::max({v[0][d], v[1][d], v[2][d]});
        if (lo >= h || hi <= -h) return true;
    }
    // the triangle's normal
    const glm::dvec3 e[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
    {
        const glm::dvec3 n = glm::cross(e[0], e[1]);
        const double p = glm::dot(n, v[0]);
        const double r = h * (std::abs(n.x) + std::abs(n.y) + std::abs(n.z));
        if (p >= r || p <= -r) return true;
    }
    // the nine cross products of the box's edges (the unit axes) with the triangle's edges
    for (int d = 0; d < 3; ++d) {
        for (const glm::dvec3& ed : e) {
            glm::dvec3 unit(0.0);
            unit[d] = 1.0;
            const glm::dvec3 a = glm::cross(unit, ed);
            if (a == glm::dvec3(0.0)) continue;  // the edge is parallel to the box edge: no axis
            const double p0 = glm::dot(a, v[0]), p1 = glm::dot(a, v[1]), p2 = glm::dot(a, v[2]);
            const double lo = std::min({p0, p1, p2}), hi = std::max({p0, p1, p2});
            const double r = h * (std::abs(a.x) + std::abs(a.y) + std::abs(a.z));
            if (lo >= r || hi <= -r) return true;
        }
    }
    return false;
}

}  // namespace
// END SOLUTION

bool triangle_overlaps_voxel(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, std::int64_t i,
                             std::int64_t j, std::int64_t k) {
    // BEGIN SOLUTION
    const glm::dvec3 n = glm::cross(b - a, c - a);
    if (n == glm::dvec3(0.0)) return false;  // zero area (exactly: the cross product's components are 0)
    const glm::dvec3 centre(double(i) + 0.5, double(j) + 0.5, double(k) + 0.5);
    glm::dvec3 v[3] = {a - centre, b - centre, c - centre};
    // A triangle in a voxel plane x = m (or y, z) moves half a voxel to the side its normal points away from:
    // there the open test is the in-plane test of the layer behind it.
    for (int d = 0; d < 3; ++d) {
        if (a[d] == b[d] && b[d] == c[d] && std::floor(a[d]) == a[d]) {
            const double shift = n[d] > 0 ? -0.5 : 0.5;
            for (glm::dvec3& p : v) p[d] += shift;
            break;
        }
    }
    return !separated(v, 0.5);
    // END SOLUTION
}

}  // namespace geolab::voxels
