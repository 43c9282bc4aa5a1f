// Task 1: build the half-face mesh from a cell list (handout §3).
#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>

#include "geolab/halfface.hpp"

namespace geolab::halfface {

namespace {
// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.

// "(a b c)": a face's vertices for messages.
std::string face_text(std::span<const std::uint32_t> f) {
    std::ostringstream os;
    os << '(';
    for (std::size_t i = 0; i < f.size(); ++i) os << (i ? " " : "") << f[i];
    os << ')';
    return os.str();
}

// The vertex indices in range and the positions finite (std::invalid_argument otherwise).
void check_indices(const CellList& cl) {
    for (std::size_t v = 0; v < cl.n_vertices(); ++v) {
        const glm::dvec3& p = cl.positions[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw std::invalid_argument("build_mesh: vertex " + std::to_string(v) + " has a position that is not finite");
    }
    if (cl.cell_begin.empty() || cl.face_begin.empty() || cl.cell_begin.back() + 1 != cl.face_begin.size() ||
        cl.face_begin.back() != cl.face_vertices.size())
        throw std::invalid_argument("build_mesh: the cell list's offsets do not match its faces");
    for (std::size_t c = 0; c < cl.n_cells(); ++c) {
        if (cl.cell_begin[c] > cl.cell_begin[c + 1])
            throw std::invalid_argument("build_mesh: cell " + std::to_string(c) + " has decreasing offsets");
        for (std::size_t i = 0; i < cl.n_faces(c); ++i) {
            const std::size_t j = cl.cell_begin[c] + i;
            if (cl.face_begin[j] > cl.face_begin[j + 1])
                throw std::invalid_argument("build_mesh: cell " + std::to_string(c) + " face " + std::to_string(i) +
                                            " has decreasing offsets");
            for (std::uint32_t v : cl.face(c, i))
                if (v >= cl.n_vertices())
                    throw std::invalid_argument("build_mesh: cell " + std::to_string(c) + " face " + std::to_string(i) +
                                                ": vertex " + std::to_string(v) + " out of range (" +
                                                std::to_string(cl.n_vertices()) + " vertices)");
        }
    }
}

// The canonical form of a face cycle: rotated to start at its smallest vertex and read in the direction of its
// smaller neighbour. `reversed` says whether that direction is against the listed one.
void canonical(std::span<const std::uint32_t> f, std::uint32_t* out, bool& reversed) {
    const std::size_t k = f.size();
    const std::size_t m = std::size_t(std::min_element(f.begin(), f.end()) - f.begin());
    reversed = f[(m + k - 1) % k] < f[(m + 1) % k];
    for (std::size_t i = 0; i < k; ++i) out[i] = reversed ? f[(m + k - i) % k] : f[(m + i) % k];
}

// Cell c is not degenerate and closed (geolab::TopologyError otherwise).
void check_cell(const CellList& cl, std::size_t c, std::vector<std::array<std::uint32_t, 2>>& directed,
                std::vector<std::vector<std::uint32_t>>& canon) {
    const std::string name = "build_mesh: degenerate cell " + std::to_string(c) + ": ";
    const std::size_t nf = cl.n_faces(c);
    if (nf < 4) throw TopologyError(name + "it has " + std::to_string(nf) + " faces (a cell needs at least 4)");
    directed.clear();
    canon.resize(nf);
    for (std::size_t i = 0; i < nf; ++i) {
        const auto f = cl.face(c, i);
        if (f.size() < 3)
            throw TopologyError(name + "face " + std::to_string(i) + " has " + std::to_string(f.size()) +
                                " vertices (a face needs at least 3)");
        for (std::size_t a = 0; a < f.size(); ++a)
            for (std::size_t b = a + 1; b < f.size(); ++b)
                if (f[a] == f[b]) throw TopologyError(name + "face " + std::to_string(i) + " repeats vertex " +
                                                      std::to_string(f[a]));
        canon[i].resize(f.size());
        bool rev = false;
        canonical(f, canon[i].data(), rev);
        for (std::size_t j = 0; j < i; ++j)
            if (canon[j] == canon[i])
                throw TopologyError(name + "faces " + std::to_string(j) + " and " + std::to_string(i) +
                                    " are the same polygon " + face_text(cl.face(c, j)));
        for (std::size_t a = 0; a < f.size(); ++a) directed.push_back({f[a], f[(a + 1) % f.size()]});
    }
    std::sort(directed.begin(), directed.end());
    for (std::size_t a = 0; a < directed.size();) {
        std::size_t b = a;
        while (b < directed.size() && directed[b] == directed[a]) ++b;
        const std::array<std::uint32_t, 2> rev{directed[a][1], directed[a][0]};
        const auto r = std::equal_range(directed.begin(), directed.end(), rev);
        const std::size_t back = std::size_t(r.second - r.first);
        if (b - a != 1 || back != 1)
            throw TopologyError("build_mesh: cell " + std::to_string(c) + " is not closed: the edge from vertex " +
                                std::to_string(directed[a][0]) + " to vertex " + std::to_string(directed[a][1]) +
                                " is used " + std::to_string(b - a) + " time(s) in that direction and " +
                                std::to_string(back) +
                                " time(s) in the other by its faces (a closed cell uses each edge once each way)");
        a = b;
    }
}

// END SOLUTION
}  // namespace

Mesh build_mesh(const CellList& cl) {
    // BEGIN SOLUTION
    check_indices(cl);
    const std::size_t nc = cl.n_cells();
    {
        std::vector<std::array<std::uint32_t, 2>> directed;
        std::vector<std::vector<std::uint32_t>> canon;
        for (std::size_t c = 0; c < nc; ++c) check_cell(cl, c, directed, canon);
    }

    // Face occurrences (one per face of each cell, in list order) and their canonical forms.
    const std::size_t n_occ = cl.face_begin.size() - 1;
    std::vector<std::uint32_t> canon(cl.face_vertices.size());
    std::vector<std::uint8_t> reversed(n_occ);
    std::vector<std::uint32_t> occ_cell(n_occ);
    for (std::size_t c = 0; c < nc; ++c)
        for (std::uint32_t j = cl.cell_begin[c]; j < cl.cell_begin[c + 1]; ++j) occ_cell[j] = std::uint32_t(c);
    for (std::size_t j = 0; j < n_occ; ++j) {
        bool rev = false;
        canonical({cl.face_vertices.data() + cl.face_begin[j], cl.face_vertices.data() + cl.face_begin[j + 1]},
                  canon.data() + cl.face_begin[j], rev);
        reversed[j] = rev;
    }
    auto key = [&](std::uint32_t j) {
        return std::span<const std::uint32_t>(canon.data() + cl.face_begin[j], canon.data() + cl.face_begin[j + 1]);
    };
    std::vector<std::uint32_t> order(n_occ);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        const auto ka = key(a), kb = key(b);
        if (ka.size() != kb.size()) return ka.size() < kb.size();
        const int cmp = std::memcmp(ka.data(), kb.data(), ka.size() * sizeof(std::uint32_t));
        return cmp != 0 ? cmp < 0 : a < b;  // equal faces in occurrence order
    });
    // Groups of equal faces: the first occurrence of each group, and per occurrence its group's first.
    std::vector<std::uint32_t> first_of(n_occ);
    std::string error;
    std::uint32_t error_at = invalid_index;
    for (std::size_t a = 0; a < n_occ;) {
        std::size_t b = a + 1;
        while (b < n_occ && key(order[b]).size() == key(order[a]).size() &&
               std::equal(key(order[b]).begin(), key(order[b]).end(), key(order[a]).begin()))
            ++b;
        const std::uint32_t first = order[a];
        for (std::size_t i = a; i < b; ++i) first_of[order[i]] = first;
        if (first < error_at) {
            const std::string face = face_text(cl.face(occ_cell[first], first - cl.cell_begin[occ_cell[first]]));
            if (b - a >= 3) {
                std::string cells;
                for (std::size_t i = a; i < b; ++i) cells += (i > a ? ", cell " : "cell ") + std::to_string(occ_cell[order[i]]);
                error = "build_mesh: face " + face + " is used by 3 or more cells: " + cells;
                error_at = first;
            } else if (b - a == 2 && reversed[order[a]] == reversed[order[a + 1]]) {
                error = "build_mesh: inconsistent orientation: cell " + std::to_string(occ_cell[order[a]]) + " and cell " +
                        std::to_string(occ_cell[order[a + 1]]) + " both list face " + face + " in the same direction";
                error_at = first;
            }
        }
        a = b;
    }
    if (error_at != invalid_index) throw TopologyError(error);

