// Task 4: marching cubes (handout §5).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include "geolab/blobby.hpp"
#include "geolab/mc_tables.hpp"

namespace geolab::blobby {

namespace {
// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.

// The tie rule's crossing parameter: t = (iso − f0)/(f1 − f0), clamped to [δ, 1 − δ] (blobby.hpp, Task 4).
double crossing_parameter(double f0, double f1, double iso) {
    return std::clamp((iso - f0) / (f1 - f0), crossing_margin, 1.0 - crossing_margin);
}

// The errors marching_cubes promises, before any work.
void check_lattice(const Lattice& L, double iso) {
    const glm::ivec3 n = L.n;
    if (n.x < 2 || n.y < 2 || n.z < 2) throw std::invalid_argument("marching_cubes: n must be >= 2 on every axis");
    const std::size_t N = std::size_t(n.x) * n.y * n.z;
    if (L.values.size() != N)
        throw std::invalid_argument("marching_cubes: " + std::to_string(L.values.size()) + " values for " +
                                    std::to_string(N) + " samples");
    if (L.gradients.size() != N)
        throw std::invalid_argument("marching_cubes: " + std::to_string(L.gradients.size()) +
                                    " gradients for " + std::to_string(N) + " samples");
    if (!(L.h > 0) || !std::isfinite(L.h)) throw std::invalid_argument("marching_cubes: h must be finite and > 0");
    if (!std::isfinite(iso)) throw std::invalid_argument("marching_cubes: iso is not finite");
    // The tie rule's margin δ·h must outweigh a rounding step of every coordinate: |coordinate| ≤ 2^30 h.
    const glm::dvec3 far(std::ldexp(L.h, 30)), last = L.origin + L.h * glm::dvec3(n - 1);
    if (!glm::all(glm::lessThanEqual(glm::abs(L.origin), far)) || !glm::all(glm::lessThanEqual(glm::abs(last), far)))
        throw std::invalid_argument("marching_cubes: the lattice reaches more than 2^30 cells (h = " +
                                    std::to_string(L.h) + ") from 0: vertices would round onto lattice points");
}

// Marching cubes slab by slab: the cubes between planes z = k and z = k + 1 need only those two planes' samples
// and the vertices on their edges, so the vertex ids live in arrays of one plane each (no map over the lattice),
// and a cube row whose four sample rows lie wholly on one side is skipped at once.
class SlabMarcher {
public:
    SlabMarcher(const Lattice& L, double iso, McMesh& mesh)
        : L_(L), iso_(iso), mesh_(mesh), nx_(L.n.x), ny_(L.n.y), rising_(std::size_t(nx_) * ny_) {}

    void run() {
        load_plane(0, lo_);
        make_plane_vertices(0, lo_);
        for (int k = 0; k + 1 < L_.n.z; ++k) {
            load_plane(k + 1, hi_);
            make_plane_vertices(k + 1, hi_);
            make_rising_vertices(k);
            march_slab();
            std::swap(lo_, hi_);
        }
    }

private:
    // A row's samples wholly outside, wholly inside, or both.
    enum Row : std::uint8_t { all_outside, all_inside, mixed };

    // One plane z = k: which samples are inside, each row's summary, and the vertex ids of the crossed edges
    // along x and y that start at each sample (written for crossed edges only, and only those are read).
    struct Plane {
        std::vector<std::uint8_t> inside;  // inside[i + nx j] = f < iso
        std::vector<Row> rows;             // rows.at(j) (checked: one check a row costs nothing)
        std::vector<std::uint32_t> x_edge, y_edge;
    };

    std::size_t sample(int i, int j, int k) const { return i + std::size_t(nx_) * (j + std::size_t(ny_) * k); }
    glm::dvec3 position(int i, int j, int k) const { return L_.origin + L_.h * glm::dvec3(i, j, k); }
    static bool same_uniform(Row a, Row b) { return a == b && a != mixed; }

    // Classifies plane k (the tie rule: f == iso is outside) and checks that its values are finite.
    void load_plane(int k, Plane& P) const {
        P.inside.resize(std::size_t(nx_) * ny_);
        P.rows.resize(ny_);
        P.x_edge.resize(P.inside.size());
        P.y_edge.resize(P.inside.size());
        for (int j = 0; j < ny_; ++j) {
            int count = 0;
            for (int i = 0; i < nx_; ++i) {
                const double f = L_.values[sample(i, j, k)];
                if (!std::isfinite(f))
                    throw std::invalid_argument("marching_cubes: sample (" + std::to_string(i) + ", " +
                                                std::to_string(j) + ", " + std::to_string(k) + ") is not finite");
                const bool in = f < iso_;
                P.inside[i + std::size_t(nx_) * j] = in;
                count += in;
            }
            P.rows.at(j) = count == 0 ? all_outside : count == nx_ ? all_inside : mixed;
        }
    }

    // The vertex on the crossed lattice edge from sample (i, j, k) one step along `axis`: edge_crossing places
    // it, the gradient interpolated with the same t gives its normal.
    std::uint32_t add_vertex(int i, int j, int k, int axis) {
        glm::ivec3 q1(i, j, k);
        ++q1[axis];
        const std::size_t s0 = sample(i, j, k), s1 = sample(q1.x, q1.y, q1.z);
        const double f0 = L_.values[s0], f1 = L_.values[s1];
        const double t = crossing_parameter(f0, f1, iso_);
        const glm::dvec3 g = L_.gradients[s0] + t * (L_.gradients[s1] - L_.gradients[s0]);
        const double len = glm::length(g);
        const auto id = std::uint32_t(mesh_.soup.positions.size());
        mesh_.soup.positions.push_back(edge_crossing(position(i, j, k), position(q1.x, q1.y, q1.z), f0, f1, iso_));
        mesh_.normals.push_back(len > 0 ? g / len : glm::dvec3(0.0));
        return id;
    }

