#pragma once
// Lab 02 test helpers: reference answers computed from the cell list by brute force (sorting, std::map / std::set),
// independently of any half-face code; checks of a Mesh through the kernel's accessors in every configuration.
#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "fixtures.hpp"
#include "geolab/errors.hpp"
#include "geolab/grading/test.hpp"
#include "geolab/halfface.hpp"
#include "geolab/io.hpp"
#include "geolab/models.hpp"
#include "geolab/volume_io.hpp"
#include "stored.hpp"

namespace lab02 {

using namespace geolab::halfface;
using geolab::PolygonSoup;

inline std::string describe(const Fixture& f) { return "input: " + f.name; }

// ---- brute force from the cell list ---------------------------------------------------------------------------

// The vertex cycle rotated to its smallest vertex (direction kept).
inline std::vector<std::uint32_t> rotate_min(std::vector<std::uint32_t> c) {
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    return c;
}
template <class R>
std::vector<std::uint32_t> to_vec(const R& r) {
    std::vector<std::uint32_t> v;
    for (auto x : r) v.push_back(std::uint32_t(x));
    return v;
}
// An undirected face key: the sorted vertex set (faces of valid cell lists are identified by it).
inline std::vector<std::uint32_t> face_key(std::vector<std::uint32_t> c) {
    std::sort(c.begin(), c.end());
    return c;
}

struct Reference {
    std::size_t V = 0, E = 0, F = 0, C = 0, boundary_faces = 0;
};

// The counts of a cell list by sorting: distinct undirected edges (vertex pairs), distinct faces (sorted vertex
// sets) and the faces used once (boundary).
inline Reference reference(const CellList& cl) {
    Reference r;
    r.V = cl.n_vertices();
    r.C = cl.n_cells();
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    std::vector<std::vector<std::uint32_t>> faces;
    for (std::size_t c = 0; c < cl.n_cells(); ++c)
        for (std::size_t i = 0; i < cl.n_faces(c); ++i) {
            auto f = to_vec(cl.face(c, i));
            for (std::size_t k = 0; k < f.size(); ++k) {
                const auto a = f[k], b = f[(k + 1) % f.size()];
                edges.push_back({std::min(a, b), std::max(a, b)});
            }
            faces.push_back(face_key(f));
        }
    std::sort(edges.begin(), edges.end());
    r.E = std::size_t(std::unique(edges.begin(), edges.end()) - edges.begin());
    std::sort(faces.begin(), faces.end());
    for (std::size_t a = 0; a < faces.size();) {
        std::size_t b = a + 1;
        while (b < faces.size() && faces[b] == faces[a]) ++b;
        ++r.F;
        r.boundary_faces += b - a == 1;
        a = b;
    }
    return r;
}

// ---- the mesh through the kernel's accessors ------------------------------------------------------------------

template <class M>
std::vector<std::uint32_t> loop_vertices(const M& m, HalfFace hf) {
    std::vector<std::uint32_t> out;
    const HalfEdge h0 = m.halfedge(hf);
    HalfEdge h = h0;
    do {
        out.push_back(m.from_vertex(h).idx);
        h = m.next(h);
        if (out.size() > m.n_halfedges()) break;
    } while (h != h0);
    return out;
}

// Deletes cell c through the kernel alone, as delete_cell's contract says, for the tests of the other tasks
// (which must not depend on your Task 3): its half-faces lose their cell and their half-edges their twin, a face
// with no cell left is deleted, an edge without an alive half-edge is deleted, halfedge(e) and halfedge(v) move
// to alive half-edges (found by a scan) or become invalid, and the vertex cache is rebuilt.
inline void kernel_delete_cell(Mesh& m, Cell c) {
    if (m.is_deleted(c)) return;
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
    std::vector<HalfEdge> of_edge(m.n_edges()), leaving(m.n_vertices());
    for (HalfEdge h : m.halfedges())
        if (!m.is_deleted(h)) {
            if (!of_edge[m.edge(h).idx].is_valid()) of_edge[m.edge(h).idx] = h;
            if (!leaving[m.from_vertex(h).idx].is_valid()) leaving[m.from_vertex(h).idx] = h;
        }
    for (Edge e : m.edges())
        if (!m.is_deleted(e) && m.is_deleted(m.halfedge(e))) {
            m.set_halfedge(e, of_edge[e.idx]);
            if (!of_edge[e.idx].is_valid()) m.set_deleted(e, true);
        }
    for (Vertex v : m.vertices())
        if (!m.is_deleted(v) && m.halfedge(v).is_valid() && m.is_deleted(m.halfedge(v))) m.set_halfedge(v, leaving[v.idx]);
    m.rebuild_vertex_cache();
}

// Runs validate() and fails the test with its message.
inline void require_valid(const Mesh& m, const std::string& what) {
    try {
        validate(m);
    } catch (const geolab::TopologyError& e) {
        FAIL(what << ": validate() rejects the mesh: " << std::string(e.what()));
    }
}

// Calls f with the mesh converted to each of the 8 configurations, and the configuration's name.
template <class F>
void for_each_config(const Mesh& m, F&& f) {
    f(convert<Traits<true, true, true>>(m), "store prev+mate, cache");
    f(convert<Traits<true, true, false>>(m), "store prev+mate, no cache");
    f(convert<Traits<true, false, true>>(m), "store prev, derive mate, cache");
    f(convert<Traits<true, false, false>>(m), "store prev, derive mate, no cache");
    f(convert<Traits<false, true, true>>(m), "derive prev, store mate, cache");
    f(convert<Traits<false, true, false>>(m), "derive prev, store mate, no cache");
    f(convert<Traits<false, false, true>>(m), "derive prev+mate, cache");
    f(convert<Traits<false, false, false>>(m), "derive prev+mate, no cache");
}

// The radial walk around e in any configuration, as the handout defines it (a test-side reference built on the
// kernel's accessors): cells in order from the fan's start (boundary) or the lowest cell (interior).
template <class M>
std::vector<Cell> radial_cells(const M& m, Edge e) {
    std::vector<Cell> out;
    const Vertex b = m.edge_vertices(e)[1];
    // every alive half-edge of e directed b -> a with a cell
    std::vector<HalfEdge> cand;
    for (HalfFace hf : m.vertex_halffaces(b)) {  // the half-faces at b (the cache, or the walk around b)
        const HalfEdge h0 = m.halfedge(hf);
        HalfEdge h = h0;
        do {
            if (!m.is_deleted(h) && m.edge(h) == e && m.from_vertex(h) == b && m.cell(m.halfface(h)).is_valid())
                cand.push_back(h);
            h = m.next(h);
        } while (h != h0);
    }
    if (cand.empty()) return out;
    HalfEdge start = cand[0];
    for (HalfEdge h : cand)
        if (m.is_boundary(m.halfface(m.mate(h)))) start = h;  // a fan starts where the mate has no cell
    bool fan = false;
    for (HalfEdge h : cand) fan = fan || m.is_boundary(m.halfface(m.mate(h)));
    if (!fan)
        for (HalfEdge h : cand)
            if (m.cell(m.halfface(h)) < m.cell(m.halfface(start))) start = h;
    HalfEdge h = start;
    do {
        out.push_back(m.cell(m.halfface(h)));
        h = m.mate(m.twin(h));
        if (out.size() > cand.size()) break;
    } while (h != start && m.cell(m.halfface(h)).is_valid());
    return out;
}

template <class T>
std::string list(const std::vector<T>& v) {
    std::ostringstream os;
    os << '[';
    for (std::size_t i = 0; i < v.size(); ++i) os << (i ? " " : "") << v[i];
    os << ']';
    return os.str();
}

// The signed volume enclosed by a closed polygon soup (divergence theorem, fan triangulation).
inline double enclosed_volume(const PolygonSoup& s) {
    double v = 0;
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        auto vs = s.face(f);
        for (std::size_t i = 1; i + 1 < vs.size(); ++i)
            v += glm::dot(s.positions[vs[0]], glm::cross(s.positions[vs[i]], s.positions[vs[i + 1]])) / 6.0;
    }
    return v;
}

