// Given code of lab 08 (read it, do not write it): the grid's geometry, the packed grid's constructor, the file
// wrappers of the .binvox codec.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>

#include "geolab/io.hpp"
#include "geolab/voxels.hpp"

namespace geolab::voxels {

BitGrid::BitGrid(Dims d) : dims(d) {
    if (d.nx < 0 || d.ny < 0 || d.nz < 0) throw std::invalid_argument("BitGrid: a negative size");
    constexpr std::int64_t max_voxels = std::int64_t(1) << 40;
    // the product, checked step by step against the cap (so it never overflows)
    std::int64_t n = d.nx;
    for (std::int64_t f : {d.ny, d.nz}) {
        if (f != 0 && n > max_voxels / f) throw std::invalid_argument("BitGrid: more than 2^40 voxels");
        n *= f;
    }
    words.assign(std::size_t((std::uint64_t(n) + 63) / 64), 0);
}

Grid fit_grid(const PolygonSoup& mesh, std::int64_t res, int pad) {
    if (mesh.positions.empty()) throw std::invalid_argument("fit_grid: the mesh has no vertex");
    if (res < 1 || pad < 0 || res <= 2 * std::int64_t(pad))
        throw std::invalid_argument("fit_grid: need res >= 1 and res > 2 * pad (res " + std::to_string(res) + ", pad " +
                                    std::to_string(pad) + ")");
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const glm::dvec3& p : mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const glm::dvec3 size = hi - lo;
    const double longest = std::max({size.x, size.y, size.z});
    if (!(longest > 0) || !std::isfinite(longest)) throw std::invalid_argument("fit_grid: the mesh is a single point");
    Grid g;
    g.voxel_size = longest / double(res - 2 * pad);
    g.dims = {res, res, res};
    const glm::dvec3 centre = 0.5 * (lo + hi);
    g.origin = centre - 0.5 * double(res) * g.voxel_size;
    return g;
}

PolygonSoup to_grid_units(const PolygonSoup& mesh, const Grid& grid) {
    PolygonSoup out = mesh;
    for (glm::dvec3& p : out.positions) p = (p - grid.origin) / grid.voxel_size;
    return out;
}

void write_binvox(const std::filesystem::path& path, const Binvox& file) {
    const std::string bytes = encode_binvox(file);
    std::ofstream out(path, std::ios::binary);
    if (!out) throw IoError(path.string(), 0, "cannot open for writing");
    out.write(bytes.data(), std::streamsize(bytes.size()));
    if (!out) throw IoError(path.string(), 0, "write failed");
}

Binvox read_binvox(const std::filesystem::path& path) {
    // lib's read_text_file: a FIFO (it blocked forever), /dev/zero (it grew without bound) or a directory is refused
    const std::string bytes = read_text_file(path, ReadOptions{.max_file_bytes = (std::uint64_t(64) << 20) + 4096});
    return decode_binvox(bytes, path.string());
}

}  // namespace geolab::voxels
