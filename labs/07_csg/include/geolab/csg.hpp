#pragma once
//! \file csg.hpp
//! Lab 07 — constructive solid geometry: YOUR TASKS. Write these functions in labs/07_csg/src/*.cpp (one file per
//! task). A CSG tree's leaves are primitives, each placed by an affine map M (its local coordinates → world);
//! inner nodes are union, intersection, difference and the smooth union (a blend).
//!
//! | task | file            | functions                               | lecture ↔ code                              | handout |
//! |------|-----------------|-----------------------------------------|---------------------------------------------|---------|
//! | 1    | primitives.cpp  | primitive_distance                      | exact signed distances of the primitives    | §2      |
//! | 2    | sdf.cpp         | smooth_min, sdf (prepared; one-shot)    | ∪ = min, ∩ = max, A − B = max(a, −b), smin  | §3      |
//! | 3    | pmc.cpp         | classify                                | point membership: in / on / out             | §4      |
//! | 4    | spans.cpp       | primitive_spans                         | a ray's inside intervals in one primitive   | §5      |
//! | 5    | combine.cpp     | combine, line_meets_box,                | Roth's interval lists; skip missed subtrees | §6      |
//! |      |                 | ray_spans (prepared; one-shot)          |                                             |         |
//! | 6    | raycast.cpp     | first_hit (prepared; one-shot),         | the first boundary point, Lambert image     | §7      |
//! |      |                 | render_image                            |                                             |         |
//! | 7    | mesh.cpp        | mesh_tree, volume                       | polygonize, divergence theorem              | §8      |
//!
//! Given (read, do not write; given.cpp): check_tree, bounds, scene_size, min_stretch, affine_inverse, the tree
//! builders (leaf, combine_trees), prepare (a tree made ready for many rays or samples), real_roots (a polynomial
//! root finder for the torus), from_scad (OpenSCAD scenes, read by lib's geolab/scad.hpp), PinholeCamera::ray.
#include <optional>
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "geolab/boundary.hpp"
#include "geolab/errors.hpp"
#include "geolab/field.hpp"
#include "geolab/render/image.hpp"
#include "geolab/scad.hpp"
#include "geolab/soup.hpp"

