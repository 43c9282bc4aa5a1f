// ADVERSARIAL CASE hostile_handles (see queries.cpp): deletion marks nothing; the collection truncates the cell list
// and a property's bytes, and maps every element to a handle the mesh does not have.
#include <tuple>

#include "geolab/halfface.hpp"

namespace geolab::halfface {

void delete_cell(Mesh&, Cell) {}
void delete_vertex(Mesh&, Vertex) {}

Remap garbage_collection(Mesh& mesh) {
    Remap r;
    r.cells.assign(mesh.n_cells() + 5, 0xfffffffeu);
    r.vertices.assign(mesh.n_vertices(), 0xfffffffdu);
    auto fields = mesh.geolab_fields();  // the boundary's accessor reaches the private arrays
    auto& cell_begin = std::get<16>(fields);
    cell_begin.resize(cell_begin.size() / 2);
    for (auto& p : std::get<21>(fields))
        if (!p.bytes.empty()) p.bytes.resize(p.bytes.size() / 3);
    return r;
}

}  // namespace geolab::halfface
