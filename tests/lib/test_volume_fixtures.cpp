// Procedural volume meshes (geolab/volume_fixtures.hpp) and the radius ratio (geolab/tet_quality.hpp): every
// documented count and invariant, checked from the cell lists by brute force (faces as sorted vertex sets).
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <numbers>
#include <set>
#include <stdexcept>
#include <vector>

#include "geolab/tet_quality.hpp"
#include "geolab/volume_fixtures.hpp"

namespace {
using geolab::VolumeCell;
using geolab::VolumeMesh;
namespace vf = geolab::volume_fixtures;
using Face = std::vector<std::uint32_t>;

// The faces of cell c, counter-clockwise seen from outside it (the corner orders of volume_io.hpp).
std::vector<Face> cell_faces(const VolumeMesh& m, std::size_t c) {
    const auto v = m.cell(c);
    if (m.types[c] == VolumeCell::tetrahedron)
        return {{v[0], v[2], v[1]}, {v[0], v[1], v[3]}, {v[1], v[2], v[3]}, {v[2], v[0], v[3]}};
    REQUIRE(m.types[c] == VolumeCell::hexahedron);
    return {{v[0], v[3], v[2], v[1]}, {v[4], v[5], v[6], v[7]}, {v[0], v[1], v[5], v[4]},
            {v[1], v[2], v[6], v[5]}, {v[2], v[3], v[7], v[6]}, {v[3], v[0], v[4], v[7]}};
}

double tet_volume(const VolumeMesh& m, std::size_t c) {
    const auto v = m.cell(c);
    const auto& a = m.positions[v[0]];
    return glm::dot(m.positions[v[1]] - a, glm::cross(m.positions[v[2]] - a, m.positions[v[3]] - a)) / 6.0;
}

// The volume enclosed by a cell's outward faces (divergence theorem, fans).
double cell_volume(const VolumeMesh& m, std::size_t c) {
    double vol = 0;
    for (const Face& f : cell_faces(m, c))
        for (std::size_t i = 1; i + 1 < f.size(); ++i)
            vol += glm::dot(m.positions[f[0]], glm::cross(m.positions[f[i]], m.positions[f[i + 1]])) / 6.0;
    return vol;
}

struct FaceUse {
    std::vector<Face> cycles;  // as listed by each cell using the face
    std::vector<std::size_t> cells;
};

// Every face by its sorted vertex set.
std::map<Face, FaceUse> faces_of(const VolumeMesh& m) {
    std::map<Face, FaceUse> out;
    for (std::size_t c = 0; c < m.n_cells(); ++c)
        for (const Face& f : cell_faces(m, c)) {
            Face k = f;
            std::sort(k.begin(), k.end());
            out[k].cycles.push_back(f);
            out[k].cells.push_back(c);
        }
    return out;
}

// The cycle f read backwards equals g up to rotation.
bool opposite(Face f, const Face& g) {
    std::reverse(f.begin(), f.end());
    for (std::size_t r = 0; r < f.size(); ++r) {
        if (f == g) return true;
        std::rotate(f.begin(), f.begin() + 1, f.end());
    }
    return false;
}

struct Surface {
    std::size_t V = 0, E = 0, F = 0;
    long chi = 0;
    bool closed = true;  // every edge in exactly two of its faces
};

// The surface made of the given faces.
Surface surface_of(const std::vector<Face>& faces) {
    Surface s;
    std::set<std::uint32_t> vs;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (const Face& f : faces)
        for (std::size_t i = 0; i < f.size(); ++i) {
            vs.insert(f[i]);
            ++edges[{std::min(f[i], f[(i + 1) % f.size()]), std::max(f[i], f[(i + 1) % f.size()])}];
        }
    for (auto& [e, n] : edges) s.closed = s.closed && n == 2;
    s.V = vs.size(), s.E = edges.size(), s.F = faces.size();
    s.chi = long(s.V) - long(s.E) + long(s.F);
    return s;
}

// Conforming: a face is used by one or two cells, by two in opposite directions. Returns the boundary faces.
std::vector<Face> check_conforming(const VolumeMesh& m) {
    std::vector<Face> boundary;
    for (auto& [k, use] : faces_of(m)) {
        REQUIRE_MESSAGE(use.cells.size() <= 2, "a face is used by " << use.cells.size() << " cells");
        if (use.cells.size() == 2)
            REQUIRE_MESSAGE(opposite(use.cycles[0], use.cycles[1]), "cells "
                                                                        << use.cells[0] << " and " << use.cells[1]
                                                                        << " list their face in the same direction");
        else
            boundary.push_back(use.cycles[0]);
    }
    return boundary;
}
}  // namespace

