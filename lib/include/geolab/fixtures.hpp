#pragma once
//! \file fixtures.hpp
//! Small procedural meshes for tests and demos. All closed fixtures are consistently oriented with outward
//! normals (counter-clockwise seen from outside). The expected topology of each is documented here, so tests
//! can check invariants against it. A size parameter outside its documented range throws std::invalid_argument.
#include "geolab/soup.hpp"

namespace geolab::fixtures {

//! Regular tetrahedron inscribed in the unit sphere. V=4 E=6 F=4, χ=2, closed.
PolygonSoup tetrahedron();
//! Axis-aligned cube [-1,1]³ made of 6 quads (or 12 triangles when `triangulate`). V=8, χ=2, closed.
PolygonSoup cube(bool triangulate = false);
//! Icosphere of radius 1: icosahedron subdivided `subdivisions` times. F = 20·4ⁿ, V = 10·4ⁿ + 2, χ=2.
//! 0 ≤ subdivisions ≤ 10.
PolygonSoup icosphere(int subdivisions = 2);
//! Torus about the z axis, major radius R, minor radius r, `rings` × `sides` quads (triangles when
//! `triangulate`). V = rings·sides, χ=0, genus 1, closed. rings, sides ≥ 3.
PolygonSoup torus(int rings = 24, int sides = 12, double R = 1.0, double r = 0.35, bool triangulate = true);
//! Flat grid in z = 0 over [0,1]², nx × ny cells split into triangles: V=(nx+1)(ny+1), one boundary loop, χ=1.
//! nx, ny ≥ 1.
PolygonSoup grid(int nx = 4, int ny = 4);
//! Two disjoint tetrahedra, the second shifted by (3,0,0). 2 components, χ=4.
PolygonSoup two_components();
//! Non-manifold "bowtie": two triangles sharing only vertex 0 (a complex vertex). V=5, F=2.
PolygonSoup bowtie();
//! Non-manifold "fan": three triangles sharing the edge 0-1 (a complex edge). V=5, F=3.
PolygonSoup fan();
//! Möbius strip: `segments` quads (triangles when `triangulate`) around a half-twisted band. Non-orientable:
//! building a half-edge mesh from it must fail with an inconsistent-orientation error. segments ≥ 5.
PolygonSoup mobius(int segments = 12, bool triangulate = true);
//! The same soup with the orientation of face `f` reversed (for orientation tests).
PolygonSoup flip_face(PolygonSoup soup, std::size_t f);

}  // namespace geolab::fixtures
