// Tests of geolab::fixtures: every documented count and invariant (V, E, F, χ, closedness, orientation,
// bounding box) is checked from the soup itself.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <numbers>
#include <queue>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "geolab/fixtures.hpp"

namespace {

using geolab::PolygonSoup;
namespace fx = geolab::fixtures;

// How often an undirected edge {a, b} (a < b) is used as a→b and as b→a.
struct EdgeUse {
    int forward = 0;
    int backward = 0;
    int total() const { return forward + backward; }
};

std::map<std::pair<std::uint32_t, std::uint32_t>, EdgeUse> edge_uses(const PolygonSoup& soup) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, EdgeUse> uses;
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        auto vs = soup.face(f);
        for (std::size_t k = 0; k < vs.size(); ++k) {
            std::uint32_t a = vs[k], b = vs[(k + 1) % vs.size()];
            auto& use = uses[{std::min(a, b), std::max(a, b)}];
            (a < b ? use.forward : use.backward)++;
        }
    }
    return uses;
}

std::size_t n_edges(const PolygonSoup& soup) { return edge_uses(soup).size(); }

long euler_characteristic(const PolygonSoup& soup) {
    return long(soup.n_vertices()) - long(n_edges(soup)) + long(soup.n_faces());
}

// Every undirected edge is used by exactly two faces.
bool is_closed(const PolygonSoup& soup) {
    auto uses = edge_uses(soup);
    return std::all_of(uses.begin(), uses.end(), [](const auto& e) { return e.second.total() == 2; });
}

// Every edge is used at most once in each direction (neighbouring faces agree on orientation).
bool is_consistently_oriented(const PolygonSoup& soup) {
    auto uses = edge_uses(soup);
    return std::all_of(uses.begin(), uses.end(),
                       [](const auto& e) { return e.second.forward <= 1 && e.second.backward <= 1; });
}

std::size_t n_boundary_edges(const PolygonSoup& soup) {
    auto uses = edge_uses(soup);
    return std::count_if(uses.begin(), uses.end(), [](const auto& e) { return e.second.total() == 1; });
}

// Whether the faces can be flipped so that neighbours agree: propagate a flip bit over shared edges (two faces
// agree when they run through their shared edge in opposite directions) and look for a contradiction.
bool is_orientable(const PolygonSoup& soup) {
    // for every undirected edge: the faces using it and whether they run a→b (a < b)
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::pair<std::size_t, bool>>> faces_of;
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        auto vs = soup.face(f);
        for (std::size_t k = 0; k < vs.size(); ++k) {
            std::uint32_t a = vs[k], b = vs[(k + 1) % vs.size()];
            faces_of[{std::min(a, b), std::max(a, b)}].push_back({f, a < b});
        }
    }
    std::vector<int> flip(soup.n_faces(), -1);
    for (std::size_t seed = 0; seed < soup.n_faces(); ++seed) {
        if (flip[seed] != -1) continue;
        flip[seed] = 0;
        std::queue<std::size_t> todo;
        todo.push(seed);
        while (!todo.empty()) {
            std::size_t f = todo.front();
            todo.pop();
            auto vs = soup.face(f);
            for (std::size_t k = 0; k < vs.size(); ++k) {
                std::uint32_t a = vs[k], b = vs[(k + 1) % vs.size()];
                bool f_forward = (a < b) != bool(flip[f]);
                for (auto [g, g_dir] : faces_of[{std::min(a, b), std::max(a, b)}]) {
                    if (g == f) continue;
                    int needed = (g_dir == f_forward) ? 1 : 0;  // g must run the other way
                    if (flip[g] == -1) {
                        flip[g] = needed;
                        todo.push(g);
                    } else if (flip[g] != needed) {
                        return false;
                    }
                }
            }
        }
    }
    return true;
}

// Σ over fan triangles of a · (b × c) / 6: the enclosed volume, positive when the normals point outward.
double signed_volume(const PolygonSoup& soup) {
    double volume = 0;
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        auto vs = soup.face(f);
        for (std::size_t k = 1; k + 1 < vs.size(); ++k)
            volume += glm::dot(soup.positions[vs[0]], glm::cross(soup.positions[vs[k]], soup.positions[vs[k + 1]])) / 6;
    }
    return volume;
}

