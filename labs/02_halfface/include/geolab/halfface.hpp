#pragma once
//! \file halfface.hpp
//! Lab 02 — half-face volume meshes: YOUR TASKS. Write these functions in labs/02_halfface/src/*.cpp (one file
//! per task). The mesh kernel you build and query is given in geolab/halfface/mesh.hpp; the cell lists you build
//! from are given in geolab/halfface/cells.hpp.
//!
//! | task | file            | functions                                                               | handout |
//! |------|-----------------|-------------------------------------------------------------------------|---------|
//! | 1    | build_mesh.cpp  | build_mesh                                                              | §3      |
//! | 2    | queries.cpp     | halfface_vertices, face_cells, cell_vertices, boundary_halffaces,       | §4      |
//! |      |                 | edge_cells (the paper's EdgeCellIter), vertex_cells                     |         |
//! | 3    | garbage.cpp     | delete_cell, delete_vertex, garbage_collection                          | §5      |
//! | 4    | smoothing.cpp   | volume_smoothing                                                        | §6      |
//! | 5    | surface.cpp     | boundary_surface                                                        | §7      |
//!
//! Lecture ↔ code: the paper's HalfFace / HalfEdge / mate / EdgeCellIter / garbage_collection are the kernel's
//! HalfFace, HalfEdge, mate(h), your edge_cells and your garbage_collection (table in halfface/mesh.hpp).
#include <cstdint>
#include <vector>

#include "geolab/boundary.hpp"
#include "geolab/errors.hpp"
#include "geolab/halfface/cells.hpp"
#include "geolab/halfface/mesh.hpp"
#include "geolab/soup.hpp"

