#pragma once
// Lab 01 test helpers: the fixture family with its expected topology, and reference answers computed from the
// soup by brute force (std::set / std::map), independently of any half-edge code.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "geolab/errors.hpp"
#include "geolab/fixtures.hpp"
#include "geolab/grading/test.hpp"
#include "geolab/halfedge.hpp"
#include "geolab/io.hpp"
#include "geolab/models.hpp"
#include "geolab/soup.hpp"

namespace lab01 {

using namespace geolab::halfedge;
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

// Builds the mesh of `soup` (named `what` in messages) and fails the test (with validate()'s message) if it does not
// validate.
inline Mesh build_valid(const PolygonSoup& soup, const std::string& what) {
    Mesh m = build_mesh(soup);
    try {
        validate(m);
    } catch (const geolab::TopologyError& e) {
        FAIL(what << ": validate() rejects the mesh that build_mesh returned: " << std::string(e.what()));
    }
    return m;
}
inline Mesh build_valid(const Fixture& f) { return build_valid(f.soup, "fixture '" + f.name + "'"); }

// ---- brute-force references from the soup ---------------------------------------------------------------------

using VertexPair = std::pair<std::uint32_t, std::uint32_t>;

// Directed edges (u, v) of all faces, with how many faces use each.
inline std::map<VertexPair, int> directed_edges(const PolygonSoup& s) {
    std::map<VertexPair, int> d;
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        auto vs = s.face(f);
        for (std::size_t i = 0; i < vs.size(); ++i) ++d[{vs[i], vs[(i + 1) % vs.size()]}];
    }
    return d;
}

// Undirected edges as (min, max).
inline std::set<VertexPair> undirected_edges(const PolygonSoup& s) {
    std::set<VertexPair> e;
    for (auto& [uv, n] : directed_edges(s)) e.insert({std::min(uv.first, uv.second), std::max(uv.first, uv.second)});
    return e;
}

// The face that uses the directed edge u→v, or -1.
inline std::map<VertexPair, int> face_of_directed_edge(const PolygonSoup& s) {
    std::map<VertexPair, int> m;
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        auto vs = s.face(f);
        for (std::size_t i = 0; i < vs.size(); ++i) m[{vs[i], vs[(i + 1) % vs.size()]}] = static_cast<int>(f);
    }
    return m;
}

// Per vertex, its neighbours (vertices sharing an edge with it).
inline std::vector<std::set<std::uint32_t>> neighbours(const PolygonSoup& s) {
    std::vector<std::set<std::uint32_t>> n(s.n_vertices());
    for (auto& [u, v] : undirected_edges(s)) n[u].insert(v), n[v].insert(u);
    return n;
}

// Per vertex, the faces using it.
inline std::vector<std::set<std::uint32_t>> vertex_faces(const PolygonSoup& s) {
    std::vector<std::set<std::uint32_t>> r(s.n_vertices());
    for (std::size_t f = 0; f < s.n_faces(); ++f)
        for (auto v : s.face(f)) r[v].insert(static_cast<std::uint32_t>(f));
    return r;
}

// Edges used by exactly one face (as directed in that face).
inline std::vector<VertexPair> boundary_edges(const PolygonSoup& s) {
    auto d = directed_edges(s);
    std::vector<VertexPair> b;
    for (auto& [uv, n] : d)
        if (!d.count({uv.second, uv.first})) b.push_back(uv);
    return b;
}

inline std::vector<bool> boundary_vertices(const PolygonSoup& s) {
    std::vector<bool> b(s.n_vertices(), false);
    for (auto& [u, v] : boundary_edges(s)) b[u] = b[v] = true;
    return b;
}

