#pragma once
// Lab 01 test inputs: the fixture family (soups with the topology a correct build must report) and every other soup
// the tests use. Plain data, no test framework: the instructors' generator of the stored connectivity
// (hidden/tools/fixture_data.cpp) includes it too.
#include <array>
#include <cmath>
#include <cstdint>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "geolab/fixtures.hpp"
#include "geolab/soup.hpp"

namespace lab01 {

using geolab::PolygonSoup;
namespace fx = geolab::fixtures;

// ---- printing ------------------------------------------------------------------------------------------------

// A small soup as C++ code that rebuilds it, so a failing case can be pasted into a test or a main().
inline std::string mesh_to_string(const PolygonSoup& soup) {
    std::ostringstream os;
    os.precision(17);
    os << "PolygonSoup soup;\nsoup.positions = {";
    for (std::size_t v = 0; v < soup.n_vertices(); ++v) {
        const auto& p = soup.positions[v];
        os << (v ? ", " : "") << "{" << p.x << ", " << p.y << ", " << p.z << "}";
    }
    os << "};\n";
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        os << "soup.add_face({";
        for (std::size_t i = 0; i < soup.face(f).size(); ++i) os << (i ? ", " : "") << soup.face(f)[i];
        os << "});\n";
    }
    return os.str();
}

// ---- the fixture family --------------------------------------------------------------------------------------

// A named soup with the topology a correct build must report.
struct Fixture {
    std::string name;
    PolygonSoup soup;
    int V, E, F;
    int chi;         // V - E + F
    int loops;       // boundary loops (holes)
    int components;  // connected components (isolated vertices count)
    int genus;
};

// What a failing test prints about its input: the name and, when small, the soup itself.
inline std::string describe(const Fixture& f) {
    std::string s = "fixture '" + f.name + "'";
    if (f.soup.n_faces() <= 12) s += ", built from:\n" + mesh_to_string(f.soup);
    return s;
}

// Octahedron with vertices ±x (0, 1), ±y (2, 3), ±z (4, 5); faces counter-clockwise seen from outside.
inline PolygonSoup octahedron() {
    PolygonSoup s;
    s.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (auto f : {std::array<std::uint32_t, 3>{0, 2, 4},
                   {2, 1, 4},
                   {1, 3, 4},
                   {3, 0, 4},
                   {2, 0, 5},
                   {1, 2, 5},
                   {3, 1, 5},
                   {0, 3, 5}})
        s.add_face({f[0], f[1], f[2]});
    return s;
}

// Square pyramid without its base: apex 0 at (0,0,1) is the only interior vertex, 1..4 the boundary square.
inline PolygonSoup open_pyramid() {
    PolygonSoup s;
    s.positions = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
    s.add_face({0, 1, 2});
    s.add_face({0, 2, 3});
    s.add_face({0, 3, 4});
    s.add_face({0, 4, 1});
    return s;
}

// A single polygon with n corners on the unit circle.
inline PolygonSoup polygon(int n) {
    PolygonSoup s;
    std::vector<std::uint32_t> vs;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * 3.14159265358979323846 * i / n;
        s.positions.emplace_back(std::cos(a), std::sin(a), 0.0);
        vs.push_back(static_cast<std::uint32_t>(i));
    }
    s.add_face(vs);
    return s;
}

// A mixed polygon mesh: square 0 1 2 3 with a triangular roof 3 2 4 (planar, open).
inline PolygonSoup house() {
    PolygonSoup s;
    s.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 1.5, 0}};
    s.add_face({0, 1, 2, 3});
    s.add_face({3, 2, 4});
    return s;
}

// The soup without the faces listed (they must not share vertices with each other or the border: holes).
inline PolygonSoup without_faces(const PolygonSoup& in, std::set<std::size_t> drop) {
    PolygonSoup s;
    s.positions = in.positions;
    for (std::size_t f = 0; f < in.n_faces(); ++f)
        if (!drop.count(f)) s.add_face(in.face(f));
    return s;
}

// grid(6, 6) with two separate triangles removed: three boundary loops.
inline PolygonSoup grid_with_two_holes() {
    // cell (i, j) of grid(nx, ny) has faces 2(j nx + i) and 2(j nx + i) + 1
    return without_faces(fx::grid(6, 6), {2 * (1 * 6 + 1), 2 * (4 * 6 + 4)});
}

// The cube's six quads minus the top (+z): an open box.
inline PolygonSoup open_box() { return without_faces(fx::cube(false), {1}); }

// The tetrahedron plus one vertex that no face uses.
inline PolygonSoup tetrahedron_with_isolated_vertex() {
    PolygonSoup s = fx::tetrahedron();
    s.positions.emplace_back(5.0, 5.0, 5.0);
    return s;
}

