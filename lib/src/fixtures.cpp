// Procedural fixtures. Face orders are chosen so that (b - a) × (c - a) points outward (counter-clockwise seen
// from outside); tests/lib/test_fixtures.cpp checks every documented invariant.
#include "geolab/fixtures.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace geolab::fixtures {
namespace {

void require(bool ok, const std::string& message) {
    if (!ok) throw std::invalid_argument(message);
}

// Adds the quad a b c d, or the triangles a b c and a c d (same orientation) when `triangulate`.
void add_quad(PolygonSoup& soup, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d, bool triangulate) {
    if (triangulate) {
        soup.add_face({a, b, c});
        soup.add_face({a, c, d});
    } else {
        soup.add_face({a, b, c, d});
    }
}

// Appends `part` to `soup`, shifting its vertex indices.
void append(PolygonSoup& soup, const PolygonSoup& part) {
    const auto base = static_cast<std::uint32_t>(soup.n_vertices());
    soup.positions.insert(soup.positions.end(), part.positions.begin(), part.positions.end());
    for (std::size_t f = 0; f < part.n_faces(); ++f) {
        std::vector<std::uint32_t> vs(part.face(f).begin(), part.face(f).end());
        for (auto& v : vs) v += base;
        soup.add_face(vs);
    }
}

// The icosahedron on the unit sphere (12 vertices, 20 outward triangles).
PolygonSoup icosahedron() {
    const double t = std::numbers::phi;
    PolygonSoup soup;
    soup.positions = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                      {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    for (auto& p : soup.positions) p = glm::normalize(p);
    const std::uint32_t faces[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                        {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                        {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                        {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (const auto& f : faces) soup.add_face({f[0], f[1], f[2]});
    return soup;
}

// One 1-to-4 split of every triangle; edge midpoints are shared and pushed onto the unit sphere.
PolygonSoup subdivide_on_sphere(const PolygonSoup& in) {
    PolygonSoup out;
    out.positions = in.positions;
    out.positions.reserve(in.n_vertices() + in.n_faces() * 3 / 2);
    out.indices.reserve(4 * in.indices.size());
    out.offsets.reserve(4 * in.n_faces() + 1);
    std::unordered_map<std::uint64_t, std::uint32_t> midpoint_of;  // key: (min, max) vertex pair
    midpoint_of.reserve(in.n_faces() * 3 / 2);
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
        const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
        auto [it, inserted] = midpoint_of.try_emplace(key, static_cast<std::uint32_t>(out.positions.size()));
        if (inserted) out.positions.push_back(glm::normalize(out.positions[a] + out.positions[b]));
        return it->second;
    };
    for (std::size_t f = 0; f < in.n_faces(); ++f) {
        auto t = in.face(f);
        const std::uint32_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
        out.add_face({t[0], ab, ca});
        out.add_face({t[1], bc, ab});
        out.add_face({t[2], ca, bc});
        out.add_face({ab, bc, ca});
    }
    return out;
}

}  // namespace

PolygonSoup tetrahedron() {
    PolygonSoup soup;
    soup.positions = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    for (auto& p : soup.positions) p /= std::sqrt(3.0);
    soup.add_face({0, 1, 2});  // opposite vertex 3, and so on
    soup.add_face({0, 3, 1});
    soup.add_face({0, 2, 3});
    soup.add_face({1, 3, 2});
    return soup;
}

PolygonSoup cube(bool triangulate) {
    PolygonSoup soup;
    for (int i = 0; i < 8; ++i)  // vertex i has x, y, z = ±1 from bits 0, 1, 2 of i
        soup.positions.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
    add_quad(soup, 0, 2, 3, 1, triangulate);  // -z
    add_quad(soup, 4, 5, 7, 6, triangulate);  // +z
    add_quad(soup, 0, 1, 5, 4, triangulate);  // -y
    add_quad(soup, 2, 6, 7, 3, triangulate);  // +y
    add_quad(soup, 0, 4, 6, 2, triangulate);  // -x
    add_quad(soup, 1, 3, 7, 5, triangulate);  // +x
    return soup;
}

PolygonSoup icosphere(int subdivisions) {
    require(subdivisions >= 0 && subdivisions <= 10, "icosphere: subdivisions must be in [0, 10]");
    PolygonSoup soup = icosahedron();
    for (int s = 0; s < subdivisions; ++s) soup = subdivide_on_sphere(soup);
    return soup;
}

PolygonSoup torus(int rings, int sides, double R, double r, bool triangulate) {
    require(rings >= 3 && sides >= 3, "torus: rings and sides must be at least 3");
    const double two_pi = 2 * std::numbers::pi;
    PolygonSoup soup;
    // vertex (i, j) at major angle u = 2πi/rings, minor angle v = 2πj/sides:
    // ((R + r cos v) cos u, (R + r cos v) sin u, r sin v)
    for (int i = 0; i < rings; ++i) {
        const double u = two_pi * i / rings;
        for (int j = 0; j < sides; ++j) {
            const double v = two_pi * j / sides;
            soup.positions.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                                        r * std::sin(v));
        }
    }
    auto id = [&](int i, int j) { return static_cast<std::uint32_t>((i % rings) * sides + (j % sides)); };
    // ∂p/∂u × ∂p/∂v points outward, so the quad goes +u then +v
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < sides; ++j)
            add_quad(soup, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1), triangulate);
    return soup;
}

PolygonSoup grid(int nx, int ny) {
    require(nx >= 1 && ny >= 1, "grid: nx and ny must be at least 1");
    PolygonSoup soup;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) soup.positions.emplace_back(double(i) / nx, double(j) / ny, 0.0);
    auto id = [&](int i, int j) { return static_cast<std::uint32_t>(j * (nx + 1) + i); };
    for (int j = 0; j < ny; ++j)  // counter-clockwise seen from +z
        for (int i = 0; i < nx; ++i) add_quad(soup, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1), true);
    return soup;
}