TEST_CASE("volume fixtures: kuhn_cube is 6 positive tetrahedra of volume 1/6 filling the unit cube") {
    const VolumeMesh m = vf::kuhn_cube();
    geolab::check_volume_mesh(m);
    REQUIRE(m.n_vertices() == 8);
    REQUIRE(m.n_cells() == 6);
    for (int i = 0; i < 8; ++i) CHECK(m.positions[i] == glm::dvec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
    for (std::size_t c = 0; c < 6; ++c) {
        CHECK(m.types[c] == VolumeCell::tetrahedron);
        CHECK_MESSAGE(std::abs(tet_volume(m, c) - 1.0 / 6.0) < 1e-15, "tet " << c << " volume " << tet_volume(m, c));
        const auto v = m.cell(c);
        CHECK_MESSAGE((v[0] == 0 && v[3] == 7), "tet " << c << " is not around the diagonal 0-7");
    }
    const auto boundary = check_conforming(m);
    CHECK(boundary.size() == 12);
    CHECK(faces_of(m).size() == 18);  // 12 boundary + 6 interior
    const Surface s = surface_of(boundary);
    CHECK(s.closed);
    CHECK(s.chi == 2);
}

TEST_CASE("volume fixtures: tet_grid(n) and hex_grid(n) are conforming, positive, fill [0,1]^3, closed spheres") {
    for (int n : {1, 2, 3, 5}) {
        INFO("n = " << n);
        const VolumeMesh t = vf::tet_grid(n), h = vf::hex_grid(n);
        geolab::check_volume_mesh(t), geolab::check_volume_mesh(h);
        const std::size_t nv = std::size_t(n + 1) * (n + 1) * (n + 1);
        CHECK(t.n_vertices() == nv);
        CHECK(h.n_vertices() == nv);
        REQUIRE(t.n_cells() == std::size_t(6 * n * n * n));
        REQUIRE(h.n_cells() == std::size_t(n * n * n));
        // vertex (i, j, k) and the cells of cube (i, j, k) where documented
        const int i = n - 1, j = n / 2, k = 0;
        CHECK(t.positions[(k * (n + 1) + j) * (n + 1) + i] == glm::dvec3(i, j, k) / double(n));
        double vt = 0, vh = 0;
        for (std::size_t c = 0; c < t.n_cells(); ++c) {
            const double v = tet_volume(t, c);
            REQUIRE_MESSAGE(v > 0, "tet " << c << " is not positive: " << v);
            vt += v;
        }
        for (std::size_t c = 0; c < h.n_cells(); ++c) {
            REQUIRE_MESSAGE(std::abs(cell_volume(h, c) - 1.0 / (n * n * n)) < 1e-12, "hex " << c << " is not outward");
            vh += cell_volume(h, c);
        }
        CHECK(std::abs(vt - 1.0) < 1e-12);
        CHECK(std::abs(vh - 1.0) < 1e-12);
        // cube (i, j, k)'s tetrahedra and hexahedron contain the cube's centre region: their corners lie in the cube
        const std::size_t cube = std::size_t((k * n + j) * n + i);
        const glm::dvec3 lo = glm::dvec3(i, j, k) / double(n), hi = glm::dvec3(i + 1, j + 1, k + 1) / double(n);
        for (std::size_t c = 6 * cube; c < 6 * cube + 6; ++c)
            for (auto v : t.cell(c))
                CHECK((glm::all(glm::greaterThanEqual(t.positions[v], lo)) &&
                       glm::all(glm::lessThanEqual(t.positions[v], hi))));
        for (auto v : h.cell(cube))
            CHECK((glm::all(glm::greaterThanEqual(h.positions[v], lo)) &&
                   glm::all(glm::lessThanEqual(h.positions[v], hi))));
        const auto bt = check_conforming(t), bh = check_conforming(h);
        CHECK(bt.size() == std::size_t(12 * n * n));
        CHECK(bh.size() == std::size_t(6 * n * n));
        for (const auto* b : {&bt, &bh}) {
            const Surface s = surface_of(*b);
            CHECK(s.closed);
            CHECK(s.chi == 2);
        }
    }
    CHECK_THROWS_AS((void)vf::tet_grid(0), std::invalid_argument);
    CHECK_THROWS_AS((void)vf::hex_grid(257), std::invalid_argument);
}

TEST_CASE("volume fixtures: ball_with_torus is a ball (sphere χ 2) with a solid-torus region (interface χ 0)") {
    for (int n : {5, 6, 8, 10}) {
        INFO("n = " << n);
        const VolumeMesh m = vf::ball_with_torus(n);
        geolab::check_volume_mesh(m);
        REQUIRE(m.n_vertices() == std::size_t(n + 1) * (n + 1) * (n + 1));
        REQUIRE(m.n_cells() == std::size_t(6 * n * n * n));
        double volume = 0, min_volume = 1;
        std::size_t labelled = 0;
        for (std::size_t c = 0; c < m.n_cells(); ++c) {
            const double v = tet_volume(m, c);
            min_volume = std::min(min_volume, v);
            volume += v;
            REQUIRE((m.labels[c] == 0 || m.labels[c] == 1));
            labelled += m.labels[c] == 1;
        }
        CHECK_MESSAGE(min_volume > 0, "an inverted or flat tetrahedron: minimum volume " << min_volume);
        // inscribed polyhedron: below the ball's volume, and close to it
        const double ball = 4.0 / 3.0 * std::numbers::pi;
        CHECK_MESSAGE((volume < ball && volume > 0.75 * ball), "volume " << volume << " vs the ball's " << ball);
        const std::size_t ring_cubes = n == 5 ? 8 : n == 10 ? 128 : 24;  // see volume_fixtures.hpp
        CHECK(labelled == 6 * ring_cubes);
        for (const auto& p : m.positions) REQUIRE(glm::length(p) <= 1.0 + 1e-12);
        const auto boundary = check_conforming(m);
        const Surface outer = surface_of(boundary);
        CHECK(outer.closed);
        CHECK(outer.chi == 2);
        for (const Face& f : boundary)
            for (auto v : f)
                REQUIRE_MESSAGE(std::abs(glm::length(m.positions[v]) - 1.0) < 1e-12, "boundary vertex " << v);
        // the interface: faces with label 1 on one side and 0 on the other
        std::vector<Face> interface;
        for (auto& [k, use] : faces_of(m)) {
            if (use.cells.size() == 1) CHECK_MESSAGE(m.labels[use.cells[0]] == 0, "the torus touches the sphere");
            if (use.cells.size() == 2 && m.labels[use.cells[0]] != m.labels[use.cells[1]])
                interface.push_back(use.cycles[0]);
        }
        const Surface torus = surface_of(interface);
        CHECK(torus.closed);
        CHECK(torus.chi == 0);
        CHECK(torus.F > 0);
    }
    CHECK_THROWS_AS((void)vf::ball_with_torus(4), std::invalid_argument);
}

TEST_CASE("tet quality: the radius ratio is 1 for the regular tetrahedron, smaller for others, signed") {
    const glm::dvec3 a(1, 1, 1), b(1, -1, -1), c(-1, 1, -1), d(-1, -1, 1);
    const double reg = geolab::tet_radius_ratio(a, b, c, d);
    const double flipped = geolab::tet_radius_ratio(a, c, b, d);
    CHECK_MESSAGE((std::abs(std::abs(reg) - 1.0) < 1e-12), "regular: " << reg);
    CHECK(reg * flipped < 0);
    CHECK(std::abs(reg + flipped) < 1e-12);
    // the corner tetrahedron (0, e1, e2, e3): r = 1/(3 + √3), R = √3/2 → ρ = 3r/R = 6/(√3(3 + √3)) = 0.7320508...
    const double corner = geolab::tet_radius_ratio({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
    CHECK(std::abs(corner - 6.0 / (std::sqrt(3.0) * (3.0 + std::sqrt(3.0)))) < 1e-12);
    // scale and translation invariant
    CHECK(std::abs(geolab::tet_radius_ratio({5, 5, 5}, {5.001, 5, 5}, {5, 5.001, 5}, {5, 5, 5.001}) - corner) < 1e-9);
    // a sliver: four points near a square
    CHECK(std::abs(geolab::tet_radius_ratio({0, 0, 0}, {1, 0, 0}, {1, 1, 1e-3}, {0, 1, 0})) < 0.01);
    CHECK(geolab::tet_radius_ratio({0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}) == 0.0);
}
