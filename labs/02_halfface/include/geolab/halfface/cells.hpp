#pragma once
//! \file halfface/cells.hpp
//! Lab 02 — cell lists, the input of build_mesh (GIVEN). A cell is a closed polyhedron given by its faces; each
//! face is a cycle of vertex indices counter-clockwise seen from OUTSIDE the cell. The add_* helpers write the
//! standard cells from their corners (VTK's corner order) with outward faces.
#include <cstdint>
#include <glm/vec3.hpp>
#include <initializer_list>
#include <span>
#include <vector>

#include "geolab/boundary.hpp"
#include "geolab/volume_io.hpp"

namespace geolab::halfface {

//! Cell kinds, for statistics and file formats (a general polyhedron is `polyhedron`).
enum class CellType : std::uint8_t { tetrahedron, hexahedron, prism, pyramid, polyhedron };

struct CellList {
    std::vector<glm::dvec3> positions;
    std::vector<std::uint32_t> face_vertices;    //!< all faces' vertices, one face after the other
    std::vector<std::uint32_t> face_begin{0};    //!< face j is face_vertices[face_begin[j] .. face_begin[j+1])
    std::vector<std::uint32_t> cell_begin{0};    //!< cell c has faces cell_begin[c] .. cell_begin[c+1]-1
    std::vector<CellType> types;                 //!< per cell
    std::vector<std::int32_t> labels;            //!< per cell: a region label (0 unless set)
    GEOLAB_FIELDS(positions, face_vertices, face_begin, cell_begin, types, labels)

    std::size_t n_vertices() const { return positions.size(); }
    std::size_t n_cells() const { return cell_begin.size() - 1; }
    //! The number of faces of cell c.
    std::size_t n_faces(std::size_t c) const { return cell_begin[c + 1] - cell_begin[c]; }
    //! Face i of cell c.
    std::span<const std::uint32_t> face(std::size_t c, std::size_t i) const {
        const std::size_t j = cell_begin[c] + i;
        return {face_vertices.data() + face_begin[j], face_vertices.data() + face_begin[j + 1]};
    }
    //! A general polyhedron given by its faces; returns the cell's index.
    std::size_t add_polyhedron(std::initializer_list<std::initializer_list<std::uint32_t>> faces,
                               CellType type = CellType::polyhedron, std::int32_t label = 0) {
        for (auto f : faces) add_face(std::span(f.begin(), f.size()));
        return close_cell(type, label);
    }
    //! Append one face to the cell being written; close it with close_cell.
    void add_face(std::span<const std::uint32_t> f) {
        for (std::uint32_t v : f) face_vertices.push_back(v);
        face_begin.push_back(std::uint32_t(face_vertices.size()));
    }
    //! End the cell whose faces were added since the last cell.
    std::size_t close_cell(CellType type = CellType::polyhedron, std::int32_t label = 0) {
        cell_begin.push_back(std::uint32_t(face_begin.size() - 1));
        types.push_back(type);
        labels.push_back(label);
        return n_cells() - 1;
    }
    //! Tetrahedron a b c d, positive when d is on the side of (a, b, c) that sees it counter-clockwise.
    std::size_t add_tet(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d, std::int32_t label = 0) {
        return add_polyhedron({{a, c, b}, {a, b, d}, {b, c, d}, {c, a, d}}, CellType::tetrahedron, label);
    }
    //! Hexahedron: bottom 0 1 2 3 counter-clockwise seen from the top 4 5 6 7 (4 above 0, ...).
    std::size_t add_hex(std::span<const std::uint32_t, 8> v, std::int32_t label = 0) {
        return add_polyhedron({{v[0], v[3], v[2], v[1]}, {v[4], v[5], v[6], v[7]}, {v[0], v[1], v[5], v[4]},
                               {v[1], v[2], v[6], v[5]}, {v[2], v[3], v[7], v[6]}, {v[3], v[0], v[4], v[7]}},
                              CellType::hexahedron, label);
    }
    //! Prism (wedge): bottom 0 1 2 counter-clockwise seen from the top 3 4 5 (3 above 0, ...).
    std::size_t add_prism(std::span<const std::uint32_t, 6> v, std::int32_t label = 0) {
        return add_polyhedron({{v[0], v[2], v[1]}, {v[3], v[4], v[5]}, {v[0], v[1], v[4], v[3]},
                               {v[1], v[2], v[5], v[4]}, {v[2], v[0], v[3], v[5]}},
                              CellType::prism, label);
    }
    //! Pyramid: base 0 1 2 3 counter-clockwise seen from the apex 4.
    std::size_t add_pyramid(std::span<const std::uint32_t, 5> v, std::int32_t label = 0) {
        return add_polyhedron({{v[0], v[3], v[2], v[1]}, {v[0], v[1], v[4]}, {v[1], v[2], v[4]}, {v[2], v[3], v[4]},
                               {v[3], v[0], v[4]}},
                              CellType::pyramid, label);
    }
};

//! The cell list of a volume mesh read from a file (geolab/volume_io.hpp): same vertices, cells and labels; each
//! cell's faces by the add_* helpers (so a positive tetrahedron's faces are outward).
inline CellList cells_from(const VolumeMesh& m) {
    CellList c;
    c.positions = m.positions;
    for (std::size_t i = 0; i < m.n_cells(); ++i) {
        const auto v = m.cell(i);
        const std::int32_t label = m.labels[i];
        switch (m.types[i]) {
            case VolumeCell::tetrahedron: c.add_tet(v[0], v[1], v[2], v[3], label); break;
            case VolumeCell::hexahedron: c.add_hex(std::span<const std::uint32_t, 8>(v.data(), 8), label); break;
            case VolumeCell::prism: c.add_prism(std::span<const std::uint32_t, 6>(v.data(), 6), label); break;
            case VolumeCell::pyramid: c.add_pyramid(std::span<const std::uint32_t, 5>(v.data(), 5), label); break;
        }
    }
    return c;
}

}  // namespace geolab::halfface