    Mesh m;
    std::size_t n_faces = 0;
    for (std::size_t j = 0; j < n_occ; ++j) n_faces += first_of[j] == j;
    m.reserve(cl.n_vertices(), 0, 2 * cl.face_vertices.size(), n_faces, nc);
    for (const glm::dvec3& p : cl.positions) m.add_vertex(p);

    // Faces in order of first use, each with its two half-faces' loops (edges found below).
    std::vector<std::uint32_t> face_of(n_occ, invalid_index);
    std::vector<std::uint32_t> he_from;  // per half-edge, its start vertex (until edges exist)
    he_from.reserve(2 * cl.face_vertices.size());
    for (std::uint32_t j = 0; j < n_occ; ++j) {
        if (first_of[j] != j) {
            face_of[j] = face_of[first_of[j]];
            continue;
        }
        const Face f = m.add_face();
        face_of[j] = f.idx;
        const auto w = cl.face(occ_cell[j], j - cl.cell_begin[occ_cell[j]]);
        const std::size_t k = w.size();
        for (unsigned side = 0; side < 2; ++side) {
            const HalfFace hf = Mesh::halfface(f, side);
            const auto base = std::uint32_t(m.n_halfedges());
            for (std::size_t i = 0; i < k; ++i) {
                const std::uint32_t from = side == 0 ? w[i] : w[(k - i) % k];
                const std::uint32_t to = side == 0 ? w[(i + 1) % k] : w[(2 * k - i - 1) % k];
                m.add_halfedge(Edge{}, Vertex{to}, hf);
                he_from.push_back(from);
            }
            for (std::size_t i = 0; i < k; ++i) {
                const HalfEdge h{base + std::uint32_t(i)};
                m.set_next(h, HalfEdge{base + std::uint32_t((i + 1) % k)});
                m.set_prev(h, HalfEdge{base + std::uint32_t((i + k - 1) % k)});
                // the opposite loop runs backwards from the same vertex: mate of corner i is corner k-1-i
                const std::uint32_t other = side == 0 ? base + std::uint32_t(k) : base - std::uint32_t(k);
                m.set_mate(h, HalfEdge{other + std::uint32_t(k - 1 - i)});
            }
            m.set_halfedge(hf, HalfEdge{base});
        }
    }

