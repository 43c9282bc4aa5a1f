// Task 1: build the half-face mesh from a cell list (handout §3).
#include <algorithm>
#include <cmath>
#include <span>
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
    const auto bad = std::find_if(cl.positions.begin(), cl.positions.end(), [](const glm::dvec3& p) {
        return !(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    });
    if (bad != cl.positions.end())
        throw std::invalid_argument("build_mesh: vertex " + std::to_string(bad - cl.positions.begin()) +
                                    " has a position that is not finite");
    if (cl.cell_begin.empty() || cl.face_begin.empty() || cl.cell_begin.front() != 0 || cl.face_begin.front() != 0 ||
        cl.cell_begin.back() + 1 != cl.face_begin.size() || cl.face_begin.back() != cl.face_vertices.size())
        throw std::invalid_argument("build_mesh: the cell list's offsets do not match its faces");
    for (std::size_t c = 0; c < cl.n_cells(); ++c)  // then every face index below is a face
        if (cl.cell_begin[c] > cl.cell_begin[c + 1])
            throw std::invalid_argument("build_mesh: cell " + std::to_string(c) + " has decreasing offsets");
    for (std::size_t c = 0; c < cl.n_cells(); ++c)  // then every vertex index below is in face_vertices
        for (std::size_t i = 0; i < cl.n_faces(c); ++i) {
            const std::size_t j = cl.cell_begin[c] + i;
            if (cl.face_begin[j] > cl.face_begin[j + 1])
                throw std::invalid_argument("build_mesh: cell " + std::to_string(c) + " face " + std::to_string(i) +
                                            " has decreasing offsets");
        }
    for (std::size_t c = 0; c < cl.n_cells(); ++c)
        for (std::size_t i = 0; i < cl.n_faces(c); ++i)
            for (std::uint32_t v : cl.face(c, i))
                if (v >= cl.n_vertices())
                    throw std::invalid_argument("build_mesh: cell " + std::to_string(c) + " face " + std::to_string(i) +
                                                ": vertex " + std::to_string(v) + " out of range (" +
                                                std::to_string(cl.n_vertices()) + " vertices)");
}

// The canonical form of a face cycle: rotated to start at its smallest vertex and read in the direction of its
// smaller neighbour. `reversed` says whether that direction is against the listed one. Two listings of one
// polygon have the same canonical form.
void canonical(std::span<const std::uint32_t> f, std::uint32_t* out, bool& reversed) {
    const std::size_t k = f.size();
    const std::size_t m = std::size_t(std::min_element(f.begin(), f.end()) - f.begin());
    reversed = f[m == 0 ? k - 1 : m - 1] < f[m + 1 == k ? 0 : m + 1];
    std::size_t i = m;
    for (std::size_t n = 0; n < k; ++n) {  // from f[m] on, forwards or backwards around the cycle
        out[n] = f[i];
        i = reversed ? (i == 0 ? k - 1 : i - 1) : (i + 1 == k ? 0 : i + 1);
    }
}

// Canonical forms compared (negative, 0, positive): the shorter first, then vertex by vertex.
int compare(std::span<const std::uint32_t> a, std::span<const std::uint32_t> b) {
    if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
    return 0;
}

// Counting sort: `order` lists 0..n-1 grouped by bucket(i) < n_buckets, increasing within a bucket; bucket b is
// order[begin[b] .. begin[b+1]). O(n + n_buckets).
template <class Bucket>
void bucket_sort(std::size_t n, std::size_t n_buckets, Bucket bucket, std::vector<std::uint32_t>& order,
                 std::vector<std::uint32_t>& begin) {
    begin.assign(n_buckets + 1, 0);
    for (std::uint32_t i = 0; i < n; ++i) ++begin[bucket(i) + 1];
    for (std::size_t b = 0; b < n_buckets; ++b) begin[b + 1] += begin[b];
    std::vector<std::uint32_t> fill = begin;  // the next free place in each bucket
    order.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) order[fill[bucket(i)]++] = i;
}