// Union-find over vertices.
struct UnionFind {
    std::vector<std::uint32_t> parent;
    explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
    std::uint32_t find(std::uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
    void unite(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

// The number of boundary loops: components of the graph of boundary edges.
inline int count_boundary_loops(const PolygonSoup& s) {
    UnionFind uf(s.n_vertices());
    std::set<std::uint32_t> on_boundary;
    for (auto& [u, v] : boundary_edges(s)) uf.unite(u, v), on_boundary.insert(u), on_boundary.insert(v);
    std::set<std::uint32_t> roots;
    for (auto v : on_boundary) roots.insert(uf.find(v));
    return static_cast<int>(roots.size());
}

// Per vertex, a component label (the root of its union-find set).
inline std::vector<std::uint32_t> component_roots(const PolygonSoup& s) {
    UnionFind uf(s.n_vertices());
    for (auto& [u, v] : undirected_edges(s)) uf.unite(u, v);
    std::vector<std::uint32_t> r(s.n_vertices());
    for (std::uint32_t v = 0; v < s.n_vertices(); ++v) r[v] = uf.find(v);
    return r;
}

// valence -> number of vertices with it
inline std::map<int, int> valence_histogram(const PolygonSoup& s) {
    std::map<int, int> h;
    for (auto& n : neighbours(s)) ++h[static_cast<int>(n.size())];
    return h;
}

// One Jacobi step of uniform Laplacian smoothing computed from the soup: boundary and isolated vertices fixed.
inline std::vector<glm::dvec3> reference_smoothing_step(const PolygonSoup& s, const std::vector<glm::dvec3>& p,
                                                        double t) {
    const auto nb = neighbours(s);
    const auto boundary = boundary_vertices(s);
    std::vector<glm::dvec3> out = p;
    for (std::size_t v = 0; v < p.size(); ++v) {
        if (boundary[v] || nb[v].empty()) continue;
        glm::dvec3 mean(0.0);
        for (auto w : nb[v]) mean += p[w];
        mean /= double(nb[v].size());
        out[v] = p[v] + t * (mean - p[v]);
    }
    return out;
}

// Area-weighted vertex normals of a triangle soup: normalize(Σ (b - a) × (c - a)) over the triangles at v.
inline std::vector<glm::dvec3> reference_vertex_normals(const PolygonSoup& s) {
    std::vector<glm::dvec3> n(s.n_vertices(), glm::dvec3(0.0));
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        auto t = s.face(f);
        const glm::dvec3 c = glm::cross(s.positions[t[1]] - s.positions[t[0]], s.positions[t[2]] - s.positions[t[0]]);
        for (auto v : t) n[v] += c;
    }
    for (auto& x : n) x = glm::normalize(x);
    return n;
}

// The largest distance of a vertex from the centroid (the scale tolerances are relative to).
inline double scale_of(const std::vector<glm::dvec3>& p) {
    glm::dvec3 c(0.0);
    for (auto& x : p) c += x;
    c /= double(p.size());
    double r = 0;
    for (auto& x : p) r = std::max(r, glm::length(x - c));
    return r;
}

inline std::string str(const glm::dvec3& p) {
    std::ostringstream os;
    os.precision(10);
    os << "(" << p.x << ", " << p.y << ", " << p.z << ")";
    return os.str();
}

// A valence histogram as "valence:count ...".
inline std::string str(const std::map<int, int>& histogram) {
    std::string s;
    for (auto [valence, count] : histogram) s += std::to_string(valence) + ":" + std::to_string(count) + " ";
    return s;
}

// Checks the valences of all vertices of m against the soup's brute-force histogram.
inline void check_valence_histogram(const Mesh& m, const PolygonSoup& soup) {
    std::map<int, int> hist;
    for (Vertex v : m.vertices()) ++hist[valence(m, v)];
    const auto ref = valence_histogram(soup);
    CHECK_MESSAGE(hist == ref, "valence histogram (valence:count): expected " << str(ref) << "got " << str(hist));
}

// The message of the exception build_mesh(soup) throws, or "" if it returns. Tests use it after a
// CHECK_THROWS_AS to look inside the message.
inline std::string build_error_message(const PolygonSoup& soup) {
    try {
        build_mesh(soup);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

inline bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// ---- real models ------------------------------------------------------------------------------------------------
// A model test needs the CGAL meshes in data/models (tools/fetch_models.sh, the README's first command). When a
// model is missing the test FAILS with that instruction — it never passes without checking anything.
inline PolygonSoup load_model(const std::string& name) {
    auto path = geolab::model_path(name);
    if (!path)
        FAIL("model " << name << " not found in " << geolab::models_dir().string() << ": run tools/fetch_models.sh");
    return geolab::read_mesh(*path);
}

}  // namespace lab01
