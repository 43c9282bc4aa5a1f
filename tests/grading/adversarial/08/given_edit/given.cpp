// ADVERSARIAL CASE given_edit: lab 08's given code (public: it ships to students), changed: BitGrid(Dims) makes one
// word too many and fit_grid pads one voxel less. The grader compiles the course's given.cpp whatever a submission
// holds (and says the changes are ignored); were this copy used, the tests' own grids and meshes in the student's
// process would differ from the judge's. Honest: the case without this file (bitgrid.cpp's Task 1 points).
// Given code of lab 08 (read it, do not write it): the grid's geometry, the packed grid's constructor, the file
// wrappers of the .binvox codec.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>

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
    words.assign(std::size_t((std::uint64_t(n) + 63) / 64) + 1, 0);
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
    g.voxel_size = longest / double(res - 2 * pad + 1);
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
    std::ifstream in(path, std::ios::binary);
    if (!in) throw IoError(path.string(), 0, "cannot open");
    constexpr std::uintmax_t max_bytes = (std::uintmax_t(64) << 20) + 4096;
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (!ec && size > max_bytes) throw IoError(path.string(), 0, "larger than 64 MiB: not read");
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw IoError(path.string(), 0, "read failed");
    return decode_binvox(bytes, path.string());
}

}  // namespace geolab::voxels
