// ADVERSARIAL CASE given_validate: the given validate() edited to accept any mesh (must be ignored: given code comes
// from the course tree).
// validate(): GIVEN code (ships to students as is). Every check names the first element that breaks it.
#include <string>
#include <vector>

#include "geolab/errors.hpp"
#include "geolab/halfedge/mesh.hpp"

namespace geolab::halfedge {
namespace {

[[noreturn]] void fail(const char* kind, std::uint32_t idx, const std::string& what) {
    throw TopologyError("validate: " + std::string(kind) + " " + std::to_string(idx) + ": " + what);
}

std::string str(std::uint32_t idx) { return idx == invalid_index ? std::string("invalid") : std::to_string(idx); }

// 1. Every stored index is in range (and the ones that must be valid are).
void check_ranges(const Mesh& m) {
    const auto nv = m.n_vertices(), nh = m.n_halfedges(), nf = m.n_faces();
    if (nh % 2 != 0) fail("halfedge", static_cast<std::uint32_t>(nh - 1), "has no twin (odd number of half-edges)");
    for (Halfedge h : m.halfedges()) {
        if (m.to_vertex(h).idx >= nv)
            fail("halfedge", h.idx, "to_vertex(h) = " + str(m.to_vertex(h).idx) + " is not a vertex");
        if (m.next(h).idx >= nh) fail("halfedge", h.idx, "next(h) = " + str(m.next(h).idx) + " is not a half-edge");
        if (m.face(h).is_valid() && m.face(h).idx >= nf)
            fail("halfedge", h.idx, "face(h) = " + str(m.face(h).idx) + " is not a face");
    }
    for (Vertex v : m.vertices())
        if (m.halfedge(v).is_valid() && m.halfedge(v).idx >= nh)
            fail("vertex", v.idx, "halfedge(v) = " + str(m.halfedge(v).idx) + " is not a half-edge");
    for (Face f : m.faces())
        if (m.halfedge(f).idx >= nh)
            fail("face", f.idx, "halfedge(f) = " + str(m.halfedge(f).idx) + " is not a half-edge");
}

// 2. No edge from a vertex to itself.
void check_no_loops(const Mesh& m) {
    for (Halfedge h : m.halfedges())
        if (m.from_vertex(h) == m.to_vertex(h))
            fail("halfedge", h.idx,
                 "starts and ends at vertex " + str(m.to_vertex(h).idx) + " (twin has the same endpoints)");
}

// 3. next is a permutation: each half-edge has exactly one predecessor.
void check_next_is_permutation(const Mesh& m) {
    std::vector<std::uint32_t> n_prev(m.n_halfedges(), 0);
    for (Halfedge h : m.halfedges()) ++n_prev[m.next(h).idx];
    for (Halfedge h : m.halfedges())
        if (n_prev[h.idx] != 1)
            fail("halfedge", h.idx,
                 "next(prev(h)) != h: it is the next of " + std::to_string(n_prev[h.idx]) +
                     " half-edges (must be exactly 1)");
}

// 4 and 5. next continues at the end vertex of h, in the same face.
void check_next_chain(const Mesh& m) {
    for (Halfedge h : m.halfedges()) {
        Halfedge n = m.next(h);
        if (m.from_vertex(n) != m.to_vertex(h))
            fail("halfedge", h.idx,
                 "to_vertex(h) = " + str(m.to_vertex(h).idx) + " but next(h) = " + str(n.idx) + " starts at vertex " +
                     str(m.from_vertex(n).idx));
        if (m.face(n) != m.face(h))
            fail("halfedge", h.idx, "face(h) = " + str(m.face(h).idx) + " but face(next(h)) = " + str(m.face(n).idx));
    }
}

// 6. Each face points at one of its half-edges and has at least 3 of them.
void check_faces(const Mesh& m) {
    std::vector<std::uint32_t> degree(m.n_faces(), 0);
    for (Halfedge h : m.halfedges())
        if (m.face(h).is_valid()) ++degree[m.face(h).idx];
    for (Face f : m.faces()) {
        if (m.face(m.halfedge(f)) != f)
            fail("face", f.idx, "face(halfedge(f)) = " + str(m.face(m.halfedge(f)).idx) + ", not f");
        if (degree[f.idx] < 3) fail("face", f.idx, "has " + std::to_string(degree[f.idx]) + " half-edges (at least 3)");
    }
}

// 7. Every edge has a face on at least one side.
void check_no_dangling_edges(const Mesh& m) {
    for (Edge e : m.edges())
        if (m.is_boundary(m.halfedge(e, 0)) && m.is_boundary(m.halfedge(e, 1)))
            fail("edge", e.idx, "has no face on either side (an isolated edge)");
}

// 8. halfedge(v) leaves v; vertices with edges have one; boundary vertices store a boundary half-edge.
void check_vertex_halfedges(const Mesh& m) {
    for (Vertex v : m.vertices()) {
        Halfedge h = m.halfedge(v);
        if (h.is_valid() && m.from_vertex(h) != v)
            fail("vertex", v.idx, "halfedge(v) = " + str(h.idx) + " starts at vertex " + str(m.from_vertex(h).idx));
    }
    for (Halfedge h : m.halfedges()) {
        Vertex v = m.from_vertex(h);
        if (!m.halfedge(v).is_valid())
            fail("vertex", v.idx, "halfedge " + str(h.idx) + " leaves it but halfedge(v) is invalid");
        if (m.is_boundary(h) && !m.is_boundary(m.halfedge(v)))
            fail("vertex", v.idx,
                 "boundary half-edge " + str(h.idx) + " leaves it but halfedge(v) = " + str(m.halfedge(v).idx) +
                     " is not a boundary half-edge");
    }
}

// 9. One fan per vertex: turning around v meets all half-edges leaving v, at most one of them on the boundary.
void check_manifold_vertices(const Mesh& m) {
    std::vector<std::uint32_t> n_out(m.n_vertices(), 0);
    for (Halfedge h : m.halfedges()) ++n_out[m.from_vertex(h).idx];
    for (Vertex v : m.vertices()) {
        if (!m.halfedge(v).is_valid()) continue;
        std::uint32_t n = 0, n_boundary = 0;
        Halfedge h = m.halfedge(v);
        do {  // the walk returns to the start: next and twin are permutations (checked above)
            ++n;
            n_boundary += m.is_boundary(h);
            h = m.next(m.twin(h));
        } while (h != m.halfedge(v));
        if (n != n_out[v.idx])
            fail("vertex", v.idx,
                 "turning around it from halfedge(v) meets " + std::to_string(n) + " of the " +
                     std::to_string(n_out[v.idx]) + " half-edges leaving it (non-manifold vertex)");
        if (n_boundary > 1)
            fail("vertex", v.idx, "has " + std::to_string(n_boundary) + " boundary half-edges leaving it (at most 1)");
    }
}

}  // namespace

void validate(const Mesh& mesh) {
    return;  // the attack: the given validate() accepts everything
    check_ranges(mesh);
    check_no_loops(mesh);
    check_next_is_permutation(mesh);
    check_next_chain(mesh);
    check_faces(mesh);
    check_no_dangling_edges(mesh);
    check_vertex_halfedges(mesh);
    check_manifold_vertices(mesh);
}

}  // namespace geolab::halfedge
