#pragma once
// Lab 02 hidden tests: an independent builder (std::map based, no error checks) for the meshes of Tasks 2-5 that
// are too large to store as data. Hidden: not in the student release. It follows the numbering rules of
// build_mesh's contract for faces and half-faces (half-edges and edges in its own order).
#include <map>
#include <utility>
#include <vector>

#include "geolab/halfface/cells.hpp"
#include "geolab/halfface/mesh.hpp"

namespace lab02 {

inline geolab::halfface::Mesh hidden_build(const geolab::halfface::CellList& cl) {
    using namespace geolab::halfface;
    Mesh m;
    for (const auto& p : cl.positions) m.add_vertex(p);
    std::map<std::vector<std::uint32_t>, Face> face_of_key;
    std::map<std::pair<std::uint32_t, std::uint32_t>, Edge> edge_of;
    auto edge = [&](std::uint32_t a, std::uint32_t b) {
        const auto key = std::make_pair(std::min(a, b), std::max(a, b));
        auto it = edge_of.find(key);
        if (it != edge_of.end()) return it->second;
        const Edge e = m.add_edge(Vertex{a}, Vertex{b});
        edge_of[key] = e;
        return e;
    };
    for (std::size_t c = 0; c < cl.n_cells(); ++c) {
        std::vector<HalfFace> hfs;
        for (std::size_t i = 0; i < cl.n_faces(c); ++i) {
            const auto f = cl.face(c, i);
            std::vector<std::uint32_t> key(f.begin(), f.end());
            std::sort(key.begin(), key.end());
            auto it = face_of_key.find(key);
            if (it != face_of_key.end()) {
                hfs.push_back(Mesh::halfface(it->second, 1));
                continue;
            }
            const Face face = m.add_face();
            face_of_key[key] = face;
            const std::size_t k = f.size();
            std::vector<HalfEdge> side[2];
            for (unsigned s = 0; s < 2; ++s) {
                for (std::size_t j = 0; j < k; ++j) {
                    const std::uint32_t from = s == 0 ? f[j] : f[(k - j) % k];
                    const std::uint32_t to = s == 0 ? f[(j + 1) % k] : f[(2 * k - j - 1) % k];
                    const HalfEdge h = m.add_halfedge(edge(from, to), Vertex{to}, Mesh::halfface(face, s));
                    side[s].push_back(h);
                    if (!m.halfedge(m.edge(h)).is_valid()) m.set_halfedge(m.edge(h), h);
                    if (!m.halfedge(Vertex{from}).is_valid()) m.set_halfedge(Vertex{from}, h);
                }
                m.set_halfedge(Mesh::halfface(face, s), side[s][0]);
            }
            for (unsigned s = 0; s < 2; ++s)
                for (std::size_t j = 0; j < k; ++j) {
                    m.set_next(side[s][j], side[s][(j + 1) % k]);
                    m.set_prev(side[s][j], side[s][(j + k - 1) % k]);
                    m.set_mate(side[s][j], side[1 - s][k - 1 - j]);
                }
            hfs.push_back(Mesh::halfface(face, 0));
        }
        const Cell cell = m.add_cell(hfs);
        std::map<std::pair<std::uint32_t, std::uint32_t>, HalfEdge> directed;
        for (HalfFace hf : hfs) {
            m.set_cell(hf, cell);
            HalfEdge h = m.halfedge(hf);
            const HalfEdge h0 = h;
            do {
                directed[{m.from_vertex(h).idx, m.to_vertex(h).idx}] = h;
                h = m.next(h);
            } while (h != h0);
        }
        for (auto& [uv, h] : directed) {
            auto back = directed.find({uv.second, uv.first});
            if (back != directed.end()) m.set_twin(h, back->second);
        }
    }
    m.rebuild_vertex_cache();
    return m;
}

}  // namespace lab02
