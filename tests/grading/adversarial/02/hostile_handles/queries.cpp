// ADVERSARIAL CASE hostile_handles: every query answers handles no mesh has (2^32 − 2, just below the invalid
// handle), a million of them, or the test's own elements doubled; garbage_collection (garbage.cpp) leaves the mesh
// with a cell list that ends early, a property whose bytes are short, and maps to nowhere. The judge's containers
// check every index (the test stops) and the property accessors check the bytes: nothing is read outside an
// answer. Honest: 0.
#include <vector>

#include "geolab/halfface.hpp"

namespace geolab::halfface {
namespace {
constexpr std::uint32_t far = 0xfffffffeu;
}

void halfface_vertices(const Mesh&, HalfFace, std::vector<Vertex>& out) { out.assign(1u << 20, Vertex{far}); }
std::pair<Cell, Cell> face_cells(const Mesh&, Face) { return {Cell{far}, Cell{far - 1}}; }
void cell_vertices(const Mesh& mesh, Cell, std::vector<Vertex>& out) {
    out.clear();
    for (Vertex v : mesh.vertices()) out.push_back(v), out.push_back(v);
}
void boundary_halffaces(const Mesh&, std::vector<HalfFace>& out) { out.assign(3, HalfFace{far}); }
void edge_cells(const Mesh&, Edge, std::vector<Cell>& out) { out.assign(2, Cell{far}); }
void vertex_cells(const Mesh&, Vertex, std::vector<Cell>& out) { out.assign(2, Cell{far}); }

}  // namespace geolab::halfface
