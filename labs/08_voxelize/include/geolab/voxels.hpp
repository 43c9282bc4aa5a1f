#pragma once
//! \file voxels.hpp
//! Lab 08 — voxelization: YOUR TASKS. Write these functions in labs/08_voxelize/src/*.cpp (one file per task).
//!
//! | task | file         | functions                                              | lecture ↔ code                         | handout |
//! |------|--------------|--------------------------------------------------------|----------------------------------------|---------|
//! | 1    | bitgrid.cpp  | voxel_index, count_set                                 | 1 bit per voxel, 64-bit indices        | §2      |
//! | 2    | sat.cpp      | triangle_overlaps_voxel                                | separating axes (Akenine-Möller 2001)  | §3      |
//! | 3    | surface.cpp  | voxelize_surface_layers, voxelize_surface              | every voxel a triangle meets           | §4      |
//! | 4    | solid.cpp    | parity_fill_layers, parity_fill, count_boundary_edges, | parity along a ray, exact ties;        | §5      |
//! |      |              | flood_fill_solid, voxelize_solid                       | outside flood fill for open meshes     |         |
//! | 5    | csg.cpp      | csg_union, csg_intersection, csg_add, csg_subtract,    | max, min, C1·F1 + C2·F2, max(F1−F2, 0);| §6      |
//! |      |              | bits_union, bits_intersection, bits_difference,        | bitwise on packed grids                |         |
//! |      |              | bits_complement                                        |                                        |         |
//! | 6    | binvox.cpp   | encode_binvox, decode_binvox                           | x, z, y order, run-length pairs        | §7      |
//! | 7    | gl.cpp       | slicing_camera, slab_range, store_layer, voxelize_gl   | slices through OpenGL, XOR parity      | §9      |
//!
//! Given (read, do not write; given.cpp and this header): the grid's geometry (Grid, fit_grid, to_grid_units), the
//! packed grid's layout and accessors (BitGrid::get/set), word-aligned slabs for threads (word_aligned_slabs), file
//! wrappers (read_binvox, write_binvox), the raw format and the file-backed mode that streams slabs of your
//! voxelization to a file (write_raw, read_raw, voxelize_to_file; handout §8); for Task 7, lib's SliceRasterizer
//! (geolab/render/slicer.hpp: the OpenGL plumbing).
//!
//! **Grid units.** Every task works in grid units: voxel (i, j, k) is the closed box [i, i+1] × [j, j+1] × [k, k+1]
//! and its centre is (i + ½, j + ½, k + ½). to_grid_units() maps a mesh from world coordinates (Grid) there; the
//! results are exact functions of those double coordinates (the tie rules below decide every exact contact).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "geolab/boundary.hpp"
#include "geolab/errors.hpp"
#include "geolab/render/slicer.hpp"  // Task 7 draws with SliceRasterizer
#include "geolab/soup.hpp"

namespace geolab::voxels {

//! The number of voxels along x, y and z (each ≥ 0). 64-bit: 2048³ voxels is 2³³, beyond 32-bit indices.
struct Dims {
    std::int64_t nx = 0, ny = 0, nz = 0;
    GEOLAB_FIELDS(nx, ny, nz)
    std::int64_t count() const { return nx * ny * nz; }  //!< nx·ny·nz (given)
    bool operator==(const Dims&) const = default;
};

//! A grid of 1-bit voxels, packed (given layout). Voxel (i, j, k) has the linear index
//!     index = i + nx·(j + ny·k)            (x fastest, then y, then z; computed in 64-bit arithmetic)
//! and is bit (index mod 64) of words[index / 64]. words.size() = ⌈nx·ny·nz / 64⌉, and the bits past the last
//! voxel in the last word are always 0 (every function that returns a BitGrid keeps that true).
struct BitGrid {
    Dims dims;
    std::vector<std::uint64_t> words;
    GEOLAB_FIELDS(dims, words)