// The pair (a, b) as one number a · 2^32 + b: pairs sort as their numbers do.
std::uint64_t pair_key(std::uint32_t a, std::uint32_t b) { return (std::uint64_t(a) << 32) | b; }

// Buffers of check_cell, reused from cell to cell (no allocation per cell).
struct CellScratch {
    std::vector<std::uint32_t> canon, canon_begin, by_key;
    std::vector<std::uint64_t> directed;  // the directed edges u -> v of the cell's faces, as u · 2^32 + v
    std::vector<std::uint32_t> stamp;  // per vertex: the last face (counted from 1) that used it
    std::uint32_t face = 0;
};

// Cell c is not degenerate and closed (geolab::TopologyError otherwise).
void check_cell(const CellList& cl, std::size_t c, CellScratch& s) {
    auto degenerate = [&](const std::string& why) {
        return TopologyError("build_mesh: degenerate cell " + std::to_string(c) + ": " + why);
    };
    const std::size_t nf = cl.n_faces(c);
    if (nf < 4) throw degenerate("it has " + std::to_string(nf) + " faces (a cell needs at least 4)");
    s.canon.clear(), s.canon_begin.assign(1, 0), s.directed.clear();
    for (std::size_t i = 0; i < nf; ++i) {
        const auto f = cl.face(c, i);
        if (f.size() < 3)
            throw degenerate("face " + std::to_string(i) + " has " + std::to_string(f.size()) +
                             " vertices (a face needs at least 3)");
        ++s.face;  // a vertex already stamped with this face's number repeats in it
        for (std::uint32_t v : f) {
            if (s.stamp[v] == s.face) throw degenerate("face " + std::to_string(i) + " repeats vertex " + std::to_string(v));
            s.stamp[v] = s.face;
        }
        s.canon.resize(s.canon.size() + f.size());
        bool rev = false;
        canonical(f, s.canon.data() + s.canon_begin.back(), rev);
        s.canon_begin.push_back(std::uint32_t(s.canon.size()));
        for (std::size_t a = 0; a + 1 < f.size(); ++a) s.directed.push_back(pair_key(f[a], f[a + 1]));
        s.directed.push_back(pair_key(f.back(), f.front()));
    }
    // the same polygon twice: equal canonical forms are neighbours once sorted
    auto key = [&](std::uint32_t i) {
        return std::span<const std::uint32_t>(s.canon.data() + s.canon_begin[i], s.canon.data() + s.canon_begin[i + 1]);
    };
    s.by_key.resize(nf);
    for (std::uint32_t i = 0; i < nf; ++i) s.by_key[i] = i;
    std::sort(s.by_key.begin(), s.by_key.end(),
              [&](std::uint32_t a, std::uint32_t b) { return compare(key(a), key(b)) < 0; });
    for (std::size_t i = 0; i + 1 < nf; ++i)
        if (compare(key(s.by_key[i]), key(s.by_key[i + 1])) == 0) {
            const auto [first, second] = std::minmax(s.by_key[i], s.by_key[i + 1]);
            throw degenerate("faces " + std::to_string(first) + " and " + std::to_string(second) +
                             " are the same polygon " + face_text(cl.face(c, first)));
        }
    // closed: every directed edge once, and its reverse once
    std::sort(s.directed.begin(), s.directed.end());
    for (std::size_t a = 0; a < s.directed.size();) {
        std::size_t b = a;
        while (b < s.directed.size() && s.directed[b] == s.directed[a]) ++b;
        const std::uint32_t u = std::uint32_t(s.directed[a] >> 32), v = std::uint32_t(s.directed[a]);
        const auto r = std::equal_range(s.directed.begin(), s.directed.end(), pair_key(v, u));
        const std::size_t back = std::size_t(r.second - r.first);
        if (b - a != 1 || back != 1)
            throw TopologyError("build_mesh: cell " + std::to_string(c) + " is not closed: the edge from vertex " +
                                std::to_string(u) + " to vertex " + std::to_string(v) + " is used " +
                                std::to_string(b - a) + " time(s) in that direction and " + std::to_string(back) +
                                " time(s) in the other by its faces (a closed cell uses each edge once each way)");
        a = b;
    }
}

