// ADVERSARIAL CASE trivial_answers: every function of lab 02 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 2: queries and circulators (handout §4).
#include <algorithm>

#include "geolab/halfface.hpp"

namespace geolab::halfface {

void halfface_vertices(const Mesh& mesh, HalfFace hf, std::vector<Vertex>& out) {
    return;
}

std::pair<Cell, Cell> face_cells(const Mesh& mesh, Face f) {
    return {};
}

void cell_vertices(const Mesh& mesh, Cell c, std::vector<Vertex>& out) {
    return;
}

void boundary_halffaces(const Mesh& mesh, std::vector<HalfFace>& out) {
    return;
}

void edge_cells(const Mesh& mesh, Edge e, std::vector<Cell>& out) {
    return;
}

void vertex_cells(const Mesh& mesh, Vertex v, std::vector<Cell>& out) {
    return;
}

}  // namespace geolab::halfface
