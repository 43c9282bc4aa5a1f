#pragma once
// Lab 01 tests: half-edge connectivity as plain numbers, loaded into a Mesh through its own building API, checked
// against a soup, and combined (disjoint union): what stored.hpp needs, without the data (the instructors'
// generator hidden/tools/fixture_data.cpp includes this file before the data exists).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "geolab/halfedge/mesh.hpp"
#include "geolab/soup.hpp"

namespace lab01 {

using geolab::PolygonSoup;

// The layout of a stored connectivity (-1 is an invalid handle):
//   V, H, F;  to_vertex[H];  next[H];  face[H];  halfedge(v)[V];  halfedge(f)[F]
inline std::size_t stored_size(std::size_t V, std::size_t H, std::size_t F) { return 3 + 3 * H + V + F; }

// The mesh held by `data`, with the given positions. Uses only the given Mesh (mesh.hpp), never lab code.
// \throw std::logic_error when the numbers are inconsistent (sizes, ranges).
inline geolab::halfedge::Mesh mesh_from_connectivity(std::span<const std::int32_t> d,
                                                     const std::vector<glm::dvec3>& positions,
                                                     const std::string& what) {
    using namespace geolab::halfedge;
    auto bad = [&](const std::string& why) { return std::logic_error("stored connectivity '" + what + "': " + why); };
    if (d.size() < 3) throw bad("fewer than 3 numbers");
    const auto V = std::size_t(d[0]), H = std::size_t(d[1]), F = std::size_t(d[2]);
    if (d[0] < 0 || d[1] < 0 || d[2] < 0 || H % 2 || d.size() != stored_size(V, H, F))
        throw bad("the counts V H F = " + std::to_string(d[0]) + " " + std::to_string(d[1]) + " " +
                  std::to_string(d[2]) + " do not fit its " + std::to_string(d.size()) + " numbers");
    if (positions.size() != V)
        throw bad(std::to_string(V) + " vertices but the soup has " + std::to_string(positions.size()));
    auto in = [&](std::size_t i, std::size_t n, bool may_be_invalid) {
        const std::int32_t x = d[i];
        if ((x < 0 && !(may_be_invalid && x == -1)) || (x >= 0 && std::size_t(x) >= n))
            throw bad("number " + std::to_string(i) + " = " + std::to_string(x) + " is out of range");
        return x < 0 ? invalid_index : std::uint32_t(x);
    };
    const std::size_t to = 3, nx = to + H, fc = nx + H, vh = fc + H, fh = vh + V;
    Mesh m;
    m.reserve(V, H / 2, F);
    for (const auto& p : positions) m.add_vertex(p);
    for (std::size_t e = 0; e < H / 2; ++e) m.add_edge(Vertex{in(to + 2 * e + 1, V, false)}, Vertex{in(to + 2 * e, V, false)});
    for (std::size_t f = 0; f < F; ++f) m.add_face();
    for (Halfedge h : m.halfedges()) {
        m.set_next(h, Halfedge{in(nx + h.idx, H, false)});
        m.set_face(h, Face{in(fc + h.idx, F, true)});
    }
    for (Vertex v : m.vertices()) m.set_halfedge(v, Halfedge{in(vh + v.idx, H, true)});
    for (Face f : m.faces()) m.set_halfedge(f, Halfedge{in(fh + f.idx, H, false)});
    return m;
}

// Checks, with the given Mesh accessors only, that m is the mesh of `soup`: same vertex and face counts, each face
// f's next loop from halfedge(f) visits soup.face(f) in order, every half-edge without a face has a twin with one,
// and one edge per undirected soup edge. Throws std::logic_error naming the first difference.
inline void check_connectivity_matches_soup(const geolab::halfedge::Mesh& m, const PolygonSoup& soup,
                                            const std::string& what) {
    using namespace geolab::halfedge;
    auto bad = [&](const std::string& why) {
        return std::logic_error("stored connectivity '" + what + "' does not match its soup: " + why +
                                " (instructors: regenerate tests/01_halfedge/data, see stored.hpp)");
    };
    if (m.n_vertices() != soup.n_vertices() || m.n_faces() != soup.n_faces())
        throw bad("V, F = " + std::to_string(m.n_vertices()) + ", " + std::to_string(m.n_faces()) + "; the soup has " +
                  std::to_string(soup.n_vertices()) + ", " + std::to_string(soup.n_faces()));
    std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (Face f : m.faces()) {
        const auto c = soup.face(f.idx);
        Halfedge h = m.halfedge(f);
        for (std::size_t i = 0; i < c.size(); ++i, h = m.next(h)) {
            const std::uint32_t u = c[i], v = c[(i + 1) % c.size()];
            if (m.from_vertex(h).idx != u || m.to_vertex(h).idx != v || m.face(h) != f)
                throw bad("face " + std::to_string(f.idx) + ", corner " + std::to_string(i));
            edges.insert({std::min(u, v), std::max(u, v)});
        }
        if (h != m.halfedge(f)) throw bad("face " + std::to_string(f.idx) + " is not a closed next loop");
    }
    if (edges.size() != m.n_edges())
        throw bad(std::to_string(m.n_edges()) + " edges, the soup has " + std::to_string(edges.size()));
    for (Halfedge h : m.halfedges())
        if (m.is_boundary(h) && m.is_boundary(m.twin(h))) throw bad("edge " + std::to_string(h.idx / 2) + " has no face");
}

// The disjoint union of meshes: b's elements renumbered after a's, positions moved by `shift` (like
// disjoint_union of soups in fixtures.hpp, so the union's faces are the soups' union's faces).
inline geolab::halfedge::Mesh disjoint_union(const geolab::halfedge::Mesh& a, const geolab::halfedge::Mesh& b,
                                             const glm::dvec3& shift) {
    using namespace geolab::halfedge;
    Mesh m = a;
    const auto nv = std::uint32_t(a.n_vertices()), nh = std::uint32_t(a.n_halfedges()),
               nf = std::uint32_t(a.n_faces());
    auto vtx = [&](Vertex v) { return Vertex{v.idx + nv}; };
    auto he = [&](Halfedge h) { return h.is_valid() ? Halfedge{h.idx + nh} : h; };
    auto fc = [&](Face f) { return f.is_valid() ? Face{f.idx + nf} : f; };
    for (Vertex v : b.vertices()) m.add_vertex(b.position(v) + shift);
    for (Edge e : b.edges()) {
        const Halfedge h = b.halfedge(e, 0);
        m.add_edge(vtx(b.from_vertex(h)), vtx(b.to_vertex(h)));
    }
    for (std::size_t f = 0; f < b.n_faces(); ++f) m.add_face();
    for (Halfedge h : b.halfedges()) {
        m.set_next(he(h), he(b.next(h)));
        m.set_face(he(h), fc(b.face(h)));
    }
    for (Vertex v : b.vertices()) m.set_halfedge(vtx(v), he(b.halfedge(v)));
    for (Face f : b.faces()) m.set_halfedge(fc(f), he(b.halfedge(f)));
    return m;
}

}  // namespace lab01
