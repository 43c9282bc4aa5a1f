// GIVEN: the invariants of a half-face mesh (declared in geolab/halfface/mesh.hpp). You do not write this file.
#include <algorithm>
#include <sstream>
#include <string>

#include "geolab/halfface.hpp"

namespace geolab::halfface {

namespace {

template <class... A>
[[noreturn]] void fail(const A&... parts) {
    std::ostringstream os;
    os << "validate: ";
    (os << ... << parts);
    throw TopologyError(os.str());
}

}  // namespace

void validate(const Mesh& m) {
    const std::size_t nv = m.n_vertices(), ne = m.n_edges(), nh = m.n_halfedges(), nhf = m.n_halffaces(),
                      nc = m.n_cells();
    if (nhf != 2 * m.n_faces()) fail(nhf, " half-faces for ", m.n_faces(), " faces (must be twice as many)");
    // 1. ranges of the half-edges' handles
    for (HalfEdge h : m.halfedges()) {
        if (m.is_deleted(h)) continue;
        if (m.to_vertex(h).idx >= nv) fail(h, ": to_vertex out of range");
        if (m.edge(h).idx >= ne) fail(h, ": edge out of range");
        if (m.next(h).idx >= nh) fail(h, ": next out of range");
        if (m.mate(h).idx >= nh) fail(h, ": mate invalid or out of range");
        if (m.prev(h).idx >= nh) fail(h, ": prev invalid or out of range");
        if (m.twin(h).is_valid() && m.twin(h).idx >= nh) fail(h, ": twin out of range");
        if (m.is_deleted(m.edge(h))) fail(h, ": its edge ", m.edge(h), " is deleted");
        const auto ev = m.edge_vertices(m.edge(h));
        if (ev[0].idx >= nv || ev[1].idx >= nv || ev[0] == ev[1]) fail(m.edge(h), ": bad end vertices");
        if (ev[0] != m.to_vertex(h) && ev[1] != m.to_vertex(h)) fail(h, ": to_vertex is not an end of its edge");
    }
    for (HalfFace hf : m.halffaces()) {
        if (m.is_deleted(hf)) continue;
        if (m.cell(hf).is_valid() && m.cell(hf).idx >= nc) fail(hf, ": cell out of range");
        if (m.cell(hf).is_valid() && m.is_deleted(m.cell(hf))) fail(hf, ": its cell ", m.cell(hf), " is deleted");
        const HalfEdge h0 = m.halfedge(hf);
        if (h0.idx >= nh) fail(hf, ": halfedge invalid or out of range");
        // 2. the loop
        std::size_t k = 0;
        HalfEdge h = h0;
        do {
            if (m.halfface(h) != hf) fail(h, " is on the loop of ", hf, " but halfface(h) = ", m.halfface(h));
            if (m.next(m.prev(h)) != h) fail(h, ": next(prev(h)) != h");
            if (m.from_vertex(m.next(h)) != m.to_vertex(h)) fail(h, ": next(h) does not start where h ends");
            if (++k > nh) fail(hf, ": its loop does not close");
            h = m.next(h);
        } while (h != h0);
        if (k < 3) fail(hf, ": its loop has ", k, " half-edges (at least 3)");
        if (!m.cell(hf).is_valid() && !m.cell(Mesh::opposite(hf)).is_valid())
            fail(Mesh::face(hf), ": alive with no cell on either side");
    }
    for (HalfEdge h : m.halfedges()) {
        if (m.is_deleted(h)) continue;
        // 3. mate and twin
        const HalfEdge g = m.mate(h);
        if (m.halfface(g) != Mesh::opposite(m.halfface(h)) || m.edge(g) != m.edge(h) ||
            m.to_vertex(g) != m.from_vertex(h) || m.mate(g) != h)
            fail(h, ": mate(h) = ", g, " is not the reversed same edge of the opposite half-face");
        const bool has_cell = m.cell(m.halfface(h)).is_valid();
        const HalfEdge t = m.twin(h);
        if (has_cell != t.is_valid())
            fail(h, has_cell ? ": its half-face has a cell but twin(h) is invalid"
                             : ": its half-face has no cell but twin(h) is valid");
        if (t.is_valid()) {
            if (m.is_deleted(t) || m.cell(m.halfface(t)) != m.cell(m.halfface(h)) || m.halfface(t) == m.halfface(h) ||
                m.edge(t) != m.edge(h) || m.to_vertex(t) != m.from_vertex(h) || m.twin(t) != h)
                fail(h, ": twin(h) = ", t, " is not the reversed same edge in another half-face of its cell");
        }
    }
    // 4. cells
    for (Cell c : m.cells()) {
        if (m.is_deleted(c)) continue;
        for (HalfFace hf : m.halffaces(c)) {
            if (hf.idx >= nhf || m.is_deleted(hf)) fail(c, ": half-face ", hf, " out of range or deleted");
            if (m.cell(hf) != c) fail(c, ": lists ", hf, " but cell(hf) = ", m.cell(hf));
        }
    }
    for (HalfFace hf : m.halffaces())
        if (!m.is_deleted(hf) && m.cell(hf).is_valid()) {
            const auto hfs = m.halffaces(m.cell(hf));
            if (std::find(hfs.begin(), hfs.end(), hf) == hfs.end()) fail(hf, ": not listed by its cell ", m.cell(hf));
        }
    // 5. entry points
    std::vector<std::uint8_t> used(nv, 0);
    std::vector<std::vector<HalfFace>> around(nv);
    for (HalfEdge h : m.halfedges())
        if (!m.is_deleted(h)) used[m.from_vertex(h).idx] = 1, around[m.to_vertex(h).idx].push_back(m.halfface(h));
    for (Edge e : m.edges()) {
        if (m.is_deleted(e)) continue;
        const HalfEdge h = m.halfedge(e);
        if (h.idx >= nh || m.is_deleted(h) || m.edge(h) != e) fail(e, ": halfedge(e) = ", h, " is not an alive half-edge of e");
    }
    for (Vertex v : m.vertices()) {
        if (m.is_deleted(v)) continue;
        const HalfEdge h = m.halfedge(v);
        if (!used[v.idx]) {
            if (h.is_valid()) fail(v, ": used by no face but halfedge(v) = ", h);
            continue;
        }
        if (h.idx >= nh || m.is_deleted(h) || m.from_vertex(h) != v)
            fail(v, ": halfedge(v) = ", h, " is not an alive half-edge leaving v");
        // 6. the cache
        std::sort(around[v.idx].begin(), around[v.idx].end());
        if (Mesh::traits::vertex_cache && m.vertex_halffaces(v) != around[v.idx])
            fail(v, ": the vertex cache does not list the half-faces around v");
    }
}

}  // namespace geolab::halfface
