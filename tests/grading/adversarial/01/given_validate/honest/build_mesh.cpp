// ADVERSARIAL CASE given_validate: build_mesh forgets one line (boundary vertices keep a face half-edge). Task 1 from a polygon soup (handout §3).
#include <algorithm>
#include <span>
#include <string>
#include <vector>

#include "geolab/halfedge.hpp"

namespace geolab::halfedge {
namespace {
// STUB: // Helper functions of your own can go here.

// A corner k of the soup is the directed edge from soup.indices[k] to the next vertex of its face.
// `out` lists the corners by their start vertex (a counting sort): the corners leaving u are
// out[start[u] .. start[u+1]), each stored with the vertex it goes to.
struct DirectedEdges {
    struct Out {
        std::uint32_t to;
        std::uint32_t corner;
    };
    std::vector<std::uint32_t> start;
    std::vector<Out> out;

    std::span<const Out> leaving(std::uint32_t u) const { return {out.data() + start[u], out.data() + start[u + 1]}; }
};

// The vertex that corner k (in face f) goes to.
std::uint32_t corner_target(const PolygonSoup& soup, std::size_t f, std::size_t k) {
    return soup.indices[k + 1 < soup.offsets[f + 1] ? k + 1 : soup.offsets[f]];
}

// Bucket the corners by start vertex: count, prefix sum, fill.
DirectedEdges bucket_by_start(const PolygonSoup& soup) {
    DirectedEdges d;
    d.start.assign(soup.n_vertices() + 1, 0);
    for (std::uint32_t u : soup.indices) ++d.start[u + 1];
    for (std::size_t v = 0; v < soup.n_vertices(); ++v) d.start[v + 1] += d.start[v];
    d.out.resize(soup.indices.size());
    std::vector<std::uint32_t> fill(d.start.begin(), d.start.end() - 1);
    for (std::size_t f = 0; f < soup.n_faces(); ++f)
        for (std::size_t k = soup.offsets[f]; k < soup.offsets[f + 1]; ++k)
            d.out[fill[soup.indices[k]]++] = {corner_target(soup, f, k), static_cast<std::uint32_t>(k)};
    return d;
}

// The face that corner k belongs to (used for error messages only).
std::size_t face_of_corner(const PolygonSoup& soup, std::uint32_t k) {
    return static_cast<std::size_t>(std::upper_bound(soup.offsets.begin(), soup.offsets.end(), k) -
                                    soup.offsets.begin() - 1);
}

// The corners going from u to v.
std::vector<std::uint32_t> corners_from_to(const DirectedEdges& d, std::uint32_t u, std::uint32_t v) {
    std::vector<std::uint32_t> ks;
    for (auto o : d.leaving(u))
        if (o.to == v) ks.push_back(o.corner);
    return ks;
}

[[noreturn]] void throw_complex_edge(const PolygonSoup& soup, const DirectedEdges& d, std::uint32_t u,
                                     std::uint32_t v) {
    std::vector<std::size_t> faces;
    for (auto k : corners_from_to(d, u, v)) faces.push_back(face_of_corner(soup, k));
    for (auto k : corners_from_to(d, v, u)) faces.push_back(face_of_corner(soup, k));
    std::sort(faces.begin(), faces.end());
    std::string list;
    for (std::size_t i = 0; i < faces.size(); ++i) list += (i ? ", face " : "face ") + std::to_string(faces[i]);
    throw TopologyError("build_mesh: complex edge between vertex " + std::to_string(std::min(u, v)) + " and vertex " +
                        std::to_string(std::max(u, v)) + ": used by " + list +
                        " (a manifold edge has at most 2 faces)");
}

[[noreturn]] void throw_orientation(const PolygonSoup& soup, std::uint32_t k1, std::uint32_t k2, std::uint32_t u,
                                    std::uint32_t v) {
    throw TopologyError("build_mesh: inconsistent orientation: face " + std::to_string(face_of_corner(soup, k1)) +
                        " and face " + std::to_string(face_of_corner(soup, k2)) +
                        " both use the directed edge from vertex " + std::to_string(u) + " to vertex " +
                        std::to_string(v));
}

[[noreturn]] void throw_complex_vertex(std::uint32_t v, std::size_t face_a, std::size_t face_b) {
    throw TopologyError("build_mesh: complex vertex " + std::to_string(v) +
                        ": its faces form more than one fan (face " + std::to_string(std::min(face_a, face_b)) +
                        " and face " + std::to_string(std::max(face_a, face_b)) + " are in different fans)");
}

// The corner v→u that is the twin of corner k = u→v, or invalid_index if there is none (a boundary edge).
// Throws if the edge has 3+ faces or is used twice in the same direction.
std::uint32_t find_twin_corner(const PolygonSoup& soup, const DirectedEdges& d, std::uint32_t k, std::uint32_t u,
                               std::uint32_t v) {
    std::uint32_t same = invalid_index, twin = invalid_index;
    int n_same = 0, n_twin = 0;
    for (auto o : d.leaving(u))
        if (o.to == v && o.corner != k) ++n_same, same = o.corner;
    for (auto o : d.leaving(v))
        if (o.to == u) ++n_twin, twin = o.corner;
    if (1 + n_same + n_twin > 2) throw_complex_edge(soup, d, u, v);
    if (n_same == 1) throw_orientation(soup, std::min(k, same), std::max(k, same), u, v);
    return twin;
}

// The half-edge made for each corner, and the boundary half-edge leaving each vertex (if any).
struct Sides {
    std::vector<Halfedge> corner_halfedge;
    std::vector<Halfedge> boundary_out;
    std::vector<std::uint32_t> boundary_corner;  // the corner whose twin is boundary_out[v] (for messages)
};

// One edge per undirected edge: the corner's half-edge plus its twin, which is the matching corner v→u or,
// if there is none, a boundary half-edge leaving v.
Sides add_edges(Mesh& mesh, const PolygonSoup& soup, const DirectedEdges& d) {
    Sides s{std::vector<Halfedge>(soup.indices.size()), std::vector<Halfedge>(soup.n_vertices()),
            std::vector<std::uint32_t>(soup.n_vertices())};
    for (std::size_t f = 0; f < soup.n_faces(); ++f)
        for (auto k = soup.offsets[f]; k < soup.offsets[f + 1]; ++k) {
            if (s.corner_halfedge[k].is_valid()) continue;  // made as the twin of an earlier corner
            const std::uint32_t u = soup.indices[k], v = corner_target(soup, f, k);
            const std::uint32_t t = find_twin_corner(soup, d, k, u, v);
            const Halfedge h = mesh.add_edge(Vertex{u}, Vertex{v});
            s.corner_halfedge[k] = h;
            if (t != invalid_index) {
                s.corner_halfedge[t] = mesh.twin(h);
            } else {  // twin(h) = v→u has no face; a manifold vertex has at most one such half-edge leaving it
                if (s.boundary_out[v].is_valid())
                    throw_complex_vertex(v, f, face_of_corner(soup, s.boundary_corner[v]));
                s.boundary_out[v] = mesh.twin(h);
                s.boundary_corner[v] = k;
            }
        }
    return s;
}

// Faces: link each face's half-edges in the soup's order and set their face.
void link_faces(Mesh& mesh, const PolygonSoup& soup, const std::vector<Halfedge>& corner_halfedge) {
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        const Face face = mesh.add_face();
        const auto first = soup.offsets[f], end = soup.offsets[f + 1];
        mesh.set_halfedge(face, corner_halfedge[first]);
        for (auto k = first; k < end; ++k) {
            mesh.set_next(corner_halfedge[k], corner_halfedge[k + 1 < end ? k + 1 : first]);
            mesh.set_face(corner_halfedge[k], face);
        }
    }
}

// Vertices and holes: halfedge(v) is any outgoing half-edge, replaced by the boundary one where there is one;
// the boundary half-edge b = v→u continues with the boundary half-edge leaving u.
void link_vertices_and_holes(Mesh& mesh, const PolygonSoup& soup, const Sides& s) {
    for (std::size_t k = 0; k < soup.indices.size(); ++k)
        if (const Vertex v{soup.indices[k]}; !mesh.halfedge(v).is_valid()) mesh.set_halfedge(v, s.corner_halfedge[k]);
    for (Vertex v : mesh.vertices())
        if (const Halfedge b = s.boundary_out[v.idx]; b.is_valid()) {
            // (forgot: mesh.set_halfedge(v, b);)
            mesh.set_next(b, s.boundary_out[mesh.to_vertex(b).idx]);
        }
}

// Walk around every vertex from halfedge(v): at a manifold vertex the walk meets every face corner at v.
// (Hourglass vertices with a boundary were caught in add_edges; this catches those without.)
void check_single_fans(const Mesh& mesh, const PolygonSoup& soup, const DirectedEdges& d,
                       const std::vector<Halfedge>& corner_halfedge) {
    for (Vertex v : mesh.vertices()) {
        const Halfedge h0 = mesh.halfedge(v);
        if (!h0.is_valid()) continue;
        std::size_t n_faces_met = 0;
        Halfedge h = h0;
        do {
            n_faces_met += !mesh.is_boundary(h);
            h = mesh.next(mesh.twin(h));
        } while (h != h0);
        const auto n_corners = d.start[v.idx + 1] - d.start[v.idx];
        if (n_faces_met == n_corners) continue;
        // Name a face of the fan we walked and a face we did not meet.
        std::vector<Halfedge> fan;
        for (Halfedge h = h0; fan.empty() || h != h0; h = mesh.next(mesh.twin(h))) fan.push_back(h);
        for (auto o : d.leaving(v.idx))
            if (std::find(fan.begin(), fan.end(), corner_halfedge[o.corner]) == fan.end()) {
                Halfedge in_fan = mesh.is_boundary(h0) ? mesh.next(mesh.twin(h0)) : h0;
                throw_complex_vertex(v.idx, mesh.face(in_fan).idx, face_of_corner(soup, o.corner));
            }
    }
}

}  // namespace

Mesh build_mesh(const PolygonSoup& soup) {
    check_soup(soup);
    const DirectedEdges d = bucket_by_start(soup);
    Mesh mesh;
    mesh.reserve(soup.n_vertices(), soup.indices.size(), soup.n_faces());  // at most one edge per corner
    for (const auto& p : soup.positions) mesh.add_vertex(p);
    const Sides sides = add_edges(mesh, soup, d);  // twins found, boundary half-edges made
    link_faces(mesh, soup, sides.corner_halfedge);
    link_vertices_and_holes(mesh, soup, sides);
    check_single_fans(mesh, soup, d, sides.corner_halfedge);  // hourglass vertices without boundary
    return mesh;
}

}  // namespace geolab::halfedge