    // Edges in order of first use: sort the half-edges by their undirected vertex pair.
    const std::size_t nh = m.n_halfedges();
    std::vector<std::uint64_t> pair_key(nh);
    for (std::uint32_t h = 0; h < nh; ++h) {
        const std::uint64_t a = he_from[h], b = m.to_vertex(HalfEdge{h}).idx;
        pair_key[h] = (std::min(a, b) << 32) | std::max(a, b);
    }
    std::vector<std::uint32_t> by_pair(nh);
    std::iota(by_pair.begin(), by_pair.end(), 0u);
    std::sort(by_pair.begin(), by_pair.end(), [&](std::uint32_t a, std::uint32_t b) {
        return pair_key[a] != pair_key[b] ? pair_key[a] < pair_key[b] : a < b;
    });
    std::vector<std::uint32_t> first_he(nh);
    for (std::size_t a = 0; a < nh;) {
        std::size_t b = a;
        while (b < nh && pair_key[by_pair[b]] == pair_key[by_pair[a]]) ++b;
        for (std::size_t i = a; i < b; ++i) first_he[by_pair[i]] = by_pair[a];
        a = b;
    }
    std::vector<Edge> edge_of(nh);
    for (std::uint32_t h = 0; h < nh; ++h) {
        if (first_he[h] == h) {
            edge_of[h] = m.add_edge(Vertex{he_from[h]}, m.to_vertex(HalfEdge{h}));
            m.set_halfedge(edge_of[h], HalfEdge{h});
        } else {
            edge_of[h] = edge_of[first_he[h]];
        }
    }
    for (HalfEdge h : m.halfedges()) {
        m.set_edge(h, edge_of[h.idx]);
        if (!m.halfedge(Vertex{he_from[h.idx]}).is_valid()) m.set_halfedge(Vertex{he_from[h.idx]}, h);
    }

    // Cells: the side of each face occurrence, and the twins inside each cell (pairs of half-edges on one edge).
    std::vector<HalfFace> hfs;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> corners;  // (edge, half-edge)
    for (std::uint32_t c = 0; c < nc; ++c) {
        hfs.clear();
        corners.clear();
        for (std::uint32_t j = cl.cell_begin[c]; j < cl.cell_begin[c + 1]; ++j) {
            const HalfFace hf = Mesh::halfface(Face{face_of[j]}, first_of[j] == j ? 0 : 1);
            hfs.push_back(hf);
            const HalfEdge h0 = m.halfedge(hf);
            HalfEdge h = h0;
            do {
                corners.push_back({m.edge(h).idx, h.idx});
                h = m.next(h);
            } while (h != h0);
        }
        const Cell cell = m.add_cell(hfs);
        for (HalfFace hf : hfs) m.set_cell(hf, cell);
        std::sort(corners.begin(), corners.end());
        for (std::size_t i = 0; i + 1 < corners.size(); i += 2) {
            m.set_twin(HalfEdge{corners[i].second}, HalfEdge{corners[i + 1].second});
            m.set_twin(HalfEdge{corners[i + 1].second}, HalfEdge{corners[i].second});
        }
    }
    m.rebuild_vertex_cache();
    return m;
    // END SOLUTION
}

}  // namespace geolab::halfface
