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
    const Vertex b = mesh.edge_vertices(e)[1];
    // Any half-edge of e directed b -> a with a cell: the edge's half-edge, its mate, or the walk to one.
    HalfEdge h = mesh.halfedge(e);
    if (!h.is_valid()) return;
    if (mesh.from_vertex(h) != b) h = mesh.mate(h);
    if (mesh.is_boundary(mesh.halfface(h))) {
        // a boundary half-face: the cell on the other side of its face has the same edge reversed (mate), whose
        // twin is b -> a in that cell
        const HalfEdge g = mesh.mate(h);
        if (mesh.is_boundary(mesh.halfface(g))) return;  // a face with no cell on either side
        h = mesh.twin(g);
    }
    // Walk backwards to the start: the previous cell's b -> a half-edge is twin(mate(h)).
    const HalfEdge start = h;
    for (;;) {
        const HalfEdge back = mesh.mate(h);
        if (mesh.is_boundary(mesh.halfface(back))) break;  // h's cell is the first of a fan
        h = mesh.twin(back);
        if (h == start) {  // a full turn: start at the lowest cell
            HalfEdge best = h;
            HalfEdge g = h;
            do {
                g = mesh.mate(mesh.twin(g));
                if (mesh.cell(mesh.halfface(g)) < mesh.cell(mesh.halfface(best))) best = g;
            } while (g != h);
            h = best;
            break;
        }
    }
    const HalfEdge first = h;
    do {
        out.push_back(mesh.cell(mesh.halfface(h)));
        h = mesh.mate(mesh.twin(h));
    } while (h != first && !mesh.is_boundary(mesh.halfface(h)));
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
