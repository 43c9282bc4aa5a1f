#pragma once
//! \file bezier.hpp
//! Lab 05 — Bézier curves and surfaces, de Casteljau, the Utah teapot: YOUR TASKS. Write these functions in
//! labs/05_bezier/src/*.cpp (one file per task). A degree-n Bézier curve with control points P_0 .. P_n is
//!     C(t) = Σ_k B_k^n(t) P_k,   B_k^n(t) = C(n, k) t^k (1 − t)^(n−k),   t ∈ [0, 1].
//!
//! | task | file            | functions                                                          | lecture ↔ code          | handout |
//! |------|-----------------|--------------------------------------------------------------------|-------------------------|---------|
//! | 1    | basics.cpp      | bernstein, de_casteljau (2D, 3D), de_casteljau_triangle,           | repeated (1−t):t        | §2      |
//! |      |                 | evaluate_bernstein (2D, 3D)                                        | interpolation           |         |
//! | 2    | operations.cpp  | subdivide, restrict_to, hodograph, derivative, second_derivative,  | hodograph n ΔP_k        | §3      |
//! |      |                 | elevate, curvature, torsion, signed_curvature                      |                         |         |
//! | 3    | measure.cpp     | arc_length, parameter_at_length, bounding_box, closest_point       | Gauss–Legendre, roots   | §4      |
//! | 4    | composite.cpp   | evaluate_composite, continuity, join_c1, join_g1                   | Cⁿ, Gⁿ at a joint       | §5      |
//! | 5    | patch.cpp       | patch_point, patch_du, patch_dv, patch_normal, tessellate_patches  | de Casteljau in u, v    | §6      |
//! | 6    | (tests only)    | the Utah teapot through task 5's functions                         | Newell's 32 patches     | §7      |
//! | 7    | glyph.cpp       | flatten_contour, contour_area, glyph_area                          | Green's theorem         | §8      |
//! | 8    | advanced.cpp    | rational_point, circle_arc, de_boor, insert_knot                   | weights; de Boor        | §9      |
//!
//! Given (read, do not write): lib's readers geolab::read_bpt (the teapot) and geolab::read_glyph (FreeType) in
//! geolab/bezier_data.hpp. Curves in 2D or 3D: task 1 takes both; tasks 2–4 and 8 work in 3D (a planar curve has
//! z = 0); signed curvature and glyphs are 2D. Errors: std::invalid_argument with the function's name and reason.
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "geolab/bezier_data.hpp"
#include "geolab/boundary.hpp"
#include "geolab/errors.hpp"
#include "geolab/soup.hpp"