// The volume of a cell list (each cell by the divergence theorem over its faces).
inline double cells_volume(const CellList& cl) {
    double v = 0;
    for (std::size_t c = 0; c < cl.n_cells(); ++c)
        for (std::size_t i = 0; i < cl.n_faces(c); ++i) {
            auto vs = cl.face(c, i);
            for (std::size_t k = 1; k + 1 < vs.size(); ++k)
                v += glm::dot(cl.positions[vs[0]], glm::cross(cl.positions[vs[k]], cl.positions[vs[k + 1]])) / 6.0;
        }
    return v;
}

// Polygon-soup topology: V (used vertices), E, F, Euler characteristic, and whether every edge has exactly two
// faces using it in opposite directions (closed and consistently oriented).
struct SoupTopology {
    std::size_t V = 0, E = 0, F = 0;
    long chi = 0;
    bool closed_oriented = true;
};
inline SoupTopology soup_topology(const PolygonSoup& s) {
    SoupTopology t;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    std::set<std::uint32_t> used;
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        auto vs = s.face(f);
        for (std::size_t i = 0; i < vs.size(); ++i) {
            ++directed[{vs[i], vs[(i + 1) % vs.size()]}];
            used.insert(vs[i]);
        }
    }
    std::set<std::pair<std::uint32_t, std::uint32_t>> und;
    for (auto& [uv, n] : directed) {
        und.insert({std::min(uv.first, uv.second), std::max(uv.first, uv.second)});
        auto back = directed.find({uv.second, uv.first});
        if (n != 1 || back == directed.end() || back->second != 1) t.closed_oriented = false;
    }
    t.V = used.size(), t.E = und.size(), t.F = s.n_faces();
    t.chi = long(t.V) - long(t.E) + long(t.F);
    return t;
}

// The tetrahedral mesh tools/fetch_models.sh made of model `name` with tetgen (data/models/NAME.1.node/.ele).
inline CellList tet_model(const std::string& name) {
    const std::filesystem::path base = geolab::models_dir() / (name + ".1");
    if (!std::filesystem::exists(base.string() + ".ele"))
        FAIL("tet mesh " << base.string() << ".ele not found: run tools/fetch_models.sh (needs the tetgen package)");
    return cells_from(geolab::read_tetgen(base));
}
// The surface model `name` (data/models/NAME.off).
inline PolygonSoup surface_model(const std::string& name) {
    auto path = geolab::model_path(name);
    if (!path) FAIL("model " << name << " not found in " << geolab::models_dir().string() << ": run tools/fetch_models.sh");
    return geolab::read_mesh(*path);
}

}  // namespace lab02
