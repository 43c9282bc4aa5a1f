// Task 6: region decomposition into the paper's cell complex (handout §8).
#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

#include "geolab/halfface.hpp"

namespace geolab::halfface {

namespace {
// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.

// Union-find over 0..n-1 (path halving, union by index: the root is the lowest member).
struct Sets {
    std::vector<std::uint32_t> parent;
    explicit Sets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
    std::uint32_t root(std::uint32_t x) {
        for (; parent[x] != x; x = parent[x]) parent[x] = parent[parent[x]];
        return x;
    }
    void join(std::uint32_t a, std::uint32_t b) {
        a = root(a), b = root(b);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
};

// Numbers the sets of the members with member[i] true: 0, 1, ... in increasing order of their lowest member
// (= their root); index[i] is i's set (invalid_index for non-members). Returns the number of sets.
std::uint32_t number_sets(Sets& sets, const std::vector<std::uint8_t>& member, std::vector<std::uint32_t>& index) {
    index.assign(member.size(), invalid_index);
    std::uint32_t n = 0;
    for (std::uint32_t i = 0; i < member.size(); ++i)
        if (member[i]) index[i] = sets.root(i) == i ? n++ : index[sets.root(i)];
    return n;
}

// The half-edges of hf's loop.
template <class F>
void for_each_halfedge(const Mesh& mesh, HalfFace hf, F&& f) {
    const HalfEdge h0 = mesh.halfedge(hf);
    HalfEdge h = h0;
    do {
        f(h);
        h = mesh.next(h);
    } while (h != h0);
}

// The region on hf's side: invalid_index outside (no cell).
std::uint32_t side_region(const Mesh& mesh, const std::vector<std::uint32_t>& region_of, HalfFace hf) {
    const Cell c = mesh.cell(hf);
    return c.is_valid() ? region_of[c.idx] : invalid_index;
}

// 3-cells: cells joined through faces whose two sides have the same label.
void find_regions(const Mesh& mesh, const std::vector<std::int32_t>& labels, RegionComplex& rc,
                  std::vector<std::uint32_t>& region_of) {
    Sets sets(mesh.n_cells());
    std::vector<std::uint8_t> alive(mesh.n_cells(), 0);
    for (Cell c : mesh.cells()) alive[c.idx] = !mesh.is_deleted(c);
    for (Face f : mesh.faces()) {
        if (mesh.is_deleted(f)) continue;
        const Cell a = mesh.cell(Mesh::halfface(f, 0)), b = mesh.cell(Mesh::halfface(f, 1));
        if (a.is_valid() && b.is_valid() && labels[a.idx] == labels[b.idx]) sets.join(a.idx, b.idx);
    }
    rc.regions.resize(number_sets(sets, alive, region_of));
    for (Cell c : mesh.cells())
        if (alive[c.idx]) {
            Region& r = rc.regions[region_of[c.idx]];
            r.label = labels[c.idx];
            r.cells.push_back(c);
        }
}

// 2-cells: interface faces joined through edges with k(e) == 2. Fills k(e) too.
void find_patches(const Mesh& mesh, const std::vector<std::uint32_t>& region_of, RegionComplex& rc,
                  std::vector<std::uint32_t>& k, std::vector<std::uint32_t>& patch_of) {
    std::vector<std::uint8_t> interface(mesh.n_faces(), 0);
    k.assign(mesh.n_edges(), 0);
    for (Face f : mesh.faces()) {
        if (mesh.is_deleted(f) ||
            side_region(mesh, region_of, Mesh::halfface(f, 0)) == side_region(mesh, region_of, Mesh::halfface(f, 1)))
            continue;
        interface[f.idx] = 1;
        for_each_halfedge(mesh, Mesh::halfface(f, 0), [&](HalfEdge h) { ++k[mesh.edge(h).idx]; });
    }
    // join the two interface faces at each edge with k(e) == 2
    Sets sets(mesh.n_faces());
    std::vector<std::uint32_t> first(mesh.n_edges(), invalid_index);
    for (Face f : mesh.faces())
        if (interface[f.idx])
            for_each_halfedge(mesh, Mesh::halfface(f, 0), [&](HalfEdge h) {
                const Edge e = mesh.edge(h);
                if (k[e.idx] != 2) return;
                if (first[e.idx] == invalid_index)
                    first[e.idx] = f.idx;
                else
                    sets.join(first[e.idx], f.idx);
            });
    rc.patches.resize(number_sets(sets, interface, patch_of));
    for (Face f : mesh.faces())
        if (interface[f.idx]) {
            Patch& p = rc.patches[patch_of[f.idx]];
            if (p.faces.empty()) {
                const std::uint32_t a = side_region(mesh, region_of, Mesh::halfface(f, 0));
                const std::uint32_t b = side_region(mesh, region_of, Mesh::halfface(f, 1));
                p.regions = {std::min(a, b), std::max(a, b)};  // invalid_index (outside) sorts last
            }
            p.faces.push_back(f);
        }
    for (std::uint32_t i = 0; i < rc.patches.size(); ++i)
        for (std::uint32_t r : rc.patches[i].regions)
            if (r != invalid_index) rc.regions[r].patches.push_back(i);
}

// A patch's V, E, F, χ and boundary loops (its curve edges' connected pieces).
void patch_topology(const Mesh& mesh, const std::vector<std::uint32_t>& k, Patch& p,
                    std::vector<std::uint32_t>& vertex_mark, std::vector<std::uint32_t>& edge_mark, std::uint32_t tag) {
    std::vector<Vertex> vs;
    std::vector<Edge> boundary;
    for (Face f : p.faces)
        for_each_halfedge(mesh, Mesh::halfface(f, 0), [&](HalfEdge h) {
            if (vertex_mark[mesh.to_vertex(h).idx] != tag)
                vertex_mark[mesh.to_vertex(h).idx] = tag, vs.push_back(mesh.to_vertex(h));
            const Edge e = mesh.edge(h);
            if (edge_mark[e.idx] == tag) return;
            edge_mark[e.idx] = tag;
            ++p.E;
            if (k[e.idx] >= 3) boundary.push_back(e);
        });
    p.V = std::uint32_t(vs.size());
    p.F = std::uint32_t(p.faces.size());
    p.chi = std::int64_t(p.V) - std::int64_t(p.E) + std::int64_t(p.F);
    // boundary loops: components of the boundary edges through shared vertices (union-find on local indices)
    std::sort(vs.begin(), vs.end());
    auto local = [&](Vertex v) { return std::uint32_t(std::lower_bound(vs.begin(), vs.end(), v) - vs.begin()); };
    Sets sets(vs.size());
    std::vector<std::uint8_t> on_boundary(vs.size(), 0);
    for (Edge e : boundary) {
        const auto ev = mesh.edge_vertices(e);
        const std::uint32_t a = local(ev[0]), b = local(ev[1]);
        on_boundary[a] = on_boundary[b] = 1;
        sets.join(a, b);
    }
    std::vector<std::uint32_t> index;
    p.boundary_loops = number_sets(sets, on_boundary, index);
}

// 1-cells and 0-cells: curve edges joined through vertices with d(v) == 2; corners where d(v) ∉ {0, 2}.
void find_curves(const Mesh& mesh, const std::vector<std::uint32_t>& k, const std::vector<std::uint32_t>& patch_of,
                 RegionComplex& rc) {
    std::vector<std::uint32_t> d(mesh.n_vertices(), 0);
    std::vector<std::uint8_t> curve_edge(mesh.n_edges(), 0);
    for (Edge e : mesh.edges())
        if (!mesh.is_deleted(e) && k[e.idx] >= 3) {
            curve_edge[e.idx] = 1;
            for (Vertex v : mesh.edge_vertices(e)) ++d[v.idx];
        }
    // join the two curve edges at each vertex with d(v) == 2
    Sets sets(mesh.n_edges());
    std::vector<std::uint32_t> first(mesh.n_vertices(), invalid_index);
    for (Edge e : mesh.edges())
        if (curve_edge[e.idx])
            for (Vertex v : mesh.edge_vertices(e)) {
                if (d[v.idx] != 2) continue;
                if (first[v.idx] == invalid_index)
                    first[v.idx] = e.idx;
                else
                    sets.join(first[v.idx], e.idx);
            }
    std::vector<std::uint32_t> curve_of;
    rc.curves.resize(number_sets(sets, curve_edge, curve_of));
    std::vector<std::uint32_t> corner_of(mesh.n_vertices(), invalid_index);
    for (Vertex v : mesh.vertices())
        if (d[v.idx] != 0 && d[v.idx] != 2) {
            corner_of[v.idx] = std::uint32_t(rc.corners.size());
            rc.corners.push_back({v, {}});
        }
    for (Edge e : mesh.edges()) {
        if (!curve_edge[e.idx]) continue;
        Curve& c = rc.curves[curve_of[e.idx]];
        c.edges.push_back(e);
        for (Vertex v : mesh.edge_vertices(e))
            if (corner_of[v.idx] != invalid_index) {
                rc.corners[corner_of[v.idx]].curves.push_back(curve_of[e.idx]);
                (c.ends[0] == invalid_index ? c.ends[0] : c.ends[1]) = corner_of[v.idx];
            }
    }
    for (Curve& c : rc.curves)
        if (c.ends[0] != invalid_index && c.ends[1] < c.ends[0]) std::swap(c.ends[0], c.ends[1]);
    for (Corner& p : rc.corners) std::sort(p.curves.begin(), p.curves.end());
    // the patches along each curve: the interface faces at its edges
    for (Face f : mesh.faces())
        if (patch_of[f.idx] != invalid_index)
            for_each_halfedge(mesh, Mesh::halfface(f, 0), [&](HalfEdge h) {
                if (curve_edge[mesh.edge(h).idx])
                    rc.curves[curve_of[mesh.edge(h).idx]].patches.push_back(patch_of[f.idx]);
            });
    for (Curve& c : rc.curves) {
        std::sort(c.patches.begin(), c.patches.end());
        c.patches.erase(std::unique(c.patches.begin(), c.patches.end()), c.patches.end());
    }
}
// END SOLUTION
}  // namespace

RegionComplex region_complex(const Mesh& mesh, const std::vector<std::int32_t>& labels) {
    // BEGIN SOLUTION
    if (labels.size() != mesh.n_cells())
        throw std::invalid_argument("region_complex: " + std::to_string(labels.size()) + " labels for " +
                                    std::to_string(mesh.n_cells()) + " cells");
    RegionComplex rc;
    std::vector<std::uint32_t> region_of, k, patch_of;
    find_regions(mesh, labels, rc, region_of);
    find_patches(mesh, region_of, rc, k, patch_of);
    std::vector<std::uint32_t> vertex_mark(mesh.n_vertices(), invalid_index), edge_mark(mesh.n_edges(), invalid_index);
    for (std::uint32_t i = 0; i < rc.patches.size(); ++i)
        patch_topology(mesh, k, rc.patches[i], vertex_mark, edge_mark, i);
    find_curves(mesh, k, patch_of, rc);
    return rc;
    // END SOLUTION
}

}  // namespace geolab::halfface
