// ADVERSARIAL CASE always_throws: every function of lab 02 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 2: queries and circulators (handout §4).
#include <algorithm>

#include "geolab/halfface.hpp"

namespace geolab::halfface {

void halfface_vertices(const Mesh& mesh, HalfFace hf, std::vector<Vertex>& out) {
    throw std::invalid_argument(__func__);
}

std::pair<Cell, Cell> face_cells(const Mesh& mesh, Face f) {
    throw std::invalid_argument(__func__);
}

void cell_vertices(const Mesh& mesh, Cell c, std::vector<Vertex>& out) {
    throw std::invalid_argument(__func__);
}

void boundary_halffaces(const Mesh& mesh, std::vector<HalfFace>& out) {
    throw std::invalid_argument(__func__);
}

void edge_cells(const Mesh& mesh, Edge e, std::vector<Cell>& out) {
    throw std::invalid_argument(__func__);
}

void vertex_cells(const Mesh& mesh, Vertex v, std::vector<Cell>& out) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::halfface