// Every valid input of the lab with its expected topology (closed, open, polygons, holes, several components).
inline std::vector<Fixture> manifold_fixtures() {
    return {
        {"tetrahedron", fx::tetrahedron(), 4, 6, 4, 2, 0, 1, 0},
        {"cube (quads)", fx::cube(false), 8, 12, 6, 2, 0, 1, 0},
        {"cube (triangles)", fx::cube(true), 8, 18, 12, 2, 0, 1, 0},
        {"octahedron", octahedron(), 6, 12, 8, 2, 0, 1, 0},
        {"icosphere(0)", fx::icosphere(0), 12, 30, 20, 2, 0, 1, 0},
        {"icosphere(2)", fx::icosphere(2), 162, 480, 320, 2, 0, 1, 0},
        {"torus(8 x 6 triangles)", fx::torus(8, 6, 1.0, 0.35, true), 48, 144, 96, 0, 0, 1, 1},
        {"torus(6 x 4 quads)", fx::torus(6, 4, 1.0, 0.35, false), 24, 48, 24, 0, 0, 1, 1},
        {"grid(1 x 1)", fx::grid(1, 1), 4, 5, 2, 1, 1, 1, 0},
        {"grid(4 x 4)", fx::grid(4, 4), 25, 56, 32, 1, 1, 1, 0},
        {"grid(3 x 2)", fx::grid(3, 2), 12, 23, 12, 1, 1, 1, 0},
        {"grid(6 x 6) with two holes", grid_with_two_holes(), 49, 120, 70, -1, 3, 1, 0},
        {"open box (5 quads)", open_box(), 8, 12, 5, 1, 1, 1, 0},
        {"open pyramid", open_pyramid(), 5, 8, 4, 1, 1, 1, 0},
        {"triangle", polygon(3), 3, 3, 1, 1, 1, 1, 0},
        {"pentagon", polygon(5), 5, 5, 1, 1, 1, 1, 0},
        {"house (quad + triangle)", house(), 5, 6, 2, 1, 1, 1, 0},
        {"two components", fx::two_components(), 8, 12, 8, 4, 0, 2, 0},
        {"tetrahedron + isolated vertex", tetrahedron_with_isolated_vertex(), 5, 6, 4, 3, 0, 2, 0},
    };
}

inline Fixture fixture(const std::string& name) {
    for (auto& f : manifold_fixtures())
        if (f.name == name) return f;
    throw std::logic_error("no fixture named " + name);
}


// ---- further soups of the tests ------------------------------------------------------------------------------

// Two triangles at vertex 0 with different areas: (0, 1, 2) in z = 0 (Newell vector (0,0,4)) and (0, 2, 3)
// (Newell vector (2,0,2)).
inline PolygonSoup tent() {
    PolygonSoup s;
    s.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {-1, 0, 1}};
    s.add_face({0, 1, 2});
    s.add_face({0, 2, 3});
    return s;
}

// The faces of `b` appended to `a` with b's vertices renumbered after a's and moved by `shift`.
inline PolygonSoup disjoint_union(PolygonSoup a, const PolygonSoup& b, const glm::dvec3& shift) {
    const auto base = static_cast<std::uint32_t>(a.n_vertices());
    for (const auto& p : b.positions) a.positions.push_back(p + shift);
    for (std::size_t f = 0; f < b.n_faces(); ++f) {
        std::vector<std::uint32_t> vs(b.face(f).begin(), b.face(f).end());
        for (auto& v : vs) v += base;
        a.add_face(vs);
    }
    return a;
}

// Two tori side by side (torus(8, 6) and torus(7, 5), shifted by 5 along x): genus 2.
inline PolygonSoup two_tori() { return disjoint_union(fx::torus(8, 6), fx::torus(7, 5), {5, 0, 0}); }

// A closed double cone over an n-gon: ring vertices 0..n-1, apices n (top) and n + 1 (bottom). Each apex has n
// corners (more than a short scan of its edges: build_mesh's sorted long-bucket path) and is not vertex 0; face 0
// starts at the top apex, so corner 0 lies in the apex's bucket. Face i < n is (n, i+1, i+2), face n + i is
// (n+1, i+2, i+1), indices mod n. V = n + 2, E = 3n, F = 2n.
inline PolygonSoup apex_first_bipyramid(int n) {
    PolygonSoup s;
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * 3.14159265358979323846 * i / n;
        s.positions.push_back({std::cos(a), std::sin(a), 0.0});
    }
    s.positions.push_back({0.0, 0.0, 1.0});
    s.positions.push_back({0.0, 0.0, -1.0});
    const auto u = std::uint32_t(n);
    for (std::uint32_t i = 0; i < u; ++i) s.add_face({u, (i + 1) % u, (i + 2) % u});
    for (std::uint32_t i = 0; i < u; ++i) s.add_face({u + 1, (i + 2) % u, (i + 1) % u});
    return s;
}

// n tetrahedra in a row, 3 apart: n components, genus 0.
inline PolygonSoup tetrahedra_in_a_row(int n) {
    PolygonSoup s;
    for (int i = 0; i < n; ++i) s = disjoint_union(s, fx::tetrahedron(), {3.0 * i, 0, 0});
    return s;
}

// A soup with its stored connectivity: the tests of Tasks 2-5 take the mesh of `key` from tests/01_halfedge/data
// (stored.hpp), the connectivity the reference build_mesh makes, so that they never call your build_mesh.
struct StoredSoup {
    std::string key;
    PolygonSoup soup;
};

// Every soup whose connectivity is stored: the fixture family, then the other soups the tests of Tasks 2-5 use
// (a soup with other positions but the same faces shares the key: "polygon(4)" serves any single quad 0 1 2 3).
inline std::vector<StoredSoup> stored_soups() {
    std::vector<StoredSoup> out;
    for (auto& f : manifold_fixtures()) out.push_back({f.name, f.soup});
    out.push_back({"icosphere(1)", fx::icosphere(1)});
    out.push_back({"grid(6 x 6)", fx::grid(6, 6)});
    out.push_back({"torus(7 x 5 triangles)", fx::torus(7, 5)});
    out.push_back({"polygon(4)", polygon(4)});
    out.push_back({"polygon(6)", polygon(6)});
    out.push_back({"tent", tent()});
    return out;
}

}  // namespace lab01
