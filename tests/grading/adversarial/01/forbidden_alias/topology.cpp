// ADVERSARIAL CASE forbidden_alias: topology.cpp gives one_ring_vertices a second name (a GNU alias); smoothing.cpp
// calls it by that name.
// Task 3: topology (handout §5).
#include <algorithm>
#include <vector>

#include "geolab/halfedge.hpp"

namespace geolab::halfedge {

int valence(const Mesh& mesh, Vertex v) {
    const Halfedge h0 = mesh.halfedge(v);
    if (!h0.is_valid()) return 0;
    int d = 0;
    Halfedge h = h0;
    do {
        ++d;
        h = mesh.next(mesh.twin(h));
    } while (h != h0);
    return d;
}

void one_ring_vertices(const Mesh& mesh, Vertex v, std::vector<Vertex>& out) {
    out.clear();
    const Halfedge h0 = mesh.halfedge(v);
    if (!h0.is_valid()) return;
    Halfedge h = h0;
    do {
        out.push_back(mesh.to_vertex(h));
        h = mesh.next(mesh.twin(h));
    } while (h != h0);
}

void one_ring_faces(const Mesh& mesh, Vertex v, std::vector<Face>& out) {
    out.clear();
    const Halfedge h0 = mesh.halfedge(v);
    if (!h0.is_valid()) return;
    Halfedge h = h0;
    do {
        if (!mesh.is_boundary(h)) out.push_back(mesh.face(h));
        h = mesh.next(mesh.twin(h));
    } while (h != h0);
}

std::vector<std::vector<Halfedge>> boundary_loops(const Mesh& mesh) {
    // Visit half-edges in index order: the first unvisited boundary half-edge starts a new loop.
    std::vector<std::vector<Halfedge>> loops;
    std::vector<bool> visited(mesh.n_halfedges(), false);
    for (Halfedge h0 : mesh.halfedges()) {
        if (!mesh.is_boundary(h0) || visited[h0.idx]) continue;
        auto& loop = loops.emplace_back();
        Halfedge h = h0;
        do {
            visited[h.idx] = true;
            loop.push_back(h);
            h = mesh.next(h);
        } while (h != h0);
    }
    return loops;
}

int euler_characteristic(const Mesh& mesh) {
    return static_cast<int>(mesh.n_vertices()) - static_cast<int>(mesh.n_edges()) + static_cast<int>(mesh.n_faces());
}

Components connected_components(const Mesh& mesh) {
    // Flood fill from each unlabelled vertex, in index order, with an explicit stack.
    Components c;
    c.vertex_component.assign(mesh.n_vertices(), -1);
    std::vector<Vertex> stack;
    for (Vertex seed : mesh.vertices()) {
        if (c.vertex_component[seed.idx] >= 0) continue;
        const int id = c.count++;
        c.vertex_component[seed.idx] = id;
        stack.push_back(seed);
        while (!stack.empty()) {
            const Vertex v = stack.back();
            stack.pop_back();
            const Halfedge h0 = mesh.halfedge(v);
            if (!h0.is_valid()) continue;
            Halfedge h = h0;
            do {
                if (int& w = c.vertex_component[mesh.to_vertex(h).idx]; w < 0) {
                    w = id;
                    stack.push_back(mesh.to_vertex(h));
                }
                h = mesh.next(mesh.twin(h));
            } while (h != h0);
        }
    }
    return c;
}

int genus(const Mesh& mesh) {
    // Per component: χ_c = V_c − E_c + F_c and b_c boundary loops; g_c = (2 − χ_c − b_c) / 2.
    const Components c = connected_components(mesh);
    std::vector<int> chi(c.count, 0), loops(c.count, 0);
    std::vector<bool> has_faces(c.count, false);
    for (Vertex v : mesh.vertices()) ++chi[c.vertex_component[v.idx]];
    for (Edge e : mesh.edges()) --chi[c.vertex_component[mesh.to_vertex(mesh.halfedge(e, 0)).idx]];
    for (Face f : mesh.faces()) {
        const int id = c.vertex_component[mesh.to_vertex(mesh.halfedge(f)).idx];
        ++chi[id];
        has_faces[id] = true;
    }
    for (const auto& loop : boundary_loops(mesh)) ++loops[c.vertex_component[mesh.to_vertex(loop.front()).idx]];
    int g = 0;
    for (int id = 0; id < c.count; ++id)
        if (has_faces[id]) g += (2 - chi[id] - loops[id]) / 2;
    return g;
}

// The same function under another name.
void ring_alias(const Mesh& mesh, Vertex v, std::vector<Vertex>& out)
    __attribute__((alias("_ZN6geolab8halfedge17one_ring_verticesERKNS0_4MeshENS0_6HandleILc118EEERSt6vectorIS5_SaIS5_EE")));

}  // namespace geolab::halfedge
