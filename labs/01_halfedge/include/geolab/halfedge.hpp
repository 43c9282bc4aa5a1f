#pragma once
//! \file halfedge.hpp
//! Lab 01 — half-edge meshes: YOUR TASKS. Write these functions in labs/01_halfedge/src/*.cpp
//! (one file per task). The mesh class you build and query is given in geolab/halfedge/mesh.hpp.
//!
//! | task | file            | functions                                                               | handout |
//! |------|-----------------|-------------------------------------------------------------------------|---------|
//! | 1    | build_mesh.cpp  | build_mesh                                                              | §3      |
//! | 2    | queries.cpp     | edge_vertices, edge_faces, face_halfedges, outgoing_halfedges           | §4      |
//! | 3    | topology.cpp    | valence, one_ring_vertices, one_ring_faces, boundary_loops,             | §5      |
//! |      |                 | euler_characteristic, connected_components, genus                       |         |
//! | 4    | geometry.cpp    | face_normal, face_area, vertex_normal                                   | §6      |
//! | 5    | smoothing.cpp   | laplacian_smoothing                                                     | §7      |
//!
//! Functions that list many elements come in two forms: `f(mesh, x, out)` clears `out` and fills it (you write
//! this one; reusing one buffer for a sweep over a whole mesh allocates nothing), and `f(mesh, x)` returns a new
//! vector (given: it calls yours).
#include <utility>
#include <vector>

#include "geolab/boundary.hpp"
#include "geolab/errors.hpp"
#include "geolab/halfedge/mesh.hpp"
#include "geolab/soup.hpp"

