// Task 7: voxelization through the graphics pipeline (handout §9).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "geolab/render/slicer.hpp"
#include "geolab/voxels.hpp"

namespace geolab::voxels {

// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.
namespace {

// The two axes other than `axis`, in increasing order: the image's u (pixel x) and v (pixel y).
constexpr int axis_u[3] = {1, 0, 0}, axis_v[3] = {2, 2, 1};

void check_axis(int axis, const char* where) {
    if (axis < 0 || axis > 2)
        throw std::invalid_argument(std::string(where) + ": axis must be 0, 1 or 2 (got " + std::to_string(axis) + ")");
}

// The slab that holds depth d: d in (k − ½, k + ½] for k = ⌈d − ½⌉, and slab 0 for everything below.
double slab_of(double d) { return std::max(0.0, std::ceil(d - 0.5)); }

}  // namespace
// END SOLUTION

glm::dmat4 slicing_camera(const Dims& dims, int axis) {
    // BEGIN SOLUTION
    check_axis(axis, "slicing_camera");
    if (dims.nx < 1 || dims.ny < 1 || dims.nz < 1)
        throw std::invalid_argument("slicing_camera: every size must be >= 1 (dims " + std::to_string(dims.nx) + " x " +
                                    std::to_string(dims.ny) + " x " + std::to_string(dims.nz) + ")");
    const std::int64_t n[3] = {dims.nx, dims.ny, dims.nz};
    const int u = axis_u[axis], v = axis_v[axis];
    glm::dmat4 m(0.0);  // glm is column-major: m[column][row]
    m[u][0] = 2.0 / double(n[u]);
    m[3][0] = -1.0;
    m[v][1] = 2.0 / double(n[v]);
    m[3][1] = -1.0;
    m[axis][2] = 1.0;
    m[3][3] = 1.0;
    return m;
    // END SOLUTION
}

SlabRange slab_range(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const Dims& dims, int axis) {
    // BEGIN SOLUTION
    check_axis(axis, "slab_range");
    const std::int64_t n = axis == 0 ? dims.nx : axis == 1 ? dims.ny : dims.nz;
    const double lo = std::min({a[axis], b[axis], c[axis]}), hi = std::max({a[axis], b[axis], c[axis]});
    // clamped in double first: a far-away triangle must not overflow the integer conversion
    const double first = std::max(0.0, slab_of(lo) - 1), last = std::min(double(n - 1), slab_of(hi) + 1);
    if (!(first <= last)) return {0, -1};
    return {std::int64_t(first), std::int64_t(last)};
    // END SOLUTION
}

void store_layer(const std::vector<std::uint8_t>& image, int axis, std::int64_t k, BitGrid& grid) {
    // BEGIN SOLUTION
    check_axis(axis, "store_layer");
    const std::int64_t n[3] = {grid.dims.nx, grid.dims.ny, grid.dims.nz};
    const int u = axis_u[axis], v = axis_v[axis];
    if (std::uint64_t(image.size()) != std::uint64_t(n[u]) * std::uint64_t(n[v]))
        throw std::invalid_argument("store_layer: the image has " + std::to_string(image.size()) + " pixels, expected " +
                                    std::to_string(n[u]) + " x " + std::to_string(n[v]));
    if (k < 0 || k >= n[axis])
        throw std::out_of_range("store_layer: layer " + std::to_string(k) + " is not in [0, " + std::to_string(n[axis]) + ")");
    std::int64_t ijk[3];
    ijk[axis] = k;
    for (ijk[v] = 0; ijk[v] < n[v]; ++ijk[v])
        for (ijk[u] = 0; ijk[u] < n[u]; ++ijk[u])
            grid.set(ijk[0], ijk[1], ijk[2], image[std::size_t(ijk[v] * n[u] + ijk[u])] != 0);
    // END SOLUTION
}

BitGrid voxelize_gl(const PolygonSoup& mesh, const Dims& dims, int axis) {
    // BEGIN SOLUTION
    check_axis(axis, "voxelize_gl");
    check_soup(mesh);
    const std::int64_t n[3] = {dims.nx, dims.ny, dims.nz};
    const std::int64_t nu = n[axis_u[axis]], nv = n[axis_v[axis]], na = n[axis];
    if (nu > 8192 || nv > 8192)  // before the grid is allocated
        throw std::invalid_argument("voxelize_gl: an image of " + std::to_string(nu) + " x " + std::to_string(nv) +
                                    " pixels is larger than 8192 x 8192");
    BitGrid grid(dims);
    if (dims.count() == 0) return grid;
    // Step 1: the fan triangles and their slabs; count the triangles of each slab.
    std::vector<std::array<std::uint32_t, 3>> tris;
    for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
        const auto vs = mesh.face(f);
        for (std::size_t t = 1; t + 1 < vs.size(); ++t) tris.push_back({vs[0], vs[t], vs[t + 1]});
    }
    std::vector<SlabRange> ranges(tris.size());
    std::vector<std::size_t> start(std::size_t(na) + 1);  // slab k's triangles: [start[k], start[k + 1])
    for (std::size_t t = 0; t < tris.size(); ++t) {
        const auto& [i, j, l] = tris[t];
        ranges[t] = slab_range(mesh.positions[i], mesh.positions[j], mesh.positions[l], dims, axis);
        for (std::int64_t k = ranges[t].first; k <= ranges[t].last; ++k) ++start[std::size_t(k) + 1];
    }
    std::partial_sum(start.begin(), start.end(), start.begin());
    // Step 2: the corners, grouped by slab (a triangle once per slab it is drawn in).
    std::vector<glm::dvec3> corners(3 * start.back());
    std::vector<std::size_t> next = start;  // the next free place of each slab
    for (std::size_t t = 0; t < tris.size(); ++t)
        for (std::int64_t k = ranges[t].first; k <= ranges[t].last; ++k) {
            const std::size_t s = next[std::size_t(k)]++;
            for (int c = 0; c < 3; ++c) corners[3 * s + c] = mesh.positions[tris[t][c]];
        }
    // Step 3: slab by slab, XOR the crossings into the same image; its parity is layer k.
    render::SliceRasterizer raster{int(nu), int(nv)};
    raster.set_triangles(corners, slicing_camera(dims, axis));
    raster.set_depth_rank(axis);  // ties like parity_fill: c + (ε, ε², ε³) in (x, y, z)
    for (std::int64_t k = 0; k < na; ++k) {
        const float lo = k == 0 ? -std::numeric_limits<float>::infinity() : float(k) - 0.5f, hi = float(k) + 0.5f;
        raster.draw_xor(start[std::size_t(k)], start[std::size_t(k) + 1] - start[std::size_t(k)], lo, hi);
        store_layer(raster.read(), axis, k, grid);
    }
    return grid;
    // END SOLUTION
}

}  // namespace geolab::voxels
