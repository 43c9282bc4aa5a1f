// Given code of lab 08 (read it, do not write it): the grid's geometry, the packed grid's constructor, word-aligned
// slabs, the file wrappers of the .binvox codec, the raw format and the file-backed mode (handout §8).
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <numeric>
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

std::vector<std::int64_t> word_aligned_slabs(const Dims& dims, std::int64_t k0, std::int64_t k1, int parts) {
    if (k0 > k1 || dims.nx < 0 || dims.ny < 0 || parts < 1)
        throw std::invalid_argument("word_aligned_slabs: need k0 <= k1, sizes >= 0 and parts >= 1");
    // a layer is nx·ny bits: q layers (q = 64 / gcd(nx·ny, 64)) are the fewest that fill whole words
    const std::uint64_t layer_bits = std::uint64_t(dims.nx) * std::uint64_t(dims.ny);
    const auto q = std::int64_t(64 / std::gcd(layer_bits % 64, std::uint64_t(64)));
    const std::int64_t n = k1 - k0, share = (n + parts - 1) / parts, per = (share + q - 1) / q * q;
    std::vector<std::int64_t> b{k0};
    for (std::int64_t k = k0 + per; k < k1; k += per) b.push_back(k);
    if (k1 > k0) b.push_back(k1);
    return b;
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

// ---- the raw format -------------------------------------------------------------------------------------------
static_assert(std::endian::native == std::endian::little, "the raw format writes the words as they are in memory");

namespace {

constexpr char raw_magic[8] = {'G', 'L', 'V', 'O', 'X', 'R', 'A', 'W'};
constexpr std::size_t raw_trailer_bytes = 40;

std::array<char, raw_trailer_bytes> raw_trailer(const Dims& d, std::uint64_t count) {
    std::array<char, raw_trailer_bytes> t{};
    std::memcpy(t.data(), raw_magic, 8);
    const std::int64_t v[4] = {d.nx, d.ny, d.nz, std::int64_t(count)};
    std::memcpy(t.data() + 8, v, sizeof v);
    return t;
}

std::uint64_t popcount_words(const std::uint64_t* w, std::size_t n) {
    std::uint64_t c = 0;
    for (std::size_t i = 0; i < n; ++i) c += std::uint64_t(std::popcount(w[i]));
    return c;
}

// An output file that reports its failures as IoError.
struct RawWriter {
    std::filesystem::path path;
    std::ofstream out;
    explicit RawWriter(const std::filesystem::path& p) : path(p), out(p, std::ios::binary) {
        if (!out) throw IoError(path.string(), 0, "cannot open for writing");
    }
    void write(const void* data, std::size_t bytes) {
        out.write(static_cast<const char*>(data), std::streamsize(bytes));
        if (!out) throw IoError(path.string(), 0, "write failed (disk full?)");
    }
    void close() {
        out.close();
        if (!out) throw IoError(path.string(), 0, "write failed when closing");
    }
};

}  // namespace

void write_raw(const std::filesystem::path& path, const BitGrid& grid) {
    RawWriter w(path);
    w.write(grid.words.data(), grid.words.size() * 8);
    const auto t = raw_trailer(grid.dims, popcount_words(grid.words.data(), grid.words.size()));
    w.write(t.data(), t.size());
    w.close();
}

BitGrid read_raw(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) throw IoError(name, 0, "cannot open");
    const auto size = std::uint64_t(std::streamoff(in.tellg()));
    if (size < raw_trailer_bytes) throw IoError(name, 0, "shorter than the 40-byte trailer");
    std::array<char, raw_trailer_bytes> t{};
    in.seekg(std::streamoff(size - raw_trailer_bytes));
    in.read(t.data(), std::streamsize(t.size()));
    if (!in) throw IoError(name, 0, "cannot read the trailer");
    if (std::memcmp(t.data(), raw_magic, 8) != 0) throw IoError(name, 0, "no GLVOXRAW trailer: not a raw voxel file");
    std::int64_t v[4];
    std::memcpy(v, t.data() + 8, sizeof v);
    BitGrid g;
    try {
        g = BitGrid(Dims{v[0], v[1], v[2]});
    } catch (const std::invalid_argument& e) {
        throw IoError(name, 0, std::string("the trailer's dims: ") + e.what());
    }
    if (size != g.words.size() * 8 + raw_trailer_bytes)
        throw IoError(name, 0, std::to_string(size) + " bytes, but dims " + std::to_string(v[0]) + " x " +
                                   std::to_string(v[1]) + " x " + std::to_string(v[2]) + " need " +
                                   std::to_string(g.words.size() * 8 + raw_trailer_bytes));
    in.seekg(0);
    in.read(reinterpret_cast<char*>(g.words.data()), std::streamsize(g.words.size() * 8));
    if (!in) throw IoError(name, 0, "read failed");
    const std::uint64_t used = std::uint64_t(g.dims.count()) % 64;
    if (used != 0 && (g.words.back() >> used) != 0) throw IoError(name, 0, "a bit past the last voxel is set");
    const std::uint64_t count = popcount_words(g.words.data(), g.words.size());
    if (count != std::uint64_t(v[3]))
        throw IoError(name, 0, "the trailer says " + std::to_string(v[3]) + " set voxels, the data holds " +
                                   std::to_string(count));
    return g;
}

