#pragma once
//! \file predicates.hpp
//! Exact geometric predicates on double coordinates. Each one first evaluates its determinant in double
//! precision with a conservative forward error bound; only when the sign is not certain does it redo the
//! determinant exactly in integer arithmetic (GMP; a double is an integer times a power of two), so the answer is the sign of the exact real determinant of
//! the given doubles: never wrong, and as fast as the plain formula on all but near-degenerate inputs.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace geolab {

//! Sign (−1, 0, +1) of det[a−d; b−d; c−d]: +1 when d lies below the plane through a, b, c oriented so that
//! a, b, c appear counter-clockwise seen from above (d on the side the right-hand normal (b−a)×(c−a) points away
//! from), 0 when the four points are exactly coplanar.
int orient3d(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d);

//! Sign (−1, 0, +1) of det[a−c; b−c]: +1 when a, b, c turn counter-clockwise, 0 when exactly collinear.
int orient2d(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c);

//! True when a, b, c are exactly collinear (coincident points included).
bool collinear(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

}  // namespace geolab