// Newell normal of face f (length = twice the area for planar faces).
glm::dvec3 face_normal(const PolygonSoup& soup, std::size_t f) {
    glm::dvec3 n(0.0);
    auto vs = soup.face(f);
    for (std::size_t k = 0; k < vs.size(); ++k)
        n += glm::cross(soup.positions[vs[k]], soup.positions[vs[(k + 1) % vs.size()]]);
    return n;
}

glm::dvec3 face_centroid(const PolygonSoup& soup, std::size_t f) {
    glm::dvec3 c(0.0);
    for (auto v : soup.face(f)) c += soup.positions[v];
    return c / double(soup.face(f).size());
}

// For shapes that are convex and star-shaped about the origin: every face normal points away from the origin.
bool every_face_points_outward(const PolygonSoup& soup) {
    for (std::size_t f = 0; f < soup.n_faces(); ++f)
        if (glm::dot(face_normal(soup, f), face_centroid(soup, f)) <= 0) return false;
    return true;
}

std::pair<glm::dvec3, glm::dvec3> bounding_box(const PolygonSoup& soup) {
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const auto& p : soup.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return {lo, hi};
}

void check_box(const PolygonSoup& soup, glm::dvec3 lo, glm::dvec3 hi) {
    auto [blo, bhi] = bounding_box(soup);
    for (int k = 0; k < 3; ++k) {
        CHECK(blo[k] == doctest::Approx(lo[k]).epsilon(1e-12));
        CHECK(bhi[k] == doctest::Approx(hi[k]).epsilon(1e-12));
    }
}

// The invariants every closed, outward-oriented fixture has.
void check_closed_outward(const PolygonSoup& soup) {
    CHECK(is_closed(soup));
    CHECK(is_consistently_oriented(soup));
    CHECK(signed_volume(soup) > 0);
    auto uses = edge_uses(soup);  // closed + orientable: each edge once in each direction
    CHECK(std::all_of(uses.begin(), uses.end(),
                      [](const auto& e) { return e.second.forward == 1 && e.second.backward == 1; }));
}

// Every face has ≥ 3 distinct in-range vertices, and every vertex is used.
void check_well_formed(const PolygonSoup& soup) {
    std::vector<bool> used(soup.n_vertices(), false);
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        auto vs = soup.face(f);
        REQUIRE(vs.size() >= 3);
        for (auto v : vs) {
            REQUIRE(v < soup.n_vertices());
            used[v] = true;
        }
        std::vector<std::uint32_t> sorted(vs.begin(), vs.end());
        std::sort(sorted.begin(), sorted.end());
        CHECK(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end());
    }
    CHECK(std::all_of(used.begin(), used.end(), [](bool u) { return u; }));
    for (const auto& p : soup.positions) CHECK((std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)));
}

}  // namespace