// The faces of a cell list, matched: the face occurrences (face i of cell c is occurrence cell_begin[c] + i)
// that list the same polygon are one face, numbered in order of first use.
struct FaceMatch {
    std::vector<std::uint32_t> face_of;    // per occurrence: its face
    std::vector<std::uint32_t> first_use;  // per face: the occurrence that used it first (its side 2f)
};

// The cell of occurrence j.
std::uint32_t cell_of(const CellList& cl, std::uint32_t j) {
    return std::uint32_t(std::upper_bound(cl.cell_begin.begin(), cl.cell_begin.end(), j) - cl.cell_begin.begin() - 1);
}

// The error of a group of occurrences listing one polygon, or "" when it is one face (1 or 2 users, opposite ways).
std::string group_error(const CellList& cl, std::span<const std::uint32_t> group, const std::vector<std::uint8_t>& reversed) {
    if (group.size() < 2 || (group.size() == 2 && reversed[group[0]] != reversed[group[1]])) return "";
    const std::uint32_t c0 = cell_of(cl, group[0]);
    const std::string face = face_text(cl.face(c0, group[0] - cl.cell_begin[c0]));
    if (group.size() == 2)
        return "build_mesh: inconsistent orientation: cell " + std::to_string(c0) + " and cell " +
               std::to_string(cell_of(cl, group[1])) + " both list face " + face + " in the same direction";
    std::string error = "build_mesh: face " + face + " is used by 3 or more cells: ";
    for (std::size_t i = 0; i < group.size(); ++i) error += (i ? ", cell " : "cell ") + std::to_string(cell_of(cl, group[i]));
    return error;
}

// Group equal polygons: a bucket per smallest vertex, sorted inside by canonical form. Throws the error of the
// group whose first use comes first (3 or more users, or two users listing it the same way).
FaceMatch match_faces(const CellList& cl) {
    const std::size_t n_occ = cl.face_begin.size() - 1;
    std::vector<std::uint32_t> canon(cl.face_vertices.size());
    std::vector<std::uint8_t> reversed(n_occ);
    auto key = [&](std::uint32_t j) {
        return std::span<const std::uint32_t>(canon.data() + cl.face_begin[j], canon.data() + cl.face_begin[j + 1]);
    };
    for (std::uint32_t j = 0; j < n_occ; ++j) {
        bool rev = false;
        canonical({cl.face_vertices.data() + cl.face_begin[j], cl.face_vertices.data() + cl.face_begin[j + 1]},
                  canon.data() + cl.face_begin[j], rev);
        reversed[j] = rev;
    }
    std::vector<std::uint32_t> order, begin;
    bucket_sort(n_occ, cl.n_vertices(), [&](std::uint32_t j) { return key(j)[0]; }, order, begin);

    FaceMatch fm;
    fm.face_of.resize(n_occ);  // first the first use of each occurrence's polygon, then its face
    std::string error;
    std::uint32_t error_at = invalid_index;  // the first use of the group with the error
    for (std::size_t v = 0; v < cl.n_vertices(); ++v) {
        const auto b0 = order.begin() + begin[v], b1 = order.begin() + begin[v + 1];
        std::sort(b0, b1, [&](std::uint32_t a, std::uint32_t b) {
            const int cmp = compare(key(a), key(b));
            return cmp != 0 ? cmp < 0 : a < b;
        });
        for (auto g0 = b0; g0 != b1;) {  // one group of equal polygons, in occurrence order
            auto g1 = g0 + 1;
            while (g1 != b1 && compare(key(*g1), key(*g0)) == 0) ++g1;
            for (auto it = g0; it != g1; ++it) fm.face_of[*it] = *g0;
            if (*g0 < error_at) {
                std::string e = group_error(cl, {&*g0, std::size_t(g1 - g0)}, reversed);
                if (!e.empty()) error = std::move(e), error_at = *g0;
            }
            g0 = g1;
        }
    }
    if (error_at != invalid_index) throw TopologyError(error);
    for (std::uint32_t j = 0; j < n_occ; ++j) {  // faces in order of first use
        if (fm.face_of[j] == j) {
            fm.face_of[j] = std::uint32_t(fm.first_use.size());
            fm.first_use.push_back(j);
        } else {
            fm.face_of[j] = fm.face_of[fm.face_of[j]];  // its first use came before: already a face
        }
    }
    return fm;
}

