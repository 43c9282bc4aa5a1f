#pragma once
// Lab 02, Task 6: labelled inputs for the region decomposition, and an independent brute-force decomposition
// computed from the CELL LIST with std::map / union-find (no half-face code), mapped to the mesh's numbering.
#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "fixtures.hpp"
#include "geolab/halfface.hpp"

namespace lab02 {

using namespace geolab::halfface;

namespace fx {

// The paper's example on hexahedra: a 5 × 5 × 3 box of unit cubes (a ball) whose middle layer holds a ring of 8
// cubes around the centre cube, labelled 1 (a solid torus); the rest is labelled 0.
inline CellList ring_in_box() {
    CellList c;
    const int nx = 5, ny = 5, nz = 3;
    auto index = [&](int i, int j, int k) { return std::uint32_t((k * (ny + 1) + j) * (nx + 1) + i); };
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i) c.positions.push_back({double(i), double(j), double(k)});
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                const bool ring = k == 1 && std::max(std::abs(i - 2), std::abs(j - 2)) == 1;
                const std::array<std::uint32_t, 8> v{
                    index(i, j, k),     index(i + 1, j, k),     index(i + 1, j + 1, k),     index(i, j + 1, k),
                    index(i, j, k + 1), index(i + 1, j, k + 1), index(i + 1, j + 1, k + 1), index(i, j + 1, k + 1)};
                c.add_hex(v, ring ? 1 : 0);
            }
    return c;
}

}  // namespace fx

// The fixtures of Task 6 whose connectivity is stored (tests/02_halfface/data), beside stored_fixtures().
inline std::vector<Fixture> region_stored_fixtures() { return {{"ring in a box (hex 5x5x3)", fx::ring_in_box()}}; }

// ---- labels ----------------------------------------------------------------------------------------------------

// The cell's centroid (mean of its face corners, each corner once per face using it) from the cell list.
inline glm::dvec3 list_centroid(const CellList& cl, std::size_t c) {
    glm::dvec3 s(0);
    int n = 0;
    for (std::size_t i = 0; i < cl.n_faces(c); ++i)
        for (auto v : cl.face(c, i)) s += cl.positions[v], ++n;
    return s / double(n);
}
// labels[c] = f(centroid of cell c).
template <class F>
std::vector<std::int32_t> labels_by_centroid(const CellList& cl, F&& f) {
    std::vector<std::int32_t> l(cl.n_cells());
    for (std::size_t c = 0; c < cl.n_cells(); ++c) l[c] = f(list_centroid(cl, c));
    return l;
}

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

// ---- comparing -------------------------------------------------------------------------------------------------

inline std::string idx_text(std::uint32_t i) {
    return i == invalid_index ? std::string("outside/none") : std::to_string(i);
}
template <class H>
std::string handles_text(const std::vector<H>& v, std::size_t max = 12) {
    std::ostringstream os;
    os << '[';
    for (std::size_t i = 0; i < v.size() && i < max; ++i) os << (i ? " " : "") << v[i];
    if (v.size() > max) os << " ... (" << v.size() << ")";
    os << ']';
    return os.str();
}

// The counts "3-cells R, 2-cells P, 1-cells C, 0-cells K".
inline std::string counts_text(const RegionComplex& rc) {
    std::ostringstream os;
    os << rc.regions.size() << " regions, " << rc.patches.size() << " patches, " << rc.curves.size() << " curves, "
       << rc.corners.size() << " corners";
    return os.str();
}

// "" when `got` equals `want`, else the first difference, in words.
inline std::string first_difference(const RegionComplex& want, const RegionComplex& got) {
    std::ostringstream os;
    if (want.regions.size() != got.regions.size() || want.patches.size() != got.patches.size() ||
        want.curves.size() != got.curves.size() || want.corners.size() != got.corners.size()) {
        os << "expected " << counts_text(want) << ", got " << counts_text(got);
        return os.str();
    }
    for (std::size_t i = 0; i < want.regions.size(); ++i) {
        const Region &a = want.regions[i], &b = got.regions[i];
        if (a.cells != b.cells)
            os << "region " << i << ": cells expected " << handles_text(a.cells) << ", got " << handles_text(b.cells);
        else if (a.label != b.label)
            os << "region " << i << ": label expected " << a.label << ", got " << b.label;
        else if (a.patches != b.patches)
            os << "region " << i << ": patches expected " << handles_text(a.patches) << ", got "
               << handles_text(b.patches);
        if (!os.str().empty()) return os.str();
    }
    for (std::size_t i = 0; i < want.patches.size(); ++i) {
        const Patch &a = want.patches[i], &b = got.patches[i];
        if (a.faces != b.faces)
            os << "patch " << i << ": faces expected " << handles_text(a.faces) << ", got " << handles_text(b.faces);
        else if (a.regions != b.regions)
            os << "patch " << i << ": regions expected (" << idx_text(a.regions[0]) << ", " << idx_text(a.regions[1])
               << "), got (" << idx_text(b.regions[0]) << ", " << idx_text(b.regions[1]) << ")";
        else if (a.V != b.V || a.E != b.E || a.F != b.F || a.chi != b.chi)
            os << "patch " << i << ": V E F χ expected " << a.V << " " << a.E << " " << a.F << " " << a.chi << ", got "
               << b.V << " " << b.E << " " << b.F << " " << b.chi;
        else if (a.boundary_loops != b.boundary_loops)
            os << "patch " << i << ": boundary loops expected " << a.boundary_loops << ", got " << b.boundary_loops;
        if (!os.str().empty()) return os.str();
    }
    for (std::size_t i = 0; i < want.curves.size(); ++i) {
        const Curve &a = want.curves[i], &b = got.curves[i];
        if (a.edges != b.edges)
            os << "curve " << i << ": edges expected " << handles_text(a.edges) << ", got " << handles_text(b.edges);
        else if (a.ends != b.ends)
            os << "curve " << i << ": ends expected (" << idx_text(a.ends[0]) << ", " << idx_text(a.ends[1])
               << "), got (" << idx_text(b.ends[0]) << ", " << idx_text(b.ends[1]) << ")";
        else if (a.patches != b.patches)
            os << "curve " << i << ": patches expected " << handles_text(a.patches) << ", got "
               << handles_text(b.patches);
        if (!os.str().empty()) return os.str();
    }
    for (std::size_t i = 0; i < want.corners.size(); ++i) {
        const Corner &a = want.corners[i], &b = got.corners[i];
        if (a.vertex != b.vertex)
            os << "corner " << i << ": vertex expected " << a.vertex << ", got " << b.vertex;
        else if (a.curves != b.curves)
            os << "corner " << i << " (" << a.vertex << "): curves expected " << handles_text(a.curves) << ", got "
               << handles_text(b.curves);
        if (!os.str().empty()) return os.str();
    }
    return "";
}

// The alternating sum #0-cells − #1-cells + #2-cells − #3-cells: χ of the solid when every cell is a ball of its
// dimension (a true CW complex); the paper's ball with a torus region gives 0, not 1.
inline long complex_chi(const RegionComplex& rc) {
    return long(rc.corners.size()) - long(rc.curves.size()) + long(rc.patches.size()) - long(rc.regions.size());
}

}  // namespace lab02