TEST_SUITE("fixtures") {
    TEST_CASE("tetrahedron: V=4 E=6 F=4, chi=2, closed, outward, on the unit sphere") {
        PolygonSoup t = fx::tetrahedron();
        check_well_formed(t);
        CHECK(t.n_vertices() == 4);
        CHECK(n_edges(t) == 6);
        CHECK(t.n_faces() == 4);
        CHECK(euler_characteristic(t) == 2);
        check_closed_outward(t);
        CHECK(every_face_points_outward(t));
        for (const auto& p : t.positions) CHECK(glm::length(p) == doctest::Approx(1.0));
        // regular: all edges have the same length √(8/3)
        for (const auto& [e, use] : edge_uses(t))
            CHECK(glm::distance(t.positions[e.first], t.positions[e.second]) == doctest::Approx(std::sqrt(8.0 / 3.0)));
        CHECK(signed_volume(t) == doctest::Approx(8.0 / (9.0 * std::sqrt(3.0))));
    }

    TEST_CASE("cube: quads and triangles, V=8, chi=2, volume 8, box [-1,1]^3") {
        for (bool triangulate : {false, true}) {
            CAPTURE(triangulate);
            PolygonSoup c = fx::cube(triangulate);
            check_well_formed(c);
            CHECK(c.n_vertices() == 8);
            CHECK(c.n_faces() == (triangulate ? 12u : 6u));
            CHECK(n_edges(c) == (triangulate ? 18u : 12u));
            CHECK(c.is_triangle_soup() == triangulate);
            CHECK(euler_characteristic(c) == 2);
            check_closed_outward(c);
            CHECK(every_face_points_outward(c));
            CHECK(signed_volume(c) == doctest::Approx(8.0));
            check_box(c, glm::dvec3(-1), glm::dvec3(1));
        }
    }

    TEST_CASE("icosphere: F = 20*4^n, V = 10*4^n + 2, chi=2, unit radius, outward") {
        for (int n = 0; n <= 3; ++n) {
            CAPTURE(n);
            PolygonSoup s = fx::icosphere(n);
            const std::size_t p = std::size_t(1) << (2 * n);  // 4^n
            check_well_formed(s);
            CHECK(s.n_faces() == 20 * p);
            CHECK(s.n_vertices() == 10 * p + 2);
            CHECK(n_edges(s) == 30 * p);
            CHECK(euler_characteristic(s) == 2);
            CHECK(s.is_triangle_soup());
            check_closed_outward(s);
            CHECK(every_face_points_outward(s));
            for (const auto& q : s.positions) CHECK(glm::length(q) == doctest::Approx(1.0).epsilon(1e-12));
            CHECK(signed_volume(s) < 4.0 / 3.0 * std::numbers::pi);  // inscribed polyhedron
        }
        CHECK(signed_volume(fx::icosphere(4)) == doctest::Approx(4.0 / 3.0 * std::numbers::pi).epsilon(0.01));
        CHECK_THROWS_AS(fx::icosphere(-1), std::invalid_argument);
    }

    TEST_CASE("torus: V = rings*sides, chi=0, closed, orientable, outward, box") {
        for (bool triangulate : {false, true}) {
            CAPTURE(triangulate);
            const int rings = 24, sides = 12;
            const double R = 1.0, r = 0.35;
            PolygonSoup t = fx::torus(rings, sides, R, r, triangulate);
            check_well_formed(t);
            const std::size_t cells = rings * sides;
            CHECK(t.n_vertices() == cells);
            CHECK(t.n_faces() == (triangulate ? 2 * cells : cells));
            CHECK(n_edges(t) == (triangulate ? 3 * cells : 2 * cells));
            CHECK(euler_characteristic(t) == 0);
            check_closed_outward(t);
            CHECK(is_orientable(t));
            // close to the smooth torus volume 2π²Rr², from below
            CHECK(signed_volume(t) ==
                  doctest::Approx(2 * std::numbers::pi * std::numbers::pi * R * r * r).epsilon(0.05));
            check_box(t, {-(R + r), -(R + r), -r}, {R + r, R + r, r});
            // outward: each face normal points away from the tube's centre circle
            for (std::size_t f = 0; f < t.n_faces(); ++f) {
                glm::dvec3 c = face_centroid(t, f);
                glm::dvec3 on_circle = R * glm::normalize(glm::dvec3(c.x, c.y, 0));
                CHECK(glm::dot(face_normal(t, f), c - on_circle) > 0);
            }
        }
        CHECK(fx::torus(3, 3).n_vertices() == 9);
        CHECK_THROWS_AS(fx::torus(2, 12), std::invalid_argument);
    }

    TEST_CASE("grid: V=(nx+1)(ny+1), chi=1, one boundary loop, faces up +z, box [0,1]^2") {
        for (auto [nx, ny] : {std::pair{4, 4}, std::pair{1, 1}, std::pair{3, 5}}) {
            CAPTURE(nx);
            CAPTURE(ny);
            PolygonSoup g = fx::grid(nx, ny);
            check_well_formed(g);
            CHECK(g.n_vertices() == std::size_t((nx + 1) * (ny + 1)));
            CHECK(g.n_faces() == std::size_t(2 * nx * ny));
            CHECK(euler_characteristic(g) == 1);
            CHECK_FALSE(is_closed(g));
            CHECK(is_consistently_oriented(g));
            CHECK(n_boundary_edges(g) == std::size_t(2 * (nx + ny)));
            for (std::size_t f = 0; f < g.n_faces(); ++f) CHECK(face_normal(g, f).z > 0);
            check_box(g, {0, 0, 0}, {1, 1, 0});
        }
    }

    TEST_CASE("two_components: two closed tetrahedra, chi=4, the second shifted by (3,0,0)") {
        PolygonSoup s = fx::two_components();
        check_well_formed(s);
        CHECK(s.n_vertices() == 8);
        CHECK(s.n_faces() == 8);
        CHECK(n_edges(s) == 12);
        CHECK(euler_characteristic(s) == 4);
        check_closed_outward(s);
        CHECK(signed_volume(s) == doctest::Approx(2 * signed_volume(fx::tetrahedron())));
        for (std::size_t f = 0; f < 4; ++f)  // the faces of each component use only its own vertices
            for (auto v : s.face(f)) CHECK(v < 4);
        for (std::size_t f = 4; f < 8; ++f)
            for (auto v : s.face(f)) CHECK(v >= 4);
        const double a = 1 / std::sqrt(3.0);
        check_box(s, {-a, -a, -a}, {3 + a, a, a});
    }

    TEST_CASE("bowtie: two triangles sharing only vertex 0") {
        PolygonSoup b = fx::bowtie();
        check_well_formed(b);
        CHECK(b.n_vertices() == 5);
        CHECK(b.n_faces() == 2);
        CHECK(n_edges(b) == 6);
        auto f0 = b.face(0), f1 = b.face(1);
        std::vector<std::uint32_t> shared;
        for (auto v : f0)
            if (std::find(f1.begin(), f1.end(), v) != f1.end()) shared.push_back(v);
        CHECK(shared == std::vector<std::uint32_t>{0});
    }

    TEST_CASE("fan: three triangles on the edge 0-1 (a complex edge)") {
        PolygonSoup f = fx::fan();
        check_well_formed(f);
        CHECK(f.n_vertices() == 5);
        CHECK(f.n_faces() == 3);
        CHECK(n_edges(f) == 7);
        auto uses = edge_uses(f);
        CHECK(uses[{0, 1}].total() == 3);
        CHECK_FALSE(is_consistently_oriented(f));  // three faces cannot alternate around one edge
    }

    TEST_CASE("mobius: chi=0, one boundary loop, not orientable") {
        for (bool triangulate : {true, false}) {
            for (int n : {5, 12, 13}) {
                CAPTURE(triangulate);
                CAPTURE(n);
                PolygonSoup m = fx::mobius(n, triangulate);
                check_well_formed(m);
                const std::size_t N = n;
                CHECK(m.n_vertices() == 2 * N);
                CHECK(m.n_faces() == (triangulate ? 2 * N : N));
                CHECK(n_edges(m) == (triangulate ? 4 * N : 3 * N));
                CHECK(euler_characteristic(m) == 0);
                CHECK_FALSE(is_closed(m));
                CHECK(n_boundary_edges(m) == 2 * N);  // one loop through all 2N vertices (two would be N each)
                CHECK_FALSE(is_consistently_oriented(m));
                CHECK_FALSE(is_orientable(m));  // no choice of flips fixes it
                // the boundary is a single loop: walking it from vertex 0 visits all 2N vertices
                std::map<std::uint32_t, std::vector<std::uint32_t>> next;
                for (const auto& [e, use] : edge_uses(m))
                    if (use.total() == 1) {
                        next[e.first].push_back(e.second);
                        next[e.second].push_back(e.first);
                    }
                std::size_t steps = 0;
                for (std::uint32_t prev = 0, v = next[0][0]; v != 0 && steps <= 2 * N; ++steps) {
                    std::uint32_t w = next[v][0] == prev ? next[v][1] : next[v][0];
                    prev = v;
                    v = w;
                }
                CHECK(steps + 1 == 2 * N);
            }
        }
        // controls: the orientability check does accept orientable surfaces
        CHECK(is_orientable(fx::torus()));
        CHECK(is_orientable(fx::grid()));
        CHECK_THROWS_AS(fx::mobius(4), std::invalid_argument);
    }

    TEST_CASE("flip_face reverses one face only") {
        PolygonSoup t = fx::tetrahedron();
        PolygonSoup flipped = fx::flip_face(t, 2);
        CHECK_FALSE(is_consistently_oriented(flipped));
        CHECK(is_orientable(flipped));
        for (std::size_t f = 0; f < t.n_faces(); ++f) {
            std::vector<std::uint32_t> a(t.face(f).begin(), t.face(f).end()),
                b(flipped.face(f).begin(), flipped.face(f).end());
            if (f == 2) std::reverse(a.begin(), a.end());
            CHECK(a == b);
        }
        PolygonSoup twice = fx::flip_face(flipped, 2);
        CHECK(twice.indices == t.indices);
        CHECK(signed_volume(twice) == doctest::Approx(signed_volume(t)));
        CHECK_THROWS_AS(fx::flip_face(t, 4), std::invalid_argument);
    }

}  // TEST_SUITE
