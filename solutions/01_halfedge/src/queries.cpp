// Task 2: the lecture's queries (handout §4).
#include "geolab/halfedge.hpp"

namespace geolab::halfedge {

std::pair<Vertex, Vertex> edge_vertices(const Mesh& mesh, Edge e) {
    // BEGIN SOLUTION
    const Halfedge h = mesh.halfedge(e, 0);
    return {mesh.from_vertex(h), mesh.to_vertex(h)};
    // END SOLUTION
}

std::pair<Face, Face> edge_faces(const Mesh& mesh, Edge e) {
    // BEGIN SOLUTION
    return {mesh.face(mesh.halfedge(e, 0)), mesh.face(mesh.halfedge(e, 1))};
    // END SOLUTION
}

void face_halfedges(const Mesh& mesh, Face f, std::vector<Halfedge>& out) {
    // BEGIN SOLUTION
    out.clear();
    const Halfedge h0 = mesh.halfedge(f);
    Halfedge h = h0;
    do {  // follow next until back at the start
        out.push_back(h);
        h = mesh.next(h);
    } while (h != h0);
    // END SOLUTION
}

void outgoing_halfedges(const Mesh& mesh, Vertex v, std::vector<Halfedge>& out) {
    // BEGIN SOLUTION
    out.clear();
    const Halfedge h0 = mesh.halfedge(v);
    if (!h0.is_valid()) return;  // isolated vertex
    Halfedge h = h0;
    do {  // edge = edge->pair->next until back at the start
        out.push_back(h);
        h = mesh.next(mesh.twin(h));
    } while (h != h0);
    // END SOLUTION
}

}  // namespace geolab::halfedge