// The edges of the faces' first listings: corner i of face f goes from w[i] to w[i + 1] (w the first use's
// vertices, corners numbered face after face). Per corner its edge; edges numbered in order of first use, each
// with the corner that used it first. A bucket per smaller vertex, sorted inside by the larger one.
struct EdgeMatch {
    std::vector<std::uint32_t> edge_of;     // per corner
    std::vector<std::uint32_t> first_use;   // per edge: a corner
};

EdgeMatch match_edges(std::span<const std::uint32_t> from, std::span<const std::uint32_t> to, std::size_t nv) {
    const std::size_t n = from.size();
    auto other = [&](std::uint32_t c) { return std::max(from[c], to[c]); };
    std::vector<std::uint32_t> order, begin;
    bucket_sort(n, nv, [&](std::uint32_t c) { return std::min(from[c], to[c]); }, order, begin);
    EdgeMatch em;
    em.edge_of.resize(n);  // first the first corner of each corner's edge, then the edge
    for (std::size_t v = 0; v < nv; ++v) {
        const auto b0 = order.begin() + begin[v], b1 = order.begin() + begin[v + 1];
        std::sort(b0, b1, [&](std::uint32_t a, std::uint32_t b) {
            return other(a) != other(b) ? other(a) < other(b) : a < b;
        });
        for (auto g0 = b0; g0 != b1;) {
            auto g1 = g0 + 1;
            while (g1 != b1 && other(*g1) == other(*g0)) ++g1;
            for (auto it = g0; it != g1; ++it) em.edge_of[*it] = *g0;
            g0 = g1;
        }
    }
    for (std::uint32_t c = 0; c < n; ++c) {  // edges in order of first use
        if (em.edge_of[c] == c) {
            em.edge_of[c] = std::uint32_t(em.first_use.size());
            em.first_use.push_back(c);
        } else {
            em.edge_of[c] = em.edge_of[em.edge_of[c]];
        }
    }
    return em;
}

// END SOLUTION
}  // namespace

