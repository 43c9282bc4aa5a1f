// Task 4: geometry (handout §6).
#include <glm/geometric.hpp>

#include "geolab/halfedge.hpp"

namespace geolab::halfedge {
namespace {
// Helper functions of your own can go here.
}  // namespace

glm::dvec3 face_normal(const Mesh& mesh, Face f) {
    throw geolab::NotImplemented(__func__);
}

double face_area(const Mesh& mesh, Face f) {
    throw geolab::NotImplemented(__func__);
}

glm::dvec3 vertex_normal(const Mesh& mesh, Vertex v) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::halfedge
