#pragma once
//! \file sweeps.hpp
//! Lab 06 — sweep representations: YOUR TASKS. Write these functions in labs/06_sweeps/src/*.cpp (one file per
//! task). A 2D profile (outer loop with holes) is moved through space: translated (extrusion), rotated about an
//! axis (revolution) or carried along a 3D curve by a moving frame (sweep).
//!
//! | task | file            | functions                                   | lecture ↔ code                          | handout |
//! |------|-----------------|---------------------------------------------|-----------------------------------------|---------|
//! | 1    | profile.cpp     | signed_area, validate_profile               | shoelace; outer CCW, holes CW           | §2      |
//! | 2    | triangulate.cpp | triangulate                                 | ear clipping, hole bridging             | §3      |
//! | 3    | extrude.cpp     | extrude                                     | P(s) = R(θs)·σ(s)·p + s·d               | §4      |
//! | 4    | revolve.cpp     | clip_to_axis, revolve                       | (r, z) ↦ (r cos φ, r sin φ, z)          | §5      |
//! | 5    | frames.cpp      | frenet_frames, rotation_minimizing_frames   | T, N, B; double reflection (Wang 2008)  | §6      |
//! | 6    | sweep.cpp       | sweep, check_sweep                          | X(s, u, v) = c(s) + u N(s) + v B(s)     | §7      |
//! | 7    | measure.cpp     | mesh_volume, mesh_area, pappus              | divergence theorem; Pappus              | §8      |
//!
//! Given (read, do not write; given.cpp): profile_points, rectangle_loop, circle_loop, helix_path, trefoil_path,
//! polyline_path. All meshes are PolygonSoups of triangles, counter-clockwise seen from outside (normals point
//! out of the solid), closed 2-manifolds whose vertices are shared (never duplicated along a seam).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "geolab/boundary.hpp"
#include "geolab/errors.hpp"
#include "geolab/soup.hpp"