    // Vertices on the crossed edges along x and y in plane k.
    void make_plane_vertices(int k, Plane& P) {
        for (int j = 0; j < ny_; ++j) {
            const std::size_t row = std::size_t(nx_) * j;
            if (P.rows.at(j) == mixed)
                for (int i = 0; i + 1 < nx_; ++i)
                    if (P.inside[row + i] != P.inside[row + i + 1]) P.x_edge[row + i] = add_vertex(i, j, k, 0);
            if (j + 1 < ny_ && !same_uniform(P.rows.at(j), P.rows.at(j + 1)))
                for (int i = 0; i < nx_; ++i)
                    if (P.inside[row + i] != P.inside[row + nx_ + i]) P.y_edge[row + i] = add_vertex(i, j, k, 1);
        }
    }

    // Vertices on the crossed edges along z from plane k (lo_) to plane k + 1 (hi_).
    void make_rising_vertices(int k) {
        for (int j = 0; j < ny_; ++j) {
            if (same_uniform(lo_.rows.at(j), hi_.rows.at(j))) continue;
            const std::size_t row = std::size_t(nx_) * j;
            for (int i = 0; i < nx_; ++i)
                if (lo_.inside[row + i] != hi_.inside[row + i]) rising_[row + i] = add_vertex(i, j, k, 2);
        }
    }

    // The vertex id of cube edge e (mc_tables.hpp numbering) of the cube whose lowest sample is (i, j) in lo_.
    std::uint32_t edge_vertex(int e, int i, int j) const {
        const int c = mc_edge_corners[e][0];  // the edge's lower corner
        const std::size_t s = std::size_t(i + (c & 1)) + std::size_t(nx_) * (j + ((c >> 1) & 1));
        const Plane& P = (c & 4) ? hi_ : lo_;
        const std::vector<std::uint32_t>& ids = e < 4 ? P.x_edge : e < 8 ? P.y_edge : rising_;  // along x, y, z
        return ids[s];
    }

    // The triangles of the cubes between lo_ and hi_. The corners of a cube's face x = i, as four bits in the
    // places of corners 0, 2, 4, 6 of the case index; the face x = i + 1 shifted by one gives corners 1, 3, 5, 7.
    void march_slab() {
        std::vector<int>& face = face_;
        face.resize(nx_);
        for (int j = 0; j + 1 < ny_; ++j) {
            if (same_uniform(lo_.rows.at(j), lo_.rows.at(j + 1)) && same_uniform(lo_.rows.at(j), hi_.rows.at(j)) &&
                same_uniform(lo_.rows.at(j), hi_.rows.at(j + 1)))
                continue;  // the four rows lie wholly on one side: no cube of this row is crossed
            const std::size_t row = std::size_t(nx_) * j, up = row + nx_;
            for (int i = 0; i < nx_; ++i)
                face[i] = lo_.inside[row + i] | lo_.inside[up + i] << 2 | hi_.inside[row + i] << 4 |
                          hi_.inside[up + i] << 6;
            for (int i = 0; i + 1 < nx_; ++i) {
                const int index = face[i] | face[i + 1] << 1;  // as cube_index: bit c set for an inside corner
                const int n_triangles = mc_tables.n_triangles[index];
                for (int t = 0; t < n_triangles; ++t) {
                    const auto& e = mc_tables.triangles[index];
                    mesh_.soup.add_face({edge_vertex(e[3 * t], i, j), edge_vertex(e[3 * t + 1], i, j),
                                         edge_vertex(e[3 * t + 2], i, j)});
                }
            }
        }
    }

    const Lattice& L_;
    const double iso_;
    McMesh& mesh_;
    const int nx_, ny_;
    Plane lo_, hi_;                     // planes k and k + 1
    std::vector<std::uint32_t> rising_;  // vertex ids of the crossed edges along z from plane k
    std::vector<int> face_;              // the cube row's faces (march_slab)
};

// END SOLUTION
}  // namespace

int cube_index(const std::array<double, 8>& f, double iso) {
    // BEGIN SOLUTION
    int index = 0;
    for (int c = 0; c < 8; ++c)
        if (f[c] < iso) index |= 1 << c;
    return index;
    // END SOLUTION
}

glm::dvec3 edge_crossing(const glm::dvec3& p0, const glm::dvec3& p1, double f0, double f1, double iso) {
    // BEGIN SOLUTION
    if ((f0 < iso) == (f1 < iso))
        throw std::invalid_argument("edge_crossing: both ends are on the same side of the iso-value (f0 " +
                                    std::to_string(f0) + ", f1 " + std::to_string(f1) + ", iso " +
                                    std::to_string(iso) + ")");
    return p0 + crossing_parameter(f0, f1, iso) * (p1 - p0);
    // END SOLUTION
}

McMesh marching_cubes(const Lattice& lattice, double iso) {
    // BEGIN SOLUTION
    check_lattice(lattice, iso);
    McMesh mesh;
    SlabMarcher(lattice, iso, mesh).run();
    return mesh;
    // END SOLUTION
}

}  // namespace geolab::blobby
