// ADVERSARIAL CASE change_test_data: the queries answer nothing useful, and instead rewrite the test's own mesh
// (const_cast) so that it agrees with them: every half-face's loop emptied of its vertices' positions, the deleted
// flags set, the properties zeroed. The judge keeps its own copy of the test's data (and compares every later call's
// arguments with it): rewriting the student's copy moves no verdict. Honest: 0.
#include <algorithm>
#include <tuple>
#include <vector>

#include "geolab/halfface.hpp"

namespace geolab::halfface {
namespace {
void rewrite(const Mesh& mesh) {
    auto fields = const_cast<Mesh&>(mesh).geolab_fields();
    for (auto& p : std::get<0>(fields)) p = glm::dvec3(0.0);
    for (auto& d : std::get<2>(fields)) d = 1;
    for (auto& p : std::get<21>(fields)) std::fill(p.bytes.begin(), p.bytes.end(), 0);
}
}  // namespace

void halfface_vertices(const Mesh& mesh, HalfFace, std::vector<Vertex>& out) { out.clear(); rewrite(mesh); }
std::pair<Cell, Cell> face_cells(const Mesh& mesh, Face) { rewrite(mesh); return {}; }
void cell_vertices(const Mesh& mesh, Cell, std::vector<Vertex>& out) { out.clear(); rewrite(mesh); }
void boundary_halffaces(const Mesh& mesh, std::vector<HalfFace>& out) { out.clear(); rewrite(mesh); }
void edge_cells(const Mesh& mesh, Edge, std::vector<Cell>& out) { out.clear(); rewrite(mesh); }
void vertex_cells(const Mesh& mesh, Vertex, std::vector<Cell>& out) { out.clear(); rewrite(mesh); }

}  // namespace geolab::halfface