PolygonSoup two_components() {
    PolygonSoup soup = tetrahedron();
    PolygonSoup second = tetrahedron();
    for (auto& p : second.positions) p += glm::dvec3(3, 0, 0);
    append(soup, second);
    return soup;
}

PolygonSoup bowtie() {
    PolygonSoup soup;
    soup.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
    soup.add_face({0, 1, 2});
    soup.add_face({0, 3, 4});
    return soup;
}

PolygonSoup fan() {
    PolygonSoup soup;
    soup.positions = {{0, 0, 0}, {0, 0, 1}};  // the shared edge 0-1 along z
    for (int k = 0; k < 3; ++k) {
        const double a = 2 * std::numbers::pi * k / 3;
        soup.positions.emplace_back(std::cos(a), std::sin(a), 0.5);
    }
    soup.add_face({0, 1, 2});
    soup.add_face({1, 0, 3});
    soup.add_face({0, 1, 4});
    return soup;
}

PolygonSoup mobius(int segments, bool triangulate) {
    require(segments >= 5, "mobius: segments must be at least 5");
    const double half_width = 0.3;
    PolygonSoup soup;
    // segment i at angle u: the rung from side s = -1 (vertex 2i) to s = +1 (vertex 2i+1), turned by u/2:
    // ((1 + s w cos(u/2)) cos u, (1 + s w cos(u/2)) sin u, s w sin(u/2))
    for (int i = 0; i < segments; ++i) {
        const double u = 2 * std::numbers::pi * i / segments;
        for (double s : {-1.0, 1.0}) {
            const double radius = 1 + s * half_width * std::cos(u / 2);
            soup.positions.emplace_back(radius * std::cos(u), radius * std::sin(u), s * half_width * std::sin(u / 2));
        }
    }
    for (int i = 0; i < segments; ++i) {
        const auto lo = static_cast<std::uint32_t>(2 * i), hi = lo + 1;
        // after a full turn the rung has turned by π: segment 0's sides arrive swapped (the half twist)
        const bool last = i + 1 == segments;
        const std::uint32_t next_lo = last ? 1 : lo + 2, next_hi = last ? 0 : lo + 3;
        add_quad(soup, lo, next_lo, next_hi, hi, triangulate);
    }
    return soup;
}

PolygonSoup flip_face(PolygonSoup soup, std::size_t f) {
    require(f < soup.n_faces(), "flip_face: face " + std::to_string(f) + " out of range");
    std::reverse(soup.indices.begin() + soup.offsets[f], soup.indices.begin() + soup.offsets[f + 1]);
    return soup;
}

}  // namespace geolab::fixtures
