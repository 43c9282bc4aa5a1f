// Lab 02, Task 3: deletion and garbage collection (handout §5). Meshes from stored data (stored.hpp).
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab02;

namespace {
// The cell list without the cells in `gone` (vertices kept, so indices do not move).
CellList without(const CellList& cl, const std::set<std::uint32_t>& gone) {
    CellList r;
    r.positions = cl.positions;
    for (std::size_t c = 0; c < cl.n_cells(); ++c) {
        if (gone.count(std::uint32_t(c))) continue;
        for (std::size_t i = 0; i < cl.n_faces(c); ++i) r.add_face(cl.face(c, i));
        r.close_cell(cl.types[c], cl.labels[c]);
    }
    return r;
}
// Checks the alive part of m against the reference of `cl` (same vertices).
void check_alive_counts(const Mesh& m, const CellList& cl, const std::string& what) {
    INFO("input: " << what);
    const Reference r = reference(cl);
    CHECK_MESSAGE(m.n_alive(Kind::cell) == r.C, "alive cells: expected " << r.C << ", got " << m.n_alive(Kind::cell));
    CHECK_MESSAGE(m.n_alive(Kind::face) == r.F, "alive faces: expected " << r.F << ", got " << m.n_alive(Kind::face));
    CHECK_MESSAGE(m.n_alive(Kind::edge) == r.E, "alive edges: expected " << r.E << ", got " << m.n_alive(Kind::edge));
    std::size_t bnd = 0;
    for (HalfFace hf : m.halffaces()) bnd += !m.is_deleted(hf) && !m.cell(hf).is_valid();
    CHECK_MESSAGE(bnd == r.boundary_faces, "alive boundary half-faces: expected " << r.boundary_faces << ", got " << bnd);
}
std::vector<HalfFace> scan_halffaces(const Mesh& m, Vertex v) {
    std::vector<HalfFace> out;
    for (HalfEdge h : m.halfedges())
        if (!m.is_deleted(h) && m.to_vertex(h) == v) out.push_back(m.halfface(h));
    std::sort(out.begin(), out.end());
    return out;
}
// True when the alive half-faces at v form one group joined by "same face" (hf, opposite(hf)) and "same cell":
// then the walk of a configuration without the cache finds them all (halfface/mesh.hpp). After deletions a vertex
// can be pinched (its cells meet only at v, or along an edge).
bool walk_finds_all(const Mesh& m, Vertex v) {
    const auto hfs = scan_halffaces(m, v);
    std::vector<std::size_t> group(hfs.size());
    for (std::size_t i = 0; i < hfs.size(); ++i) group[i] = i;
    auto root = [&](std::size_t i) {
        while (group[i] != i) i = group[i];
        return i;
    };
    for (std::size_t i = 0; i < hfs.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (Mesh::face(hfs[i]) == Mesh::face(hfs[j]) || (m.cell(hfs[i]).is_valid() && m.cell(hfs[i]) == m.cell(hfs[j])))
                group[root(i)] = root(j);
    for (std::size_t i = 0; i < hfs.size(); ++i)
        if (root(i) != root(0)) return false;
    return true;
}

// The mesh in each configuration answers as the stored one: prev, mate, the half-faces around each vertex (the
// cache, or the walk where it finds them all) and the radial walk around each alive edge.
void check_configs(const Mesh& m, const std::string& what) {
    for_each_config(m, [&](const auto& x, const char* config) {
        INFO("input: " << what << ", configuration " << std::string(config));
        for (HalfEdge h : m.halfedges()) {
            if (m.is_deleted(h)) continue;
            REQUIRE_MESSAGE(x.prev(h) == m.prev(h), h << ": prev " << x.prev(h) << ", stored " << m.prev(h));
            REQUIRE_MESSAGE(x.mate(h) == m.mate(h), h << ": mate " << x.mate(h) << ", stored " << m.mate(h));
        }
        const bool cached = std::decay_t<decltype(x)>::traits::vertex_cache;
        std::vector<bool> whole(m.n_vertices());
        for (Vertex v : m.vertices()) {
            whole[v.idx] = !m.is_deleted(v) && (cached || walk_finds_all(m, v));
            if (whole[v.idx])
                REQUIRE_MESSAGE(x.vertex_halffaces(v) == scan_halffaces(m, v),
                                v << ": half-faces around it " << list(x.vertex_halffaces(v)) << ", alive ones there "
                                  << list(scan_halffaces(m, v)));
        }
        for (Edge e : m.edges())
            if (!m.is_deleted(e) && whole[m.edge_vertices(e)[1].idx])
                REQUIRE_MESSAGE(radial_cells(x, e) == radial_cells(m, e), e << ": the cells around it "
                                                                            << list(radial_cells(x, e)) << ", stored "
                                                                            << list(radial_cells(m, e)));
    });
}
}  // namespace

TEST_SUITE("Task 3: deletion and garbage collection") {
    TEST_CASE("delete_cell: the cell's faces become boundary or go / edges without faces go / the mesh stays valid" *
              geolab::points(2) *
              geolab::hint("Clear cell(hf) and the twins of the cell's half-faces; delete a face with no cell left on "
                           "either side, an edge with no alive half-edge; move halfedge(e) and halfedge(v).")) {
        for (const char* key : {"tet grid 2", "two tets", "hex grid 2", "prisms and pyramids"}) {
            const Fixture f = [&] {
                for (auto& x : stored_fixtures())
                    if (x.name == key) return x;
                return Fixture{};
            }();
            Mesh m = stored_mesh(f);
            std::set<std::uint32_t> gone;
            for (std::uint32_t c = 0; c < m.n_cells(); c += 3) {
                delete_cell(m, Cell{c});
                gone.insert(c);
                REQUIRE_MESSAGE(m.is_deleted(Cell{c}), key << ": c" << c << " not marked deleted");
                require_valid(m, std::string(key) + " after deleting c" + std::to_string(c));
            }
            delete_cell(m, Cell{0});  // again: nothing happens
            require_valid(m, std::string(key) + " after deleting c0 twice");
            check_alive_counts(m, without(f.cells, gone), std::string(key) + " without cells " + list(std::vector(gone.begin(), gone.end())));
        }
    }

    TEST_CASE("delete_cell: the vertex cache never lists a deleted half-face" * geolab::points(2) *
              geolab::hint("After deleting, vertex_halffaces(v) must list exactly the alive half-faces at v: rebuild the "
                           "cache (rebuild_vertex_cache) or remove the entries.")) {
        Mesh m = stored_mesh("tet grid 3");
        for (std::uint32_t c : {5u, 17u, 40u, 41u, 100u}) {
            delete_cell(m, Cell{c});
            REQUIRE_MESSAGE(m.is_deleted(Cell{c}), "c" << c << " is not deleted");
            for (Vertex v : m.vertices()) {
                const auto expected = scan_halffaces(m, v);
                REQUIRE_MESSAGE(m.vertex_halffaces(v) == expected,
                                "after deleting c" << c << ", " << v << ": cache " << list(m.vertex_halffaces(v))
                                                   << ", alive half-faces there " << list(expected));
            }
        }
        // every configuration of the result: the walk around each vertex (no cache) finds the same half-faces
        check_configs(m, "tet grid 3 after deleting c5, c17, c40, c41, c100");
    }

    TEST_CASE("delete_vertex: removes the vertex / its cells and its edges" * geolab::points(2) *
              geolab::hint("Delete every cell at v (delete_cell), then mark v and its edges deleted.")) {
        Mesh m = stored_mesh("tet grid 2");
        const CellList cl = fx::tet_grid(2, 0.3);
        const Vertex centre{std::uint32_t(fx::grid_index(2, 1, 1, 1))};
        std::set<std::uint32_t> gone;
        for (std::size_t c = 0; c < cl.n_cells(); ++c)
            for (std::size_t i = 0; i < cl.n_faces(c); ++i)
                for (auto v : cl.face(c, i))
                    if (v == centre.idx) gone.insert(std::uint32_t(c));
        delete_vertex(m, centre);
        CHECK_MESSAGE(m.is_deleted(centre), "the vertex itself is not marked deleted");
        require_valid(m, "tet grid 2 after deleting its centre vertex");
        for (std::uint32_t c = 0; c < m.n_cells(); ++c)
            CHECK_MESSAGE(m.is_deleted(Cell{c}) == (gone.count(c) > 0),
                          "c" << c << (gone.count(c) ? " uses the vertex and must be deleted" : " must stay"));
        for (Edge e : m.edges())
            if (!m.is_deleted(e)) {
                const auto ev = m.edge_vertices(e);
                CHECK_MESSAGE((ev[0] != centre && ev[1] != centre), e << " uses the deleted vertex but is alive");
            }
        check_alive_counts(m, without(cl, gone), "tet grid 2 without the cells at its centre");
    }

    TEST_CASE("garbage_collection: compacts every kind in order and returns the maps" * geolab::points(3) *
              geolab::hint("New index = number of alive elements before it; half-faces 2f, 2f+1 -> 2f', 2f'+1; renumber "
                           "every stored handle (remap_handles) before compacting the arrays (compact).")) {
        Mesh m = stored_mesh("tet grid 3");
        const CellList cl = fx::tet_grid(3, 0.3);
        std::set<std::uint32_t> gone;
        for (std::uint32_t c = 0; c < m.n_cells(); c += 4) delete_cell(m, Cell{c}), gone.insert(c);
        delete_vertex(m, Vertex{std::uint32_t(fx::grid_index(3, 1, 1, 1))});
        std::vector<bool> alive_before[6];
        for (int k = 0; k < 6; ++k) {
            alive_before[k].resize(m.count(Kind(k)));
        }
        for (Vertex v : m.vertices()) alive_before[0][v.idx] = !m.is_deleted(v);
        for (Cell c : m.cells()) alive_before[5][c.idx] = !m.is_deleted(c);
        const Mesh before = m;
        const Remap r = garbage_collection(m);
        require_valid(m, "tet grid 3 after garbage collection");
        CHECK_MESSAGE(!m.has_garbage(), "elements marked deleted remain after garbage collection");
        check_configs(m, "tet grid 3 after garbage collection");
        auto check_map = [&](const std::vector<std::uint32_t>& map, std::size_t n, auto is_alive, const char* kind) {
            REQUIRE_MESSAGE(map.size() == n, kind << " map: one entry per old element expected (" << n << "), got " << map.size());
            std::uint32_t next = 0;
            for (std::uint32_t i = 0; i < n; ++i) {
                const std::uint32_t expected = is_alive(i) ? next++ : geolab::halfface::invalid_index;
                REQUIRE_MESSAGE(map[i] == expected, kind << " map: old " << i << " expected " << std::int64_t(expected == geolab::halfface::invalid_index ? -1 : expected)
                                                        << ", got " << std::int64_t(map[i] == geolab::halfface::invalid_index ? -1 : map[i]));
            }
        };
        check_map(r.vertices, before.n_vertices(), [&](std::uint32_t i) { return !before.is_deleted(Vertex{i}); }, "vertex");
        check_map(r.edges, before.n_edges(), [&](std::uint32_t i) { return !before.is_deleted(Edge{i}); }, "edge");
        check_map(r.halfedges, before.n_halfedges(), [&](std::uint32_t i) { return !before.is_deleted(HalfEdge{i}); }, "half-edge");
        check_map(r.faces, before.n_faces(), [&](std::uint32_t i) { return !before.is_deleted(Face{i}); }, "face");
        check_map(r.halffaces, before.n_halffaces(), [&](std::uint32_t i) { return !before.is_deleted(HalfFace{i}); }, "half-face");
        check_map(r.cells, before.n_cells(), [&](std::uint32_t i) { return !before.is_deleted(Cell{i}); }, "cell");
        // the structure is the same: every alive old half-edge maps to one with the mapped relations
        for (HalfEdge h : before.halfedges()) {
            if (before.is_deleted(h)) continue;
            const HalfEdge n{r.halfedges[h.idx]};
            REQUIRE(n.idx < m.n_halfedges());
            CHECK(m.next(n).idx == r.halfedges[before.next(h).idx]);
            CHECK(m.mate(n).idx == r.halfedges[before.mate(h).idx]);
            CHECK(m.to_vertex(n).idx == r.vertices[before.to_vertex(h).idx]);
            CHECK(m.halfface(n).idx == r.halffaces[before.halfface(h).idx]);
            CHECK(m.edge(n).idx == r.edges[before.edge(h).idx]);
            CHECK(m.position(m.to_vertex(n)) == before.position(before.to_vertex(h)));
        }
        for (Cell c : before.cells())
            if (!before.is_deleted(c)) {
                const auto a = before.halffaces(c);
                const auto b = m.halffaces(Cell{r.cells[c.idx]});
                REQUIRE(a.size() == b.size());
                for (std::size_t i = 0; i < a.size(); ++i) CHECK(b[i].idx == r.halffaces[a[i].idx]);
            }
    }

    TEST_CASE("garbage_collection: dynamic properties follow their elements" * geolab::points(3) *
              geolab::hint("Compact each kind's properties with the same map (compact_properties).")) {
        Mesh m = stored_mesh("hex grid 2");
        auto pc = m.add_property<Kind::cell, std::int32_t>("old cell");
        auto pv = m.add_property<Kind::vertex, glm::dvec3>("old position");
        auto pe = m.add_property<Kind::edge, std::uint32_t>("old edge");
        auto phf = m.add_property<Kind::halfface, std::uint32_t>("old half-face");
        auto ph = m.add_property<Kind::halfedge, std::uint32_t>("old half-edge");
        for (Cell c : m.cells()) m.set(pc, c, std::int32_t(c.idx));
        for (Vertex v : m.vertices()) m.set(pv, v, m.position(v));
        for (Edge e : m.edges()) m.set(pe, e, e.idx);
        for (HalfFace hf : m.halffaces()) m.set(phf, hf, hf.idx);
        for (HalfEdge h : m.halfedges()) m.set(ph, h, h.idx);
        const std::size_t cells = m.n_cells(), vertices = m.n_vertices();
        delete_cell(m, Cell{1});
        delete_cell(m, Cell{6});
        delete_vertex(m, Vertex{0});
        const Remap r = garbage_collection(m);
        require_valid(m, "hex grid 2 after garbage collection");
        // (an empty map moves nothing: it must cover every old element, and the deleted ones are gone)
        REQUIRE_MESSAGE((r.cells.size() == cells && r.vertices.size() == vertices), "the maps must have one entry per old "
                        "cell and vertex: " << r.cells.size() << " of " << cells << ", " << r.vertices.size() << " of " << vertices);
        CHECK((r.cells[1] == geolab::halfface::invalid_index && r.cells[6] == geolab::halfface::invalid_index &&
               r.vertices[0] == geolab::halfface::invalid_index));
        CHECK(m.n_cells() < cells - 1);
        for (std::uint32_t i = 0; i < r.cells.size(); ++i)
            if (r.cells[i] != geolab::halfface::invalid_index)
                REQUIRE_MESSAGE(m.get(pc, Cell{r.cells[i]}) == std::int32_t(i),
                                "cell property: new c" << r.cells[i] << " holds " << m.get(pc, Cell{r.cells[i]})
                                                       << ", expected the value of old c" << i);
        for (Vertex v : m.vertices()) REQUIRE_MESSAGE(m.get(pv, v) == m.position(v), "vertex property of " << v << " not moved with it");
        for (std::uint32_t i = 0; i < r.edges.size(); ++i)
            if (r.edges[i] != geolab::halfface::invalid_index) REQUIRE(m.get(pe, Edge{r.edges[i]}) == i);
        for (std::uint32_t i = 0; i < r.halffaces.size(); ++i)
            if (r.halffaces[i] != geolab::halfface::invalid_index) REQUIRE(m.get(phf, HalfFace{r.halffaces[i]}) == i);
        for (std::uint32_t i = 0; i < r.halfedges.size(); ++i)
            if (r.halfedges[i] != geolab::halfface::invalid_index) REQUIRE(m.get(ph, HalfEdge{r.halfedges[i]}) == i);
        const auto& props = m.properties();
        for (const auto& p : props)
            if (p.alive) CHECK_MESSAGE(p.bytes.size() == m.count(Kind(p.kind)) * p.value_size, "property '" << p.name << "' has the wrong size");
    }

    TEST_CASE("garbage_collection: without garbage it changes nothing" * geolab::points(1) *
              geolab::hint("Every map is the identity; the arrays stay as they are.")) {
        Mesh m = stored_mesh("prisms and pyramids");
        const Mesh before = m;
        const Remap r = garbage_collection(m);
        for (std::uint32_t i = 0; i < r.halfedges.size(); ++i) REQUIRE(r.halfedges[i] == i);
        REQUIRE(r.cells.size() == before.n_cells());
        for (HalfEdge h : m.halfedges()) {
            CHECK(m.next(h) == before.next(h));
            CHECK(m.twin(h) == before.twin(h));
        }
        require_valid(m, "prisms and pyramids after garbage collection");
    }
}
