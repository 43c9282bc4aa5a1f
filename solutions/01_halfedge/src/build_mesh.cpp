// Task 1: build a half-edge mesh from a polygon soup (handout §3).
#include <algorithm>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "geolab/halfedge.hpp"

namespace geolab::halfedge {
namespace {
// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.

// A corner k of the soup is the directed edge u→v from soup.indices[k] to the next vertex of its face.
// `out` lists the corners by their start vertex (a counting sort): the corners leaving u are
// out[start[u] .. start[u+1]), each stored as the vertex it goes to and its half-edge h(u→v), invalid until the
// build makes it. Besides the mesh, these two arrays are all the memory the build uses: 8 bytes a corner.
// A bucket of typical size (at most kScanned corners: one or two cache lines) is scanned; a longer one is sorted
// by `to` and bisected, so a fan's apex (thousands of corners) costs O(log valence) a look-up, not O(valence).
struct DirectedEdges {
    struct Out {
        std::uint32_t to;
        Halfedge h;
    };
    // The corners u→v: how many there are, and one of them (the only one when count is 1).
    struct Found {
        std::size_t count;
        Out* corner;
    };
    static constexpr std::size_t kScanned = 16;
    std::vector<std::uint32_t> start;
    std::vector<Out> out;

    std::span<Out> leaving(std::uint32_t u) { return {out.data() + start[u], out.data() + start[u + 1]}; }
    std::span<const Out> leaving(std::uint32_t u) const { return {out.data() + start[u], out.data() + start[u + 1]}; }
    Found find(std::uint32_t u, std::uint32_t v) {
        const auto l = leaving(u);
        if (l.size() <= kScanned) {
            Found found{0, nullptr};
            for (Out& o : l)
                if (o.to == v) found = {found.count + 1, &o};
            return found;
        }
        const auto same = std::ranges::equal_range(l, v, {}, &Out::to);
        return {same.size(), same.data()};
    }
};

// The vertex that corner k (in face f) goes to.
std::uint32_t corner_target(const PolygonSoup& soup, std::size_t f, std::size_t k) {
    return soup.indices[k + 1 < soup.offsets[f + 1] ? k + 1 : soup.offsets[f]];
}

// Bucket the corners by start vertex: count, prefix sum (start[u] = the end of u's bucket), fill each bucket
// from its end (start[u] moves back to its beginning: no second array); then sort the long buckets
// (O(#corners log valence)).
DirectedEdges bucket_by_start(const PolygonSoup& soup) {
    DirectedEdges d;
    d.start.assign(soup.n_vertices() + 1, 0);
    for (std::uint32_t u : soup.indices) ++d.start[u];
    std::partial_sum(d.start.begin(), d.start.end(), d.start.begin());
    d.out.reserve(soup.indices.size());
    prefer_huge_pages(d.out);  // 2 MiB pages: fewer page faults (lib memory.hpp)
    d.out.resize(soup.indices.size());
    for (std::size_t f = 0; f < soup.n_faces(); ++f)
        for (std::size_t k = soup.offsets[f]; k < soup.offsets[f + 1]; ++k)
            d.out[--d.start[soup.indices[k]]] = {corner_target(soup, f, k), Halfedge{}};
    for (std::uint32_t v = 0; v < soup.n_vertices(); ++v)
        if (d.leaving(v).size() > DirectedEdges::kScanned) std::ranges::sort(d.leaving(v), {}, &DirectedEdges::Out::to);
    return d;
}

// The faces that use the directed edge u→v (and, if `both_ways`, v→u), in increasing order: for error messages
// only, so a pass over the whole soup is fine.
std::vector<std::size_t> faces_using(const PolygonSoup& soup, std::uint32_t u, std::uint32_t v, bool both_ways) {
    std::vector<std::size_t> faces;
    for (std::size_t f = 0; f < soup.n_faces(); ++f)
        for (std::size_t k = soup.offsets[f]; k < soup.offsets[f + 1]; ++k) {
            const std::uint32_t a = soup.indices[k], b = corner_target(soup, f, k);
            if ((a == u && b == v) || (both_ways && a == v && b == u)) faces.push_back(f);
        }
    return faces;
}

[[noreturn]] void throw_complex_edge(const PolygonSoup& soup, std::uint32_t u, std::uint32_t v) {
    std::string list;
    for (std::size_t f : faces_using(soup, u, v, true))
        list += (list.empty() ? "face " : ", face ") + std::to_string(f);
    throw TopologyError("build_mesh: complex edge between vertex " + std::to_string(std::min(u, v)) + " and vertex " +
                        std::to_string(std::max(u, v)) + ": used by " + list +
                        " (a manifold edge has at most 2 faces)");
}

[[noreturn]] void throw_orientation(const PolygonSoup& soup, std::uint32_t u, std::uint32_t v) {
    const auto faces = faces_using(soup, u, v, false);  // exactly two
    throw TopologyError("build_mesh: inconsistent orientation: face " + std::to_string(faces[0]) + " and face " +
                        std::to_string(faces[1]) + " both use the directed edge from vertex " + std::to_string(u) +
                        " to vertex " + std::to_string(v));
}

[[noreturn]] void throw_complex_vertex(std::uint32_t v, std::size_t face_a, std::size_t face_b) {
    throw TopologyError("build_mesh: complex vertex " + std::to_string(v) +
                        ": its faces form more than one fan (face " + std::to_string(std::min(face_a, face_b)) +
                        " and face " + std::to_string(std::max(face_a, face_b)) + " are in different fans)");
}

// h(u→v), the half-edge of the corner u→v of face f. Made with its twin by an earlier corner v→u, or made now by
// add_edge: its twin is then the matching corner v→u, or, if there is none, a boundary half-edge leaving v, which
// becomes halfedge(v) (a manifold vertex has at most one). Throws if the edge has 3+ faces or is used twice in the
// same direction.
Halfedge corner_halfedge(Mesh& mesh, const PolygonSoup& soup, DirectedEdges& d, std::uint32_t u, std::uint32_t v,
                         std::size_t f) {
    const auto twin = d.find(v, u);
    if (twin.count == 1 && twin.corner->h.is_valid()) return mesh.twin(twin.corner->h);  // made with its twin
    const auto same = d.find(u, v);  // this corner (and any other u→v)
    if (same.count + twin.count > 2) throw_complex_edge(soup, u, v);
    if (same.count == 2) throw_orientation(soup, u, v);
    const Halfedge h = mesh.add_edge(Vertex{u}, Vertex{v});
    same.corner->h = h;
    if (twin.count == 1) {
        twin.corner->h = mesh.twin(h);
    } else {
        // b = v→w, the boundary half-edge already leaving v, is the twin of the corner w→v of another face
        if (const Halfedge b = mesh.halfedge(Vertex{v}); b.is_valid() && mesh.is_boundary(b))
            throw_complex_vertex(v, f, mesh.face(mesh.twin(b)).idx);
        mesh.set_halfedge(Vertex{v}, mesh.twin(h));
    }
    return h;
}

// Edges and faces, in one pass over the soup: each corner's half-edge gets its face and the next corner's
// half-edge as next (the last one the first's); halfedge(f) is its first corner's, halfedge(u) the first corner's
// leaving u unless a boundary half-edge leaves u.
void add_faces(Mesh& mesh, const PolygonSoup& soup, DirectedEdges& d) {
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        const Face face = mesh.add_face();
        Halfedge previous;
        for (auto k = soup.offsets[f]; k < soup.offsets[f + 1]; ++k) {
            const std::uint32_t u = soup.indices[k];
            const Halfedge h = corner_halfedge(mesh, soup, d, u, corner_target(soup, f, k), f);
            mesh.set_face(h, face);
            if (!mesh.halfedge(Vertex{u}).is_valid()) mesh.set_halfedge(Vertex{u}, h);
            if (previous.is_valid())
                mesh.set_next(previous, h);
            else
                mesh.set_halfedge(face, h);
            previous = h;
        }
        mesh.set_next(previous, mesh.halfedge(face));
    }
}

// Holes: the boundary half-edge b = v→u (halfedge(v) of a boundary vertex) continues with the one leaving u.
void link_holes(Mesh& mesh) {
    for (Vertex v : mesh.vertices())
        if (const Halfedge b = mesh.halfedge(v); b.is_valid() && mesh.is_boundary(b))
            mesh.set_next(b, mesh.halfedge(mesh.to_vertex(b)));
}

// Walk around every vertex from halfedge(v): at a manifold vertex the walk meets every face corner at v.
// (Hourglass vertices with a boundary were caught in corner_halfedge; this catches those without.)
void check_single_fans(const Mesh& mesh, const DirectedEdges& d) {
    for (Vertex v : mesh.vertices()) {
        const Halfedge h0 = mesh.halfedge(v);
        if (!h0.is_valid()) continue;
        std::size_t n_faces_met = 0;
        Halfedge h = h0;
        do {
            n_faces_met += !mesh.is_boundary(h);
            h = mesh.next(mesh.twin(h));
        } while (h != h0);
        const auto corners = d.leaving(v.idx);
        if (n_faces_met == corners.size()) continue;
        // Name a face of the fan we walked and the first face at v (in soup order) that the walk did not meet
        // (the fan's half-edges sorted, so the search is O(n log n)).
        std::vector<Halfedge> fan;
        for (Halfedge h = h0; fan.empty() || h != h0; h = mesh.next(mesh.twin(h))) fan.push_back(h);
        std::sort(fan.begin(), fan.end());
        std::uint32_t missed = invalid_index;
        for (auto o : corners)
            if (!std::binary_search(fan.begin(), fan.end(), o.h)) missed = std::min(missed, mesh.face(o.h).idx);
        if (missed != invalid_index) {
            Halfedge in_fan = mesh.is_boundary(h0) ? mesh.next(mesh.twin(h0)) : h0;
            throw_complex_vertex(v.idx, mesh.face(in_fan).idx, missed);
        }
    }
}

// END SOLUTION
}  // namespace

Mesh build_mesh(const PolygonSoup& soup) {
    // BEGIN SOLUTION
    check_soup(soup);
    DirectedEdges d = bucket_by_start(soup);
    Mesh mesh;
    mesh.reserve(soup.n_vertices(), soup.indices.size(), soup.n_faces());  // at most one edge per corner
    for (const auto& p : soup.positions) mesh.add_vertex(p);
    add_faces(mesh, soup, d);  // twins found, boundary half-edges made, faces linked
    link_holes(mesh);
    check_single_fans(mesh, d);  // hourglass vertices without boundary
    return mesh;
    // END SOLUTION
}

}  // namespace geolab::halfedge
