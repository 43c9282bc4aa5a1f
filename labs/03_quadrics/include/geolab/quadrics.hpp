#pragma once
//! \file quadrics.hpp
//! Lab 03 — quadric surfaces: YOUR TASKS. Write these functions in labs/03_quadrics/src/*.cpp (one file per
//! task). The lecture's general quadric is
//!     a x² + b y² + c z² + 2f yz + 2g zx + 2h xy + 2p x + 2q y + 2r z + d = 0.
//!
//! | task | file              | functions                                                         | lecture ↔ code                      | handout |
//! |------|-------------------|-------------------------------------------------------------------|-------------------------------------|---------|
//! | 1    | matrix_form.cpp   | to_matrix, to_coefficients, evaluate, gradient                    | Σ Qᵢⱼ xᵢ xⱼ + Σ Pᵢ xᵢ + R = XᵀQX      | §3      |
//! | 2    | transform.cpp     | transform_quadric                                                 | Q' = M⁻ᵀ Q M⁻¹                      | §4      |
//! | 3    | classify.cpp      | classify                                                          | ranks, eigenvalue signs, det Q      | §5      |
//! | 4    | ray.cpp           | solve_quadratic, intersect, intersect_in_box                      | X(t) = O + tD in XᵀQX = 0           | §6      |
//! | 5    | superquadric.cpp  | spow, inside_outside, superquadric_point, superquadric_normal,    | Barr's ε₁, ε₂                       | §7      |
//! |      |                   | superquadric_volume, intersect_superquadric                       |                                     |         |
//! | 6    | tessellate.cpp    | tessellate_superquadric, tessellate_ellipsoid                     | closed meshes, χ = 2                | §8      |
//! | 7    | render.cpp        | render_lambert                                                    | one ray per pixel, Lambert shading  | §9      |
//!
//! Given (read, do not write): type_name, canonical_form, symmetric_eigen (given.cpp) and the camera's rays
//! (PinholeCamera below).
//! Points are homogeneous X = (x, y, z, 1); directions D = (dx, dy, dz, 0). Matrices are glm::dmat4, column-major
//! (Q[col][row]); every Q here is symmetric.
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "geolab/boundary.hpp"
#include "geolab/errors.hpp"
#include "geolab/render/image.hpp"
#include "geolab/soup.hpp"

