// Task 3: deletion and garbage collection (handout §5).
#include <algorithm>

#include "geolab/halfface.hpp"

namespace geolab::halfface {

void delete_cell(Mesh& mesh, Cell c) {
    // BEGIN SOLUTION
    if (mesh.is_deleted(c)) return;
    std::vector<HalfEdge> hes;  // the cell's half-edges
    for (HalfFace hf : mesh.halffaces(c)) {
        HalfEdge h = mesh.halfedge(hf);
        const HalfEdge h0 = h;
        do {
            hes.push_back(h);
            h = mesh.next(h);
        } while (h != h0);
    }
    mesh.set_deleted(c, true);
    for (HalfFace hf : mesh.halffaces(c)) {
        mesh.set_cell(hf, Cell{});
        if (!mesh.cell(Mesh::opposite(hf)).is_valid()) mesh.set_deleted(Mesh::face(hf), true);
    }
    for (HalfEdge h : hes) mesh.set_twin(h, HalfEdge{});
    mesh.rebuild_vertex_cache();
    // Edges and vertices whose half-edge died: another alive half-edge through the cache of the start vertex (the
    // cells left around an edge need not be connected any more), or delete the edge / isolate the vertex.
    auto alive_leaving = [&](Vertex v, auto&& accept) {
        for (HalfFace hf : mesh.vertex_halffaces(v)) {
            HalfEdge h = mesh.halfedge(hf);
            const HalfEdge h0 = h;
            do {
                if (mesh.from_vertex(h) == v && accept(h)) return h;
                h = mesh.next(h);
            } while (h != h0);
        }
        return HalfEdge{};
    };
    for (HalfEdge h : hes) {
        const Edge e = mesh.edge(h);
        if (!mesh.is_deleted(e) && mesh.is_deleted(mesh.halfedge(e))) {
            const HalfEdge found = alive_leaving(mesh.from_vertex(h), [&](HalfEdge g) { return mesh.edge(g) == e; });
            mesh.set_halfedge(e, found);
            if (!found.is_valid()) mesh.set_deleted(e, true);
        }
        const Vertex v = mesh.from_vertex(h);
        if (mesh.halfedge(v).is_valid() && mesh.is_deleted(mesh.halfedge(v)))
            mesh.set_halfedge(v, alive_leaving(v, [](HalfEdge) { return true; }));
    }
    // END SOLUTION
}

void delete_vertex(Mesh& mesh, Vertex v) {
    // BEGIN SOLUTION
    if (mesh.is_deleted(v)) return;
    // the cells at v: the cells of the half-faces around it
    std::vector<Cell> cells;
    for (HalfFace hf : mesh.vertex_halffaces(v))
        if (mesh.cell(hf).is_valid()) cells.push_back(mesh.cell(hf));
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    // delete_cell takes each face and edge at v with the last cell that used it, and leaves v isolated
    for (Cell c : cells) delete_cell(mesh, c);
    mesh.set_deleted(v, true);
    // END SOLUTION
}

Remap garbage_collection(Mesh& mesh) {
    // BEGIN SOLUTION
    Remap r;
    auto number = [&](auto kind_handle, std::vector<std::uint32_t>& map, std::size_t n) {
        using H = decltype(kind_handle);
        map.assign(n, invalid_index);
        std::uint32_t next = 0;
        for (std::uint32_t i = 0; i < n; ++i)
            if (!mesh.is_deleted(H{i})) map[i] = next++;
    };
    number(Vertex{}, r.vertices, mesh.n_vertices());
    number(Edge{}, r.edges, mesh.n_edges());
    number(HalfEdge{}, r.halfedges, mesh.n_halfedges());
    number(Face{}, r.faces, mesh.n_faces());
    number(Cell{}, r.cells, mesh.n_cells());
    r.halffaces.assign(mesh.n_halffaces(), invalid_index);
    for (std::uint32_t hf = 0; hf < mesh.n_halffaces(); ++hf)
        if (r.faces[hf >> 1] != invalid_index) r.halffaces[hf] = 2 * r.faces[hf >> 1] + (hf & 1u);

    mesh.remap_handles(r.vertices, r.edges, r.halfedges, r.halffaces, r.cells);
    const std::pair<Kind, const std::vector<std::uint32_t>*> kinds[] = {
        {Kind::vertex, &r.vertices}, {Kind::edge, &r.edges},         {Kind::halfedge, &r.halfedges},
        {Kind::face, &r.faces},      {Kind::halfface, &r.halffaces}, {Kind::cell, &r.cells}};
    for (const auto& [k, map] : kinds) {
        mesh.compact(k, *map);
        mesh.compact_properties(k, *map);
    }
    mesh.rebuild_vertex_cache();
    return r;
    // END SOLUTION
}

}  // namespace geolab::halfface
