#pragma once
//! \file surface_checks.hpp
//! Everything that can be wrong with a polygon mesh that claims to be a closed surface, counted. Used by
//! `geolab contour --json`, `geolab table1` and tests; each count has a hand-made mesh with exactly that defect
//! in tests/lib/test_surface_checks.cpp.
#include <cstddef>
#include <string>

#include "geolab/soup.hpp"

namespace geolab {

//! The counts of check_surface(). Vertices are the ones some face uses; a face with k vertices is the fan of
//! k − 2 triangles (v0, vi, vi+1) for the geometric counts.
struct SurfaceCheck {
    std::size_t vertices = 0;                //!< vertices used by at least one face
    std::size_t edges = 0;                   //!< distinct undirected edges
    std::size_t faces = 0;                   //!< faces
    std::size_t boundary_edges = 0;          //!< undirected edges in exactly one face
    std::size_t non_manifold_edges = 0;      //!< undirected edges in three or more faces
    std::size_t misoriented_edges = 0;       //!< edges in two faces that traverse it in the same direction
    std::size_t non_manifold_vertices = 0;   //!< vertices whose faces form more than one fan (edge-connected set)
    std::size_t repeated_index_faces = 0;    //!< faces that list a vertex index twice
    std::size_t zero_area_faces = 0;         //!< faces whose vertices are all exactly collinear (coincident included)
    std::size_t coincident_vertices = 0;     //!< used vertices at exactly the position of an earlier used vertex
    std::size_t components = 0;              //!< connected components (faces joined through shared vertices)
    long euler_characteristic = 0;           //!< χ = vertices − edges + faces
    //! Pairs of faces whose triangles meet other than in the vertices and edge the two faces share (exact
    //! predicates; zero-area triangles are left out, they are counted above). Split by what the pair shares:
    std::size_t intersecting_disjoint = 0;      //!< no vertex in common, yet they intersect
    std::size_t intersecting_vertex_sharing = 0;  //!< one vertex in common, and they meet somewhere else too
    std::size_t intersecting_edge_sharing = 0;    //!< an edge in common, and they overlap (folded onto each other)
    bool self_intersection_checked = false;  //!< false when CheckOptions::self_intersections was off

    std::size_t self_intersecting_pairs() const {
        return intersecting_disjoint + intersecting_vertex_sharing + intersecting_edge_sharing;
    }
    //! True only when every count allows a closed, oriented 2-manifold without self-intersections (and the
    //! self-intersection test ran): no boundary, non-manifold or misoriented edge, no non-manifold vertex, no
    //! repeated index, no zero-area face, no coincident vertices, no intersecting pair, at least one face.
    bool closed_manifold() const;
    //! One line: "V 10 E 24 F 16 χ 2, 1 component; boundary 0, non-manifold edges 0 / vertices 0, ...".
    std::string summary() const;
};

//! What check_surface() computes.
struct CheckOptions {
    bool self_intersections = true;  //!< the only count that is not linear-time (a uniform grid of boxes)
};

//! Counts the defects of `soup` (see SurfaceCheck). Throws std::invalid_argument for an index out of range or a
//! face of fewer than 3 vertices. Roughly O(n log n) for a surface of n faces whose triangles are of similar size.
SurfaceCheck check_surface(const PolygonSoup& soup, const CheckOptions& options = {});

}  // namespace geolab
