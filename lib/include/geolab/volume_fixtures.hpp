#pragma once
//! \file volume_fixtures.hpp
//! Small procedural volume meshes for tests, demos and benchmarks, as plain cell lists (geolab::VolumeMesh; lab 02
//! builds its half-face mesh from them). Corner orders as volume_io.hpp says: every tetrahedron is positive
//! (det(b − a, c − a, d − a) > 0), every hexahedron lists its bottom quad counter-clockwise seen from its top. The
//! meshes are conforming (two cells that touch share a whole face, listed in opposite directions); the expected
//! counts of each are documented here and checked in tests/lib/test_volume_fixtures.cpp. A size outside its
//! documented range throws std::invalid_argument.
#include "geolab/volume_io.hpp"

namespace geolab::volume_fixtures {

//! The unit cube [0,1]³ split into 6 tetrahedra around its diagonal from (0,0,0) to (1,1,1) (the Kuhn or
//! Freudenthal split: one tetrahedron per order of the axes). V 8, C 6 (each of volume 1/6), 12 boundary
//! triangles, 6 interior triangles. Vertex i is the corner (i & 1, i >> 1 & 1, i >> 2 & 1).
VolumeMesh kuhn_cube();

//! [0,1]³ cut into n³ cubes, each split as kuhn_cube (the same diagonal direction everywhere, so neighbouring
//! cubes' faces match). V (n+1)³, C 6n³, 12n² boundary triangles; vertex (i, j, k) is (k(n+1) + j)(n+1) + i at
//! (i, j, k)/n; the tetrahedra of cube (i, j, k) are cells 6((k n + j) n + i) .. +5. 1 ≤ n ≤ 256.
VolumeMesh tet_grid(int n);

//! [0,1]³ cut into n³ hexahedra, numbered (k n + j) n + i; vertices as tet_grid. V (n+1)³, C n³, 6n² boundary
//! quads. 1 ≤ n ≤ 256.
VolumeMesh hex_grid(int n);

//! The paper's example: a tetrahedralised ball of radius 1 about the origin with a region shaped like a solid
//! torus about the z axis. Made as tet_grid(n) of the cube [−1,1]³ (cube (i, j, k) centred at
//! c = (2i + 1 − n, 2j + 1 − n, 2k + 1 − n)/n) mapped onto the ball by p ↦ p·‖p‖∞/‖p‖₂ (rays from the centre are
//! kept, the cube's surface goes onto the unit sphere). Label 1 on the tetrahedra of the cubes whose centre has
//! 0.3 ≤ max(|c.x|, |c.y|) ≤ 0.6 and |c.z| ≤ 0.3 (decided in integers, so exactly symmetric: a square ring of
//! cubes, i.e. a solid torus, never touching the sphere), label 0 elsewhere. So the label-0 cells form a ball with a
//! solid torus taken out, the label-1 cells the solid torus: the boundary of the ball is a sphere (χ 2), the interface
//! between the labels a torus (χ 0). V (n+1)³, C 6n³, boundary vertices on the unit sphere. 5 ≤ n ≤ 256 (ring cubes: 8
//! for n = 5, 24 for n = 6 and 8, 128 for n = 10).
VolumeMesh ball_with_torus(int n = 10);

}  // namespace geolab::volume_fixtures
