#pragma once
// Lab 01 test helpers: reference answers computed from the soup by brute force (std::set / std::map), independently
// of any half-edge code. The inputs are in fixtures.hpp. The tests of Task 1 build their meshes with build_mesh
// (build_valid); those of Tasks 2-5 take them from the stored connectivity (stored.hpp: stored_mesh), so that they
// never depend on your build_mesh.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <map>
#include <numeric>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "fixtures.hpp"
#include "stored.hpp"
#include "geolab/errors.hpp"
#include "geolab/fixtures.hpp"
#include "geolab/grading/test.hpp"
#include "geolab/halfedge.hpp"
#include "geolab/io.hpp"
#include "geolab/models.hpp"
#include "geolab/soup.hpp"

namespace lab01 {

using namespace geolab::halfedge;
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

// The mesh of two_tori() (fixtures.hpp) from stored connectivity.
inline Mesh two_tori_mesh() {
    Mesh m = disjoint_union(stored_mesh("torus(8 x 6 triangles)", fx::torus(8, 6)),
                            stored_mesh("torus(7 x 5 triangles)", fx::torus(7, 5)), {5, 0, 0});
    check_connectivity_matches_soup(m, two_tori(), "two tori");
    return m;
}

// The mesh of tetrahedra_in_a_row(n) (fixtures.hpp), followed by `then` (positions moved by 3n along x), from stored
// connectivity.
inline Mesh tetrahedra_in_a_row_mesh(int n, const Mesh& then = Mesh{}) {
    const Mesh tet = stored_mesh("tetrahedron", fx::tetrahedron());
    Mesh m;
    for (int i = 0; i < n; ++i) m = disjoint_union(m, tet, {3.0 * i, 0, 0});
    return disjoint_union(m, then, {3.0 * n, 0, 0});
}

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

// The faces of `soup` that use vertex v.
inline std::set<std::uint32_t> faces_at(const PolygonSoup& soup, std::uint32_t v) { return vertex_faces(soup)[v]; }

// Checks build_mesh's complex-vertex message for `soup`: exactly the header's format, naming vertex v and two
// different faces at v that lie in different fans, i.e. fan_of(A) != fan_of(B) (fan_of: the instructor's labelling
// of the faces at v, e.g. which of two solids sharing v a face belongs to).
template <class FanOf>
void check_complex_vertex_message(const PolygonSoup& soup, std::uint32_t v, FanOf fan_of) {
    const std::string msg = build_error_message(soup);
    CAPTURE(msg);
    std::smatch m;
    static const std::regex format(
        R"(build_mesh: complex vertex (\d+): its faces form more than one fan \(face (\d+) and face (\d+) are in different fans\))");
    REQUIRE_MESSAGE(std::regex_match(msg, m, format),
                    "expected the message 'build_mesh: complex vertex " << v << ": its faces form more than one fan "
                    "(face A and face B are in different fans)', got '" << msg << "'");
    CHECK_MESSAGE(std::stoul(m[1]) == v, "expected complex vertex " << v << ", got vertex " << m[1]);
    const std::uint32_t a = std::uint32_t(std::stoul(m[2])), b = std::uint32_t(std::stoul(m[3]));
    const auto at_v = faces_at(soup, v);
    REQUIRE_MESSAGE((at_v.count(a) && at_v.count(b)),
                    "faces " << a << " and " << b << " must both use vertex " << v);
    CHECK_MESSAGE(fan_of(a) != fan_of(b), "faces " << a << " and " << b << " are in the same fan around vertex " << v);
}

// Checks build_mesh's inconsistent-orientation message for `soup`: exactly the header's format, naming two
// different faces that both use the directed edge u->v it names, one of them `flipped`.
inline void check_orientation_message(const PolygonSoup& soup, std::size_t flipped) {
    const std::string msg = build_error_message(soup);
    CAPTURE(msg);
    std::smatch m;
    static const std::regex format(
        R"(build_mesh: inconsistent orientation: face (\d+) and face (\d+) both use the directed edge from vertex (\d+) to vertex (\d+))");
    REQUIRE_MESSAGE(std::regex_match(msg, m, format),
                    "expected the message 'build_mesh: inconsistent orientation: face A and face B both use the "
                    "directed edge from vertex u to vertex v', got '" << msg << "'");
    const std::size_t a = std::stoul(m[1]), b = std::stoul(m[2]);
    const std::uint32_t u = std::uint32_t(std::stoul(m[3])), v = std::uint32_t(std::stoul(m[4]));
    CHECK_MESSAGE(a != b, "the message names face " << a << " twice: it must name the two faces that disagree");
    CHECK_MESSAGE((a == flipped || b == flipped), "face " << flipped << " (the flipped one) is not named");
    for (std::size_t f : {a, b}) {
        bool uses = false;
        if (f < soup.n_faces()) {
            const auto c = soup.face(f);
            for (std::size_t i = 0; i < c.size(); ++i) uses |= c[i] == u && c[(i + 1) % c.size()] == v;
        }
        CHECK_MESSAGE(uses, "face " << f << " does not use the directed edge " << u << "->" << v);
    }
}

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
