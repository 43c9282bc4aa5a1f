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
//! | 6    | regions.cpp     | region_complex (the paper's cell complex of a labelled mesh)            | §8      |
//!
//! Lecture ↔ code: the paper's HalfFace / HalfEdge / mate / EdgeCellIter / garbage_collection are the kernel's
//! HalfFace, HalfEdge, mate(h), your edge_cells and your garbage_collection (table in halfface/mesh.hpp).
#include <array>
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

// ==== Task 6: region decomposition into the paper's cell complex (handout §8) ================================
//
// A labelled mesh (one label per cell) falls apart into cells of four dimensions. Words used below:
//  - the REGION of an alive cell: its 3-cell (below); the outside (a boundary half-face's side, a deleted cell)
//    is no region;
//  - an INTERFACE face: an alive face whose two sides are in different regions (or one side outside);
//  - k(e) of an edge: the number of interface faces that contain e (0, 2, 3, ...; never 1);
//  - a CURVE edge: an edge with k(e) ≥ 3 (three or more sheets of interface meet there);
//  - d(v) of a vertex: the number of curve edges at v.

//! A 3-cell: a region, i.e. a maximal set of alive cells with the same label, connected through shared faces
//! (two blobs with one label are two regions).
struct Region {
    std::int32_t label = 0;
    std::vector<Cell> cells;             //!< its cells, increasing
    std::vector<std::uint32_t> patches;  //!< the 2-cells with this region on one side (indices), increasing
    GEOLAB_FIELDS(label, cells, patches)
};

//! A 2-cell: a patch, i.e. a maximal set of interface faces connected through edges e with k(e) == 2 (the
//! two faces at such an edge always separate the same two regions). Its own topology: the surface made of its
//! faces, each vertex and edge counted once.
struct Patch {
    //! The regions on its two sides, the lower index first; the second is invalid_index when the other side is
    //! the outside.
    std::array<std::uint32_t, 2> regions{invalid_index, invalid_index};
    std::vector<Face> faces;  //!< increasing
    std::uint32_t V = 0, E = 0, F = 0;  //!< distinct vertices, edges and faces of its faces
    std::int64_t chi = 0;               //!< χ = V − E + F (sphere 2, disk 1, annulus and torus 0)
    //! The patch's boundary: the connected pieces (joined through shared vertices) of its curve edges, i.e. of
    //! its edges with k(e) ≥ 3. 0 for a closed patch (sphere, torus), 1 for a disk.
    std::uint32_t boundary_loops = 0;
    GEOLAB_FIELDS(regions, faces, V, E, F, chi, boundary_loops)
};

//! A 1-cell: a curve, i.e. a maximal set of curve edges connected through vertices v with d(v) == 2.
struct Curve {
    std::vector<Edge> edges;  //!< increasing
    //! The corners (0-cell indices) at its two ends, the lower first (the same twice for a curve that leaves a
    //! corner and comes back to it); both invalid_index for a closed curve (every vertex with d(v) == 2).
    std::array<std::uint32_t, 2> ends{invalid_index, invalid_index};
    std::vector<std::uint32_t> patches;  //!< the 2-cells that have a face on one of its edges, increasing
    GEOLAB_FIELDS(edges, ends, patches)
};

//! A 0-cell: a corner, i.e. a vertex where curves end or meet: d(v) ≥ 1 and d(v) ≠ 2.
struct Corner {
    Vertex vertex;
    //! The curves ending here, increasing, one entry per curve edge at the vertex (so curves.size() == d(v);
    //! a curve with both ends here is listed twice).
    std::vector<std::uint32_t> curves;
    GEOLAB_FIELDS(vertex, curves)
};

//! The cell complex: 3-cells (regions), 2-cells (patches), 1-cells (curves), 0-cells (corners).
struct RegionComplex {
    std::vector<Region> regions;   //!< numbered in increasing order of their lowest cell
    std::vector<Patch> patches;    //!< numbered in increasing order of their lowest face
    std::vector<Curve> curves;     //!< numbered in increasing order of their lowest edge
    std::vector<Corner> corners;   //!< numbered in increasing order of their vertex
    GEOLAB_FIELDS(regions, patches, curves, corners)
};

//! The paper's CW-cell decomposition of a labelled volume mesh (see the words above; handout §8): regions,
//! then patches between them, the curves where three or more sheets of patch meet, and the corners where curves
//! end or meet, each with the topology its struct lists. The paper's example, a ball with a torus-shaped
//! region, gives two regions, two patches (a sphere χ 2 and a torus χ 0, no boundary), no curve and no corner.
//! Deleted cells, faces and edges take no part (a deleted cell's side is outside). O(N log N) or better in the
//! mesh size.
//! \param labels one label per cell index (labels[c] for cell c; deleted cells' labels are ignored).
//! \throw std::invalid_argument when labels.size() != mesh.n_cells():
//!   "region_complex: L labels for C cells".
RegionComplex region_complex(const Mesh& mesh, const std::vector<std::int32_t>& labels);

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
GEOLAB_BOUNDARY(region_complex, RegionComplex(const Mesh&, const std::vector<std::int32_t>&))
#endif

}  // namespace geolab::halfface
