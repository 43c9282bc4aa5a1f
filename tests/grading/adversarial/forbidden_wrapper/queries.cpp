// ADVERSARIAL CASE forbidden_wrapper: queries.cpp gets a wrapper of the forbidden one_ring_vertices; smoothing.cpp
// calls the wrapper (nm -u of smoothing.o shows only the wrapper).
// Task 2: the lecture's queries (handout §4).
#include "geolab/halfedge.hpp"

namespace geolab::halfedge {

std::pair<Vertex, Vertex> edge_vertices(const Mesh& mesh, Edge e) {
    const Halfedge h = mesh.halfedge(e, 0);
    return {mesh.from_vertex(h), mesh.to_vertex(h)};
}

std::pair<Face, Face> edge_faces(const Mesh& mesh, Edge e) {
    return {mesh.face(mesh.halfedge(e, 0)), mesh.face(mesh.halfedge(e, 1))};
}

void face_halfedges(const Mesh& mesh, Face f, std::vector<Halfedge>& out) {
    out.clear();
    const Halfedge h0 = mesh.halfedge(f);
    Halfedge h = h0;
    do {  // follow next until back at the start
        out.push_back(h);
        h = mesh.next(h);
    } while (h != h0);
}

void outgoing_halfedges(const Mesh& mesh, Vertex v, std::vector<Halfedge>& out) {
    out.clear();
    const Halfedge h0 = mesh.halfedge(v);
    if (!h0.is_valid()) return;  // isolated vertex
    Halfedge h = h0;
    do {  // edge = edge->pair->next until back at the start
        out.push_back(h);
        h = mesh.next(mesh.twin(h));
    } while (h != h0);
}

void ring_of(const Mesh& mesh, Vertex v, std::vector<Vertex>& out) { one_ring_vertices(mesh, v, out); }

}  // namespace geolab::halfedge