namespace geolab::halfface {

// ==== Task 1: build the mesh (handout §3) ===================================================================

//! Build the half-face mesh of a cell list (every face of every cell counter-clockwise seen from outside it).
//!
//! Result: vertex i is list vertex i (same position, isolated vertices kept); cell c is list cell c and
//! `halffaces(c)` lists its faces in the list's order; each face polygon shared by two cells (the same vertex
//! cycle, listed in opposite directions) is one Face, each undirected edge one Edge. Faces are numbered in order
//! of first use (cell 0's faces first); half-face 2f is the side of the cell that used f first and its loop
//! starts at the vertex that cell listed first; 2f + 1 runs the other way (starting at the same vertex).
//! next, prev, twin, mate, halfface, edge and cell are set as halfface/mesh.hpp says; halfedge(e) and halfedge(v)
//! are any alive half-edge of e / leaving v; the vertex cache is rebuilt. The result passes validate().
//! Cost: O(V + N log N) for V vertices and N face corners (the benchmark builds 1M tetrahedra in about 0.6 s).
//!
//! \throw std::invalid_argument, checked before anything else, when the list's offsets do not fit ("build_mesh:
//!   the cell list's offsets do not match its faces"; "build_mesh: cell C has decreasing offsets"; "build_mesh:
//!   cell C face I has decreasing offsets"), a vertex index is out of range ("build_mesh: cell C face I: vertex N
//!   out of range (M vertices)") or a position is not finite ("build_mesh: vertex N has a position that is not
//!   finite"). Checked in this order: positions, the offsets' sizes, every cell's offsets, every face's
//!   offsets, every vertex index (each in cell and face order).
//! \throw geolab::TopologyError, checked cell by cell (in cell order) and then face by face, with these messages
//!   (C, A, B cell indices; I, J face indices in the cell; u, v vertex indices; "(a b c)" a face's vertices as
//!   listed, for a shared face by its first cell):
//!   - "build_mesh: degenerate cell C: ..." — "it has N faces (a cell needs at least 4)", "face I has N
//!     vertices (a face needs at least 3)", "face I repeats vertex u", or "faces I and J are the same polygon
//!     (a b c)" (I < J, as face I lists it);
//!   - "build_mesh: cell C is not closed: the edge from vertex u to vertex v is used N time(s) in that direction
//!     and M time(s) in the other ..." — a directed edge of its faces not used exactly once each way; of those,
//!     the smallest (u, then v);
//!   - "build_mesh: face (a b c) is used by 3 or more cells: cell A, cell B, cell C" (every cell using it, in
//!     cell order);
//!   - "build_mesh: inconsistent orientation: cell A and cell B both list face (a b c) in the same direction".
//!   When several faces are wrong, the error names the face whose first use comes first.
Mesh build_mesh(const CellList& cells);

// ==== Task 2: queries and circulators (handout §4) ==========================================================

//! The vertices of hf's loop in order: to_vertex of halfedge(hf)'s previous half-edge (its start) first, i.e.
//! from_vertex(halfedge(hf)), from_vertex(next(...)), ... once around.
void halfface_vertices(const Mesh& mesh, HalfFace hf, std::vector<Vertex>& out);

//! The two cells of face f: (cell(2f), cell(2f + 1)); invalid on a boundary side.
std::pair<Cell, Cell> face_cells(const Mesh& mesh, Face f);

//! The vertices of cell c, each once, in order of first appearance walking halffaces(c) in order and each loop
//! from its halfedge.
void cell_vertices(const Mesh& mesh, Cell c, std::vector<Vertex>& out);

//! All alive boundary half-faces (no cell on their side, a cell on the other), in increasing index order.
void boundary_halffaces(const Mesh& mesh, std::vector<HalfFace>& out);

//! The cells around edge e in radial order (the paper's EdgeCellIter), each once: counter-clockwise about the
//! axis from a = edge_vertices(e)[0] to b = edge_vertices(e)[1] (right-hand rule). Walk: take a half-edge h of e
//! directed b → a in a cell; the next cell is cell(halfface(mate(twin(h)))), and so on. An interior edge is a full
//! turn: start at the lowest-numbered cell. A boundary edge is a fan: start at the cell whose b → a half-edge has
//! a boundary half-face as its mate, end at the other boundary. Empty when e has no cell.
//! \pre the cells around e form one fan or one cycle (a manifold edge).
//! Cost: O(k) for the k cells around e (one turn around the edge; the benchmark circulates all 1.26M edges of
//! the 1M-tet grid).
void edge_cells(const Mesh& mesh, Edge e, std::vector<Cell>& out);

//! The cells that have v as a corner, each once, in increasing index order (use vertex_halffaces).
void vertex_cells(const Mesh& mesh, Vertex v, std::vector<Cell>& out);

// ==== Task 3: deletion and garbage collection (handout §5) ==================================================

//! Mark cell c deleted. Its half-faces lose their cell (they become boundary half-faces or, when the other side
//! has no cell either, their face is deleted with its half-edges); the half-edges of the new boundary half-faces
//! lose their twin; edges left without an alive half-edge are deleted; halfedge(e) and halfedge(v) are moved to
//! alive half-edges (invalid when none is left: the vertex stays, isolated); the vertex cache is kept right.
//! Deleting a deleted cell does nothing.
void delete_cell(Mesh& mesh, Cell c);

//! Delete every alive cell that has v as a corner (as delete_cell), then the faces still using v (deleted by
//! then), the edges at v, and v itself.
void delete_vertex(Mesh& mesh, Vertex v);

//! The renumbering done by garbage_collection: for each kind, new index of each OLD index (invalid: removed).
struct Remap {
    std::vector<std::uint32_t> vertices, edges, halfedges, faces, halffaces, cells;
    GEOLAB_FIELDS(vertices, edges, halfedges, faces, halffaces, cells)
};

//! Remove every deleted element, keeping the others in their order (new index = number of alive elements before
//! it), renumber every handle stored in the mesh, move every dynamic property's values with their elements,
//! rebuild the vertex cache, and return the maps. The result passes validate() and has no garbage. (Use the
//! kernel's compact() and remap_handles(); half-faces 2f, 2f+1 become 2f', 2f'+1.)
Remap garbage_collection(Mesh& mesh);

// ==== Task 4: volume Laplacian smoothing (handout §6) =======================================================

//! The paper's smoothing, `iterations` times: every interior vertex v (alive, not on a boundary half-face, used
//! by a cell) moves by v ← v − t · L(v), L(v) = v − (1/d) Σ v_j over its d edge neighbours (alive edges), all L(v)
//! from the positions before the iteration (Jacobi: keep the new positions in a property, apply them after).
//! Boundary and isolated vertices keep their positions bit for bit.
//! Returns the minimum signed volume over the alive tetrahedral cells afterwards (+infinity when there are none):
//! for the tet with half-face (a, b, c) and fourth vertex d, det(b − a, c − a, d − a) / 6 taken so that an
//! un-inverted tet is positive.
//! \throw std::invalid_argument when t is not in [0, 1] (or NaN), or iterations < 0.
double volume_smoothing(Mesh& mesh, double t, int iterations = 1);

// ==== Task 5: boundary surface (handout §7) =================================================================

//! The boundary surface as a polygon soup: one polygon per alive boundary half-face, in increasing half-face
//! order, with the half-face's vertices (halfface_vertices order) REVERSED so that it is counter-clockwise seen
//! from outside the solid (a boundary half-face has no cell; its opposite side's cell is inside). The soup's
//! vertices are the mesh vertices used by these polygons, renumbered 0.. in increasing mesh index order.
PolygonSoup boundary_surface(const Mesh& mesh);

// ==== The grading boundary (for the grader; nothing to do for you) ===========================================
#ifdef GEOLAB_BOUNDARY
GEOLAB_BOUNDARY(build_mesh, Mesh(const CellList&))
GEOLAB_BOUNDARY(halfface_vertices, void(const Mesh&, HalfFace, std::vector<Vertex>&))
GEOLAB_BOUNDARY(face_cells, std::pair<Cell, Cell>(const Mesh&, Face))
GEOLAB_BOUNDARY(cell_vertices, void(const Mesh&, Cell, std::vector<Vertex>&))
GEOLAB_BOUNDARY(boundary_halffaces, void(const Mesh&, std::vector<HalfFace>&))
GEOLAB_BOUNDARY(edge_cells, void(const Mesh&, Edge, std::vector<Cell>&))
GEOLAB_BOUNDARY(vertex_cells, void(const Mesh&, Vertex, std::vector<Cell>&))
GEOLAB_BOUNDARY(delete_cell, void(Mesh&, Cell))
GEOLAB_BOUNDARY(delete_vertex, void(Mesh&, Vertex))
GEOLAB_BOUNDARY(garbage_collection, Remap(Mesh&))
GEOLAB_BOUNDARY(volume_smoothing, double(Mesh&, double, int))
GEOLAB_BOUNDARY(boundary_surface, PolygonSoup(const Mesh&))
#endif

}  // namespace geolab::halfface
