// Task 3: topology (handout §5).
#include <algorithm>
#include <vector>

#include "geolab/halfedge.hpp"

namespace geolab::halfedge {

int valence(const Mesh& mesh, Vertex v) {
    throw geolab::NotImplemented(__func__);
}

void one_ring_vertices(const Mesh& mesh, Vertex v, std::vector<Vertex>& out) {
    throw geolab::NotImplemented(__func__);
}

void one_ring_faces(const Mesh& mesh, Vertex v, std::vector<Face>& out) {
    throw geolab::NotImplemented(__func__);
}

std::vector<std::vector<Halfedge>> boundary_loops(const Mesh& mesh) {
    throw geolab::NotImplemented(__func__);
}

int euler_characteristic(const Mesh& mesh) {
    throw geolab::NotImplemented(__func__);
}

Components connected_components(const Mesh& mesh) {
    throw geolab::NotImplemented(__func__);
}

int genus(const Mesh& mesh) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::halfedge