namespace geolab::bezier {

using Poly2 = std::vector<glm::dvec2>;  //!< 2D control points P_0 .. P_n (degree n = size − 1)
using Poly3 = std::vector<glm::dvec3>;  //!< 3D control points P_0 .. P_n
using geolab::BezierPatch;

// ==== Task 1: basics (handout §2) =============================================================================

//! B_i^n(t) = C(n, i) t^i (1 − t)^(n − i) for 0 ≤ i ≤ n; 0 for i < 0 or i > n. Any real t (the tests use
//! [0, 1]). \throw std::invalid_argument when n < 0.
double bernstein(int n, int i, double t);

//! C(t) by de Casteljau: P_k^0 = P_k, P_k^r = (1 − t) P_k^(r−1) + t P_(k+1)^(r−1), C(t) = P_0^n. Only sums of
//! products of the points with (1 − t) and t: exact at dyadic t for dyadic points of small degree.
//! \throw std::invalid_argument when P is empty.
glm::dvec2 de_casteljau(const Poly2& P, double t);
glm::dvec3 de_casteljau(const Poly3& P, double t);

//! The whole de Casteljau triangle at t: row r (r = 0..n) holds the n + 1 − r points P_k^r; row 0 is P, row n
//! the single point C(t). The construction lines of the handout's figure. \throw as de_casteljau.
std::vector<Poly3> de_casteljau_triangle(const Poly3& P, double t);

//! C(t) from the Bernstein form Σ_k B_k^n(t) P_k (binomials and powers computed directly: the handout measures
//! how this loses accuracy at high degree). \throw std::invalid_argument when P is empty.
glm::dvec2 evaluate_bernstein(const Poly2& P, double t);
glm::dvec3 evaluate_bernstein(const Poly3& P, double t);

// ==== Task 2: operations (handout §3) =========================================================================

//! The two halves of a curve split at t: left = the control points of C on [0, t] reparametrised to [0, 1]
//! (the left edge of the de Casteljau triangle: P_0^0, P_0^1, ..., P_0^n), right = those of C on [t, 1]
//! (P_0^n, P_1^(n−1), ..., P_n^0). Both have P's degree; left.back() == right.front() == C(t).
struct Split {
    Poly3 left, right;
    GEOLAB_FIELDS(left, right)
};
//! \throw std::invalid_argument when P is empty or t is not finite (t outside [0, 1] extrapolates).
Split subdivide(const Poly3& P, double t);

//! The control points of C restricted to [a, b] and reparametrised to [0, 1] (a > b reverses the direction).
//! \throw std::invalid_argument when P is empty, a == b, or a or b is not finite.
Poly3 restrict_to(const Poly3& P, double a, double b);

//! The hodograph: the control points n (P_(k+1) − P_k), k = 0..n−1, of C' (degree n − 1). A single point
//! (n = 0) gives the single point (0, 0, 0). \throw std::invalid_argument when P is empty.
Poly3 hodograph(const Poly3& P);

//! C'(t) and C''(t) (through the hodograph and de Casteljau). Zero for too low a degree.
glm::dvec3 derivative(const Poly3& P, double t);
glm::dvec3 second_derivative(const Poly3& P, double t);

//! Degree elevation by one: Q_0 = P_0, Q_k = (k/(n+1)) P_(k−1) + (1 − k/(n+1)) P_k, Q_(n+1) = P_n. The same
//! curve with one more control point. \throw std::invalid_argument when P is empty.
Poly3 elevate(const Poly3& P);

//! Curvature κ = |C' × C''| / |C'|³ (≥ 0) and torsion τ = (C' × C'') · C''' / |C' × C''|² at t. Where C' = 0
//! (κ undefined) or C' × C'' = 0 (τ undefined) they return 0.
double curvature(const Poly3& P, double t);
double torsion(const Poly3& P, double t);

//! Signed curvature of a plane curve: (x' y'' − y' x'') / |C'|³ — positive where the curve turns left
//! (counter-clockwise). 0 where C' = 0.
double signed_curvature(const Poly2& P, double t);

// ==== Task 3: measures (handout §4) ===========================================================================

//! The length of C on [a, b] (a ≤ b, both in [0, 1]) by Gauss–Legendre quadrature of |C'| mapped to [a, b],
//! adaptive, in pieces. [a, b] is first cut where the speed |C'| is stationary: the roots in (a, b) of C' · C''
//! (degree 2n − 3), to within 1e-12 — a cusp is one, and two rules cannot see a kink near an interval's end. On
//! each piece an interval whose 5- and 10-point values differ by more than its share of T, T · its length / (b − a),
//! is halved; T = max(tol, 1e-14 · (b − a) · max_k |n ΔP_k|) (|C'| is known to about 1e-16 of its largest
//! control point, so a tol below that acts as that); an interval too small to halve in double is kept. The result
//! is the sum of the kept intervals' 10-point values: within tol of the true length (tol > 0 absolute).
//! \throw std::invalid_argument when P is empty, tol ≤ 0, not 0 ≤ a ≤ b ≤ 1, or |C'| overflows (a hodograph point
//!        whose length is not finite: a control point too large or not finite).
double arc_length(const Poly3& P, double a, double b, double tol);

//! The parameter t with arc_length(P, 0, t) = s for 0 ≤ s ≤ the curve's length (e.g. bisection on the length,
//! or Newton kept inside a bisection bracket): |length(0, t) − s| ≤ tol, or, when tol is below what the lengths
//! resolve, t within one double of the answer. A curve with C' = 0 on a stretch returns any t of it.
//! \throw std::invalid_argument when s < 0 or s > length + tol, or as arc_length.
double parameter_at_length(const Poly3& P, double s, double tol);

//! An axis-aligned box.
struct Box {
    glm::dvec3 lo{0.0}, hi{0.0};
    GEOLAB_FIELDS(lo, hi)
};
//! The tight bounding box of C on [0, 1]: per axis, the extremes among C(0), C(1) and C at the roots in (0, 1)
//! of that coordinate of C' (the hodograph's coordinate, a polynomial of degree n − 1: its roots by the method
//! you like, e.g. recursive subdivision with Newton). Within 1e-12 · (box diagonal + 1) of the true extremes;
//! inside the control points' box (convex hull property). \throw std::invalid_argument when P is empty.
Box bounding_box(const Poly3& P);

//! The point of C nearest to q: its parameter t ∈ [0, 1], the point C(t) and the distance |C(t) − q|.
struct Closest {
    double t = 0;
    glm::dvec3 point{0.0};
    double distance = 0;
    GEOLAB_FIELDS(t, point, distance)
};
//! The global nearest point (not a local one): an end, or a root in (0, 1) of (C(t) − q) · C'(t) (e.g. isolate the
//! roots of that Bernstein polynomial of degree 2n − 1 by subdivision, or sample and refine by Newton); compare
//! them all. Distance within 1e-9 · (scale) of the true minimum, scale = control points' box diagonal + |q|; of
//! points exactly equally near, the one with the smallest t. \throw std::invalid_argument when P is empty.
Closest closest_point(const Poly3& P, const glm::dvec3& q);

// ==== Task 4: composite curves (handout §5) ===================================================================

//! A composite curve: segment k covers the global parameter u ∈ [k, k + 1] with local t = u − k. u ∈ [0, m]
//! (m segments); u = k (an inner joint) belongs to segment k (t = 0); u = m is the end of the last segment.
//! \throw std::invalid_argument when there is no segment, a segment is empty, or u is outside [0, m].
glm::dvec3 evaluate_composite(const std::vector<Poly3>& segments, double u);

//! The continuity at the joint of a (at t = 1) and b (at t = 0), each class up to order 3.
//! C^k: the derivatives of orders 0..k of a at 1 and b at 0 are equal. G^k (the lecture): G^0 = C^0 and, for
//! k ≥ 1, C^(k−1) plus the k-th derivatives parallel with the same direction (a^(k)(1) = λ b^(k)(0), λ > 0):
//! both non-zero and their unit vectors equal within tol, or both zero. Vectors compare (equality, zero) within
//! tol · (1 + the larger length).
//! c_order, g_order: the largest k ≤ 3 that holds, −1 when the ends do not meet.
struct Continuity {
    int c_order = -1, g_order = -1;
    GEOLAB_FIELDS(c_order, g_order)
};
//! \throw std::invalid_argument when a or b is empty or tol < 0.
Continuity continuity(const Poly3& a, const Poly3& b, double tol);

//! b moved to join a with C¹: b_0 = a_n, b_1 = a_n + (n/m)(a_n − a_(n−1)) (n, m the degrees of a, b); the other
//! points of b unchanged. \throw std::invalid_argument when a has degree < 1 or b degree < 1.
Poly3 join_c1(const Poly3& a, const Poly3& b);

//! b moved to join a with G¹ keeping b's first leg length: b_0 = a_n, b_1 = a_n + |b_1 − b_0| · unit(a_n − a_(n−1)).
//! \throw std::invalid_argument as join_c1, or when a_n = a_(n−1) or b_1 = b_0 (no direction or no length).
Poly3 join_g1(const Poly3& a, const Poly3& b);

// ==== Task 5: tensor-product patches (handout §6) =============================================================

//! S(u, v): de Casteljau along u on each column j (the points P_0j .. P_nj) then along v on the results.
//! \throw std::invalid_argument when a degree is < 1 or points.size() ≠ (degree_u + 1)(degree_v + 1).
glm::dvec3 patch_point(const BezierPatch& S, double u, double v);

//! The partial derivatives S_u = ∂S/∂u and S_v = ∂S/∂v at (u, v). \throw as patch_point.
glm::dvec3 patch_du(const BezierPatch& S, double u, double v);
glm::dvec3 patch_dv(const BezierPatch& S, double u, double v);

//! The unit normal along S_u × S_v at (u, v). Where S_u × S_v counts as 0 (|S_u × S_v| ≤ 1e-12 · (|S_u| + |S_v|)²:
//! a collapsed patch edge such as the teapot's lid top and bottom centre) it is the limit of the normal as (u, v)
//! moves into the patch along the diagonal (u + σ_u δ, v + σ_v δ), δ → 0+, σ = +1 where the parameter is ≤ ½ and
//! −1 above (towards the centre): the direction of the first-order term
//!     d/dδ (S_u × S_v) = (σ_u S_uu + σ_v S_uv) × S_v + S_u × (σ_u S_uv + σ_v S_vv);
//! if that is exactly zero too, the normal at (u + σ_u 10⁻⁶, v + σ_v 10⁻⁶); if that is exactly zero too (a patch
//! collapsed to a point), (0, 0, 1). Never NaN. \throw as patch_point.
glm::dvec3 patch_normal(const BezierPatch& S, double u, double v);

//! A triangle mesh of the patches with positions and unit normals per vertex.
struct PatchMesh {
    PolygonSoup soup;                  //!< triangles
    std::vector<glm::dvec3> normals;   //!< one per soup position
    GEOLAB_FIELDS(soup, normals)
};
//! Each patch sampled at the (n + 1)² parameters (i/n, j/n), two triangles per grid cell: (i, j), (i+1, j),
//! (i+1, j+1) and (i, j), (i+1, j+1), (i, j+1) with i along u, j along v, so each triangle turns like
//! S_u × S_v (counter-clockwise seen from where it points). Patches in order, samples i-major (i, then j).
//! Welding: a border sample (i or j = 0 or n) within weld_tol (absolute, distance ≤ weld_tol; 0 welds equal
//! positions) of an earlier border vertex IS the earliest such vertex (its position and normal are kept; shared
//! patch borders and collapsed edges become one vertex); otherwise, and for every interior sample, a new vertex.
//! A triangle with two equal vertices is dropped. flip = true reverses every triangle and normal: the teapot's
//! file order needs flip = true for outward triangles and normals. Normals from patch_normal.
//! \throw std::invalid_argument when n < 1, weld_tol < 0, or as patch_point.
PatchMesh tessellate_patches(const std::vector<BezierPatch>& patches, int n, double weld_tol, bool flip);

// ==== Task 7: glyphs (handout §8) ==============================================================================

using geolab::GlyphOutline;
using geolab::QuadSegment;

//! A closed contour of quadratic segments as a polygon: per segment the points at t = k/m_s, k = 0..m_s − 1, with
//! m_s = max(1, ceil(sqrt(|P_0 − 2P_1 + P_2| / (4 tol)))) — the fewest uniform steps whose chords stay within tol
//! of the segment (a quadratic's chord over a parameter step h deviates by at most |P_0 − 2P_1 + P_2| h² / 4).
//! The polygon is closed implicitly (the last point connects to the first). \throw std::invalid_argument when
//! tol ≤ 0 or the contour is empty.
Poly2 flatten_contour(const std::vector<QuadSegment>& contour, double tol);

//! The signed area enclosed by a closed contour, exactly from the control points by Green's theorem
//! (A = ½ ∮ x dy − y dx, integrated per segment in closed form): positive when counter-clockwise (y up).
//! \throw std::invalid_argument when the contour is empty.
double contour_area(const std::vector<QuadSegment>& contour);

//! The inked area of a glyph, |Σ contour_area| over its contours (holes are oriented opposite to the outer
//! contours, so they subtract). 0 for a glyph without contours (a space).
double glyph_area(const GlyphOutline& g);

// ==== Task 8: advanced — rational curves, B-splines (handout §9) =================================================

//! A rational Bézier curve: C(t) = Σ w_k B_k^n(t) P_k / Σ w_k B_k^n(t).
struct RationalCurve {
    Poly3 points;
    std::vector<double> weights;
    GEOLAB_FIELDS(points, weights)
};
//! C(t) by de Casteljau on the homogeneous points (w_k P_k, w_k), then divided by the weight.
//! \throw std::invalid_argument when the sizes differ, there is no point, or a weight is ≤ 0.
glm::dvec3 rational_point(const RationalCurve& c, double t);

//! The exact circular arc of radius r > 0 about `center` in the plane z = center.z from angle a0 to a1
//! (radians, counter-clockwise, 0 < a1 − a0 < π): the quadratic with P_0, P_2 on the circle at a0, a1, P_1 where
//! the tangents there meet, weights (1, cos((a1 − a0)/2), 1). \throw std::invalid_argument otherwise.
RationalCurve circle_arc(const glm::dvec3& center, double r, double a0, double a1);

//! A B-spline of degree p: knots t_0 ≤ ... ≤ t_(m) with m + 1 = points.size() + p + 1, domain [t_p, t_(m−p)].
struct BSpline {
    int degree = 3;
    std::vector<double> knots;
    Poly3 points;
    GEOLAB_FIELDS(degree, knots, points)
};
//! C(t) by de Boor's algorithm: the span k with t_k ≤ t < t_(k+1) (t equal to the domain's end uses the last
//! non-empty span), then p rounds of affine combinations of P_(k−p) .. P_k.
//! \throw std::invalid_argument when degree < 1, the sizes disagree, knots decrease, or t is outside the domain.
glm::dvec3 de_boor(const BSpline& s, double t);

//! Boehm's knot insertion of t (inside the domain): the same curve with one more knot and one more point.
//! \throw std::invalid_argument as de_boor.
BSpline insert_knot(const BSpline& s, double t);

// ==== The grading boundary (for the grader; nothing to do for you) ===========================================
#ifdef GEOLAB_BOUNDARY
GEOLAB_BOUNDARY(bernstein, double(int, int, double))
GEOLAB_BOUNDARY(de_casteljau, glm::dvec2(const Poly2&, double))
GEOLAB_BOUNDARY(de_casteljau, glm::dvec3(const Poly3&, double))
GEOLAB_BOUNDARY(de_casteljau_triangle, std::vector<Poly3>(const Poly3&, double))
GEOLAB_BOUNDARY(evaluate_bernstein, glm::dvec2(const Poly2&, double))
GEOLAB_BOUNDARY(evaluate_bernstein, glm::dvec3(const Poly3&, double))
GEOLAB_BOUNDARY(subdivide, Split(const Poly3&, double))
GEOLAB_BOUNDARY(restrict_to, Poly3(const Poly3&, double, double))
GEOLAB_BOUNDARY(hodograph, Poly3(const Poly3&))
GEOLAB_BOUNDARY(derivative, glm::dvec3(const Poly3&, double))
GEOLAB_BOUNDARY(second_derivative, glm::dvec3(const Poly3&, double))
GEOLAB_BOUNDARY(elevate, Poly3(const Poly3&))
GEOLAB_BOUNDARY(curvature, double(const Poly3&, double))
GEOLAB_BOUNDARY(torsion, double(const Poly3&, double))
GEOLAB_BOUNDARY(signed_curvature, double(const Poly2&, double))
GEOLAB_BOUNDARY(arc_length, double(const Poly3&, double, double, double))
GEOLAB_BOUNDARY(parameter_at_length, double(const Poly3&, double, double))
GEOLAB_BOUNDARY(bounding_box, Box(const Poly3&))
GEOLAB_BOUNDARY(closest_point, Closest(const Poly3&, const glm::dvec3&))
GEOLAB_BOUNDARY(evaluate_composite, glm::dvec3(const std::vector<Poly3>&, double))
GEOLAB_BOUNDARY(continuity, Continuity(const Poly3&, const Poly3&, double))
GEOLAB_BOUNDARY(join_c1, Poly3(const Poly3&, const Poly3&))
GEOLAB_BOUNDARY(join_g1, Poly3(const Poly3&, const Poly3&))
GEOLAB_BOUNDARY(patch_point, glm::dvec3(const BezierPatch&, double, double))
GEOLAB_BOUNDARY(patch_du, glm::dvec3(const BezierPatch&, double, double))
GEOLAB_BOUNDARY(patch_dv, glm::dvec3(const BezierPatch&, double, double))
GEOLAB_BOUNDARY(patch_normal, glm::dvec3(const BezierPatch&, double, double))
GEOLAB_BOUNDARY(tessellate_patches, PatchMesh(const std::vector<BezierPatch>&, int, double, bool))
GEOLAB_BOUNDARY(flatten_contour, Poly2(const std::vector<QuadSegment>&, double))
GEOLAB_BOUNDARY(contour_area, double(const std::vector<QuadSegment>&))
GEOLAB_BOUNDARY(glyph_area, double(const GlyphOutline&))
GEOLAB_BOUNDARY(rational_point, glm::dvec3(const RationalCurve&, double))
GEOLAB_BOUNDARY(circle_arc, RationalCurve(const glm::dvec3&, double, double, double))
GEOLAB_BOUNDARY(de_boor, glm::dvec3(const BSpline&, double))
GEOLAB_BOUNDARY(insert_knot, BSpline(const BSpline&, double))
#endif

}  // namespace geolab::bezier
