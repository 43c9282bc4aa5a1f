#include "geolab/polygonize.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace geolab {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
constexpr double kClamp = 1e-9;

// A cube corner or an edge direction as 3 bits: bit 0 = x, bit 1 = y, bit 2 = z. Every edge of the Freudenthal
// triangulation joins a lattice point u to u + d with d one of the 7 non-zero bit patterns.
struct Tet {
    std::array<int, 4> corner;  // cube corners, positively oriented: det(c1 − c0, c2 − c0, c3 − c0) > 0
};

// The 6 tetrahedra of a cube: the paths 0 → e_p → e_p + e_q → 7 over the permutations (p, q, r) of the axes.
// det(e_p, e_p + e_q, e_p + e_q + e_r) = sign of the permutation, so odd ones swap their first two corners.
constexpr std::array<Tet, 6> kTets = {{
    {{0, 1, 3, 7}},  // x, y, z (even)
    {{1, 0, 5, 7}},  // x, z, y (odd)
    {{2, 0, 3, 7}},  // y, x, z (odd)
    {{0, 2, 6, 7}},  // y, z, x (even)
    {{0, 4, 5, 7}},  // z, x, y (even)
    {{4, 0, 6, 7}},  // z, y, x (odd)
}};

// Even permutations of (0, 1, 2, 3) that put each index first: re-labelling a positive tetrahedron by one keeps
// it positive.
constexpr std::array<std::array<int, 4>, 4> kEvenFirst = {{{0, 1, 2, 3}, {1, 0, 3, 2}, {2, 0, 1, 3}, {3, 0, 2, 1}}};

std::string point_text(const glm::dvec3& p) {
    std::ostringstream s;
    s.precision(17);
    s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
    return s.str();
}

// The vertex ids of one layer of lattice points: per point, one id per edge direction d of the layer.
class EdgeLayer {
public:
    EdgeLayer(int nx, int ny) : nx_(nx + 1), ids_(static_cast<std::size_t>(nx + 1) * (ny + 1) * 8, kNone) {}
    std::uint32_t& at(int i, int j, int d) { return ids_[(static_cast<std::size_t>(j) * nx_ + i) * 8 + d]; }
    void clear() { std::fill(ids_.begin(), ids_.end(), kNone); }

private:
    int nx_;
    std::vector<std::uint32_t> ids_;
};

}  // namespace

PolygonizeLattice polygonize_lattice(const Box& box, int resolution) {
    const glm::dvec3 size = box.size();
    for (int a = 0; a < 3; ++a) {
        if (!std::isfinite(box.lo[a]) || !std::isfinite(box.hi[a]))
            throw std::invalid_argument("polygonize: the box " + point_text(box.lo) + " – " + point_text(box.hi) +
                                        " is not finite");
        if (!(size[a] > 0.0))
            throw std::invalid_argument("polygonize: the box " + point_text(box.lo) + " – " + point_text(box.hi) +
                                        " has a side of length ≤ 0");
    }
    if (resolution < 1 || resolution > 4096)
        throw std::invalid_argument("polygonize: resolution " + std::to_string(resolution) +
                                    " is outside [1, 4096] (cells along the box's longest side)");
    PolygonizeLattice lattice;
    lattice.lo = box.lo;
    lattice.h = std::max({size.x, size.y, size.z}) / resolution;
    for (int a = 0; a < 3; ++a) {
        // the longest side gets exactly `resolution` cells; the others enough to cover their side
        const double n = std::ceil(size[a] / lattice.h - 1e-9);
        lattice.cells[a] = std::max(1, std::min(resolution, static_cast<int>(n)));
    }
    return lattice;
}

