#pragma once
//! \file mesh_field.hpp
//! The signed distance to a triangle mesh: exact unsigned distance through an AABB tree (BVH), sign from the
//! generalized winding number (Jacobson, Kavan & Sorkine-Hornung 2013) evaluated hierarchically with the
//! far-field expansion of Barill, Dickson, Schmidt, Levin & Jacobson 2018 ("Fast winding numbers"). The
//! winding number makes the sign robust on meshes with holes, self-intersections or several components.
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "geolab/field.hpp"
#include "geolab/soup.hpp"

namespace geolab {

//! The point of triangle abc closest to p (Ericson, Real-Time Collision Detection, §5.1.5: Voronoi regions
//! of the vertices, then the edges, then the face). Works for degenerate triangles too.
glm::dvec3 closest_point_on_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                     const glm::dvec3& c);

//! The signed solid angle Ω of triangle abc seen from p, in [−2π, 2π]: positive when p lies behind the
//! triangle, i.e. on the side opposite to its normal (b − a) × (c − a) (so an outward-oriented closed mesh
//! sums to 4π at an inside point). Van Oosterom & Strackee 1983, with x = a − p, y = b − p, z = c − p:
//!   tan(Ω/2) = det[x y z] / (|x||y||z| + (x·y)|z| + (y·z)|x| + (z·x)|y|).
//! Returns 0 when p is on the triangle's plane outside it; ±2π or 0 when p is on the triangle itself.
double triangle_solid_angle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

//! Signed distance to a polygon soup (polygons triangulated as fans, faces with < 3 vertices ignored):
//! value(p) = −d(p) where the generalized winding number has |w(p)| ≥ 1/2 (inside), +d(p) elsewhere, with d
//! the exact Euclidean distance to the triangles. Taking |w| makes a consistently inward-oriented mesh (the
//! CGAL "head") work too.
//!
//! gradient(p) is sign · (p − q)/|p − q| with q the closest surface point: the exact gradient of the distance
//! away from the medial axis and the surface (a unit vector everywhere; on the surface itself, within
//! 1e-12 · bbox diagonal, it is the closest triangle's unit normal).
//!
//! lipschitz() is 1: |value| is the distance, 1-Lipschitz everywhere, and so is value itself wherever the sign
//! is consistent (closed, consistently oriented meshes). Across a hole the winding number switches sign on a
//! surface spanning the hole, away from the mesh, and value jumps there (from +d to −d): sign_may_jump() tells,
//! true when the mesh's oriented boundary does not cancel (holes, misoriented faces; vertices are matched by
//! exact position, so unwelded STL soups count as closed when they are).
//!
//! Costs (measured on a shared 2-core EPYC VM under load, CPU time): building is O(n log n), 0.06 s for
//! 75k triangles, 0.25 s for 328k. value() is O(log n) typical: about 7 µs on the 75k-triangle bunny for
//! queries in grid order, 11–16 µs for random ones (cache-bound: the tree and triangles are ~6 MB);
//! about 1 µs when the data stay in cache. All queries are const and thread-safe: parallelise over points.
class MeshField final : public ScalarField {
public:
    //! Builds the BVH and the winding-number expansion of `soup`.
    //! \throw std::invalid_argument if the soup has no triangle (no face with ≥ 3 vertices), a face index
    //! out of range, or a non-finite position used by a face.
    explicit MeshField(const PolygonSoup& soup);

    double value(const glm::dvec3& p) const override;
    glm::dvec3 gradient(const glm::dvec3& p) const override;
    //! The bounding box of the mesh scaled by 1.05 about its centre (each side moves out by 2.5% of its size).
    Box bounds() const override;
    double lipschitz() const override { return 1.0; }
    bool sign_may_jump() const override { return open_; }

    //! The generalized winding number w(p) = Σ Ω_t(p) / 4π: ≈ 1 inside, ≈ 0 outside a closed outward-oriented
    //! mesh (−1 inside an inward-oriented one), fractional near holes. Nodes with |c − p| > β r (β = 2) use
    //! Barill's far-field expansion to second order, the other leaves the exact solid angles. Measured error
    //! against winding_number_exact() on random points of the bbox: mean 0.005–0.013, max 0.03–0.07 (bunny,
    //! lion, head, dragon, icosphere) — far below the 1/2 that decides the sign.
    double winding_number(const glm::dvec3& p) const;

    //! True when |winding_number(p)| ≥ 1/2: the side value() reports as negative.
    bool inside(const glm::dvec3& p) const;

    //! Exact winding number: the plain sum over all triangles, O(n). For tests and checks.
    double winding_number_exact(const glm::dvec3& p) const;

    //! The exact unsigned distance from p to the triangles; the closest point goes to *closest if given.
    double unsigned_distance(const glm::dvec3& p, glm::dvec3* closest = nullptr) const;

    //! Number of triangles after fan triangulation.
    std::size_t n_triangles() const { return tris_.size(); }

private:
    struct Triangle {
        glm::dvec3 a, b, c;
    };
    //! Inner BVH node: the boxes of its two children (floats rounded outwards, so they still bound) and the
    //! references to them; one cache line decides which children to visit. A reference with kLeafBit set
    //! names leaves_[ref & ~kLeafBit], otherwise nodes_[ref].
    struct alignas(64) Node {
        float lo[2][3], hi[2][3];
        std::uint32_t child[2];
    };
    static constexpr std::uint32_t kLeafBit = 0x80000000u;
    //! A leaf: the triangles tris_[first, first + count).
    struct Leaf {
        std::uint32_t first, count;
    };
    //! Far-field data of a subtree (Barill et al. 2018): expansion point c (area-weighted centroid), radius r
    //! of the ball about c holding its triangles, first-order term N = Σ area-weighted normals N_t,
    //! second-order tensor T = Σ (centroid_t − c) ⊗ N_t (T[i][j] = (centroid_t − c)_i N_t,j).
    struct Expansion {
        glm::dvec3 c{0.0}, N{0.0};
        double r = 0.0;
        double T[3][3] = {};
    };
    struct Hit {
        double d2;
        glm::dvec3 point;
        std::uint32_t tri;
    };

    std::uint32_t build_subtree(std::vector<std::uint32_t>& order, const std::vector<glm::dvec3>& centroids,
                                std::uint32_t begin, std::uint32_t end, Box& box, std::vector<Leaf>& node_ranges);
    Expansion expansion_of(std::uint32_t first, std::uint32_t count) const;
    const Expansion& expansion(std::uint32_t ref) const;
    Hit closest_hit(const glm::dvec3& p) const;
    void test_leaf(const glm::dvec3& p, const Leaf& leaf, Hit& best) const;

    std::vector<Triangle> tris_;  // reordered so that every leaf's triangles are contiguous
    std::vector<Node> nodes_;
    std::vector<Leaf> leaves_;
    std::vector<Expansion> node_expansions_, leaf_expansions_;
    std::uint32_t root_ = 0;
    Box bbox_;
    bool open_ = false;  // the oriented boundary chain does not vanish (see sign_may_jump)
};

}  // namespace geolab
