// Task 2: queries and circulators (handout §4).
#include <algorithm>

#include "geolab/halfface.hpp"

namespace geolab::halfface {

void halfface_vertices(const Mesh& mesh, HalfFace hf, std::vector<Vertex>& out) {
    throw geolab::NotImplemented(__func__);
}

std::pair<Cell, Cell> face_cells(const Mesh& mesh, Face f) {
    throw geolab::NotImplemented(__func__);
}

void cell_vertices(const Mesh& mesh, Cell c, std::vector<Vertex>& out) {
    throw geolab::NotImplemented(__func__);
}

void boundary_halffaces(const Mesh& mesh, std::vector<HalfFace>& out) {
    throw geolab::NotImplemented(__func__);
}

void edge_cells(const Mesh& mesh, Edge e, std::vector<Cell>& out) {
    throw geolab::NotImplemented(__func__);
}

void vertex_cells(const Mesh& mesh, Vertex v, std::vector<Cell>& out) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::halfface