namespace geolab::sweeps {

//! A closed polygon: its vertices in order, the last joined to the first (do not repeat the first vertex).
using Loop = std::vector<glm::dvec2>;

//! A planar region: an outer loop, counter-clockwise (positive signed area), and holes inside it, each clockwise.
//! Coordinates (x, y); for a revolution x is the distance r from the axis and y the height z.
struct Profile {
    Loop outer;
    std::vector<Loop> holes;
    GEOLAB_FIELDS(outer, holes)
};

//! A sampled 3D curve: its points, the unit tangents there (same count), and whether the last point joins the
//! first (closed: do not repeat the first point).
struct Path {
    std::vector<glm::dvec3> points;
    std::vector<glm::dvec3> tangents;
    bool closed = false;
    GEOLAB_FIELDS(points, tangents, closed)
};

//! An orthonormal right-handed frame at a path point: T the unit tangent, N and B spanning the normal plane,
//! B = T × N. A profile point (u, v) sits at c + u·N + v·B.
struct Frame {
    glm::dvec3 T{0.0, 0.0, 1.0}, N{1.0, 0.0, 0.0}, B{0.0, 1.0, 0.0};
    GEOLAB_FIELDS(T, N, B)
};

// ==== Given (given.cpp) =======================================================================================

//! The profile's points in the order every mesh and triangulation of this lab uses: the outer loop, then each
//! hole in turn. Index i of a triangulation refers to this list.
std::vector<glm::dvec2> profile_points(const Profile& p);
//! The axis-aligned rectangle [x0, x1] × [y0, y1], counter-clockwise from (x0, y0) (reverse it for a hole).
Loop rectangle_loop(double x0, double y0, double x1, double y1);
//! n points on the circle of radius r about c, counter-clockwise from angle 0. \throw std::invalid_argument n < 3.
Loop circle_loop(glm::dvec2 c, double r, int n);
//! n samples of the helix (r cos t, r sin t, h t) over `turns` turns: t = i · turns · 2π / (n − 1), i = 0..n−1,
//! with exact unit tangents. \throw std::invalid_argument when n < 2.
Path helix_path(double r, double h, double turns, int n);
//! n samples of the trefoil knot (sin t + 2 sin 2t, cos t − 2 cos 2t, −sin 3t) · scale, t = 2π i / n, closed,
//! with exact unit tangents. \throw std::invalid_argument when n < 3.
Path trefoil_path(int n, double scale = 1.0);
//! A polyline path with tangents by central differences of the points (one-sided at an open path's ends),
//! normalized. \throw std::invalid_argument when fewer than 2 points, or two consecutive points coincide.
Path polyline_path(const std::vector<glm::dvec3>& points, bool closed);

// ==== Task 1: profiles (handout §2) ===========================================================================

//! The shoelace area ½ Σ (xᵢ yᵢ₊₁ − xᵢ₊₁ yᵢ): positive for a counter-clockwise loop. 0 for fewer than 3 points.
double signed_area(const Loop& loop);

//! Checks a profile and throws std::invalid_argument naming the loop ("outer loop", "hole 2"), the element and the
//! reason: fewer than 3 vertices ("has 2 vertices (at least 3)"); a coordinate that is not finite ("vertex 4 is not
//! finite"); two consecutive vertices equal ("vertices 3 and 0 are equal", the last and the first); the loop
//! intersects itself ("edges 1 and 4 meet": two edges that are not neighbours touch or cross, decided with exact
//! orient2d); zero area; the outer loop is clockwise or a hole counter-clockwise ("wrong orientation"); a hole not
//! strictly inside the outer loop, or two loops touching or crossing each other. Checked in this order, loop by loop
//! (the outer loop, then the holes), each loop's vertices and edges from index 0 up, so the message names the
//! first problem. Returns normally for a valid profile.
void validate_profile(const Profile& p);

// ==== Task 2: triangulation (handout §3) ======================================================================

//! Triangles covering the profile's region exactly, by ear clipping (holes bridged into the outer loop first).
//! Indices refer to profile_points(p); each triangle is counter-clockwise (positive area); the count is
//! n + 2h − 2 for n points and h holes; the areas add up to the region's area (outer minus holes) and no two
//! triangles overlap. Which bridges and which ears is yours to choose: any triangulation of the region with
//! these properties is right (each loop edge is an edge of exactly one triangle, each other edge of exactly two).
//! \throw std::invalid_argument as validate_profile.
std::vector<std::array<std::uint32_t, 3>> triangulate(const Profile& p);

// ==== Task 3: extrusion (handout §4) ==========================================================================

//! How to extrude: the profile lies in the plane z = 0 and is moved to s·direction for s ∈ [0, 1], in `steps`
//! equal layers; layer s is the profile scaled about the origin by 1 + s·(scale − 1) and turned about the z-axis
//! by s·twist radians (counter-clockwise seen from +z) before it is moved.
struct ExtrudeOptions {
    glm::dvec3 direction{0.0, 0.0, 1.0};
    int steps = 1;
    double twist = 0.0;
    double scale = 1.0;
    GEOLAB_FIELDS(direction, steps, twist, scale)
};

//! The closed solid swept by the profile: vertices layer by layer (layer k holds profile_points in order at
//! s = k / steps), side walls of two triangles per profile edge and step, and the two caps (the triangulation,
//! facing −z at the bottom and away from the solid at the top). Outward oriented; genus = number of holes.
//! \throw std::invalid_argument for an invalid profile, steps < 1, direction.z ≤ 0, scale ≤ 0, a value that is not
//!        finite, or |twist| / steps ≥ π/2 (a step of a quarter turn or more folds the side walls).
PolygonSoup extrude(const Profile& p, const ExtrudeOptions& options);

// ==== Task 4: revolution (handout §5) =========================================================================

//! The part of the profile with x ≥ 0 (the axis is x = 0): each loop is clipped to the half-plane (Sutherland–
//! Hodgman, visiting the edges into points 0, 1, 2, ... so that kept points keep their order and index 0 stays
//! first when it is kept); points that become consecutive duplicates are dropped. A profile entirely in x ≥ 0
//! comes back unchanged. \throw std::invalid_argument when nothing is left (area 0), when a hole reaches x ≤ 0, or when the
//! input profile is invalid.
Profile clip_to_axis(const Profile& p);

//! How to revolve: `segments` steps about the z-axis through `angle` radians (2π: a full revolution).
struct RevolveOptions {
    int segments = 32;
    double angle = 6.283185307179586;
    GEOLAB_FIELDS(segments, angle)
};

//! The solid swept by the profile (x = r, y = z) turned about the z-axis from φ = 0 to φ = angle,
//! (r, z) ↦ (r cos φ, r sin φ, z), after clip_to_axis. Vertices: for each point of the clipped profile in order,
//! ONE vertex (0, 0, z) when r = 0 (a pole), else its ring at φⱼ = j·angle/segments, j = 0..segments−1 for a full
//! revolution (the seam φ = 2π is the ring at φ = 0, shared, not repeated) and j = 0..segments for a partial one.
//! Edges on the axis make no faces; an edge with one end on the axis makes one triangle per segment. A partial
//! revolution is closed by the two caps (the clipped profile's triangulation at φ = 0 and at φ = angle).
//! Outward oriented, no zero-area triangle. A full revolution gives one closed surface per loop that does not
//! lie on the axis (a loop touching the axis: sphere-like; one away from it, or a hole: torus-like).
//! A full revolution is |angle − 2π| ≤ 1e-12; else angle must lie in (0, 2π).
//! \throw std::invalid_argument when segments < 3, the angle is neither, or as clip_to_axis.
PolygonSoup revolve(const Profile& p, const RevolveOptions& options);

// ==== Task 5: frames (handout §6) =============================================================================

//! Frenet frames from the sampled tangents: at sample i the curvature direction is k = Tᵢ₊₁ − Tᵢ₋₁ (an open path's
//! ends use Tᵢ₊₁ − Tᵢ and Tᵢ − Tᵢ₋₁; a closed path wraps), N = the unit part of k orthogonal to Tᵢ, B = T × N.
//! Where that part has length ≤ 1e-9 (a straight run: the frame is undefined) N and B are (0, 0, 0).
//! Frenet's N follows the curvature, so it turns over at an inflection. T is the path's tangent.
//! \throw std::invalid_argument when the path has fewer than 2 points or points and tangents differ in count.
std::vector<Frame> frenet_frames(const Path& path);

//! Rotation-minimizing frames and, for a closed path, the closing mismatch.
struct RmfResult {
    std::vector<Frame> frames;
    //! Closed path: the angle in (−π, π] from N₀ to the normal carried once around the loop (back to sample 0),
    //! measured about T₀ (positive: counter-clockwise seen from the tip of T₀, i.e. from N toward B). Open: 0.
    double mismatch = 0.0;
    GEOLAB_FIELDS(frames, mismatch)
};

//! Rotation-minimizing frames by the double reflection method (Wang, Jüttler, Zheng, Liu 2008): N₀ is
//! initial_normal made orthogonal to T₀ and unit; from sample i to i+1, reflect in the plane bisecting the
//! points (v₁ = xᵢ₊₁ − xᵢ), then in the plane that maps the reflected tangent onto Tᵢ₊₁ (v₂ = Tᵢ₊₁ − T_L); a zero
//! v₂ means no second reflection. Closed path: the frames are carried once around (the step from the last sample
//! back to sample 0 included), the mismatch is measured, and frame i is then turned about Tᵢ by −mismatch·sᵢ/L
//! (sᵢ the polyline length from sample 0 to sample i, L the loop's length), so the frames close up.
//! \throw std::invalid_argument for fewer than 2 points, counts that differ, two consecutive points equal (the
//!        message names them: "points 3 and 4 are equal"; on a closed path also the last and the first, "points 9
//!        and 0"), or an initial normal (nearly) parallel to T₀ (its part orthogonal to T₀ no longer than 1e-9 · its
//!        length).
RmfResult rotation_minimizing_frames(const Path& path, const glm::dvec3& initial_normal);

// ==== Task 6: sweeping along a path (handout §7) ==============================================================

//! The profile carried along the path by the frames: point (u, v) at sample i is pointsᵢ + u·Nᵢ + v·Bᵢ.
//! Vertices sample by sample (sample i holds profile_points in order). Open path: side walls between consecutive
//! samples and the two caps (facing −T₀ at the start and +T at the end). Closed path: the last sample joins the
//! first, no caps (each loop gives one torus-like surface: the outer loop's bounds a solid torus, each hole's a
//! tunnel through it; χ = 0 and 1 + holes components). Outward oriented as extrude (which is this
//! sweep along a straight path with T = z, N = x, B = y).
//! \throw std::invalid_argument for an invalid profile, frames.size() ≠ points.size(), or fewer than 2 samples
//!        (3 for a closed path).
PolygonSoup sweep(const Profile& p, const Path& path, const std::vector<Frame>& frames);

//! The local self-intersection check of a sweep: the profile's radius (largest distance of a profile point from
//! the path, i.e. from (0, 0)) against the path's smallest radius of curvature (the circumradius of each three
//! consecutive samples; wrapping on a closed path; collinear samples have infinite radius). Local only: a path that
//! comes back near itself (a coil wound tighter than the profile, strands of a knot too close) has no tight turn,
//! and this check does not see it; lib's check_surface on the mesh does (geolab sweep runs both, handout §7).
struct SweepCheck {
    double profile_radius = 0.0;
    double min_radius_of_curvature = 0.0;  //!< +infinity for a straight path
    std::uint32_t at_sample = 0;           //!< the middle sample of the tightest three (the first on a tie)
    bool self_intersects = false;          //!< profile_radius ≥ min_radius_of_curvature
    GEOLAB_FIELDS(profile_radius, min_radius_of_curvature, at_sample, self_intersects)
};
//! \throw std::invalid_argument as sweep (the frames are not needed).
SweepCheck check_sweep(const Profile& p, const Path& path);

// ==== Task 7: measures (handout §8) ===========================================================================

//! The enclosed volume by the divergence theorem: Σ over triangles of det(a, b, c) / 6 (a polygon as the fan
//! v₀ vᵢ vᵢ₊₁), with the points taken relative to the mesh's first vertex (the sum is the same about any point
//! for a closed mesh, and far from the origin the raw coordinates would cancel away the digits). Positive for an
//! outward-oriented closed mesh. 0 for an empty mesh.
double mesh_volume(const PolygonSoup& mesh);
//! The total area: Σ |(b − a) × (c − a)| / 2 over the same triangles.
double mesh_area(const PolygonSoup& mesh);

//! Pappus's theorems for the profile turned by `angle` about the axis x = 0 (the profile must lie in x ≥ 0).
struct Pappus {
    double volume = 0.0;        //!< angle · (region's area) · (x of its centroid)
    double lateral_area = 0.0;  //!< angle · Σ over every edge of (its length) · (x of its midpoint)
    GEOLAB_FIELDS(volume, lateral_area)
};
//! \throw std::invalid_argument for an invalid profile, a point with x < 0, or angle ≤ 0.
Pappus pappus(const Profile& p, double angle);

// ==== The grading boundary (for the grader; nothing to do for you) ===========================================
#ifdef GEOLAB_BOUNDARY
GEOLAB_BOUNDARY(signed_area, double(const Loop&))
GEOLAB_BOUNDARY(validate_profile, void(const Profile&))
GEOLAB_BOUNDARY(triangulate, std::vector<std::array<std::uint32_t, 3>>(const Profile&))
GEOLAB_BOUNDARY(extrude, PolygonSoup(const Profile&, const ExtrudeOptions&))
GEOLAB_BOUNDARY(clip_to_axis, Profile(const Profile&))
GEOLAB_BOUNDARY(revolve, PolygonSoup(const Profile&, const RevolveOptions&))
GEOLAB_BOUNDARY(frenet_frames, std::vector<Frame>(const Path&))
GEOLAB_BOUNDARY(rotation_minimizing_frames, RmfResult(const Path&, const glm::dvec3&))
GEOLAB_BOUNDARY(sweep, PolygonSoup(const Profile&, const Path&, const std::vector<Frame>&))
GEOLAB_BOUNDARY(check_sweep, SweepCheck(const Profile&, const Path&))
GEOLAB_BOUNDARY(mesh_volume, double(const PolygonSoup&))
GEOLAB_BOUNDARY(mesh_area, double(const PolygonSoup&))
GEOLAB_BOUNDARY(pappus, Pappus(const Profile&, double))
#endif

}  // namespace geolab::sweeps
