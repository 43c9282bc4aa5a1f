// Task 5: the boundary surface (handout §7).
#include "geolab/halfface.hpp"

namespace geolab::halfface {

PolygonSoup boundary_surface(const Mesh& mesh) {
    // BEGIN SOLUTION
    std::vector<HalfFace> hfs;
    boundary_halffaces(mesh, hfs);
    std::vector<std::uint32_t> index(mesh.n_vertices(), invalid_index);
    std::vector<Vertex> loop;
    for (HalfFace hf : hfs) {
        halfface_vertices(mesh, hf, loop);
        for (Vertex v : loop) index[v.idx] = 0;
    }
    PolygonSoup soup;
    for (Vertex v : mesh.vertices())
        if (index[v.idx] == 0) {
            index[v.idx] = std::uint32_t(soup.positions.size());
            soup.positions.push_back(mesh.position(v));
        }
    std::vector<std::uint32_t> face;
    for (HalfFace hf : hfs) {
        halfface_vertices(mesh, hf, loop);
        face.clear();
        for (auto it = loop.rbegin(); it != loop.rend(); ++it) face.push_back(index[it->idx]);
        soup.add_face(face);
    }
    return soup;
    // END SOLUTION
}

}  // namespace geolab::halfface