PolygonSoup polygonize(const ScalarField& f, const Box& box, int resolution, double iso) {
    if (!std::isfinite(iso)) throw std::invalid_argument("polygonize: the iso-value is not finite");
    const PolygonizeLattice lattice = polygonize_lattice(box, resolution);
    const int nx = lattice.cells.x, ny = lattice.cells.y, nz = lattice.cells.z;
    const double h = lattice.h;
    auto point = [&](int i, int j, int k) { return lattice.lo + h * glm::dvec3(i, j, k); };

    const std::size_t layer_points = static_cast<std::size_t>(nx + 1) * (ny + 1);
    auto sample_layer = [&](int k, std::vector<double>& out) {
        out.resize(layer_points);
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i) {
                const glm::dvec3 p = point(i, j, k);
                const double v = f.value(p);
                if (std::isnan(v))
                    throw std::invalid_argument("polygonize: the field is NaN at " + point_text(p));
                out[static_cast<std::size_t>(j) * (nx + 1) + i] = v;
            }
    };

    PolygonSoup soup;
    auto add_vertex = [&](const glm::dvec3& p0, double f0, const glm::dvec3& p1, double f1) {
        if (soup.positions.size() >= kNone) throw std::length_error("polygonize: more than 2^32 - 1 vertices");
        double t = (iso - f0) / (f1 - f0);  // f0 and f1 are on different sides of iso, so f1 != f0
        t = std::clamp(t, kClamp, 1.0 - kClamp);
        soup.positions.push_back(p0 + t * (p1 - p0));
        return static_cast<std::uint32_t>(soup.positions.size() - 1);
    };

    std::vector<double> below, above;  // the samples of layers k and k + 1
    EdgeLayer plane_lo(nx, ny), plane_hi(nx, ny), rising(nx, ny);
    auto value = [&](const std::vector<double>& layer, int i, int j) {
        return layer[static_cast<std::size_t>(j) * (nx + 1) + i];
    };
    // Vertices on the edges that lie in layer k (directions x, y, xy), given that layer's samples.
    auto fill_plane = [&](EdgeLayer& plane, const std::vector<double>& s, int k) {
        plane.clear();
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i) {
                const bool in0 = value(s, i, j) < iso;
                for (int d = 1; d <= 3; ++d) {
                    const int i1 = i + (d & 1), j1 = j + ((d >> 1) & 1);
                    if (i1 > nx || j1 > ny) continue;
                    if ((value(s, i1, j1) < iso) == in0) continue;
                    plane.at(i, j, d) =
                        add_vertex(point(i, j, k), value(s, i, j), point(i1, j1, k), value(s, i1, j1));
                }
            }
    };

    sample_layer(0, below);
    fill_plane(plane_lo, below, 0);
    for (int k = 0; k < nz; ++k) {
        sample_layer(k + 1, above);
        fill_plane(plane_hi, above, k + 1);
        // vertices on the edges from layer k up to layer k + 1 (directions z, xz, yz, xyz)
        rising.clear();
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i) {
                const bool in0 = value(below, i, j) < iso;
                for (int d = 4; d <= 7; ++d) {
                    const int i1 = i + (d & 1), j1 = j + ((d >> 1) & 1);
                    if (i1 > nx || j1 > ny) continue;
                    if ((value(above, i1, j1) < iso) == in0) continue;
                    rising.at(i, j, d) =
                        add_vertex(point(i, j, k), value(below, i, j), point(i1, j1, k + 1), value(above, i1, j1));
                }
            }
        // the surface pieces of each cube's 6 tetrahedra
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                std::array<double, 8> fc;
                int n_in = 0;
                for (int c = 0; c < 8; ++c) {
                    fc[c] = value((c & 4) ? above : below, i + (c & 1), j + ((c >> 1) & 1));
                    n_in += fc[c] < iso;
                }
                if (n_in == 0 || n_in == 8) continue;
                // the vertex on the tetrahedron edge between cube corners a and b (a ⊂ b as bit sets, or b ⊂ a)
                auto edge_vertex = [&](int a, int b) {
                    if ((a & b) != a) std::swap(a, b);
                    const int d = b & ~a;
                    const int ia = i + (a & 1), ja = j + ((a >> 1) & 1);
                    if (a & 4) return plane_hi.at(ia, ja, d);
                    return (d & 4) ? rising.at(ia, ja, d) : plane_lo.at(ia, ja, d);
                };
                for (const Tet& tet : kTets) {
                    int mask = 0;
                    for (int v = 0; v < 4; ++v) mask |= (fc[tet.corner[v]] < iso) << v;
                    const int count = __builtin_popcount(mask);
                    if (count == 0 || count == 4) continue;
                    if (count == 1 || count == 3) {
                        // the lone vertex s (inside when count == 1): triangle (s,p), (s,q), (s,r) for the
                        // positive relabelling (s, p, q, r); its normal points away from s, so flip when s is out
                        const int lone = count == 1 ? __builtin_ctz(mask) : __builtin_ctz(~mask & 15);
                        const auto& o = kEvenFirst[lone];
                        const int s = tet.corner[o[0]];
                        std::uint32_t a = edge_vertex(s, tet.corner[o[1]]), b = edge_vertex(s, tet.corner[o[2]]),
                                      c = edge_vertex(s, tet.corner[o[3]]);
                        if (count == 3) std::swap(b, c);
                        soup.add_face({a, b, c});
                    } else {
                        // two inside (x, y), two outside (z, w) for a positive relabelling (x, y, z, w):
                        // the quad (xz, xw, yw, yz) faces the outside corners
                        std::array<int, 4> o{};
                        int n = 0;
                        for (int v = 0; v < 4; ++v)
                            if (mask >> v & 1) o[n++] = v;
                        for (int v = 0; v < 4; ++v)
                            if (!(mask >> v & 1)) o[n++] = v;
                        // (o0, o1, o2, o3) is a permutation of (0, 1, 2, 3); make it even by swapping the two
                        // outside ones if it is odd
                        int inversions = 0;
                        for (int p = 0; p < 4; ++p)
                            for (int q = p + 1; q < 4; ++q) inversions += o[p] > o[q];
                        if (inversions & 1) std::swap(o[2], o[3]);
                        const int x = tet.corner[o[0]], y = tet.corner[o[1]], z = tet.corner[o[2]],
                                  w = tet.corner[o[3]];
                        const std::uint32_t xz = edge_vertex(x, z), xw = edge_vertex(x, w),
                                            yw = edge_vertex(y, w), yz = edge_vertex(y, z);
                        soup.add_face({xz, xw, yw});
                        soup.add_face({xz, yw, yz});
                    }
                }
            }
        std::swap(below, above);
        std::swap(plane_lo, plane_hi);
    }
    return soup;
}

}  // namespace geolab
