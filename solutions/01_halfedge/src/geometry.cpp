// Task 4: geometry (handout §6).
#include <glm/geometric.hpp>

#include "geolab/halfedge.hpp"

namespace geolab::halfedge {
namespace {
// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.

// Newell's vector of face f: Σ p_i × p_{i+1} = twice the vector area (area times unit normal).
// Taken relative to the first corner, which gives the same sum with less cancellation far from the origin.
glm::dvec3 newell_vector(const Mesh& mesh, Face f) {
    const Halfedge h0 = mesh.halfedge(f);
    const glm::dvec3 o = mesh.position(mesh.from_vertex(h0));
    glm::dvec3 n(0.0);
    Halfedge h = h0;
    do {
        n += glm::cross(mesh.position(mesh.from_vertex(h)) - o, mesh.position(mesh.to_vertex(h)) - o);
        h = mesh.next(h);
    } while (h != h0);
    return n;
}

glm::dvec3 normalized_or_zero(const glm::dvec3& n) {
    const double len = glm::length(n);
    return len > 0.0 ? n / len : glm::dvec3(0.0);
}
// END SOLUTION
}  // namespace

glm::dvec3 face_normal(const Mesh& mesh, Face f) {
    // BEGIN SOLUTION
    return normalized_or_zero(newell_vector(mesh, f));
    // END SOLUTION
}

double face_area(const Mesh& mesh, Face f) {
    // BEGIN SOLUTION
    return 0.5 * glm::length(newell_vector(mesh, f));
    // END SOLUTION
}

glm::dvec3 vertex_normal(const Mesh& mesh, Vertex v) {
    // BEGIN SOLUTION
    // Σ area(f)·normal(f) = ½ Σ newell(f): the faces' vector areas, so larger faces weigh more.
    glm::dvec3 n(0.0);
    for (Face f : one_ring_faces(mesh, v)) n += newell_vector(mesh, f);
    return normalized_or_zero(n);
    // END SOLUTION
}

}  // namespace geolab::halfedge
