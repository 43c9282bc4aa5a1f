#pragma once
// Lab 01 hidden tests: an independent half-edge builder for the hidden tests of Tasks 2-5 on meshes that are not
// stored (the fetched models, large procedural soups), so that they never call the student's build_mesh. It lives in
// hidden/ (not in the student release): it is a Task 1 answer, written plainly (std::map twin matching) and with
// its own numbering. The ctest lab01_fixture_data checks it against validate() on every stored soup and model.
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "geolab/halfedge/mesh.hpp"
#include "geolab/soup.hpp"

namespace lab01 {

// The half-edge mesh of an oriented manifold soup (valid soups only: throws std::logic_error otherwise).
// Uses only the given Mesh API; no lab code.
inline geolab::halfedge::Mesh independent_build(const geolab::PolygonSoup& soup, const std::string& what) {
    using namespace geolab::halfedge;
    auto bad = [&](const std::string& why) { return std::logic_error("independent_build(" + what + "): " + why); };
    Mesh m;
    for (const auto& p : soup.positions) m.add_vertex(p);
    std::map<std::pair<std::uint32_t, std::uint32_t>, Halfedge> directed;  // u->v: its half-edge
    std::vector<Halfedge> corner(soup.indices.size());
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        const auto c = soup.face(f);
        for (std::size_t i = 0; i < c.size(); ++i) {
            const std::uint32_t u = c[i], v = c[(i + 1) % c.size()];
            auto it = directed.find({u, v});
            if (it == directed.end()) {  // a new edge: both directions at once
                const Halfedge h = m.add_edge(Vertex{u}, Vertex{v});
                directed[{u, v}] = h;
                directed[{v, u}] = m.twin(h);
                it = directed.find({u, v});
            }
            if (m.face(it->second).is_valid()) throw bad("directed edge used twice");
            corner[soup.offsets[f] + i] = it->second;
            m.set_face(it->second, Face{std::uint32_t(f)});  // marks it used until the faces are made below
        }
    }
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        const Face face = m.add_face();
        const std::size_t first = soup.offsets[f], end = soup.offsets[f + 1];
        m.set_halfedge(face, corner[first]);
        for (std::size_t k = first; k < end; ++k) {
            m.set_next(corner[k], corner[k + 1 < end ? k + 1 : first]);
            m.set_halfedge(m.from_vertex(corner[k]), corner[k]);
        }
    }
    std::vector<Halfedge> boundary_out(m.n_vertices());
    for (Halfedge h : m.halfedges())
        if (m.is_boundary(h)) {
            if (boundary_out[m.from_vertex(h).idx].is_valid()) throw bad("two boundary half-edges leave a vertex");
            boundary_out[m.from_vertex(h).idx] = h;
        }
    for (Halfedge h : m.halfedges())
        if (m.is_boundary(h)) {
            m.set_halfedge(m.from_vertex(h), h);
            const Halfedge n = boundary_out[m.to_vertex(h).idx];
            if (!n.is_valid()) throw bad("an open boundary");
            m.set_next(h, n);
        }
    return m;
}

}  // namespace lab01
