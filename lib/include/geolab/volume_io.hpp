#pragma once
//! \file volume_io.hpp
//! Volume (cell) meshes as plain data, and their files: Medit `.mesh` (ASCII), TetGen `.node`/`.ele`/`.face`,
//! and legacy VTK unstructured grids (`.vtk`, write only, for ParaView). lib knows no half-face structure: lab 02
//! builds its own from this data.
//!
//! Readers validate as they go and throw geolab::IoError "FILE:LINE: reason" (a count that does not match, a
//! missing or malformed number, an index out of range, a non-finite coordinate, an unknown keyword, an empty
//! file); they never return a partial mesh. Counts are checked against the bytes left before anything is
//! reserved, and files are read with read_mesh's size limit (io.hpp: GEOLAB_MAX_FILE_MB).
//!
//! Corner orders: a tetrahedron (a, b, c, d) is positive when det(b − a, c − a, d − a) > 0 (TetGen's order, and
//! Medit files written by `tetgen -g`); a hexahedron lists its bottom quad counter-clockwise seen from the top,
//! then the top quad (4 above 0, ...); a prism its bottom triangle then the top one; a pyramid its base then the
//! apex (VTK's orders). The readers keep the files' orders; they do not reorient anything.
#include <array>
#include <cstdint>
#include <filesystem>
#include <glm/vec3.hpp>
#include <span>
#include <string>
#include <vector>

#include "geolab/io.hpp"

namespace geolab {

//! Cell kinds of a VolumeMesh; the value is the number of corners.
enum class VolumeCell : std::uint8_t { tetrahedron = 4, pyramid = 5, prism = 6, hexahedron = 8 };

//! A volume mesh as plain arrays: positions, cells by corners, per-cell labels (Medit references, TetGen region
//! attributes), and the labelled boundary triangles a file may carry (Medit Triangles, TetGen .face).
struct VolumeMesh {
    std::vector<glm::dvec3> positions;
    std::vector<VolumeCell> types;              //!< per cell
    std::vector<std::uint32_t> corners;         //!< all cells' corners, one cell after the other
    std::vector<std::uint32_t> offsets{0};      //!< cell c: corners[offsets[c] .. offsets[c+1])
    std::vector<std::int32_t> labels;           //!< per cell
    std::vector<std::array<std::uint32_t, 3>> triangles;  //!< boundary or interface triangles (may be empty)
    std::vector<std::int32_t> triangle_labels;  //!< per triangle

    std::size_t n_vertices() const { return positions.size(); }
    std::size_t n_cells() const { return types.size(); }
    std::span<const std::uint32_t> cell(std::size_t c) const {
        return {corners.data() + offsets[c], corners.data() + offsets[c + 1]};
    }
    //! Append a cell; `v` must hold exactly int(type) corners (std::invalid_argument otherwise).
    void add_cell(VolumeCell type, std::span<const std::uint32_t> v, std::int32_t label = 0);
};

//! Throws std::invalid_argument naming the first cell with an index out of range or a repeated corner, an array
//! whose size does not match, or the first non-finite position.
void check_volume_mesh(const VolumeMesh& mesh);

//! Medit ASCII `.mesh`: MeshVersionFormatted, Dimension 3, Vertices, Tetrahedra, Hexahedra, Prisms, Pyramids,
//! Triangles, and the sections that are read and ignored (Edges, Quadrilaterals, Corners, Ridges,
//! RequiredVertices, RequiredEdges, Normals, NormalAtVertices, Tangents, TangentAtEdges); `#` starts a comment;
//! indices are 1-based; keywords in any case. Any other keyword is an error, and so is a keyword given twice (a
//! second Tetrahedra section), a file without End (a file cut after a whole section would otherwise read as a
//! smaller mesh), anything but comments after End, a triangle that repeats a vertex and a reference (label) outside
//! 32 bits. A UTF-8 byte order mark is skipped; a line ends with LF, CRLF or a lone CR.
VolumeMesh read_medit(const std::filesystem::path& path, const ReadOptions& options = {});
VolumeMesh read_medit_from_string(const std::string& data, const std::string& name = "<memory>");

//! TetGen: `base.node` and `base.ele` (4-corner tetrahedra; a region attribute, when present, becomes the cell
//! label) and, if the file exists, `base.face` (triangles with an optional boundary marker). `path` may name
//! any of the three files or the base. Node numbering starts at the first node's index (0 or 1) and must be
//! consecutive. .ele with 10 nodes per tetrahedron (quadratic) uses the first 4. A face that repeats a node and a
//! boundary marker outside 32 bits are errors.
VolumeMesh read_tetgen(const std::filesystem::path& path, const ReadOptions& options = {});
//! The same from text in memory (face may be empty: no triangles); names are used in messages only.
VolumeMesh read_tetgen_from_strings(const std::string& node, const std::string& ele, const std::string& face,
                                    const std::string& base = "<memory>");

//! Writers. Medit writes every cell kind and the triangles (grouped by kind as the format requires: tetrahedra,
//! hexahedra, prisms, pyramids; within a kind in mesh order); TetGen writes base.node, base.ele and (when there are
//! triangles) base.face, tetrahedra only (std::invalid_argument for other cells); VTK writes a legacy ASCII
//! unstructured grid with the cell labels as CELL_DATA "label" and, when `cell_scalars` is not empty (one value
//! per cell), a second field named `scalar_name`. Shortest round-trip decimals. \throw IoError when a file
//! cannot be written; std::invalid_argument when the mesh fails check_volume_mesh.
void write_medit(const std::filesystem::path& path, const VolumeMesh& mesh);
void write_tetgen(const std::filesystem::path& base, const VolumeMesh& mesh);
void write_vtk(const std::filesystem::path& path, const VolumeMesh& mesh, const std::vector<double>& cell_scalars = {},
               const std::string& scalar_name = "scalar");

}  // namespace geolab