namespace geolab::quadrics {

//! The ten coefficients of the lecture's quadric, named as in the lecture (the cross and linear terms carry a
//! factor 2 in the equation: 2f yz, 2g zx, 2h xy, 2p x, 2q y, 2r z).
struct Coefficients {
    double a = 0, b = 0, c = 0, f = 0, g = 0, h = 0, p = 0, q = 0, r = 0, d = 0;
    GEOLAB_FIELDS(a, b, c, f, g, h, p, q, r, d)
};

// ==== Task 1: the matrix form (handout §3) ===================================================================

//! The symmetric 4×4 Q with XᵀQX = the quadric's left-hand side:
//!     | a h g p |
//!     | h b f q |      (rows = columns: Q[0][1] = Q[1][0] = h, Q[0][2] = g, Q[1][2] = f, Q[0][3] = p, ...)
//!     | g f c r |
//!     | p q r d |
glm::dmat4 to_matrix(const Coefficients& k);

//! The coefficients of a symmetric Q (the inverse of to_matrix). A non-symmetric M is read as its symmetric part
//! (M + Mᵀ)/2, which has the same XᵀMX. \throw std::invalid_argument when an entry is not finite.
Coefficients to_coefficients(const glm::dmat4& Q);

//! XᵀQX at the point x (X = (x, 1)): the left-hand side of the equation; 0 on the surface.
double evaluate(const glm::dmat4& Q, const glm::dvec3& x);

//! The gradient of XᵀQX at x: the first three entries of 2·Q·X (from the full 4×4 product: the linear terms
//! count). Not normalized; it points to where XᵀQX grows.
glm::dvec3 gradient(const glm::dmat4& Q, const glm::dvec3& x);

// ==== Task 2: transforms (handout §4) =========================================================================

//! The quadric of the surface moved by the affine map M (points X ↦ M X): Q' = M⁻ᵀ Q M⁻¹, so that
//! x on Q ⇔ M x on Q'. The result is symmetric (symmetrize it: rounding makes M⁻ᵀ Q M⁻¹ slightly asymmetric).
//! \throw std::invalid_argument when M is not affine (last row ≠ (0, 0, 0, 1)) or its 3×3 part is singular
//!        (|det| ≤ 1e-12 · ‖M₃ₓ₃‖³, ‖·‖ the largest absolute entry).
glm::dmat4 transform_quadric(const glm::dmat4& Q, const glm::dmat4& M);

// ==== Task 3: classification (handout §5) =====================================================================

//! The 17 types of a quadric with a non-zero quadratic part, each with its canonical form (given.cpp).
enum class QuadricType : int {
    real_ellipsoid,                 //!< x²/a² + y²/b² + z²/c² = 1
    imaginary_ellipsoid,            //!< x²/a² + y²/b² + z²/c² = −1 (no real point)
    hyperboloid_one_sheet,          //!< x²/a² + y²/b² − z²/c² = 1
    hyperboloid_two_sheets,         //!< x²/a² + y²/b² − z²/c² = −1
    real_cone,                      //!< x²/a² + y²/b² − z²/c² = 0
    imaginary_cone,                 //!< x²/a² + y²/b² + z²/c² = 0 (one real point)
    elliptic_paraboloid,            //!< x²/a² + y²/b² − z = 0
    hyperbolic_paraboloid,          //!< x²/a² − y²/b² − z = 0
    real_elliptic_cylinder,         //!< x²/a² + y²/b² = 1
    imaginary_elliptic_cylinder,    //!< x²/a² + y²/b² = −1 (no real point)
    hyperbolic_cylinder,            //!< x²/a² − y²/b² = 1
    parabolic_cylinder,             //!< x² − 2 r z = 0 (r ≠ 0)
    real_intersecting_planes,       //!< x²/a² − y²/b² = 0
    imaginary_intersecting_planes,  //!< x²/a² + y²/b² = 0 (one real line)
    real_parallel_planes,           //!< x² = a²
    imaginary_parallel_planes,      //!< x² = −a² (no real point)
    coincident_planes,              //!< x² = 0
};

//! The type of Q from (handout §5): r₃ = rank of the upper-left 3×3 A, r₄ = rank of Q, and the signs of the
//! eigenvalues of A and of Q (det Q's sign follows from Q's). An eigenvalue λ counts as zero when
//! |λ| ≤ 1e-9 · max |eigenvalue| of the same matrix. The type does not change under rigid motions, non-zero
//! uniform scalings of space, or multiplying Q by a non-zero number of either sign.
//! \throw std::invalid_argument when A is zero (not a quadric: a plane or nothing) or an entry is not finite.
QuadricType classify(const glm::dmat4& Q);

//! The eigen-decomposition of a symmetric n×n block (given; the lab is about what the eigenvalues say, not how to
//! compute them): values[i] is an eigenvalue with the unit eigenvector vectors[i] (entries n..3 are 0); unsorted.
//! The vectors are the columns of a product of plane rotations: orthonormal, with determinant +1.
struct SymmetricEigen {
    double values[4] = {0, 0, 0, 0};
    glm::dvec4 vectors[4] = {};
};
//! The eigenvalues and eigenvectors of the upper-left n×n block of S (n = 3: the quadratic part A; n = 4: all of
//! Q), read as its symmetric part, by cyclic Jacobi rotations (given.cpp): accurate to rounding relative to the
//! largest |eigenvalue|. \throw std::invalid_argument when n is not 3 or 4 or an entry of the block is not finite.
SymmetricEigen symmetric_eigen(const glm::dmat4& S, int n);

//! "real ellipsoid", "hyperboloid of one sheet", ... (given.cpp).
std::string type_name(QuadricType t);
//! The canonical equation of a type, e.g. "x²/a² + y²/b² + z²/c² = 1" (given.cpp).
std::string canonical_form(QuadricType t);

// ==== Task 4: rays (handout §6) ===============================================================================

//! The real roots of α t² + β t + γ = 0, sorted (t0 ≤ t1). Without cancellation (handout §6):
//! q = −(β + sign(β)·√Δ)/2, roots q/α and γ/q — never (−β ± √Δ)/(2α), which loses the small root.
//! Δ = β² − 4αγ is rounded: it counts as 0 when |Δ| ≤ 1e-12 · (β² + 4|αγ|) (a tangent ray; a ray through
//! coincident planes, where Δ is 0 exactly but rounds to ±tiny).
//! count = 0: no real root (Δ < 0 beyond that tolerance, or α = β = 0); 1: α = 0 and β ≠ 0 (the linear root), or
//! a double root (Δ counted 0: t0 = t1 = −β/(2α)); 2: two roots. When α = β = γ = 0 every t is a root: count = 0
//! by convention.
struct Roots {
    int count = 0;
    double t0 = 0, t1 = 0;
    GEOLAB_FIELDS(count, t0, t1)
};
Roots solve_quadratic(double alpha, double beta, double gamma);

//! A ray origin + t · direction (direction need not be unit length; t is in its units).
struct Ray {
    glm::dvec3 origin{0.0}, direction{0.0, 0.0, -1.0};
    GEOLAB_FIELDS(origin, direction)
};

//! Where a ray meets a surface: its parameter, the point and the unit outward normal there (the normalized
//! gradient of XᵀQX, i.e. pointing to where XᵀQX > 0; for a superquadric, to where the inside–outside
//! function exceeds 1).
struct Hit {
    double t = 0;
    glm::dvec3 point{0.0}, normal{0.0};
    GEOLAB_FIELDS(t, point, normal)
};

//! All crossings of the ray with XᵀQX = 0 for t in [t_min, t_max], sorted by t: the roots of
//! α t² + β t + γ with α = DᵀQD, β = 2 DᵀQX₀, γ = X₀ᵀQX₀ (from solve_quadratic). A double root (tangent ray)
//! is one hit; a ray starting on the surface has a hit at t = 0 (when t_min ≤ 0). A zero gradient at a hit
//! (a cone's apex) gives normal (0, 0, 0). A ray lying in the surface (α = β = γ = 0) has no hits.
//! \throw std::invalid_argument when direction is zero or t_min > t_max.
std::vector<Hit> intersect(const glm::dmat4& Q, const Ray& ray, double t_min, double t_max);

//! An axis-aligned box [lo, hi].
struct Box3 {
    glm::dvec3 lo{-1.0}, hi{1.0};
    GEOLAB_FIELDS(lo, hi)
};

//! The hits of intersect(Q, ray, 0, +inf) whose points lie in the box (the part of an unbounded surface that is
//! shown): the ray is clipped to the box (slab method) and only the roots in the clipped interval are kept.
//! Sorted by t. Empty when the ray misses the box. \throw std::invalid_argument when lo > hi on some axis.
std::vector<Hit> intersect_in_box(const glm::dmat4& Q, const Ray& ray, const Box3& box);

// ==== Task 5: superquadrics (handout §7) ======================================================================

//! Barr's superellipsoid with radii (a1, a2, a3) and exponents ε₁ (north–south) and ε₂ (east–west), both > 0.
struct Superquadric {
    glm::dvec3 radii{1.0};
    double e1 = 1.0, e2 = 1.0;
    GEOLAB_FIELDS(radii, e1, e2)
};

//! The signed power sign(x)·|x|^e (e > 0): spow(−8, 1/3) = −2, never NaN for a negative base; spow(0, e) = 0.
double spow(double x, double e);

//! Barr's inside–outside function F = (|x/a1|^(2/ε₂) + |y/a2|^(2/ε₂))^(ε₂/ε₁) + |z/a3|^(2/ε₁):
//! < 1 inside, 1 on the surface, > 1 outside. \throw std::invalid_argument when a radius or exponent is ≤ 0.
double inside_outside(const Superquadric& s, const glm::dvec3& x);

//! The surface point at latitude η ∈ [−π/2, π/2] and longitude ω ∈ [−π, π]:
//!     (a1 · spow(cos η, ε₁) spow(cos ω, ε₂),  a2 · spow(cos η, ε₁) spow(sin ω, ε₂),  a3 · spow(sin η, ε₁)).
glm::dvec3 superquadric_point(const Superquadric& s, double eta, double omega);

//! The unit outward normal at (η, ω): normalize of
//!     (spow(cos η, 2−ε₁) spow(cos ω, 2−ε₂) / a1,  spow(cos η, 2−ε₁) spow(sin ω, 2−ε₂) / a2,  spow(sin η, 2−ε₁) / a3).
//! At a point where that vector is zero (a pole with ε₁ > 2, ...) any unit vector is accepted by the tests only
//! where they say so; the tests use ε ≤ 2 for normals.
glm::dvec3 superquadric_normal(const Superquadric& s, double eta, double omega);

//! The exact volume 2 a1 a2 a3 ε₁ ε₂ B(ε₁/2 + 1, ε₁) B(ε₂/2, ε₂/2), B the Beta function (handout §7):
//! (1, 1) → 4π/3 · a1 a2 a3, (2, 2) → 4/3 · a1 a2 a3. \throw std::invalid_argument as inside_outside.
double superquadric_volume(const Superquadric& s);

//! The first crossing of the ray with the surface F = 1 for t in [t_min, t_max] (entering or leaving), by a safe
//! root finder on the inside–outside function (handout §7: clip to the bounding box, bracket a sign change of
//! F − 1 along the ray in steps of at most 1/1000 of the clipped interval, then bisect; F^(ε₁/2) − 1 has the same
//! signs and grows like a distance, better for Brent): the returned t is within 1e-9 · (1 + |t|) of the true
//! crossing. Rays that only graze the surface (touch without crossing) may be reported or not; a ray starting on
//! the surface (F = 1 at t_min) hits at t_min.
//! nullopt when there is no crossing. \throw std::invalid_argument when direction is zero or t_min > t_max.
std::optional<Hit> intersect_superquadric(const Superquadric& s, const Ray& ray, double t_min, double t_max);

// ==== Task 6: tessellation (handout §8) =======================================================================

//! The superquadric as a closed triangle mesh on an (η, ω) grid: two pole vertices (η = ±π/2, listed first: the
//! south pole is vertex 0, the north pole vertex 1), n_eta − 1 rings of n_omega vertices (vertex 2 + (i − 1)·n_omega + j
//! is superquadric_point at η = −π/2 + iπ/n_eta, ω = −π + 2πj/n_omega, 1 ≤ i < n_eta), fans at the poles and
//! two triangles per grid quad; counter-clockwise seen from outside (normals outward), every vertex on the
//! surface. V = 2 + (n_eta − 1)·n_omega, F = 2·n_omega·(n_eta − 1), χ = 2.
//! \throw std::invalid_argument when n_eta < 2 or n_omega < 3, or as inside_outside.
PolygonSoup tessellate_superquadric(const Superquadric& s, int n_eta, int n_omega);

//! The same mesh for a real ellipsoid given by Q (any centre and orientation): vertex for (η, ω) is
//! centre + Σ rᵢ uᵢ · (unit sphere point at (η, ω)), with uᵢ the eigenvectors of A (a right-handed frame) and rᵢ
//! the semi-axes; every vertex satisfies XᵀQX = 0 to rounding, the mesh is closed and outward.
//! \throw std::invalid_argument when Q is not a real ellipsoid (an eigenvalue of A with |λ| ≤ 1e-9 · max |λ| is
//!        zero, as in classify), or on bad n_eta, n_omega.
PolygonSoup tessellate_ellipsoid(const glm::dmat4& Q, int n_eta, int n_omega);

// ==== Task 7: images (handout §9) =============================================================================

//! A pinhole camera (given): rays from `eye` through the pixel centres of a width × height image looking at
//! `target`, `fov_deg` across the image height, `up` the world up (not parallel to the view direction).
struct PinholeCamera {
    glm::dvec3 eye{0.0, 0.0, 5.0}, target{0.0}, up{0.0, 1.0, 0.0};
    double fov_deg = 40.0;
    GEOLAB_FIELDS(eye, target, up, fov_deg)