// ---- the file-backed mode ----------------------------------------------------------------------------------------
namespace {

// The fan triangles of a mesh with their z-ranges, to pick each slab's quickly.
struct FanTriangles {
    std::vector<std::array<std::uint32_t, 3>> vertices;
    std::vector<double> zmin, zmax;
    explicit FanTriangles(const PolygonSoup& mesh) {
        for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
            const auto vs = mesh.face(f);
            for (std::size_t t = 1; t + 1 < vs.size(); ++t) {
                const double za = mesh.positions[vs[0]].z, zb = mesh.positions[vs[t]].z, zc = mesh.positions[vs[t + 1]].z;
                vertices.push_back({vs[0], vs[t], vs[t + 1]});
                zmin.push_back(std::min({za, zb, zc}));
                zmax.push_back(std::max({za, zb, zc}));
            }
        }
    }
    // Those whose z-range meets [z0, z1], as a soup of their own (the same vertices, in the same order, so each
    // triangle is decided exactly as in the whole mesh).
    PolygonSoup between(const PolygonSoup& mesh, double z0, double z1) const {
        PolygonSoup out;
        out.positions = mesh.positions;
        for (std::size_t t = 0; t < vertices.size(); ++t)
            if (zmax[t] >= z0 && zmin[t] <= z1) out.add_face({vertices[t][0], vertices[t][1], vertices[t][2]});
        return out;
    }
};

}  // namespace

