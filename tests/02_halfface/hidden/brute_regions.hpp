#pragma once
// Lab 02 hidden: an independent brute-force region decomposition computed from the CELL LIST with std::map and
// union-find (no half-face code but the mesh's numbering), for the hidden tests of Task 6 and for
// lab02_fixture_data, which stores its results as the expected complexes of the visible tests (region_fixtures.hpp).
// Hidden: not in the student release.
#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <numeric>
#include <set>
#include <vector>

#include "region_fixtures.hpp"

namespace lab02 {

// ---- the brute-force decomposition -----------------------------------------------------------------------------

struct BruteSets {
    std::vector<std::uint32_t> p;
    explicit BruteSets(std::size_t n) : p(n) { std::iota(p.begin(), p.end(), 0u); }
    std::uint32_t find(std::uint32_t x) { return p[x] == x ? x : p[x] = find(p[x]); }
    void join(std::uint32_t a, std::uint32_t b) { p[find(a)] = find(b); }
};

// The expected RegionComplex of the labelled cell list `cl` (cells in `deleted` removed), in the numbering of the
// mesh `m` built from it (cell c = list cell c; faces and edges matched by their vertex sets).
inline RegionComplex brute_region_complex(const CellList& cl, const std::vector<std::int32_t>& labels, const Mesh& m,
                                          const std::set<std::uint32_t>& deleted = {}) {
    using Key = std::vector<std::uint32_t>;
    using EKey = std::pair<std::uint32_t, std::uint32_t>;
    const std::uint32_t none = invalid_index;
    const std::size_t nc = cl.n_cells();
    // faces: key -> alive cells using it; the face's cycle
    std::map<Key, std::vector<std::uint32_t>> users;
    std::map<Key, Key> cycle;
    for (std::uint32_t c = 0; c < nc; ++c)
        for (std::size_t i = 0; i < cl.n_faces(c); ++i) {
            Key f(cl.face(c, i).begin(), cl.face(c, i).end()), k = f;
            std::sort(k.begin(), k.end());
            cycle.emplace(k, f);
            if (!deleted.count(c)) users[k].push_back(c);
        }
    // regions: union of same-label cells through faces
    BruteSets cells(nc);
    for (auto& [k, u] : users)
        if (u.size() == 2 && labels[u[0]] == labels[u[1]]) cells.join(u[0], u[1]);
    std::map<std::uint32_t, std::uint32_t> region_of_root;
    std::vector<std::uint32_t> region(nc, none);
    RegionComplex rc;
    for (std::uint32_t c = 0; c < nc; ++c) {
        if (deleted.count(c)) continue;
        auto [it, fresh] = region_of_root.emplace(cells.find(c), std::uint32_t(rc.regions.size()));
        if (fresh) rc.regions.push_back({labels[c], {}, {}});
        region[c] = it->second;
        rc.regions[it->second].cells.push_back(Cell{c});
    }
    // mesh numbering of faces and edges
    std::map<Key, std::uint32_t> mesh_face;
    for (Face f : m.faces()) {
        if (m.is_deleted(f)) continue;
        Key k;
        const HalfEdge h0 = m.halfedge(Mesh::halfface(f, 0));
        HalfEdge h = h0;
        do k.push_back(m.to_vertex(h).idx), h = m.next(h);
        while (h != h0);
        std::sort(k.begin(), k.end());
        mesh_face[k] = f.idx;
    }
    std::map<EKey, std::uint32_t> mesh_edge;
    for (Edge e : m.edges())
        if (!m.is_deleted(e)) {
            const auto ev = m.edge_vertices(e);
            mesh_edge[{std::min(ev[0].idx, ev[1].idx), std::max(ev[0].idx, ev[1].idx)}] = e.idx;
        }
    // interface faces in mesh order, with their two regions and edges
    struct IFace {
        std::uint32_t face;
        std::array<std::uint32_t, 2> regions;
        std::vector<EKey> edges;
        Key vertices;
    };
    std::vector<IFace> faces;
    for (auto& [k, u] : users) {
        if (u.empty()) continue;
        const std::uint32_t a = region[u[0]], b = u.size() > 1 ? region[u[1]] : none;
        if (a == b) continue;
        IFace f{mesh_face.at(k), {std::min(a, b), std::max(a, b)}, {}, k};
        const Key& cyc = cycle.at(k);
        for (std::size_t i = 0; i < cyc.size(); ++i) {
            const auto x = cyc[i], y = cyc[(i + 1) % cyc.size()];
            f.edges.push_back({std::min(x, y), std::max(x, y)});
        }
        faces.push_back(f);
    }
    std::sort(faces.begin(), faces.end(), [](const IFace& a, const IFace& b) { return a.face < b.face; });
    std::map<EKey, int> k_of;
    for (const IFace& f : faces)
        for (const EKey& e : f.edges) ++k_of[e];
    // patches: interface faces joined through edges with k == 2
    BruteSets fs(faces.size());
    std::map<EKey, std::uint32_t> first_face;
    for (std::uint32_t i = 0; i < faces.size(); ++i)
        for (const EKey& e : faces[i].edges)
            if (k_of[e] == 2) {
                auto [it, fresh] = first_face.emplace(e, i);
                if (!fresh) fs.join(it->second, i);
            }
    std::map<std::uint32_t, std::uint32_t> patch_of_root;
    std::vector<std::uint32_t> patch_of_face(faces.size());
    for (std::uint32_t i = 0; i < faces.size(); ++i) {
        auto [it, fresh] = patch_of_root.emplace(fs.find(i), std::uint32_t(rc.patches.size()));
        if (fresh) {
            Patch p;
            p.regions = faces[i].regions;
            rc.patches.push_back(p);
        }
        patch_of_face[i] = it->second;
        rc.patches[it->second].faces.push_back(Face{faces[i].face});
    }
    std::vector<std::set<std::uint32_t>> pv(rc.patches.size());
    std::vector<std::set<EKey>> pe(rc.patches.size());
    for (std::uint32_t i = 0; i < faces.size(); ++i) {
        pv[patch_of_face[i]].insert(faces[i].vertices.begin(), faces[i].vertices.end());
        pe[patch_of_face[i]].insert(faces[i].edges.begin(), faces[i].edges.end());
    }
    for (std::uint32_t p = 0; p < rc.patches.size(); ++p) {
        Patch& x = rc.patches[p];
        x.V = std::uint32_t(pv[p].size()), x.E = std::uint32_t(pe[p].size()), x.F = std::uint32_t(x.faces.size());
        x.chi = std::int64_t(x.V) - std::int64_t(x.E) + std::int64_t(x.F);
        // boundary loops: components of the patch's edges with k >= 3
        std::map<std::uint32_t, std::uint32_t> local;
        for (const EKey& e : pe[p])
            if (k_of[e] >= 3) local.emplace(e.first, 0), local.emplace(e.second, 0);
        std::uint32_t n = 0;
        for (auto& [v, i] : local) i = n++;
        BruteSets ls(n);
        for (const EKey& e : pe[p])
            if (k_of[e] >= 3) ls.join(local[e.first], local[e.second]);
        std::set<std::uint32_t> roots;
        for (std::uint32_t i = 0; i < n; ++i) roots.insert(ls.find(i));
        x.boundary_loops = std::uint32_t(roots.size());
        for (std::uint32_t r : x.regions)
            if (r != none) rc.regions[r].patches.push_back(p);
    }
    // curves: edges with k >= 3 joined through vertices with d == 2; corners where d is not 0 or 2
    std::vector<EKey> curve_edges;
    std::map<std::uint32_t, int> d;
    for (auto& [e, k] : k_of)
        if (k >= 3) curve_edges.push_back(e), ++d[e.first], ++d[e.second];
    std::sort(curve_edges.begin(), curve_edges.end(),
              [&](const EKey& a, const EKey& b) { return mesh_edge.at(a) < mesh_edge.at(b); });
    BruteSets es(curve_edges.size());
    std::map<std::uint32_t, std::uint32_t> first_edge;
    for (std::uint32_t i = 0; i < curve_edges.size(); ++i)
        for (std::uint32_t v : {curve_edges[i].first, curve_edges[i].second})
            if (d[v] == 2) {
                auto [it, fresh] = first_edge.emplace(v, i);
                if (!fresh) es.join(it->second, i);
            }
    std::map<std::uint32_t, std::uint32_t> corner_of;
    for (auto& [v, n] : d)
        if (n != 2) {
            corner_of[v] = std::uint32_t(rc.corners.size());
            rc.corners.push_back({Vertex{v}, {}});
        }
    std::map<std::uint32_t, std::uint32_t> curve_of_root;
    std::map<EKey, std::uint32_t> curve_of_edge;
    for (std::uint32_t i = 0; i < curve_edges.size(); ++i) {
        auto [it, fresh] = curve_of_root.emplace(es.find(i), std::uint32_t(rc.curves.size()));
        if (fresh) rc.curves.emplace_back();
        Curve& c = rc.curves[it->second];
        curve_of_edge[curve_edges[i]] = it->second;
        c.edges.push_back(Edge{mesh_edge.at(curve_edges[i])});
        for (std::uint32_t v : {curve_edges[i].first, curve_edges[i].second})
            if (corner_of.count(v)) {
                rc.corners[corner_of[v]].curves.push_back(it->second);
                (c.ends[0] == none ? c.ends[0] : c.ends[1]) = corner_of[v];
            }
    }
    for (Curve& c : rc.curves)
        if (c.ends[1] < c.ends[0]) std::swap(c.ends[0], c.ends[1]);
    for (Corner& x : rc.corners) std::sort(x.curves.begin(), x.curves.end());
    for (std::uint32_t i = 0; i < faces.size(); ++i)
        for (const EKey& e : faces[i].edges)
            if (curve_of_edge.count(e)) rc.curves[curve_of_edge[e]].patches.push_back(patch_of_face[i]);
    for (Curve& c : rc.curves) {
        std::sort(c.patches.begin(), c.patches.end());
        c.patches.erase(std::unique(c.patches.begin(), c.patches.end()), c.patches.end());
    }
    return rc;
}

}  // namespace lab02
