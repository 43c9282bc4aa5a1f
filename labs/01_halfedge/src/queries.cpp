// Task 2: the lecture's queries (handout §4).
#include "geolab/halfedge.hpp"

namespace geolab::halfedge {

std::pair<Vertex, Vertex> edge_vertices(const Mesh& mesh, Edge e) {
    throw geolab::NotImplemented(__func__);
}

std::pair<Face, Face> edge_faces(const Mesh& mesh, Edge e) {
    throw geolab::NotImplemented(__func__);
}

void face_halfedges(const Mesh& mesh, Face f, std::vector<Halfedge>& out) {
    throw geolab::NotImplemented(__func__);
}

void outgoing_halfedges(const Mesh& mesh, Vertex v, std::vector<Halfedge>& out) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::halfedge