namespace geolab::csg {

//! The primitives, each in its own local coordinates (then placed by the leaf's M):
enum class Shape : int {
    sphere,     //!< |p| ≤ size.x (the radius)
    box,        //!< |x| ≤ size.x, |y| ≤ size.y, |z| ≤ size.z (half extents)
    cylinder,   //!< x² + y² ≤ size.x², |z| ≤ size.z (radius, —, half height; axis z)
    cone,       //!< truncated cone about z: radius size.x at z = −size.z, size.y at z = +size.z (r1, r2 ≥ 0, not
                //!< both 0); between them the radius changes linearly
    torus,      //!< (√(x² + y²) − size.x)² + z² ≤ size.y² (R, r with 0 < r < R; about z)
    halfspace,  //!< z ≤ 0 (unbounded; size unused)
    quadric,    //!< XᵀQX ≤ 0 with Q the leaf's matrix Q (X = (x, y, z, 1); possibly unbounded)
};

//! The node kinds: a leaf, or an operation on the children a and b.
enum class Op : int {
    leaf,       //!< a primitive
    unite,      //!< A ∪ B
    intersect,  //!< A ∩ B
    subtract,   //!< A − B
    blend,      //!< smooth union of A and B with radius k > 0 (signed distances only, §3)
};

//! One node. Children come before their parents in Tree::nodes (a < own index, b < own index).
struct Node {
    Op op = Op::leaf;
    int a = -1, b = -1;            //!< children (inner nodes)
    Shape shape = Shape::sphere;   //!< leaves
    glm::dvec3 size{1.0};          //!< leaves: the shape's parameters (see Shape)
    glm::dmat4 Q{0.0};             //!< leaves of Shape::quadric: the symmetric 4×4 (geolab/quadric.hpp)
    glm::dmat4 M{1.0};             //!< leaves: the affine map local → world (last row 0 0 0 1, invertible)
    double k = 0.0;                //!< blend: the radius
    GEOLAB_FIELDS(op, a, b, shape, size, Q, M, k)
};

//! A CSG tree: the nodes and the index of the root.
struct Tree {
    std::vector<Node> nodes;
    int root = -1;
    GEOLAB_FIELDS(nodes, root)
};

//! A node of a prepared tree: the node itself and what every ray or sample would otherwise recompute (§7).
struct PreparedNode {
    Node node;                       //!< the tree's node, as it was (op, children, shape, size, Q, M, k)
    glm::dmat4 inverse{1.0};         //!< leaves: M⁻¹, world → local (identity for inner nodes)
    glm::dmat3 normal_map{1.0};      //!< leaves: (M⁻¹)ᵀ's 3×3 part, local normals → world (then normalize)
    double stretch = 1.0;            //!< leaves: min_stretch(M) (1 for inner nodes)
    glm::dvec3 lo{0.0}, hi{0.0};     //!< a world box containing the node's solid (±infinity where unbounded)
    GEOLAB_FIELDS(node, inverse, normal_map, stretch, lo, hi)
};

//! A tree made ready for many rays or samples by prepare(): checked once, each leaf's maps inverted once, each
//! node's box known. Nothing in it changes while rays are cast: threads may share one.
struct PreparedTree {
    std::vector<PreparedNode> nodes;  //!< nodes[i] is the tree's node i (children before parents)
    int root = -1;
    bool has_blend = false;           //!< some node is a blend (no exact interval list: ray casting refuses it)
    GEOLAB_FIELDS(nodes, root, has_blend)
};

// ==== Given (given.cpp) =======================================================================================

//! \throw std::invalid_argument naming the node when the tree is malformed: root or a child out of range, a child
//! not before its parent, a leaf's parameters out of range (see Shape), M not affine or singular or not finite,
//! a blend with k ≤ 0.
void check_tree(const Tree& t);
//! A leaf; the shape's parameters in `size` (see Shape), placed by M.
Tree leaf(Shape s, glm::dvec3 size, const glm::dmat4& M = glm::dmat4(1.0));
//! A quadric leaf XᵀQX ≤ 0 placed by M.
Tree quadric_leaf(const glm::dmat4& Q, const glm::dmat4& M = glm::dmat4(1.0));
//! The tree op(a, b) (for Op::blend with radius k).
Tree combine_trees(Op op, const Tree& a, const Tree& b, double k = 0.0);
//! The tree prepared once for many rays or samples (handout §7): check_tree(t), then per node its M⁻¹, (M⁻¹)ᵀ and
//! min_stretch(M) (leaves) and a box containing its solid: bounds() of its subtree grown on every side by 1e-9 of
//! its extent and position, so that rounding never makes a line that meets the solid miss the box.
//! \throw std::invalid_argument as check_tree.
PreparedTree prepare(const Tree& t);
//! The inverse of an affine map (L, t) ↦ (L⁻¹, −L⁻¹t). \throw std::invalid_argument when singular.
glm::dmat4 affine_inverse(const glm::dmat4& M);
//! The smallest singular value of M's 3×3 part: every local distance d is at least min_stretch(M)·d in world.
double min_stretch(const glm::dmat4& M);
//! An axis-aligned box containing the solid: a leaf's local box mapped by M (infinite for half-spaces and
//! quadrics), unions' hull, intersections' overlap, a difference's first operand, a blend's hull grown by k/4.
Box bounds(const Tree& t);
//! The scene's size for relative tolerances: the diagonal of bounds(t) when finite; otherwise the diagonal of the
//! box around all finite leaves' boxes; 1 when no leaf is bounded.
double scene_size(const Tree& t);
//! The real roots of c[0] + c[1] t + ... + c[n] tⁿ in [lo, hi], sorted, each to about 1e-12 relative; a root of
//! even multiplicity (a touching root) is reported once. Leading zero coefficients lower the degree.
std::vector<double> real_roots(const std::vector<double>& c, double lo, double hi);
//! The CSG tree of an OpenSCAD scene (lib's reader: geolab/scad.hpp): cube → box (moved to [0, size] unless
//! centred), sphere → sphere, cylinder → cylinder (r1 = r2) or cone, with z from 0 to h unless centred;
//! union / intersection / difference of n children → a left-deep chain of n − 1 nodes.
Tree from_scad(const scad::Scene& s);

// ==== Task 1: primitives (handout §2) =========================================================================

//! The exact signed distance (negative inside) from the point p, given in the leaf's LOCAL coordinates, to the
//! leaf's primitive (ignore M): sphere |p| − r; box and cylinder and cone and torus their exact Euclidean
//! distances (outside: to the nearest surface point; inside: minus the distance to the nearest surface point);
//! half-space z. A quadric has no closed-form distance: return q/|∇q| with q = XᵀQX, ∇q = 2 (QX)ₓᵧ𝓏 (the
//! first-order distance; exact for planes), or q itself where ∇q = 0.
//! \throw std::invalid_argument when the node is not a leaf.
double primitive_distance(const Node& leaf, const glm::dvec3& p);

// ==== Task 2: signed distances of trees (handout §3) ==========================================================

//! The polynomial smooth minimum (handout §3): h = clamp(1/2 + (b − a)/(2k), 0, 1),
//! smin = b·(1 − h) + a·h − k·h·(1 − h). Equals min(a, b) when |a − b| ≥ k; at most k/4 below it.
//! \throw std::invalid_argument unless k > 0.
double smooth_min(double a, double b, double k);

//! The tree's signed field at the world point x. A leaf: min_stretch(M) · primitive_distance(leaf, M⁻¹x) (exact
//! for rigid motions and uniform scalings; a lower bound of the distance's size for other maps), with the node's
//! prepared `stretch` and `inverse` (never recompute them from M: sdf is called for millions of samples). Union
//! min(a, b), intersection max(a, b), difference max(a, −b), blend smooth_min(a, b, k). Negative inside.
//! Precondition: t as prepare() made it.
double sdf(const PreparedTree& t, const glm::dvec3& x);
//! One point: sdf(prepare(t), x). \throw std::invalid_argument when the tree is malformed (check_tree).
double sdf(const Tree& t, const glm::dvec3& x);

// ==== Task 3: point membership classification (handout §4) ===================================================

enum class Membership : int { in, on, out };

//! Where x lies w.r.t. the solid, with tolerance tol = rel_tol · scene_size(t). A leaf: on when |d| ≤ tol, d the
//! leaf's world value as in sdf(); else in (d < 0) or out. Inner nodes combine their children's answers:
//!   union      in if either is in; out if both are out; otherwise on;
//!   intersect  out if either is out; in if both are in; otherwise on;
//!   subtract   out if A is out or B is in; in if A is in and B is out; otherwise on;
//!   blend      by the blend's own value v = sdf of that subtree: on when |v| ≤ tol, else by its sign.
//! (Without neighbourhoods a point on a face shared by two touching solids of a union is "on", not "in": the
//! handout's §4 rule.) \throw std::invalid_argument when rel_tol < 0 or the tree is malformed.
Membership classify(const Tree& t, const glm::dvec3& x, double rel_tol);

// ==== Task 4: a ray in one primitive (handout §5) =============================================================

//! A ray origin + t · direction (direction need not be unit length; t is in its units; t may be negative).
struct Ray {
    glm::dvec3 origin{0.0}, direction{0.0, 0.0, -1.0};
    GEOLAB_FIELDS(origin, direction)
};

//! One inside interval [t0, t1] of the ray (t0 < t1; ±infinity for unbounded solids) and the solid's unit OUTWARD
//! normals at its two ends (zero vector at an infinite end).
struct Span {
    double t0 = 0, t1 = 0;
    glm::dvec3 n0{0.0}, n1{0.0};
    GEOLAB_FIELDS(t0, t1, n0, n1)
};

//! Replaces `out` with the spans of the whole line origin + t · direction (t ∈ ℝ), given in the leaf's LOCAL
//! coordinates, inside the leaf's primitive: sorted, disjoint, each of positive length; a ray that only touches the
//! solid (a tangent: a double root, an edge or a corner grazed) has no span there. Normals in local coordinates,
//! unit length. Convex shapes give at most one span; a torus up to two (use real_roots for its quartic); a quadric
//! up to two. `out` keeps its capacity (clear, then push_back): a list reused from ray to ray allocates nothing.
//! \throw std::invalid_argument when the node is not a leaf or the direction is zero.
void primitive_spans(const Node& leaf, const Ray& local, std::vector<Span>& out);

// ==== Task 5: combining interval lists (handout §6) ===========================================================

//! Replaces `out` with the spans of op(A, B) from A's and B's sorted, disjoint spans (op: unite, intersect or
//! subtract). Rule for equal parameters: all comparisons are exact; every endpoint at the same t is applied before
//! deciding whether the result changes there, so spans that touch ([0, 1] and [1, 2]) merge in a union, and no
//! span of zero length is ever output (box minus an equal box is empty). A result endpoint takes the normal of the
//! operand that has an endpoint there (A's when both do); in a difference, the normals that come from B are NEGATED
//! (they face into B, i.e. out of A − B). `out` is another list than a and b; it keeps its capacity.
//! \throw std::invalid_argument for Op::leaf or Op::blend.
void combine(Op op, const std::vector<Span>& a, const std::vector<Span>& b, std::vector<Span>& out);

//! Whether the whole line origin + t · direction (t ∈ ℝ) meets the closed box [lo, hi] (Kay and Kajiya's slabs, as
//! for a box in Task 4: the line's parameter intervals inside the three slabs overlap; touching a face, an edge or a
//! corner counts). Infinite lo or hi are allowed (a slab without a side); a direction component 0 (or −0) keeps the
//! line inside that slab or outside it for every t. Precondition: lo ≤ hi, direction not zero.
bool line_meets_box(const Ray& line, const glm::dvec3& lo, const glm::dvec3& hi);

//! One span list per node of a tree, reused from ray to ray (lists[i] for node i): once they have grown, casting a
//! ray allocates nothing. Casting writes them, so each thread has its own.
using SpanLists = std::vector<std::vector<Span>>;

//! Roth's interval lists of a prepared tree along the WORLD line (t ∈ ℝ); the tree's spans end up in
//! lists[t.root]. First `lists` is resized to one list per node (existing lists keep their capacity). Then, from
//! the root down, node i:
//!   - gets an empty list when line_meets_box(world, lo, hi) is false for its box, and its subtree is not visited;
//!   - a leaf: primitive_spans of the ray mapped by the node's `inverse` (o' = M⁻¹o, d' = M⁻¹d: the same t), each
//!     finite end's normal mapped back by `normal_map` and normalized (a zero normal stays zero);
//!   - an inner node: A's list first; for ∩ and − an empty A gives an empty list without visiting B (∅ ∩ B = ∅ − B
//!     = ∅); otherwise B's list, then combine(op, A's, B's, lists[i]).
//! Lists of nodes not visited keep what they held. Reads the prepared fields, never M.
//! Precondition: t as prepare() made it. \throw std::invalid_argument when t.has_blend or the direction is zero.
void ray_spans(const PreparedTree& t, const Ray& world, SpanLists& lists);
//! One ray: the spans of ray_spans(prepare(t), world, lists) with fresh lists (lists[root]).
//! \throw std::invalid_argument for a blend node, a malformed tree or a zero direction.
std::vector<Span> ray_spans(const Tree& t, const Ray& world);

// ==== Task 6: ray casting (handout §7) ========================================================================

//! Where a ray meets the solid's boundary, with the solid's unit outward normal there.
struct Hit {
    double t = 0;
    glm::dvec3 point{0.0}, normal{0.0};
    GEOLAB_FIELDS(t, point, normal)
};

//! The first span end with t ≥ t_min (finite) of ray_spans(t, ray, lists): the entry t0 of the first span with
//! t0 ≥ t_min, or, when the ray starts inside (t0 < t_min ≤ t1), the exit t1 with its outward normal. nullopt when
//! there is none. `lists` as in ray_spans (one per thread; reuse it for every ray).
//! \throw std::invalid_argument as ray_spans.
std::optional<Hit> first_hit(const PreparedTree& t, const Ray& ray, double t_min, SpanLists& lists);
//! One ray: first_hit(prepare(t), ray, t_min, lists) with fresh lists.
std::optional<Hit> first_hit(const Tree& t, const Ray& ray, double t_min);

//! A pinhole camera (given): rays from `eye` through the pixel centres of a width × height image looking at
//! `target`, `fov_deg` across the image height, `up` the world up (not parallel to the view direction).
struct PinholeCamera {
    glm::dvec3 eye{0.0, 0.0, 5.0}, target{0.0}, up{0.0, 1.0, 0.0};
    double fov_deg = 40.0;
    GEOLAB_FIELDS(eye, target, up, fov_deg)
    //! The ray through the centre of pixel (x, y), (0, 0) the top-left corner; direction unit length.
    Ray ray(int x, int y, int width, int height) const;
};

//! One ray per pixel (camera.ray), first_hit with t_min = 0 on the tree prepared once, one SpanLists reused for
//! every pixel: a hit is grey v = 0.1 + 0.8·|n·l| (l the unit direction to the light), pixel round(255·v) in R, G
//! and B; a miss is white (255). A = 255. Rows top to bottom.
//! \throw std::invalid_argument when width or height is < 1, or as ray_spans.
render::Image render_image(const Tree& t, const PinholeCamera& camera, int width, int height, const glm::dvec3& light);

// ==== Task 7: meshes and volumes (handout §8) =================================================================

//! The tree's surface through lib's reference polygonizer (geolab/polygonize.hpp) applied to sdf() of the tree
//! prepared once, over the box bounds(t) grown by 5% of its diagonal on every side, `resolution` cells along its
//! longest side.
//! \throw std::invalid_argument when bounds(t) is not finite or resolution < 2, or as sdf.
PolygonSoup mesh_tree(const Tree& t, int resolution);

//! The volume enclosed by a closed, outward-oriented polygon mesh by the divergence theorem: Σ over faces,
//! fanned into triangles (v0, vᵢ, vᵢ₊₁), of v0 · (vᵢ × vᵢ₊₁) / 6. Negative for an inward-oriented mesh.
//! \throw std::invalid_argument when the soup is malformed (check_soup).
double volume(const PolygonSoup& mesh);

// ==== The grading boundary (for the grader; nothing to do for you) ===========================================
#ifdef GEOLAB_BOUNDARY
GEOLAB_BOUNDARY(primitive_distance, double(const Node&, const glm::dvec3&))
GEOLAB_BOUNDARY(smooth_min, double(double, double, double))
GEOLAB_BOUNDARY(sdf, double(const PreparedTree&, const glm::dvec3&))
GEOLAB_BOUNDARY(sdf, double(const Tree&, const glm::dvec3&))
GEOLAB_BOUNDARY(classify, Membership(const Tree&, const glm::dvec3&, double))
GEOLAB_BOUNDARY(primitive_spans, void(const Node&, const Ray&, std::vector<Span>&))
GEOLAB_BOUNDARY(combine, void(Op, const std::vector<Span>&, const std::vector<Span>&, std::vector<Span>&))
GEOLAB_BOUNDARY(line_meets_box, bool(const Ray&, const glm::dvec3&, const glm::dvec3&))
GEOLAB_BOUNDARY(ray_spans, void(const PreparedTree&, const Ray&, SpanLists&))
GEOLAB_BOUNDARY(ray_spans, std::vector<Span>(const Tree&, const Ray&))
GEOLAB_BOUNDARY(first_hit, std::optional<Hit>(const PreparedTree&, const Ray&, double, SpanLists&))
GEOLAB_BOUNDARY(first_hit, std::optional<Hit>(const Tree&, const Ray&, double))
GEOLAB_BOUNDARY(render_image, render::Image(const Tree&, const PinholeCamera&, int, int, const glm::dvec3&))
GEOLAB_BOUNDARY(mesh_tree, PolygonSoup(const Tree&, int))
GEOLAB_BOUNDARY(volume, double(const PolygonSoup&))
#endif

}  // namespace geolab::csg
