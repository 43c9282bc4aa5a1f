#pragma once
//! \file render/slicer.hpp
//! The graphics pipeline as a voxelizer's tool (lab 08, handout §9): a headless GL 3.3 core rasterizer (OSMesa,
//! software) that XORs triangles into a one-bit-per-pixel image, keeping only the fragments whose depth lies in a
//! slab. The GL context, the shaders, the vertex buffer and the read-back live here; the camera, which triangles
//! to draw for which slab and what the image means are the caller's.
//!
//!     geolab::render::SliceRasterizer r(64, 64);   // a 64 × 64 image, every pixel 0
//!     r.set_triangles(corners, camera);              // 3 corners per triangle; clip = camera · (p, 1)
//!     r.draw_xor(0, n, -INFINITY, 0.5f);             // flip the pixels the triangles cross at depth ≤ 0.5
//!     std::vector<std::uint8_t> bits = r.read();     // 0 or 1 per pixel, row by row from the bottom
//!
//! **What decides a fragment.** Window coordinates x = (clip.x + 1)·width/2, y = (clip.y + 1)·height/2 and depth =
//! clip.z are computed in double on the CPU; x and y are rounded to the rasterizer's sub-pixel lattice (multiples
//! of 2^−subpixel_bits() pixel: 1/256 with llvmpipe — the rasterizer would round them so anyway; doing it here
//! lets the depth test below see the very triangle the rasterizer covers); then all three are rounded to float.
//! So every corner moves by at most half a lattice step in x and y (and a float rounding).
//! - *Coverage* (GL's rasterizer): a triangle covers pixel (x, y) when the pixel's centre (x + ½, y + ½) lies in
//!   its projection, decided exactly (fixed point). A centre exactly on an edge is decided as if it were moved by
//!   (ε, ε²), ε → 0⁺ (llvmpipe's fill rule, which tests/lib/test_slicer.cpp checks): an edge shared by two
//!   triangles on either side covers each centre once, a triangle of zero area covers nothing. A triangle that
//!   reaches outside the image is clipped by GL; the corners it makes on the image's border are snapped too, so
//!   its clipped edges may tilt by a sub-pixel step (shared edges alike: still each centre once).
//! - *Depth* (this class's fragment shader): the triangle crosses the pixel's column at depth d with lo < d ≤ hi
//!   when the point (centre, hi) lies on the far side of its plane (towards +depth) and (centre, lo) does not. A
//!   point exactly on the plane is decided as if moved by a perturbation whose x component is infinitely larger
//!   than its y component (the fill rule's), with the depth component at place depth_rank() among them: (ε, ε²,
//!   ε³) in (x, y, depth) for rank 2 (the default), (ε, ε³, ε²) for rank 1, (ε², ε³, ε) for rank 0. The test is evaluated in float with the triangle's first corner and normal
//!   (b − a) × (c − a): exact when those products are (small coordinates with few fractional bits), otherwise
//!   correct except for points within a few float roundings of the plane.
//! - No near/far clipping (GL_DEPTH_CLAMP), no culling, no depth buffer: every triangle is drawn whatever its
//!   depth or orientation; only the slab test selects by depth.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>  // glm::dmat4
#include <glm/vec3.hpp>

namespace geolab::render {

class SliceRasterizer {
public:
    //! A GL 3.3 core context (OSMesa) drawing into a width × height image, every pixel 0, no triangles. The
    //! context is made current on the calling thread whenever a member is called.
    //! \throw std::invalid_argument when width or height is not in [1, 8192]; std::runtime_error when OSMesa
    //! cannot create the context or a shader does not compile (the message says which).
    SliceRasterizer(int width, int height);
    ~SliceRasterizer();
    SliceRasterizer(const SliceRasterizer&) = delete;
    SliceRasterizer& operator=(const SliceRasterizer&) = delete;

    int width() const;
    int height() const;

    //! Replaces the triangles: corners[3t], corners[3t + 1], corners[3t + 2] are triangle t, seen through `camera`
    //! (clip = camera · (p, 1), applied here in double precision). The camera must be affine (last row
    //! (0, 0, 0, 1)): clip z is then the depth, in whatever units the camera gives it (near/far clipping is off).
    //! \throw std::invalid_argument when corners.size() is not a multiple of 3, the camera is not affine, a window
    //! coordinate is not a finite float, or there are more than 2^31 − 1 corners.
    void set_triangles(std::span<const glm::dvec3> corners, const glm::dmat4& camera);
    //! The number of triangles set.
    std::size_t triangle_count() const;

    //! Where the depth's component stands in the perturbation that decides points exactly on a triangle's plane
    //! (see the file comment): 0 = largest, 1 = between x and y, 2 = smallest (the default). A voxelizer slicing
    //! along axis a whose other axes are x, y in increasing order gets the perturbation (ε, ε², ε³) in world
    //! (x, y, z) with rank a. \throw std::invalid_argument when rank is not 0, 1 or 2.
    void set_depth_rank(int rank);
    int depth_rank() const;

    //! Sets every pixel to 0.
    void clear();

    //! For each triangle t with first ≤ t < first + count and each pixel it covers where it crosses the pixel's
    //! column at a depth d with lo < d ≤ hi (see the file comment for both rules): flips that pixel (0 ↔ 1,
    //! glLogicOp(GL_XOR)). A pixel is flipped once per such triangle, so after several calls each pixel holds the
    //! parity of all the crossings drawn. lo = −∞ keeps every crossing with d ≤ hi. Slabs (lo, hi] that share
    //! their bounds never both keep a crossing. \throw std::out_of_range when first + count exceeds
    //! triangle_count(); std::invalid_argument when lo or hi is NaN.
    void draw_xor(std::size_t first, std::size_t count, float lo, float hi);

    //! The image: width · height values 0 or 1; pixel (x, y) at [y · width + x], row y = 0 at the bottom
    //! (clip y = −1). Waits for the drawing to finish.
    std::vector<std::uint8_t> read();

    //! The sub-pixel precision of the rasterizer, in bits (corners snap to multiples of 2^−bits pixel), as the GL
    //! implementation reports it (GL_SUBPIXEL_BITS; 8 with llvmpipe).
    int subpixel_bits() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace geolab::render
