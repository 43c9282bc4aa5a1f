// Task 2: queries and circulators (handout §4).
#include <algorithm>

#include "geolab/halfface.hpp"

namespace geolab::halfface {

void halfface_vertices(const Mesh& mesh, HalfFace hf, std::vector<Vertex>& out) {
    // BEGIN SOLUTION
    out.clear();
    const HalfEdge h0 = mesh.halfedge(hf);
    HalfEdge h = h0;
    do {
        out.push_back(mesh.from_vertex(h));
        h = mesh.next(h);
    } while (h != h0);
    // END SOLUTION
}

std::pair<Cell, Cell> face_cells(const Mesh& mesh, Face f) {
    // BEGIN SOLUTION
    return {mesh.cell(Mesh::halfface(f, 0)), mesh.cell(Mesh::halfface(f, 1))};
    // END SOLUTION
}

void cell_vertices(const Mesh& mesh, Cell c, std::vector<Vertex>& out) {
    // BEGIN SOLUTION
    out.clear();
    std::vector<Vertex> loop;
    for (HalfFace hf : mesh.halffaces(c)) {
        halfface_vertices(mesh, hf, loop);
        for (Vertex v : loop)
            if (std::find(out.begin(), out.end(), v) == out.end()) out.push_back(v);
    }
    // END SOLUTION
}

void boundary_halffaces(const Mesh& mesh, std::vector<HalfFace>& out) {
    // BEGIN SOLUTION
    out.clear();
    for (HalfFace hf : mesh.halffaces())
        if (!mesh.is_deleted(hf) && mesh.is_boundary(hf) && !mesh.is_boundary(Mesh::opposite(hf))) out.push_back(hf);
    // END SOLUTION
}

void edge_cells(const Mesh& mesh, Edge e, std::vector<Cell>& out) {
    // BEGIN SOLUTION
    out.clear();
    // A half-edge of e directed b -> a (b = edge_vertices(e)[1]) in a cell: the edge's half-edge or its mate, or
    // when that side is a boundary half-face, the twin of the mate (b -> a in the cell on the other side).
    HalfEdge h = mesh.halfedge(e);
    if (!h.is_valid()) return;
    if (mesh.from_vertex(h) != mesh.edge_vertices(e)[1]) h = mesh.mate(h);
    if (mesh.is_boundary(mesh.halfface(h))) {
        const HalfEdge g = mesh.mate(h);
        if (mesh.is_boundary(mesh.halfface(g))) return;  // a face with no cell on either side
        h = mesh.twin(g);
    }
    // Forwards: the next cell's b -> a half-edge is mate(twin(h)); stop back at the start (an interior edge: a
    // full turn) or at a boundary half-face (the end of a fan).
    const HalfEdge start = h;
    do {
        out.push_back(mesh.cell(mesh.halfface(h)));
        h = mesh.mate(mesh.twin(h));
    } while (h != start && !mesh.is_boundary(mesh.halfface(h)));
    if (h == start) {  // a full turn: start at the lowest cell
        std::rotate(out.begin(), std::min_element(out.begin(), out.end()), out.end());
        return;
    }
    // A fan: the cells before the start, backwards (the previous cell's b -> a half-edge is twin(mate(h))), go
    // in front, so that the list starts at the boundary.
    const std::size_t n_forward = out.size();
    for (h = start; !mesh.is_boundary(mesh.halfface(mesh.mate(h)));) {
        h = mesh.twin(mesh.mate(h));
        out.push_back(mesh.cell(mesh.halfface(h)));
    }
    std::reverse(out.begin() + std::ptrdiff_t(n_forward), out.end());
    std::rotate(out.begin(), out.begin() + std::ptrdiff_t(n_forward), out.end());
    // END SOLUTION
}

void vertex_cells(const Mesh& mesh, Vertex v, std::vector<Cell>& out) {
    // BEGIN SOLUTION
    out.clear();
    for (HalfFace hf : mesh.vertex_halffaces(v))
        if (!mesh.is_deleted(hf) && mesh.cell(hf).is_valid()) out.push_back(mesh.cell(hf));
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    // END SOLUTION
}

}  // namespace geolab::halfface
