#pragma once
// Lab 02, Task 6: labelled inputs for the region decomposition (the cases of the visible tests), their expected
// complexes (stored data, made by an independent brute-force decomposition of the cell list on the instructor's side:
// hidden/brute_regions.hpp, lab02_fixture_data), and helpers to compare and print complexes.
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
#include "stored.hpp"

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

// ---- the cases of the visible tests and their expected complexes --------------------------------------------

// Marks cell c deleted through the kernel alone (not the student's Task 3), as delete_cell's contract says.
inline void delete_through_kernel(Mesh& m, Cell c) {
    m.set_deleted(c, true);
    for (HalfFace hf : m.halffaces(c)) {
        m.set_cell(hf, Cell{});
        const HalfEdge h0 = m.halfedge(hf);
        HalfEdge h = h0;
        do {
            m.set_twin(h, HalfEdge{});
            h = m.next(h);
        } while (h != h0);
        if (!m.cell(Mesh::opposite(hf)).is_valid()) m.set_deleted(Mesh::face(hf), true);
    }
    m.rebuild_vertex_cache();
}

// One labelled input: a stored mesh (by its fixture's name), its cell list, the labels, and the cells deleted (through
// the kernel) before the decomposition.
struct RegionCase {
    std::string key;  // also the key of its expected complex in tests/02_halfface/data
    std::string mesh;
    CellList cells;
    std::vector<std::int32_t> labels;
    std::vector<std::uint32_t> deleted;
};

// The cube (i, j, k) of an n³ Kuhn tet grid that holds tet c (6 tets per cube, cubes in (k n + j) n + i order).
inline std::array<int, 3> kuhn_cube_of(int n, std::size_t c) {
    const int q = int(c / 6);
    return {q % n, (q / n) % n, q / (n * n)};
}
// Labels of an n³ Kuhn tet grid from its cubes: f(i, j, k).
template <class F>
std::vector<std::int32_t> cube_labels(int n, F&& f) {
    std::vector<std::int32_t> l(6 * n * n * n);
    for (std::size_t c = 0; c < l.size(); ++c) {
        const auto q = kuhn_cube_of(n, c);
        l[c] = f(q[0], q[1], q[2]);
    }
    return l;
}

// Every case of the visible tests, in one list (lab02_fixture_data stores each one's expected complex).
inline std::vector<RegionCase> region_cases() {
    std::vector<RegionCase> out;
    const CellList ring = fx::ring_in_box(), grid2 = fx::tet_grid(2, 0.3), grid3 = fx::tet_grid(3, 0.3),
                   hex2 = fx::hex_grid(2);
    out.push_back({"paper: ring in a box", "ring in a box (hex 5x5x3)", ring, ring.labels, {}});
    out.push_back({"tet grid 3: cubes (0,0,0) and (2,2,2) labelled 1",
                   "tet grid 3",
                   grid3,
                   cube_labels(3, [](int i, int j, int k) { return (i == j && j == k && i != 1) ? 1 : 0; }),
                   {}});
    out.push_back({"tet grid 3: cubes (0,0,0) and (1,1,0) labelled 1 (sharing an edge)",
                   "tet grid 3",
                   grid3,
                   cube_labels(3, [](int i, int j, int k) { return k == 0 && i == j && i < 2 ? 1 : 0; }),
                   {}});
    std::vector<std::int32_t> halves(8), own(8);
    for (std::size_t c = 0; c < 8; ++c) halves[c] = std::int32_t(c % 2), own[c] = std::int32_t(c);
    out.push_back({"hex grid 2: halves x < 1/2", "hex grid 2", hex2, halves, {}});
    out.push_back(
        {"tet grid 2: halves x < 1/2", "tet grid 2", grid2, cube_labels(2, [](int i, int, int) { return i; }), {}});
    out.push_back({"hex grid 2: octants", "hex grid 2", hex2, own, {}});
    out.push_back({"tet grid 2: octants",
                   "tet grid 2",
                   grid2,
                   cube_labels(2, [](int i, int j, int k) { return i + 2 * j + 4 * k; }),
                   {}});
    out.push_back({"tet grid 3: three regions along a line",
                   "tet grid 3",
                   grid3,
                   cube_labels(3, [](int i, int j, int) { return i == 0   ? 0
                                                                 : j == 0 ? 1
                                                                          : 2; }),
                   {}});
    out.push_back({"tet grid 3: cube (1,1,0) labelled 1 (touching the boundary)",
                   "tet grid 3",
                   grid3,
                   cube_labels(3, [](int i, int j, int k) { return i == 1 && j == 1 && k == 0 ? 1 : 0; }),
                   {}});
    out.push_back({"cube of 6 pyramids: labels 10..15",
                   "cube of 6 pyramids",
                   fx::cube_of_pyramids(),
                   {10, 11, 12, 13, 14, 15},
                   {}});
    for (const Fixture& f : stored_fixtures()) {
        std::vector<std::int32_t> each(f.cells.n_cells());
        for (std::size_t c = 0; c < each.size(); ++c) each[c] = std::int32_t(c % 3 == 1 ? -int(c) : int(c));
        out.push_back({f.name + ": every cell its own label", f.name, f.cells, each, {}});
    }
    std::vector<std::uint32_t> centre;
    for (std::uint32_t c = 6 * 13; c < 6 * 14; ++c) centre.push_back(c);  // cube (1,1,1)'s tets
    out.push_back({"tet grid 3 without its centre cube: one label", "tet grid 3", grid3,
                   std::vector<std::int32_t>(grid3.n_cells(), 0), centre});
    out.push_back({"tet grid 3 without its centre cube: x < 1/3 labelled 1", "tet grid 3", grid3,
                   cube_labels(3, [](int i, int, int) { return i == 0 ? 1 : 0; }), centre});
    return out;
}

// The case named `key`.
inline RegionCase region_case(const std::string& key) {
    for (RegionCase& c : region_cases())
        if (c.key == key) return c;
    throw std::logic_error("no region case '" + key + "' in region_fixtures.hpp");
}

// The case's mesh: its stored mesh (never your build_mesh) with the case's cells deleted through the kernel.
inline Mesh case_mesh(const RegionCase& rc) {
    Mesh m = stored_mesh(rc.mesh);
    for (std::uint32_t c : rc.deleted) delete_through_kernel(m, Cell{c});
    return m;
}

namespace stored_region_data {
// data/region_index.inc (generated) defines one array per case and `entries`, the table of all of them.
#include "data/region_index.inc"
}  // namespace stored_region_data

// The expected complex of case `key`, from tests/02_halfface/data. Never calls lab code.
inline RegionComplex stored_complex(const std::string& key) {
    for (const auto& e : stored_region_data::entries)
        if (key == e.key) {
            RegionComplex rc;
            std::size_t pos = 0;
            unflatten(rc, e.data, pos);
            if (pos != e.data.size()) throw std::logic_error("stored complex '" + key + "' has trailing data");
            return rc;
        }
    throw std::logic_error("no stored complex for '" + key + "' in tests/02_halfface/data (run lab02_fixture_data)");
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