Mesh build_mesh(const CellList& cl) {
    // BEGIN SOLUTION
    check_indices(cl);
    {
        CellScratch scratch;
        scratch.stamp.assign(cl.n_vertices(), 0);
        for (std::size_t c = 0; c < cl.n_cells(); ++c) check_cell(cl, c, scratch);
    }
    const FaceMatch faces = match_faces(cl);
    const std::size_t nf = faces.first_use.size();
    // the faces' first listings: w(f), and their corners (corner_begin[f] .. corner_begin[f+1])
    auto listing = [&](std::size_t f) {
        const std::uint32_t j = faces.first_use[f];
        return std::span<const std::uint32_t>(cl.face_vertices.data() + cl.face_begin[j],
                                              cl.face_vertices.data() + cl.face_begin[j + 1]);
    };
    std::vector<std::uint32_t> corner_begin(nf + 1, 0);
    for (std::size_t f = 0; f < nf; ++f) corner_begin[f + 1] = corner_begin[f] + std::uint32_t(listing(f).size());
    const std::size_t n_corners = corner_begin[nf];
    std::vector<std::uint32_t> from(n_corners), to(n_corners);
    for (std::size_t f = 0; f < nf; ++f) {
        const auto w = listing(f);
        for (std::size_t i = 0; i < w.size(); ++i)
            from[corner_begin[f] + i] = w[i], to[corner_begin[f] + i] = w[i + 1 < w.size() ? i + 1 : 0];
    }
    const EdgeMatch edges = match_edges(from, to, cl.n_vertices());

    Mesh m;
    m.reserve(cl.n_vertices(), edges.first_use.size(), 2 * n_corners, nf, cl.n_cells(), cl.face_begin.size() - 1);
    for (const glm::dvec3& p : cl.positions) m.add_vertex(p);
    for (std::uint32_t c : edges.first_use) m.add_edge(Vertex{from[c]}, Vertex{to[c]});
    // Each face: half-face 2f runs like its first listing from w[0]; 2f + 1 runs backwards from w[0]. Corner i of
    // 2f is half-edge base + i; its mate, the same edge reversed, is corner k - 1 - i of 2f + 1 (base + k + ...).
    for (std::size_t f = 0; f < nf; ++f) {
        const Face face = m.add_face();
        const std::uint32_t k = corner_begin[f + 1] - corner_begin[f], base = std::uint32_t(m.n_halfedges());
        for (unsigned side = 0; side < 2; ++side) {
            const HalfFace hf = Mesh::halfface(face, side);
            for (std::uint32_t i = 0; i < k; ++i) {
                const std::uint32_t c = corner_begin[f] + (side == 0 ? i : k - 1 - i);  // the corner of its edge
                const HalfEdge h = m.add_halfedge(Edge{edges.edge_of[c]}, Vertex{side == 0 ? to[c] : from[c]}, hf);
                const std::uint32_t side_base = base + side * k;
                m.set_next(h, HalfEdge{side_base + (i + 1 < k ? i + 1 : 0)});
                m.set_prev(h, HalfEdge{side_base + (i > 0 ? i - 1 : k - 1)});
                m.set_mate(h, HalfEdge{base + (1 - side) * k + (k - 1 - i)});
                if (side == 0 && edges.first_use[edges.edge_of[c]] == c) m.set_halfedge(Edge{edges.edge_of[c]}, h);
                const Vertex start{side == 0 ? from[c] : to[c]};
                if (!m.halfedge(start).is_valid()) m.set_halfedge(start, h);
            }
            m.set_halfedge(hf, HalfEdge{base + side * k});
        }
    }
    // Cells: each occurrence is side 2f (first use) or 2f + 1; inside a cell, the two half-edges of each of its
    // edges are twins (sort its corners by edge).
    std::vector<HalfFace> hfs;
    std::vector<std::uint64_t> corners;  // pair_key(edge, half-edge)
    for (std::uint32_t c = 0; c < cl.n_cells(); ++c) {
        hfs.clear(), corners.clear();
        for (std::uint32_t j = cl.cell_begin[c]; j < cl.cell_begin[c + 1]; ++j) {
            const Face f{faces.face_of[j]};
            const HalfFace hf = Mesh::halfface(f, faces.first_use[f.idx] == j ? 0 : 1);
            hfs.push_back(hf);
            const std::uint32_t k = corner_begin[f.idx + 1] - corner_begin[f.idx];
            const std::uint32_t first = 2 * corner_begin[f.idx] + (hf.idx & 1u) * k;
            for (std::uint32_t h = first; h < first + k; ++h) corners.push_back(pair_key(m.edge(HalfEdge{h}).idx, h));
        }
        const Cell cell = m.add_cell(hfs);
        for (HalfFace hf : hfs) m.set_cell(hf, cell);
        std::sort(corners.begin(), corners.end());
        for (std::size_t i = 0; i + 1 < corners.size(); i += 2) {  // the two corners of one edge
            const HalfEdge g{std::uint32_t(corners[i])}, h{std::uint32_t(corners[i + 1])};
            m.set_twin(g, h), m.set_twin(h, g);
        }
    }
    m.rebuild_vertex_cache();
    return m;
    // END SOLUTION
}

}  // namespace geolab::halfface