FileVoxels voxelize_to_file(const PolygonSoup& mesh, const Dims& dims, bool solid, const std::filesystem::path& path,
                            int threads, std::int64_t slab_layers,
                            const std::function<void(std::int64_t, std::int64_t)>& progress) {
    if (dims.nx < 0 || dims.ny < 0 || dims.nz < 0) throw std::invalid_argument("voxelize_to_file: a negative size");
    const BitGrid layer(Dims{dims.nx, dims.ny, 1});  // checks nx·ny (one layer, not the whole grid: no memory)
    const std::uint64_t layer_bits = std::uint64_t(dims.nx) * std::uint64_t(dims.ny);
    if (layer_bits != 0 && std::uint64_t(dims.nz) > (std::uint64_t(1) << 62) / layer_bits)
        throw std::invalid_argument("voxelize_to_file: more than 2^62 voxels");
    if (layer_bits % 64 != 0)
        throw std::invalid_argument("voxelize_to_file: nx * ny = " + std::to_string(layer_bits) +
                                    " is not a multiple of 64 (each layer must be whole words: res a multiple of 8)");
    if (slab_layers < 1 || threads < 1) throw std::invalid_argument("voxelize_to_file: need slab_layers >= 1 and threads >= 1");
    check_soup(mesh);
    FileVoxels r;
    r.slab_layers = slab_layers;
    if (solid) {
        r.boundary_edges = count_boundary_edges(mesh);
        if (r.boundary_edges != 0)
            throw std::invalid_argument("voxelize_to_file: the mesh has " + std::to_string(r.boundary_edges) +
                                        " boundary edges; the file-backed solid needs a closed mesh (parity), since "
                                        "the outside flood fill needs the whole grid");
    }
    const std::size_t layer_words = layer_bits / 64;
    const std::int64_t total = (dims.nz + slab_layers - 1) / slab_layers;
    const FanTriangles triangles(mesh);
    RawWriter out(path);
    std::vector<std::uint64_t> carry(layer_words, 0);  // solid: the z parity of the layer below the slab
    for (std::int64_t k0 = 0; k0 < dims.nz; k0 += slab_layers) {
        const std::int64_t k1 = std::min(dims.nz, k0 + slab_layers);
        // the triangles that reach the slab's voxels, their rays or their columns
        const PolygonSoup near = triangles.between(mesh, double(k0), double(k1));
        BitGrid slab;
        if (!solid) {
            slab = voxelize_surface_layers(near, dims, k0, k1, threads);
        } else {
            const BitGrid x = parity_fill_layers(near, dims, 0, k0, k1, threads);
            const BitGrid y = parity_fill_layers(near, dims, 1, k0, k1, threads);
            // Along z: the parity at layer k (k0 <= k < k1) is the carried parity of layer k0 − 1 XOR the crossings
            // between the centres of layers k0 − 1 and k, which only triangles reaching [k0 − 1, k1] can make: with
            // those, z(k) = carry ^ below(k0 − 1) ^ below(k), and their crossings under layer k0 − 1 cancel.
            // The first slab has no layer below: every triangle under it counts, and its parity is exact as it is.
            BitGrid z;
            if (k0 == 0) {
                z = parity_fill_layers(triangles.between(mesh, -std::numeric_limits<double>::infinity(), double(k1)),
                                       dims, 2, 0, k1, threads);
            } else {
                const BitGrid below = parity_fill_layers(triangles.between(mesh, double(k0 - 1), double(k1)), dims, 2,
                                                         k0 - 1, k1, threads);
                z = BitGrid(Dims{dims.nx, dims.ny, k1 - k0});
                for (std::int64_t t = 0; t < k1 - k0; ++t)
                    for (std::size_t w = 0; w < layer_words; ++w)
                        z.words[std::size_t(t) * layer_words + w] =
                            carry[w] ^ below.words[w] ^ below.words[std::size_t(t + 1) * layer_words + w];
            }
            std::copy(z.words.end() - std::ptrdiff_t(layer_words), z.words.end(), carry.begin());
            slab = BitGrid(Dims{dims.nx, dims.ny, k1 - k0});
            for (std::size_t w = 0; w < slab.words.size(); ++w) {
                const std::uint64_t all = x.words[w] & y.words[w] & z.words[w], any = x.words[w] | y.words[w] | z.words[w];
                slab.words[w] = all;
                if (any != all) r.axis_disagreements += std::uint64_t(std::popcount(any & ~all));
            }
        }
        out.write(slab.words.data(), slab.words.size() * 8);
        r.voxels += popcount_words(slab.words.data(), slab.words.size());
        ++r.slabs;
        if (progress) progress(r.slabs, total);
    }
    const auto t = raw_trailer(dims, r.voxels);
    out.write(t.data(), t.size());
    out.close();
    r.bytes = std::uint64_t(dims.count() / 64) * 8 + raw_trailer_bytes;
    return r;
}

}  // namespace geolab::voxels