    BitGrid() = default;
    //! An all-empty grid of these dimensions (given). \throw std::invalid_argument on a negative size, or when
    //! nx·ny·nz overflows 64 bits or exceeds 2⁴⁰ voxels (128 GiB of bits).
    explicit BitGrid(Dims d);
    //! The bit of voxel (i, j, k) (given; no bounds check).
    bool get(std::int64_t i, std::int64_t j, std::int64_t k) const {
        const std::uint64_t n = std::uint64_t(i) + std::uint64_t(dims.nx) * (std::uint64_t(j) + std::uint64_t(dims.ny) * std::uint64_t(k));
        return (words[n >> 6] >> (n & 63)) & 1u;
    }
    //! Sets voxel (i, j, k) to v (given; no bounds check; not thread-safe: two threads writing the same word race).
    void set(std::int64_t i, std::int64_t j, std::int64_t k, bool v = true) {
        const std::uint64_t n = std::uint64_t(i) + std::uint64_t(dims.nx) * (std::uint64_t(j) + std::uint64_t(dims.ny) * std::uint64_t(k));
        if (v)
            words[n >> 6] |= std::uint64_t(1) << (n & 63);
        else
            words[n >> 6] &= ~(std::uint64_t(1) << (n & 63));
    }
    bool operator==(const BitGrid&) const = default;
};

//! Where a grid sits in the world (given): voxel (i, j, k) covers origin + voxel_size·[i, i+1] × ... .
struct Grid {
    glm::dvec3 origin{0.0};
    double voxel_size = 1.0;
    Dims dims;
    GEOLAB_FIELDS(origin, voxel_size, dims)
};

//! A cubic grid res × res × res around the mesh's bounding box (given): cubic voxels, the box's longest side
//! spans res − 2·pad voxels and the box is centred, so `pad` empty layers surround the mesh on every side.
//! \throw std::invalid_argument when the mesh has no vertex, is a single point, res < 1 or res ≤ 2·pad.
Grid fit_grid(const PolygonSoup& mesh, std::int64_t res, int pad = 1);

//! The mesh in grid units: every position p becomes (p − origin) / voxel_size (given; faces unchanged).
PolygonSoup to_grid_units(const PolygonSoup& mesh, const Grid& grid);

//! Threads without atomics (given): splits the layers [k0, k1) of a grid of nx × ny × (k1 − k0) voxels (layer k0
//! first) into at most `parts` slabs of consecutive layers, [b[s], b[s+1]), each starting at a word boundary (its
//! first voxel's index is a multiple of 64). Threads that each write the voxels of their own slabs only never
//! write the same 64-bit word. Returns b[0] = k0 < b[1] < ... < b.back() = k1 (b = {k0} when k0 = k1; fewer slabs
//! than `parts` when the layers cannot be split so: a slab is a whole number of words, except the last).
//! \throw std::invalid_argument when k0 > k1, a size is negative or parts < 1.
std::vector<std::int64_t> word_aligned_slabs(const Dims& dims, std::int64_t k0, std::int64_t k1, int parts);

// ==== Task 1: the packed grid (handout §2) ===================================================================

//! The linear index i + nx·(j + ny·k) of voxel (i, j, k), in 64-bit unsigned arithmetic, never overflowing for
//! any grid BitGrid accepts (up to 2⁴⁰ voxels). \throw std::out_of_range when (i, j, k) is outside the grid
//! (any coordinate < 0 or ≥ its size).
std::uint64_t voxel_index(const Dims& dims, std::int64_t i, std::int64_t j, std::int64_t k);

//! The number of set voxels. \throw std::invalid_argument when words.size() ≠ ⌈count / 64⌉.
std::uint64_t count_set(const BitGrid& grid);

// ==== Task 2: the triangle–box test (handout §3) ==============================================================

//! Whether triangle (a, b, c) (grid units) belongs to voxel (i, j, k) = [i, i+1] × [j, j+1] × [k, k+1].
//! The rule (so that a closed mesh whose faces lie on voxel planes gets no extra layer):
//! - A triangle lying in a voxel plane (its three vertices have the same integer coordinate x = m, or y = m, or
//!   z = m) belongs to the voxels of the layer on the side its normal (b − a) × (c − a) points away from (layer
//!   m − 1 for a normal along +x, layer m for −x), namely those whose square, in that plane, meets the triangle in
//!   a set of positive area (an open square: touching its border only does not count).
//! - Any other triangle belongs to the voxels whose open interior (i, i+1) × (j, j+1) × (k, k+1) it meets:
//!   touching a voxel's faces, edges or corners only does not count.
//! - A triangle of zero area (three collinear or coincident points) belongs to no voxel.
//! Decide it by the separating axis theorem (handout §3: 13 axes — the box's 3 face normals, the triangle's normal
//! and the 9 cross products of the box's edges with the triangle's edges); a projection that only touches the
//! box's counts as separating. Double precision, no tolerance.
bool triangle_overlaps_voxel(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, std::int64_t i,
                             std::int64_t j, std::int64_t k);

// ==== Task 3: surface voxelization (handout §4) ===============================================================

//! Every voxel of a dims-sized grid that some face of `mesh` (grid units; a face of k vertices is the fan of
//! triangles (v0, vi, vi+1)) belongs to, by triangle_overlaps_voxel's rule. Parts of the mesh outside the grid
//! are ignored. Test only the voxels of each triangle's bounding box. `threads` ≥ 1 workers (std::thread); the
//! result is the same for every thread count (two threads never write the same word unsynchronised).
//! \throw std::invalid_argument when threads < 1 or the soup is invalid (check_soup).
BitGrid voxelize_surface(const PolygonSoup& mesh, const Dims& dims, int threads = 1);

//! The layers k0 ≤ k < k1 of voxelize_surface(mesh, dims, threads), as a grid of nx × ny × (k1 − k0) voxels whose
//! layer 0 is layer k0 (voxel (i, j, k) of the whole grid is voxel (i, j, k − k0) here). This is what a file-backed
//! run computes slab by slab (handout §8), and what threads can share without atomics (one slab each:
//! word_aligned_slabs). Same threads contract. \throw std::invalid_argument when 0 ≤ k0 ≤ k1 ≤ nz does not hold,
//! threads < 1 or the soup is invalid.
BitGrid voxelize_surface_layers(const PolygonSoup& mesh, const Dims& dims, std::int64_t k0, std::int64_t k1,
                                int threads = 1);

// ==== Task 4: solid voxelization (handout §5) =================================================================

//! Parity along `axis` (0 = x, 1 = y, 2 = z): voxel v is set when the ray from v's centre towards −axis crosses the
//! mesh's triangles an odd number of times. Ties are broken by simulation of simplicity: the centre c is moved to
//! c + (ε, ε², ε³) for an infinitely small ε > 0 (the same point for all three axes), so that no ray meets an
//! edge or vertex and no centre lies on a triangle. With orient2d/orient3d of geolab/predicates.hpp this is exact:
//! on a closed mesh (count_boundary_edges = 0) the three axes give the same grid, voxel for voxel. Triangles
//! whose projection along the axis has zero area are never crossed. Parts of the mesh outside the grid count
//! (a triangle below the grid flips whole columns). Same threads contract as voxelize_surface.
//! \throw std::invalid_argument when axis ∉ {0, 1, 2}, threads < 1 or the soup is invalid.
BitGrid parity_fill(const PolygonSoup& mesh, const Dims& dims, int axis, int threads = 1);

//! The layers k0 ≤ k < k1 of parity_fill(mesh, dims, axis, threads), as a grid of nx × ny × (k1 − k0) voxels whose
//! layer 0 is layer k0 (as voxelize_surface_layers). Along z the rays go on below layer k0: the triangles below
//! the slab count. \throw std::invalid_argument when 0 ≤ k0 ≤ k1 ≤ nz does not hold, axis ∉ {0, 1, 2},
//! threads < 1 or the soup is invalid.
BitGrid parity_fill_layers(const PolygonSoup& mesh, const Dims& dims, int axis, std::int64_t k0, std::int64_t k1,
                           int threads = 1);

//! The number of undirected edges used by an odd number of triangles (of the fan triangulation; vertices at
//! exactly the same position are one vertex; edges of zero-area triangles count too, an edge from a vertex to
//! itself does not). 0 means the mesh is
//! closed modulo 2, which is what parity needs. \throw std::invalid_argument when the soup is invalid.
std::uint64_t count_boundary_edges(const PolygonSoup& mesh);

//! The solid of a surface voxelization with holes: every voxel that cannot be reached from outside the grid
//! through 6-connected unset voxels. Set voxels stay set; an unset voxel on the grid's border is reached.
BitGrid flood_fill_solid(const BitGrid& surface);

//! How voxelize_solid decided.
enum class SolidMethod : int {
    parity,      //!< closed mesh: the voxels all three parity_fill axes set
    flood_fill,  //!< open mesh (boundary edges): flood_fill_solid of the surface voxelization
};

//! What voxelize_solid returns.
struct SolidResult {
    BitGrid grid;                        //!< the solid voxels
    SolidMethod method = SolidMethod::parity;
    std::uint64_t boundary_edges = 0;    //!< count_boundary_edges(mesh)
    std::uint64_t axis_disagreements = 0;  //!< parity: voxels not set by all three axes or by none (0 when closed)
    GEOLAB_FIELDS(grid, method, boundary_edges, axis_disagreements)
};

//! Solid voxelization: parity (the voxels set by all three axes) when count_boundary_edges(mesh) = 0, else the
//! outside flood fill of voxelize_surface (reported in `method`). Same threads contract.
SolidResult voxelize_solid(const PolygonSoup& mesh, const Dims& dims, int threads = 1);

// ==== Task 5: voxel CSG (handout §6) ==========================================================================

//! A grid of values (density, occupancy in [0, 1], ...), x fastest like BitGrid: values[i + nx·(j + ny·k)].
struct ValueGrid {
    Dims dims;
    std::vector<double> values;
    GEOLAB_FIELDS(dims, values)
};

//! Voxel by voxel: max(F1, F2). \throw std::invalid_argument when the dims differ, a size is negative or
//! values.size() ≠ dims.count().
ValueGrid csg_union(const ValueGrid& f1, const ValueGrid& f2);
//! min(F1, F2). Same errors.
ValueGrid csg_intersection(const ValueGrid& f1, const ValueGrid& f2);
//! C1·F1 + C2·F2. Same errors.
ValueGrid csg_add(const ValueGrid& f1, const ValueGrid& f2, double c1, double c2);
//! max(F1 − F2, 0). Same errors.
ValueGrid csg_subtract(const ValueGrid& f1, const ValueGrid& f2);

//! A | B, word by word. \throw std::invalid_argument when the dims differ or a words vector has the wrong size.
BitGrid bits_union(const BitGrid& a, const BitGrid& b);
//! A & B. Same errors.
BitGrid bits_intersection(const BitGrid& a, const BitGrid& b);
//! A & ~B. Same errors.
BitGrid bits_difference(const BitGrid& a, const BitGrid& b);
//! ~A, with the bits past the last voxel kept 0. \throw std::invalid_argument on a wrong words size.
BitGrid bits_complement(const BitGrid& a);

// ==== Task 6: .binvox (handout §7) ============================================================================

//! A .binvox file: a cubic grid (nx = ny = nz) plus the normalization it records: voxel (i, j, k)'s centre is at
//! translate + scale · ((i + ½, j + ½, k + ½) / n) in the mesh's coordinates.
struct Binvox {
    BitGrid grid;
    glm::dvec3 translate{0.0};
    double scale = 1.0;
    GEOLAB_FIELDS(grid, translate, scale)
};

//! The bytes of the .binvox file (format version 1): the ASCII header "#binvox 1\n", "dim n n n\n",
//! "translate tx ty tz\n", "scale s\n" (numbers with 17 significant digits), "data\n"; then the voxels as
//! run-length pairs of bytes (value 0 or 1, count 1..255), voxel order x slowest, then z, then y fastest: file
//! position x·n² + z·n + y holds voxel (i, j, k) = (x, y, z). Each run as long as possible (at most 255).
//! \throw std::invalid_argument when the grid is not cubic, is empty (n = 0), its words have the wrong size, or
//! translate or scale is not finite.
std::string encode_binvox(const Binvox& file);

//! Reads the bytes of a .binvox file: first line "#binvox 1" (or 2: any non-zero value is a set voxel); then
//! lines "dim d h w" (required, d = h = w ≥ 1), "translate tx ty tz" and "scale s" (optional, each at most once,
//! any order; default 0 0 0 and 1), then "data"; then run-length pairs covering exactly n³ voxels, nothing after.
//! A header line ends at "\n" (a "\r" before it is dropped) and has at most 256 bytes before its "\n"; its words
//! are separated by spaces or tabs, with any before the first and after the last.
//! Hostile input (a missing or repeated line, a bad number, a count 0, runs past n³ or short of it, a truncated
//! pair, trailing bytes, non-cubic dims, a header that promises more voxels than its pairs can hold) throws
//! geolab::IoError(name, line, reason) — line = the header line, or 0 in the data — before allocating the grid.
Binvox decode_binvox(const std::string& bytes, const std::string& name = "<memory>");

//! File wrappers (given): write_binvox writes encode_binvox's bytes; read_binvox reads a file (at most
//! 64 MiB + header) and decodes it. \throw geolab::IoError when the file cannot be opened or read.
void write_binvox(const std::filesystem::path& path, const Binvox& file);
Binvox read_binvox(const std::filesystem::path& path);

// ==== Given: the raw format and the file-backed mode (handout §8) ==============================================

//! The raw format (given): the grid's words as they are in memory (little-endian 64-bit words, voxel
//! i + nx·(j + ny·k) is bit index mod 64 of word index / 64), then a 40-byte trailer: the 8 bytes "GLVOXRAW",
//! nx, ny, nz and the number of set voxels (little-endian 64-bit integers). The trailer comes last so that a
//! file can be written slab by slab and closed with its count (seed 003).
//! \throw geolab::IoError when the file cannot be written.
void write_raw(const std::filesystem::path& path, const BitGrid& grid);
//! Reads a raw file. \throw geolab::IoError (file, 0, reason) when it cannot be read, has no trailer, its size is
//! not the trailer's dims' words plus the trailer, a bit past the last voxel is set, or the count differs.
BitGrid read_raw(const std::filesystem::path& path);

//! What voxelize_to_file wrote.
struct FileVoxels {
    std::uint64_t voxels = 0;              //!< set voxels in the file
    std::uint64_t boundary_edges = 0;      //!< solid: count_boundary_edges(mesh) (0: the run needs a closed mesh)
    std::uint64_t axis_disagreements = 0;  //!< solid: voxels not set by all three axes or by none
    std::int64_t slabs = 0;                //!< slabs computed and written
    std::int64_t slab_layers = 0;          //!< layers of each slab (the last may be shorter)
    std::uint64_t bytes = 0;               //!< the file's size
};

//! The file-backed mode (given; seed 003, handout §8): the raw file of voxelize_surface(mesh, dims, threads), or
//! with `solid` of voxelize_solid(mesh, dims, threads).grid, computed and written one slab of `slab_layers` layers
//! at a time with your voxelize_surface_layers and parity_fill_layers, so memory holds a few slabs and never the
//! whole grid (2048³ voxels are 1 GiB of bits). Each slab sees only the triangles that reach it; along z the
//! parity of the layer below the slab is carried over. `progress(done, total)` (if set) is called after each slab.
//! The file is byte for byte what write_raw writes for the in-memory grid.
//! \throw std::invalid_argument when nx·ny is not a multiple of 64 (each layer whole words: res a multiple of 8),
//! slab_layers < 1, threads < 1, the soup is invalid, or `solid` and the mesh is not closed (the outside flood fill
//! needs the whole grid); geolab::IoError when the file cannot be written.
FileVoxels voxelize_to_file(const PolygonSoup& mesh, const Dims& dims, bool solid, const std::filesystem::path& path,
                            int threads = 1, std::int64_t slab_layers = 32,
                            const std::function<void(std::int64_t, std::int64_t)>& progress = {});

// ==== Task 7: voxelization through the graphics pipeline (handout §9) ========================================
// Seed 002's method on OpenGL (OSMesa, software, headless): look along an axis with an orthographic camera, one
// pixel per column of voxels; for layer k = 0, 1, ... draw the triangles' crossings of the depth slab
// (k − ½, k + ½] with XOR into the same image, so that the image holds, in every pixel, the parity of the
// crossings below the voxel centres of layer k; read it back into layer k. geolab/render/slicer.hpp's
// SliceRasterizer (lib, given) is the plumbing: the GL context, the shaders, the slab test, the XOR, the read-back.
// You choose the camera, which triangles each slab draws, the slab bounds and where each pixel goes.

//! The slicing camera along `axis` for a dims-sized grid: the affine map clip = M · (p, 1) (p in grid units)
//! onto an n_u × n_v image, where u, v are the two other axes in increasing order (axis 0: u = y, v = z;
//! axis 1: u = x, v = z; axis 2: u = x, v = y):
//!     clip.x = 2·p_u / n_u − 1,   clip.y = 2·p_v / n_v − 1,   clip.z = p_axis,   clip.w = 1.
//! So pixel (i, j)'s centre looks down the column (u, v) = (i + ½, j + ½), and the depth stays in grid units
//! (no near/far clipping: nothing needs to fit [−1, 1], and the voxel centres k + ½ are exact floats).
//! \throw std::invalid_argument when axis ∉ {0, 1, 2} or a size of dims is < 1.
glm::dmat4 slicing_camera(const Dims& dims, int axis);

//! The layers first..last (empty when first > last) whose slabs a triangle must be drawn in.
struct SlabRange {
    std::int64_t first = 0, last = -1;
    GEOLAB_FIELDS(first, last)
    bool operator==(const SlabRange&) const = default;
};

//! The slabs of triangle (a, b, c) (grid units) along `axis` in a dims-sized grid (n layers along the axis).
//! Slab k ≥ 1 holds the depths (k − ½, k + ½] and slab 0 everything up to ½, (−∞, ½]: the part of a mesh below
//! the grid flips whole columns there (the paper's "virtual filled starting slice"). Depth d lies in slab
//! s(d) = max(0, ⌈d − ½⌉) (s(d) ≥ n: above the last layer's centres, in no slab). The triangle's crossings lie
//! between its corners' depths d_min and d_max, but the GPU decides them in float: draw it one slab more on each
//! side, so that a crossing rounded across a slab bound is still drawn:
//!     first = max(0, s(d_min) − 1),   last = min(n − 1, s(d_max) + 1)
//! When first > last (the triangle lies above the last layer's centres) the range is empty: return {0, −1}.
//! \throw std::invalid_argument when axis ∉ {0, 1, 2}.
SlabRange slab_range(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const Dims& dims, int axis);

//! Read-back: stores an n_u × n_v image (SliceRasterizer::read(): pixel (i, j) at [j · n_u + i], 0 or 1) into
//! layer k of `grid` along `axis`: voxel (u, v, axis) = (i, j, k) becomes set when the pixel is non-zero and
//! unset when it is 0; other layers are unchanged. \throw std::invalid_argument when axis ∉ {0, 1, 2} or
//! image.size() ≠ n_u · n_v; std::out_of_range when k is not a layer.
void store_layer(const std::vector<std::uint8_t>& image, int axis, std::int64_t k, BitGrid& grid);

//! Solid voxelization through the graphics pipeline: a SliceRasterizer of n_u × n_v pixels with the triangles
//! (fan of each face) repeated once per slab of their slab_range, grouped by slab, seen through slicing_camera;
//! set_depth_rank(axis), so that a voxel centre exactly on a face is decided like parity_fill's c + (ε, ε², ε³);
//! then for k = 0 .. n − 1: draw slab k's triangles with the bounds (k − ½, k + ½] ((−∞, ½] for k = 0) into the
//! same image (never cleared), read it, store_layer. On a closed mesh the result is parity_fill's along any axis,
//! except at voxels whose centre lies within float rounding (and the rasterizer's 1/256-pixel snapping) of the
//! surface (handout §9). An empty grid (a size 0) is returned without drawing.
//! \throw std::invalid_argument when axis ∉ {0, 1, 2}, the soup is invalid (check_soup) or n_u or n_v exceeds
//! 8192 (checked before the grid is allocated); std::runtime_error when OSMesa fails.
BitGrid voxelize_gl(const PolygonSoup& mesh, const Dims& dims, int axis = 2);

// ==== The grading boundary (for the grader; nothing to do for you) ===========================================
#ifdef GEOLAB_BOUNDARY
GEOLAB_BOUNDARY(voxel_index, std::uint64_t(const Dims&, std::int64_t, std::int64_t, std::int64_t))
GEOLAB_BOUNDARY(count_set, std::uint64_t(const BitGrid&))
GEOLAB_BOUNDARY(triangle_overlaps_voxel, bool(const glm::dvec3&, const glm::dvec3&, const glm::dvec3&, std::int64_t,
                                              std::int64_t, std::int64_t))
GEOLAB_BOUNDARY(voxelize_surface, BitGrid(const PolygonSoup&, const Dims&, int))
GEOLAB_BOUNDARY(voxelize_surface_layers, BitGrid(const PolygonSoup&, const Dims&, std::int64_t, std::int64_t, int))
GEOLAB_BOUNDARY(parity_fill, BitGrid(const PolygonSoup&, const Dims&, int, int))
GEOLAB_BOUNDARY(parity_fill_layers, BitGrid(const PolygonSoup&, const Dims&, int, std::int64_t, std::int64_t, int))
GEOLAB_BOUNDARY(count_boundary_edges, std::uint64_t(const PolygonSoup&))
GEOLAB_BOUNDARY(flood_fill_solid, BitGrid(const BitGrid&))
GEOLAB_BOUNDARY(voxelize_solid, SolidResult(const PolygonSoup&, const Dims&, int))
GEOLAB_BOUNDARY(csg_union, ValueGrid(const ValueGrid&, const ValueGrid&))
GEOLAB_BOUNDARY(csg_intersection, ValueGrid(const ValueGrid&, const ValueGrid&))
GEOLAB_BOUNDARY(csg_add, ValueGrid(const ValueGrid&, const ValueGrid&, double, double))
GEOLAB_BOUNDARY(csg_subtract, ValueGrid(const ValueGrid&, const ValueGrid&))
GEOLAB_BOUNDARY(bits_union, BitGrid(const BitGrid&, const BitGrid&))
GEOLAB_BOUNDARY(bits_intersection, BitGrid(const BitGrid&, const BitGrid&))
GEOLAB_BOUNDARY(bits_difference, BitGrid(const BitGrid&, const BitGrid&))
GEOLAB_BOUNDARY(bits_complement, BitGrid(const BitGrid&))
GEOLAB_BOUNDARY(encode_binvox, std::string(const Binvox&))
GEOLAB_BOUNDARY(decode_binvox, Binvox(const std::string&, const std::string&))
GEOLAB_BOUNDARY(slicing_camera, glm::dmat4(const Dims&, int))
GEOLAB_BOUNDARY(slab_range, SlabRange(const glm::dvec3&, const glm::dvec3&, const glm::dvec3&, const Dims&, int))
GEOLAB_BOUNDARY(store_layer, void(const std::vector<std::uint8_t>&, int, std::int64_t, BitGrid&))
GEOLAB_BOUNDARY(voxelize_gl, BitGrid(const PolygonSoup&, const Dims&, int))
#endif

}  // namespace geolab::voxels
