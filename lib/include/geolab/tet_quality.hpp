#pragma once
//! \file tet_quality.hpp
//! The shape quality of a tetrahedron, for `geolab info` and the lab 02 demo's colouring.
#include <glm/vec3.hpp>

namespace geolab {

//! The radius ratio ρ = 3 r / R of the tetrahedron (a, b, c, d): r the radius of its inscribed sphere, R of its
//! circumscribed sphere. 1 for the regular tetrahedron, towards 0 for slivers, needles and caps; 0 for a flat
//! (zero-volume) one; negative (−3 r / R) when the tetrahedron is inverted, i.e. det(b − a, c − a, d − a) < 0.
//! Computed as ρ = 9 V / (A R) with V the signed volume and A the total face area.
double tet_radius_ratio(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d);

}  // namespace geolab