namespace geolab::halfedge {

// ==== Task 1: build the mesh (handout §3) ===================================================================

//! Build the half-edge mesh of a polygon soup whose faces are counter-clockwise seen from outside.
//!
//! Result: vertex i is soup vertex i (same position); face f is soup face f, and `face_halfedges(mesh, f)`
//! visits soup.face(f) in order: the half-edge from soup.face(f)[0] to soup.face(f)[1] is halfedge(f), and so
//! on. Each undirected edge used by the faces becomes one edge; a side used by no face is a boundary half-edge,
//! and the boundary half-edges around each hole are linked by next into a closed loop. halfedge(v) is a
//! boundary half-edge when v is on the boundary; invalid when v is used by no face (isolated vertices are kept).
//! The result passes validate().
//!
//! Cost: O(#corners · log valence) time at most, whatever the valences, with flat arrays: e.g. the directed edges
//! bucketed by their start vertex (a counting sort) and sorted by end vertex within each bucket, so that the twin
//! of u→v is a binary search among the edges leaving v. (A linear scan there is quadratic at a vertex of high
//! valence: a fan of 400,000 triangles would take minutes.)
//!
//! \throw std::invalid_argument (from geolab::check_soup) when the soup is not valid data: an index out of
//!        range, a face with fewer than 3 vertices or a repeated vertex, a non-finite coordinate.
//! \throw geolab::TopologyError when the soup is not an oriented 2-manifold (with boundary), with exactly
//!        these messages (A, B, C face indices; u, v vertex indices):
//!   - "build_mesh: complex edge between vertex u and vertex v: used by face A, face B, face C (a manifold edge
//!     has at most 2 faces)" — three or more faces share an edge (u < v);
//!   - "build_mesh: inconsistent orientation: face A and face B both use the directed edge from vertex u to
//!     vertex v" — two faces on one edge run the same way (a flipped face, or a Möbius strip);
//!   - "build_mesh: complex vertex v: its faces form more than one fan (face A and face B are in different
//!     fans)" — faces meet only at v (an hourglass or bowtie).
Mesh build_mesh(const PolygonSoup& soup);

// ==== Task 2: the lecture's queries (handout §4) ============================================================

//! The two end vertices of edge e: (from_vertex, to_vertex) of halfedge(e, 0).
std::pair<Vertex, Vertex> edge_vertices(const Mesh& mesh, Edge e);

//! The two faces of edge e: (face of halfedge(e, 0), face of halfedge(e, 1)); invalid on a boundary side.
std::pair<Face, Face> edge_faces(const Mesh& mesh, Edge e);

//! The half-edges of face f, in order: halfedge(f), next of it, ... until back at the start (not repeated).
void face_halfedges(const Mesh& mesh, Face f, std::vector<Halfedge>& out);

//! The half-edges leaving v, in the lecture's order: h0 = halfedge(v), then h = next(twin(h)) (the lecture's
//! `edge = edge->pair->next`) until back at h0 (not repeated). This turns clockwise around v seen from outside.
//! On the boundary it starts with the boundary half-edge. Empty for an isolated vertex.
void outgoing_halfedges(const Mesh& mesh, Vertex v, std::vector<Halfedge>& out);

inline std::vector<Halfedge> face_halfedges(const Mesh& mesh, Face f) {
    std::vector<Halfedge> out;
    face_halfedges(mesh, f, out);
    return out;
}
inline std::vector<Halfedge> outgoing_halfedges(const Mesh& mesh, Vertex v) {
    std::vector<Halfedge> out;
    outgoing_halfedges(mesh, v, out);
    return out;
}

// ==== Task 3: topology (handout §5) =========================================================================

//! The number of edges at v (= the number of half-edges leaving v; 0 for an isolated vertex).
int valence(const Mesh& mesh, Vertex v);

//! The neighbours of v, in the order of outgoing_halfedges: to_vertex of each half-edge leaving v.
void one_ring_vertices(const Mesh& mesh, Vertex v, std::vector<Vertex>& out);

//! The faces around v, in the order of outgoing_halfedges: face of each half-edge leaving v, skipping the
//! boundary (invalid faces are never listed).
void one_ring_faces(const Mesh& mesh, Vertex v, std::vector<Face>& out);

inline std::vector<Vertex> one_ring_vertices(const Mesh& mesh, Vertex v) {
    std::vector<Vertex> out;
    one_ring_vertices(mesh, v, out);
    return out;
}
inline std::vector<Face> one_ring_faces(const Mesh& mesh, Vertex v) {
    std::vector<Face> out;
    one_ring_faces(mesh, v, out);
    return out;
}

//! The holes: one loop of boundary half-edges per hole, each following next. Each loop starts at its
//! lowest-numbered half-edge; loops are sorted by that first half-edge. Empty for a closed mesh.
std::vector<std::vector<Halfedge>> boundary_loops(const Mesh& mesh);

//! χ = V − E + F (isolated vertices count in V).
int euler_characteristic(const Mesh& mesh);

//! Connected components: vertices joined by edges are in the same component; an isolated vertex is a
//! component of its own.
struct Components {
    int count = 0;                      //!< the number of components
    std::vector<int> vertex_component;  //!< per vertex, its component in 0..count-1
    GEOLAB_FIELDS(count, vertex_component)
};

//! The connected components. Numbered in order of their lowest vertex: vertex 0 is in component 0, the first
//! vertex not in component 0 is in component 1, and so on.
Components connected_components(const Mesh& mesh);

//! The genus (number of handles) of an orientable surface: the sum over components that have faces of
//! g_c = (2 − χ_c − b_c) / 2, with χ_c the Euler characteristic and b_c the number of boundary loops of the
//! component. Sphere, disk: 0; torus: 1. Isolated vertices are ignored.
int genus(const Mesh& mesh);

// ==== Task 4: geometry (handout §6) =========================================================================

//! The unit normal of face f by Newell's method: n = Σ p_i × p_{i+1} over the face's corners (twice the vector
//! area; exact for planar polygons and well defined for non-planar ones), normalized. Points to the side from
//! which the face is counter-clockwise. (0,0,0) when the face has zero area.
glm::dvec3 face_normal(const Mesh& mesh, Face f);

//! The area of face f: half the length of Newell's vector (for a non-planar polygon: the area of its
//! projection onto the plane orthogonal to its normal).
double face_area(const Mesh& mesh, Face f);

//! The area-weighted vertex normal: normalize(Σ_{f around v} area(f) · normal(f)) — the sum of the faces'
//! Newell vectors, so a large face counts more than a small one. (0,0,0) for an isolated vertex.
glm::dvec3 vertex_normal(const Mesh& mesh, Vertex v);

// ==== Task 5: smoothing (handout §7) ========================================================================

//! Uniform Laplacian smoothing, `iterations` times. One iteration moves every interior vertex v by
//!     v ← v + t · L(v),   L(v) = (1/d) Σ_{j ∈ one-ring(v)} v_j − v   (d = valence),
//! with all L(v) computed from the positions BEFORE the iteration (Jacobi: keep a copy), then all applied.
//! Boundary and isolated vertices do not move. Connectivity is unchanged.
//! \throw std::invalid_argument when t is not in [0, 1] (or NaN), or iterations < 0.
void laplacian_smoothing(Mesh& mesh, double t, int iterations = 1);

// ==== The grading boundary (for the grader; nothing to do for you) ===========================================
// Your functions above, as the grader sees them: the tests' calls into your code are recorded in the program
// that runs it and replayed in the judge, which has no code of yours and decides each verdict
// (docs/architecture.md, "Grading protocol"). The inline forms above call these.
#ifdef GEOLAB_BOUNDARY
GEOLAB_BOUNDARY(build_mesh, Mesh(const PolygonSoup&))
GEOLAB_BOUNDARY(edge_vertices, std::pair<Vertex, Vertex>(const Mesh&, Edge))
GEOLAB_BOUNDARY(edge_faces, std::pair<Face, Face>(const Mesh&, Edge))
GEOLAB_BOUNDARY(face_halfedges, void(const Mesh&, Face, std::vector<Halfedge>&))
GEOLAB_BOUNDARY(outgoing_halfedges, void(const Mesh&, Vertex, std::vector<Halfedge>&))
GEOLAB_BOUNDARY(valence, int(const Mesh&, Vertex))
GEOLAB_BOUNDARY(one_ring_vertices, void(const Mesh&, Vertex, std::vector<Vertex>&))
GEOLAB_BOUNDARY(one_ring_faces, void(const Mesh&, Vertex, std::vector<Face>&))
GEOLAB_BOUNDARY(boundary_loops, std::vector<std::vector<Halfedge>>(const Mesh&))
GEOLAB_BOUNDARY(euler_characteristic, int(const Mesh&))
GEOLAB_BOUNDARY(connected_components, Components(const Mesh&))
GEOLAB_BOUNDARY(genus, int(const Mesh&))
GEOLAB_BOUNDARY(face_normal, glm::dvec3(const Mesh&, Face))
GEOLAB_BOUNDARY(face_area, double(const Mesh&, Face))
GEOLAB_BOUNDARY(vertex_normal, glm::dvec3(const Mesh&, Vertex))
GEOLAB_BOUNDARY(laplacian_smoothing, void(Mesh&, double, int))
#endif

}  // namespace geolab::halfedge