    //! The ray through the centre of pixel (x, y), (0, 0) the top-left corner; direction unit length.
    Ray ray(int x, int y, int width, int height) const;
};

//! What render_lambert draws: a quadric clipped to a box, or a superquadric.
struct Scene {
    bool is_superquadric = false;
    glm::dmat4 Q{0.0};    //!< the quadric (when !is_superquadric)
    Box3 box;             //!< its clipping box
    Superquadric sq;      //!< the superquadric (when is_superquadric)
    glm::dvec3 light{0.0, 0.0, 1.0};  //!< direction TO the light (need not be unit)
    GEOLAB_FIELDS(is_superquadric, Q, box, sq, light)
};

//! One ray per pixel (camera.ray); the first hit (intersect_in_box or intersect_superquadric with t ≥ 0) is
//! shaded with two-sided Lambert: v = 0.1 + 0.9·|n·l|, l the unit light direction; a miss is v = 0.
//! Pixel value round(255·v) in R, G and B; A = 255 everywhere. Rows top to bottom.
//! \throw std::invalid_argument when width or height is < 1.
render::Image render_lambert(const Scene& scene, const PinholeCamera& camera, int width, int height);

// ==== The grading boundary (for the grader; nothing to do for you) ===========================================
// Your functions above, as the grader sees them: the tests' calls into your code are recorded in the program
// that runs it and replayed in the judge, which has no code of yours and decides each verdict
// (docs/architecture.md, "Grading protocol").
#ifdef GEOLAB_BOUNDARY
GEOLAB_BOUNDARY(to_matrix, glm::dmat4(const Coefficients&))
GEOLAB_BOUNDARY(to_coefficients, Coefficients(const glm::dmat4&))
GEOLAB_BOUNDARY(evaluate, double(const glm::dmat4&, const glm::dvec3&))
GEOLAB_BOUNDARY(gradient, glm::dvec3(const glm::dmat4&, const glm::dvec3&))
GEOLAB_BOUNDARY(transform_quadric, glm::dmat4(const glm::dmat4&, const glm::dmat4&))
GEOLAB_BOUNDARY(classify, QuadricType(const glm::dmat4&))
GEOLAB_BOUNDARY(solve_quadratic, Roots(double, double, double))
GEOLAB_BOUNDARY(intersect, std::vector<Hit>(const glm::dmat4&, const Ray&, double, double))
GEOLAB_BOUNDARY(intersect_in_box, std::vector<Hit>(const glm::dmat4&, const Ray&, const Box3&))
GEOLAB_BOUNDARY(spow, double(double, double))
GEOLAB_BOUNDARY(inside_outside, double(const Superquadric&, const glm::dvec3&))
GEOLAB_BOUNDARY(superquadric_point, glm::dvec3(const Superquadric&, double, double))
GEOLAB_BOUNDARY(superquadric_normal, glm::dvec3(const Superquadric&, double, double))
GEOLAB_BOUNDARY(superquadric_volume, double(const Superquadric&))
GEOLAB_BOUNDARY(intersect_superquadric, std::optional<Hit>(const Superquadric&, const Ray&, double, double))
GEOLAB_BOUNDARY(tessellate_superquadric, PolygonSoup(const Superquadric&, int, int))
GEOLAB_BOUNDARY(tessellate_ellipsoid, PolygonSoup(const glm::dmat4&, int, int))
GEOLAB_BOUNDARY(render_lambert, render::Image(const Scene&, const PinholeCamera&, int, int))
#endif

}  // namespace geolab::quadrics
