#pragma once
//! \file soup.hpp
//! A polygon soup: positions plus faces as vertex-index lists, stored compactly (CSR) so that a soup of
//! millions of faces costs two flat arrays, not one allocation per face.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "geolab/boundary.hpp"

namespace geolab {

//! Positions and polygonal faces. Face f has the vertex indices
//! `indices[offsets[f] .. offsets[f+1])`, in counter-clockwise order seen from outside.
//! Invariant: offsets.front() == 0, offsets is non-decreasing, offsets.back() == indices.size().
struct PolygonSoup {
    std::vector<glm::dvec3> positions;
    std::vector<std::uint32_t> indices;
    std::vector<std::uint32_t> offsets{0};
    GEOLAB_FIELDS(positions, indices, offsets)  // what crosses the grading boundary (geolab/boundary.hpp)

    std::size_t n_vertices() const { return positions.size(); }
    std::size_t n_faces() const { return offsets.size() - 1; }
    //! The vertex indices of face f (f < n_faces()).
    std::span<const std::uint32_t> face(std::size_t f) const {
        return {indices.data() + offsets[f], indices.data() + offsets[f + 1]};
    }
    //! Append a face given by its vertex indices; returns its index.
    std::size_t add_face(std::initializer_list<std::uint32_t> vs) { return add_face(std::span(vs.begin(), vs.size())); }
    std::size_t add_face(std::span<const std::uint32_t> vs) {
        // Speed: faces are short; element-wise appends beat insert()'s general range copy (a memmove call a face)
        for (std::uint32_t v : vs) indices.push_back(v);
        offsets.push_back(static_cast<std::uint32_t>(indices.size()));
        return n_faces() - 1;
    }
    //! True when every face is a triangle.
    bool is_triangle_soup() const { return indices.size() == 3 * n_faces(); }
};

//! Throws std::invalid_argument naming the first face with an index out of range, fewer than 3 vertices,
//! a repeated vertex, or the first position that is not finite. O(#positions + #indices), whatever the faces'
//! sizes (a 1,000,000-vertex face is checked in linear time).
void check_soup(const PolygonSoup& soup);

}  // namespace geolab
