// Lab 09 — task 4: dual vertices, simplification and polygons; the Cartesian one-shot function.
#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <queue>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"

namespace geolab::dc {

// BEGIN SOLUTION
// STUB:
namespace {
// quadrants around an edge along axis a, counter-clockwise seen from +a: (−,−), (+,−), (+,+), (−,+) in (b, c)
constexpr int qb[4] = {-1, +1, +1, -1}, qc[4] = {-1, -1, +1, +1};
// The 12 edges of a cell: corner c → corner d = c + e_a, and the quadrant the cell occupies around that edge.
struct CellEdge {
    int c, d, a, quadrant;
    int b, cax;          // the other two axes, (a + 1) % 3 and (a + 2) % 3
    int my_b, my_c;      // the cell's side of the edge along b and cax (−1 or +1): qb[quadrant], qc[quadrant]
    int dx[4], dy[4], dz[4];  // finest cells only: the cell in quadrant k is this cell + (dx, dy, dz)[k]
    int owner_below = 0;      // the axes (bits 1 << axis) along which the quadrant-0 cell is below this cell
    int edge_in[4];           // the number of this edge as a cell edge of the cell in quadrant k (same size)
};
// The number of the cell edge along axis a whose lower end is corner c (bit a of c clear): cell_edge_corners order.
constexpr int edge_number(int a, int c) {
    return 4 * a + (a == 0 ? c >> 1 : a == 1 ? (c & 1) | ((c >> 2) << 1) : c);
}
constexpr std::array<CellEdge, 12> make_cell_edges() {
    std::array<CellEdge, 12> out{};
    int n = 0;
    for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 8; ++c) {
            if (c & (1 << a)) continue;
            const int b = (a + 1) % 3, cax = (a + 2) % 3;
            const int my_b = (c & (1 << b)) ? -1 : +1, my_c = (c & (1 << cax)) ? -1 : +1;
            int k = 0;
            while (qb[k] != my_b || qc[k] != my_c) ++k;
            CellEdge e{c, c | (1 << a), a, k, b, cax, my_b, my_c, {}, {}, {}, 0, {}};
            for (int j = 0; j < 4; ++j) {
                int d[3] = {0, 0, 0};
                d[b] = (qb[j] - my_b) / 2;
                d[cax] = (qc[j] - my_c) / 2;
                e.dx[j] = d[0], e.dy[j] = d[1], e.dz[j] = d[2];
                // the cell in quadrant j has the edge on its upper side along b (cax) when it lies below (qb < 0)
                e.edge_in[j] = edge_number(a, (qb[j] < 0) << b | (qc[j] < 0) << cax);
                if (j == 0)
                    for (int axis = 0; axis < 3; ++axis) e.owner_below |= (d[axis] < 0) << axis;
            }
            out[n++] = e;
        }
    return out;
}
constexpr std::array<CellEdge, 12> cell_edges = make_cell_edges();
constexpr bool same_numbering() {  // cell_edges[i] is cell edge i of the header's cell_edge_corners
    for (int i = 0; i < 12; ++i)
        if (cell_edges[i].c != cell_edge_corners[i][0] || cell_edges[i].d != cell_edge_corners[i][1]) return false;
    return true;
}
static_assert(same_numbering());
// Speed: the pieces of every sign configuration with no face joined (cell_surface), made once; and the
// configurations with an ambiguous face, the only ones where face_joins can change them
const std::array<CellSurface, 256>& plain_surfaces() {
    static const std::array<CellSurface, 256> table = [] {
        std::array<CellSurface, 256> t{};
        for (int m = 0; m < 256; ++m) t[m] = cell_surface(std::uint8_t(m));
        return t;
    }();
    return table;
}
constexpr std::array<bool, 256> make_ambiguous() {
    std::array<bool, 256> out{};
    for (int m = 0; m < 256; ++m)
        for (int a = 0; a < 3; ++a)
            for (int s = 0; s < 2; ++s) {
                const int b = (a + 1) % 3, c = (a + 2) % 3, base = s << a;
                const int p0 = base, p1 = base | 1 << b, p2 = base | 1 << b | 1 << c, p3 = base | 1 << c;
                const int i0 = (m >> p0) & 1, i1 = (m >> p1) & 1, i2 = (m >> p2) & 1, i3 = (m >> p3) & 1;
                if (i0 == i2 && i1 == i3 && i0 != i1) out[m] = true;
            }
    return out;
}
constexpr std::array<bool, 256> has_ambiguous_face = make_ambiguous();
// edge_index.of[a][c]: the index in cell_edges of the edge from corner c along axis a (bit a of c clear)
struct EdgeIndex {
    int of[3][8] = {};
};
constexpr EdgeIndex make_edge_index() {
    EdgeIndex t;
    for (int i = 0; i < 12; ++i) t.of[cell_edges[i].a][cell_edges[i].c] = i;
    return t;
}
constexpr EdgeIndex edge_index = make_edge_index();
// Speed: for each sign configuration (OctreeNode::signs), the edges that change sign (indices into cell_edges),
// so that the loops visit those only.
struct EdgeList {
    int n = 0;
    std::uint8_t e[12] = {};
};
constexpr std::array<EdgeList, 256> make_edge_lists() {
    std::array<EdgeList, 256> out{};
    for (int signs = 0; signs < 256; ++signs)
        for (int i = 0; i < 12; ++i)
            if (((signs >> cell_edges[i].c) ^ (signs >> cell_edges[i].d)) & 1)
                out[signs].e[out[signs].n++] = std::uint8_t(i);
    return out;
}
constexpr std::array<EdgeList, 256> changing_edges = make_edge_lists();
// the offset (i, j, k) of sub-lattice point p = i + 3j + 9k
// (a table: computing the three ints on the fly made the compiler spill and reload them at a stall)
struct SubOffsets {
    int ijk[27][3] = {};
};
constexpr SubOffsets make_sub_offsets() {
    SubOffsets t;
    for (int p = 0; p < 27; ++p) t.ijk[p][0] = p % 3, t.ijk[p][1] = (p / 3) % 3, t.ijk[p][2] = p / 9;
    return t;
}
constexpr SubOffsets sub_offsets = make_sub_offsets();
glm::ivec3 sub_offset(int p) { return {sub_offsets.ijk[p][0], sub_offsets.ijk[p][1], sub_offsets.ijk[p][2]}; }
// Speed: the sign tests of simplify as tables. point[child][c]: the sub-lattice point (i + 3j + 9k, i, j, k ∈ {0,1,2})
// of the parent that is corner c of child `child` (so point[c][c] is the parent's corner c). single_sheet[m]: the
// parent corners inside (bit c of m) and those outside are each connected through cube edges.
struct SimplifyTables {
    int point[8][8] = {};
    bool single_sheet[256] = {};
    // spread[child][signs]: the child's sign configuration as bits of the sub-lattice (bit point[child][c] for corner c)
    std::uint32_t spread[8][256] = {};
    // for the parent's corner signs m: the sub-lattice points allowed to be inside (a corner inside, or a feature with
    // an inside corner) and those allowed to be outside
    std::uint32_t may_be_inside[256] = {}, may_be_outside[256] = {};
};
constexpr bool corners_connected(int mask) {
    if (mask == 0) return true;
    int seen = mask & -mask, frontier = seen;
    while (frontier) {
        int next = 0;
        for (int c = 0; c < 8; ++c)
            if (frontier & (1 << c))
                for (int a = 0; a < 3; ++a) next |= 1 << (c ^ (1 << a));
        next &= mask & ~seen;
        seen |= next;
        frontier = next;
    }
    return seen == mask;
}
constexpr SimplifyTables make_simplify_tables() {
    SimplifyTables t;
    for (int child = 0; child < 8; ++child)
        for (int c = 0; c < 8; ++c)
            t.point[child][c] = ((child & 1) + (c & 1)) + 3 * (((child >> 1) & 1) + ((c >> 1) & 1)) +
                                9 * ((child >> 2) + (c >> 2));
    for (int m = 0; m < 256; ++m) t.single_sheet[m] = corners_connected(m) && corners_connected(~m & 0xff);
    for (int child = 0; child < 8; ++child)
        for (int signs = 0; signs < 256; ++signs)
            for (int c = 0; c < 8; ++c)
                if ((signs >> c) & 1) t.spread[child][signs] |= 1u << t.point[child][c];
    for (int p = 0; p < 27; ++p) {
        // the parent corners of the feature p is the centre of (each coordinate 1 replaced by 0 or 2): an edge, a
        // face or the cell; a corner of the parent is its own feature
        const int* ijk = sub_offsets.ijk[p];
        int corners = 0;
        for (int c = 0; c < 8; ++c) {
            bool on = true;
            for (int a = 0; a < 3; ++a)
                if (ijk[a] != 1 && ijk[a] != 2 * ((c >> a) & 1)) on = false;
            if (on) corners |= 1 << c;
        }
        for (int m = 0; m < 256; ++m) {
            if (corners & m) t.may_be_inside[m] |= 1u << p;
            if (corners & ~m & 0xff) t.may_be_outside[m] |= 1u << p;
        }
    }
    return t;
}
constexpr SimplifyTables simplify_tables = make_simplify_tables();
// The 3×3×3 sub-lattice of a parent cell (its 8 children's corners) as bit sets, bit p = i + 3j + 9k. edge_starts[a]:
// the points from which an edge along axis a leaves (coordinate a is 0 or 1).
constexpr std::uint32_t all_sub_points = (1u << 27) - 1;
constexpr std::array<std::uint32_t, 3> make_edge_starts() {
    std::array<std::uint32_t, 3> out{};
    for (int a = 0; a < 3; ++a)
        for (int p = 0; p < 27; ++p)
            if (sub_offsets.ijk[p][a] != 2) out[a] |= 1u << p;
    return out;
}
constexpr std::array<std::uint32_t, 3> edge_starts = make_edge_starts();
// Speed (contour): the edges of a group's sub-lattice, group_edges[a][p] for the edge from point p along axis a. The
// cell in quadrant k is the group's child child[k] (0..7) or, when child[k] < 0, the finest cell at offset d[k] from
// the group's child-0 cell, in a neighbouring group; edge[k] is the index in cell_edges of the edge as an edge of that
// cell.
struct GroupEdge {
    int child[4] = {};
    int d[4][3] = {};
    int edge[4] = {};
};
using GroupEdges = std::array<std::array<GroupEdge, 27>, 3>;
constexpr GroupEdges make_group_edges() {
    GroupEdges out{};
    for (int a = 0; a < 3; ++a)
        for (int p = 0; p < 27; ++p) {
            const int* o = sub_offsets.ijk[p];
            const int b = (a + 1) % 3, cax = (a + 2) % 3;
            GroupEdge& g = out[a][p];
            for (int k = 0; k < 4; ++k) {
                int l[3] = {o[0], o[1], o[2]};
                l[b] += (qb[k] - 1) / 2;
                l[cax] += (qc[k] - 1) / 2;
                const bool inside = l[b] >= 0 && l[cax] >= 0 && l[b] <= 1 && l[cax] <= 1 && o[a] <= 1;
                g.child[k] = inside ? l[0] + 2 * l[1] + 4 * l[2] : -1;
                int corner = 0;
                for (int i = 0; i < 3; ++i) {
                    g.d[k][i] = l[i];
                    corner |= (o[i] - l[i]) << i;
                }
                g.edge[k] = edge_index.of[a][corner & 7];
            }
        }
    return out;
}
constexpr GroupEdges group_edges = make_group_edges();
// Whether node nd's 8 children are finest leaves (a group of finest siblings): nd is of level L − 1 and not a leaf,
// and none of its children has children.
bool has_finest_children(const Octree& tree, const OctreeNode& nd) {
    if (nd.is_leaf() || nd.level + 1 != tree.max_level) return false;
    for (int c = 0; c < 8; ++c)
        if (!tree.nodes[nd.first_child + c].is_leaf()) return false;
    return true;
}
// The crossings of finest edges that several groups of finest leaves need (place_vertices), by edge, with how many
// groups will still ask for each: an open-addressing hash (linear probing, backward-shift deletion). Memory: the last
// group to ask removes the entry, and its crossing's room is reused, so what stays is the edges between the groups
// done and the groups to come (a front sweeping the octree), not every crossing of the surface.
class SharedCrossings {
public:
    struct Entry {
        std::uint64_t key = 0;  // 0: an empty place
        std::uint32_t slot = invalid_index;  // the crossing's index in the pool
        std::uint32_t uses = 0;  // groups still to ask; 0: kept to the end
    };
    //! The entry of `key` (≠ 0), made with `uses` if absent. Valid until the next call.
    Entry& find_or_add(std::uint64_t key, std::uint32_t uses) {
        if (2 * (size_ + 1) > table_.size()) grow();
        std::size_t i = home(key);
        while (table_[i].key != 0 && table_[i].key != key) i = (i + 1) & mask_;
        if (table_[i].key == 0) {
            table_[i] = {key, invalid_index, uses};
            ++size_;
        }
        return table_[i];
    }
    //! Remove entry e (a reference find_or_add returned): the entries after it in its probe run move back over the
    //! hole where their home place allows, so no search stops early at it.
    void erase(Entry& e) {
        std::size_t i = std::size_t(&e - table_.data());
        for (std::size_t j = (i + 1) & mask_; table_[j].key != 0; j = (j + 1) & mask_) {
            const std::size_t h = home(table_[j].key);
            if (((j - h) & mask_) >= ((j - i) & mask_)) {  // h is not in (i, j]: entry j may fill the hole
                table_[i] = table_[j];
                i = j;
            }
        }
        table_[i] = Entry{};
        --size_;
    }

private:
    std::size_t home(std::uint64_t key) const { return std::size_t((key * 0x9E3779B97F4A7C15ull) >> shift_); }
    void grow() {
        std::vector<Entry> old = std::move(table_);
        const std::size_t cap = old.empty() ? 1024 : 2 * old.size();
        table_.assign(cap, Entry{});
        mask_ = cap - 1;
        shift_ = 64 - std::countr_zero(cap);
        for (const Entry& e : old) {
            if (e.key == 0) continue;
            std::size_t i = home(e.key);
            while (table_[i].key != 0) i = (i + 1) & mask_;
            table_[i] = e;
        }
    }
    std::vector<Entry> table_;
    std::size_t size_ = 0, mask_ = 0;
    int shift_ = 64;
};
// Room for a Qef, left uninitialised. Speed: the fused traversal below keeps 8 per node on its stack and fills only
// those a collapse may read; zeroing them all (900 bytes a node) cost more than the collapses themselves.
union QefSlot {
    QefSlot() {}
    Qef qef;
};
struct Collapse {
    bool ok = false;          // collapse nd into a leaf
    std::uint8_t signs = 0;   // the new leaf's corner signs
    bool has_vertex = false;  // it gets one vertex (no surface crosses it otherwise)
    DualVertex vertex;
    QefSlot merged;           // ok: the children's QEFs merged (the vertex's QEF when it has one)
};
// Ju et al.'s collapse test (simplify's conditions (0)-(3)) of node nd, whose 8 children are leaves with their signs
// recorded. child_qef(c, v) is the QEF of child c's vertex v; it is asked for only once the sign tests have passed.
template <class ChildQef>
Collapse collapse_test(const Octree& tree, const OctreeNode& nd, double tolerance, double tau, ChildQef&& child_qef) {
    Collapse r;
    const std::int32_t s = tree.cell_span(nd.level);
    const glm::ivec3 base = tree.corner(nd, 0);
    // the signs at the 27 sub-lattice points (bit i + 3j + 9k): the children's corners, which place_vertices
    // recorded in their sign configurations. (0) Every child's own corners form one sheet: one piece, no
    // ambiguous face (else the merged vertex would join pieces, or a face of the parent would be crossed twice)
    std::uint32_t sub = 0;
    bool children_single = true;
    for (int child = 0; child < 8; ++child) {
        const std::uint8_t signs = tree.nodes[nd.first_child + child].signs;
        sub |= simplify_tables.spread[child][signs];
        children_single = children_single && simplify_tables.single_sheet[signs];
    }
    if (!children_single) return r;
    // (1) the parent's corner signs form one sheet
    int in_mask = 0;
    for (int c = 0; c < 8; ++c) in_mask |= int((sub >> simplify_tables.point[c][c]) & 1u) << c;
    if (!simplify_tables.single_sheet[in_mask]) return r;
    // (2) every sub-lattice point that is the centre of an edge, face or the cell agrees with one of that
    //     feature's corners
    if ((sub & ~simplify_tables.may_be_inside[in_mask]) ||
        (~sub & all_sub_points & ~simplify_tables.may_be_outside[in_mask]))
        return r;
    // (3) the merged QEF fits well and its minimiser lies in the cell
    Qef& merged = r.merged.qef = Qef{};
    for (int c = 0; c < 8; ++c) {
        const std::uint32_t vi = tree.nodes[nd.first_child + c].vertex;
        if (vi != invalid_index) merged.merge(child_qef(c, vi));
    }
    if (merged.count > 0) {
        if (in_mask == 0 || in_mask == 0xff) return r;  // a surface the coarse corners cannot see
        const glm::dvec3 x = merged.solve(tau);
        const glm::dvec3 lo = tree.lattice_point(base), hi = tree.lattice_point(base + glm::ivec3(s));
        const double slack = 1e-9 * tree.size;
        if (glm::any(glm::lessThan(x, lo - slack)) || glm::any(glm::greaterThan(x, hi + slack))) return r;
        if (std::sqrt(std::max(0.0, merged.error(x)) / merged.count) > tolerance) return r;
        std::uint16_t edges = 0;  // the parent's sign-changing cell edges
        for (int e = 0; e < 12; ++e)
            edges |= std::uint16_t((((in_mask >> cell_edge_corners[e][0]) ^ (in_mask >> cell_edge_corners[e][1])) & 1) << e);
        r.has_vertex = true;
        r.vertex = {glm::clamp(x, lo, hi), edges, 1};
    } else if (in_mask != 0 && in_mask != 0xff) {
        return r;  // sign changes without crossings: leave it alone
    }
    r.ok = true;
    r.signs = std::uint8_t(in_mask);
    return r;
}
// place_vertices, keeping the QEFs in tree.qefs when keep_qefs, and with `fused` (Cartesian trees) simplifying on
// the way: the one-shot function's path, which needs no QEF per vertex (memory).
struct FusedSimplify {
    double tolerance = 0.0, tau = 0.01;  // simplify's arguments
    std::size_t collapses = 0;
};
std::size_t place_vertices_impl(Octree& tree, const VertexParams& params, bool keep_qefs, FusedSimplify* fused) {
    tree.vertices.clear();
    tree.qefs.clear();
    const bool spherical = tree.coordinates == Coordinates::spherical;
    const std::int32_t n_res = tree.resolution();
    std::size_t crossings = 0;
    // Finest edges are shared by the 4 leaves around them: compute each crossing once. An edge is filed under its
    // lower end and axis, as canonical() names the end. Spherical trees: canonical() merges the lattice points on the
    // polar axis (all φ) and, when r_min = 0, at the origin, so the θ-edges leaving a pole or the radial edges leaving
    // the origin would share one entry; an edge whose lower end is such a point is filed under its upper end instead
    // (the radial edges on the axis, one edge for all φ, then still share theirs). Crossings live in a pool whose
    // rooms are reused once no group needs them (SharedCrossings).
    auto merged_point = [&](glm::ivec3 q) {
        return spherical && (q.y == 0 || q.y == n_res || (q.x == 0 && tree.r_min == 0.0));
    };
    SharedCrossings shared;
    std::vector<Crossing> computed;  // the pool of crossings
    std::vector<std::uint32_t> free_rooms;  // rooms of `computed` to reuse
    auto keep = [&](const Crossing& x) {
        if (free_rooms.empty()) {
            computed.push_back(x);
            return std::uint32_t(computed.size() - 1);
        }
        const std::uint32_t room = free_rooms.back();
        free_rooms.pop_back();
        computed[room] = x;
        return room;
    };
    const std::array<CellSurface, 256>& surfaces = plain_surfaces();
    // Speed: in the conservative band about half the leaves are cut by the surface, each with about one new crossing;
    // reserving that much avoids most copies of these large arrays while they grow (7 of 8 nodes are leaves). The
    // QEFs (112 bytes a vertex) ask for 2 MiB pages (lib memory.hpp); the vertices (32 bytes) do not: a 2 MiB page
    // is resident as a whole, and the one-shot's peak memory is what they would add to (handout §Performance).
    const std::size_t leaves_estimate = tree.nodes.size() - tree.nodes.size() / 8;
    tree.vertices.reserve(leaves_estimate / 2);
    if (keep_qefs) {
        tree.qefs.reserve(leaves_estimate / 2);
        prefer_huge_pages(tree.qefs);
    }
    // Speed: the lambdas below take lattice points by reference: passed by value, a glm::ivec3 travels in two 64-bit
    // registers that the compiler assembled from 32-bit stores to memory, a store-forwarding stall per call
    // the crossing on the edge from lattice point qc (value vc) to qd = qc + e_a (value vd)
    auto compute = [&](const glm::ivec3& qc, const glm::ivec3& qd, double vc, double vd) {
        ++crossings;
        return spherical ? find_crossing_arc(*tree.field, tree.origin, tree.lattice_spherical(qc),
                                             tree.lattice_spherical(qd), vc, vd, params.crossing_tolerance)
                         : find_crossing(*tree.field, tree.lattice_point(qc), tree.lattice_point(qd), vc, vd,
                                         params.crossing_tolerance);
    };
    // The groups of finest leaves that need the crossing of the finest edge from qc along axis a: the parents of
    // level L − 1 around it. One along a; along each other axis b one when qc_b is odd (the edge runs through the
    // parent), else the two on either side, less those outside the domain. Spherical trees: 1 for an edge inside its
    // parent, else 0 (the φ seam and the poles join parents irregularly: those crossings are kept to the end).
    auto groups_sharing = [&](const glm::ivec3& qc, int a) {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        if ((qc[b] & 1) && (qc[c] & 1)) return 1u;
        if (spherical) return 0u;
        auto around = [&](int k) { return qc[k] & 1 ? 1u : std::uint32_t(qc[k] > 0) + std::uint32_t(qc[k] < n_res); };
        return around(b) * around(c);
    };
    // the crossing of a finest edge, computed once: its room in `computed`; `done` collects the rooms this group is
    // the last to need
    auto finest_crossing = [&](const glm::ivec3& qc, const glm::ivec3& qd, int a, double vc, double vd,
                               std::uint32_t* done, int& n_done) {
        const std::uint32_t uses = groups_sharing(qc, a);
        if (uses == 1) {  // this group's alone (inside its parent, or on the domain's boundary)
            const std::uint32_t room = keep(compute(qc, qd, vc, vd));
            done[n_done++] = room;
            return room;
        }
        const bool upper = merged_point(qc);
        const glm::ivec3 q = tree.canonical(upper ? qd : qc);
        const std::uint64_t key = ((((std::uint64_t(q.x) << 11 | std::uint64_t(q.y)) << 11 | std::uint64_t(q.z)) << 2 |
                                    std::uint64_t(a)) << 1 | std::uint64_t(upper)) + 1;
        SharedCrossings::Entry& e = shared.find_or_add(key, uses);
        if (e.slot == invalid_index) e.slot = keep(compute(qc, qd, vc, vd));
        const std::uint32_t room = e.slot;
        if (e.uses != 0 && --e.uses == 0) {
            shared.erase(e);
            done[n_done++] = room;
        }
        return room;
    };
    // The vertex of a piece in the cell with corners q0 (lowest) and q7 (highest): the QEF's minimiser when it lies in
    // the cell, else the mass point (the mean of the piece's crossings), clamped into the cell. Clamping the minimiser
    // instead would pile vertices onto the cell's faces and corners, two pieces of one cell onto the same point,
    // and fold the mesh there (handout §1.1).
    auto cell_vertex = [&](const Qef& qef, const glm::ivec3& q0, const glm::ivec3& q7) {
        glm::dvec3 mass;
        const glm::dvec3 x = qef.solve(params.tau, &mass);
        if (!spherical) {
            const glm::dvec3 lo = tree.lattice_point(q0), hi = tree.lattice_point(q7);
            const bool in_cell = !glm::any(glm::lessThan(x, lo)) && !glm::any(glm::greaterThan(x, hi));
            return in_cell ? x : glm::clamp(mass, lo, hi);
        }
        const Spherical lo = tree.lattice_spherical(q0), hi = tree.lattice_spherical(q7);
        // φ relative to the cell's lower bound, in [0, 2π): inside when ≤ the cell's width
        const double w = hi.phi - lo.phi;
        auto phi_offset = [&](const Spherical& s) { return std::fmod(s.phi - lo.phi + 4.0 * pi, 2.0 * pi); };
        Spherical s = to_spherical(x - tree.origin);
        if (s.r < lo.r || s.r > hi.r || s.theta < lo.theta || s.theta > hi.theta || phi_offset(s) > w) {
            s = to_spherical(mass - tree.origin);
            s.r = std::clamp(s.r, lo.r, hi.r);
            s.theta = std::clamp(s.theta, lo.theta, hi.theta);
            double d = phi_offset(s);
            if (d > w) d = (d - w < 2.0 * pi - d) ? w : 0.0;
            s.phi = lo.phi + d;
        }
        return tree.spherical_point(s);
    };
    // leaf li's vertices, one per piece of its surface: piece k holds the crossings of qef[k] on the edges edges[k]
    auto add_vertices = [&](std::uint32_t li, const Qef* qef, const std::uint16_t* edges, int pieces,
                            const glm::ivec3& q0, const glm::ivec3& q7) {
        tree.nodes[li].vertex = std::uint32_t(tree.vertices.size());
        for (int k = 0; k < pieces; ++k) {
            tree.vertices.push_back({cell_vertex(qef[k], q0, q7), edges[k], std::uint8_t(pieces)});
            if (keep_qefs) tree.qefs.push_back(qef[k]);
        }
    };
    // the radial edge on the polar axis appears twice in a cell there (φ-lower and φ-upper corners): count it once
    auto repeated_axis_edge = [&](const CellEdge& e, glm::ivec3 qc) {
        return spherical && e.a == 0 && (e.c & 4) && (qc.y == 0 || qc.y == n_res);
    };
    // Speed (Cartesian trees of a field with a known Lipschitz constant Lf): a cell with |f(centre)| > Lf · (half
    // diagonal) holds no zero of f, so every corner has the centre's sign (the test of build_octree, with a margin
    // for rounding). One sample at the centre then stands for the 8 corners, which lie far apart in the sample cache
    // (each look-up a cache miss); most coarse leaves are such cells.
    const double lf = tree.field ? tree.field->lipschitz() : 0.0;
    const bool lipschitz_cells = !spherical && lf > 0.0 && !tree.field->sign_may_jump();
    // a leaf coarser than the finest level: its edges are not finest edges, nothing to share. *out (when not null)
    // receives its QEF if it has a vertex
    auto coarse_leaf = [&](std::uint32_t li, Qef* out) {
        OctreeNode& nd = tree.nodes[li];
        nd.vertex = invalid_index;
        if (lipschitz_cells) {
            const glm::ivec3 centre = tree.corner(nd, 0) + glm::ivec3(tree.cell_span(nd.level) / 2);
            const double vc = tree.sample(centre);
            const double half_diagonal = 0.5 * std::sqrt(3.0) * tree.size / double(std::int32_t(1) << nd.level);
            if (std::abs(vc) > lf * half_diagonal * (1.0 + 1e-9)) {
                nd.signs = inside(vc) ? 0xff : 0;
                return;
            }
        }
        glm::ivec3 q[8];
        double v[8];
        nd.signs = 0;
        for (int c = 0; c < 8; ++c) {
            q[c] = tree.corner(nd, c), v[c] = tree.value(q[c]);
            nd.signs |= std::uint8_t(inside(v[c]) << c);
        }
        // one vertex for all its crossings: its corners cannot tell its pieces apart where finer leaves see more
        const EdgeList& changing = changing_edges[nd.signs];
        Qef qef;
        std::uint16_t edges = 0;
        for (int ei = 0; ei < changing.n; ++ei) {
            const CellEdge& e = cell_edges[changing.e[ei]];
            edges |= std::uint16_t(1u << changing.e[ei]);
            if (repeated_axis_edge(e, q[e.c])) continue;
            const Crossing x = compute(q[e.c], q[e.d], v[e.c], v[e.d]);
            qef.add(x.point, x.normal);
        }
        if (qef.count == 0) return;
        add_vertices(li, &qef, &edges, 1, q[0], q[7]);
        if (out) *out = qef;
    };
    // Finest leaves come as the 8 children of a node of level L − 1: their 8 × 8 corners are the 27 points of the
    // parent's 3×3×3 sub-lattice, p = i + 3j + 9k, and their 8 × 12 edges are 54 edges of it. Speed: look the
    // samples up once (Octree::sub_lattice_values), find the sign-changing edges of the whole group with bit
    // operations, and get each of those crossings once for the 8 leaves. With `fused`, child_qef[c] receives child
    // c's QEF when it has one vertex (a leaf with several takes part in no collapse).
    auto finest_group = [&](std::uint32_t first, QefSlot (&child_qef)[8]) {
        const glm::ivec3 base = tree.corner(tree.nodes[first], 0);
        double sub[27];
        tree.sub_lattice_values(base, sub);
        std::uint32_t in = 0;  // bit p: sub-lattice point p is inside
        for (int p = 0; p < 27; ++p) in |= std::uint32_t(inside(sub[p])) << p;
        std::uint32_t index[3 * 27];  // the crossing of the group's edge from point p along axis a: index[27 a + p]
        std::uint32_t done[3 * 27];   // rooms of `computed` free once this group is done
        int n_done = 0;
        if (in != 0 && in != all_sub_points) {
            for (int a = 0; a < 3; ++a) {
                const int stride = a == 0 ? 1 : a == 1 ? 3 : 9;
                for (std::uint32_t m = (in ^ (in >> stride)) & edge_starts[a]; m; m &= m - 1) {
                    const int p = std::countr_zero(m);
                    // Speed: qd without qd[a] += 1, whose variable index made the compiler write qc and qd to
                    // memory and read them back whole before the stores had landed (a stall per edge)
                    const glm::ivec3 qc = base + sub_offset(p), qd = qc + glm::ivec3(a == 0, a == 1, a == 2);
                    index[27 * a + p] = finest_crossing(qc, qd, a, sub[p], sub[p + stride], done, n_done);
                }
            }
        }
        for (int child = 0; child < 8; ++child) {
            OctreeNode& ch = tree.nodes[first + child];
            const int offset = (child & 1) + 3 * ((child >> 1) & 1) + 9 * (child >> 2);
            const std::uint32_t s = in >> offset;  // the child's corners are the bits 0, 1, 3, 4, 9, 10, 12, 13 of s
            ch.signs = std::uint8_t((s & 0x3u) | ((s >> 1) & 0xcu) | ((s >> 5) & 0x30u) | ((s >> 6) & 0xc0u));
            ch.vertex = invalid_index;
            if (ch.signs == 0 || ch.signs == 0xff) continue;
            // one vertex per piece of the cell's surface (its ambiguous faces drawn by face_joins)
            const CellSurface* surface = &surfaces[ch.signs];
            CellSurface joined;
            if (has_ambiguous_face[ch.signs])
                if (const std::uint8_t joins = face_joins(tree, ch)) surface = &(joined = cell_surface(ch.signs, joins));
            const EdgeList& changing = changing_edges[ch.signs];
            Qef qef[4];
            for (int ei = 0; ei < changing.n; ++ei) {
                const CellEdge& e = cell_edges[changing.e[ei]];
                const int p = simplify_tables.point[child][e.c];
                if (spherical && repeated_axis_edge(e, base + sub_offset(p))) continue;
                const Crossing& x = computed[index[27 * e.a + p]];
                qef[surface->piece_of(changing.e[ei])].add(x.point, x.normal);
            }
            const glm::ivec3 q0 = base + glm::ivec3(child & 1, (child >> 1) & 1, child >> 2);
            add_vertices(first + child, qef, surface->edges, surface->count, q0, q0 + 1);
            if (fused && surface->count == 1) child_qef[child].qef = qef[0];
        }
        free_rooms.insert(free_rooms.end(), done, done + n_done);
    };
    auto finest_sibling_error = [](std::uint32_t n) {  // its parent has a child that is not a leaf: split() past L
        return std::logic_error("place_vertices: node " + std::to_string(n) + " of the finest level has a sibling "
                                "with children");
    };
    // Memory (fused: the one-shot's path). The samples of lattice points with an odd coordinate serve only the
    // groups of finest leaves, which the traversal below meets in Morton order (x fastest), where every cell's lower
    // neighbours come first. A region R of level L − 2 (4³ finest cells: one block of those samples) is read by the
    // groups of the regions R + d, d ∈ {−1, 0, 1}³ (face_joins looks one cell beyond a face); once R + (1, 1, 1), the last
    // of them in that order, is done, R's block is released. `pending`: (Morton key of R + (1, 1, 1), R).
    const int region_level = tree.max_level - 2;
    const bool release = fused && !spherical && region_level >= 2;
    const std::int32_t regions = std::int32_t(1) << std::max(region_level, 0);
    using Pending = std::pair<std::uint64_t, glm::ivec3>;
    auto later = [](const Pending& a, const Pending& b) { return a.first > b.first; };
    std::priority_queue<Pending, std::vector<Pending>, decltype(later)> pending(later);
    auto spread = [](std::uint64_t v) {  // the bits of v (< 2^10) 3 places apart
        v = (v | v << 16) & 0x30000ffull;
        v = (v | v << 8) & 0x300f00full;
        v = (v | v << 4) & 0x30c30c3ull;
        return (v | v << 2) & 0x9249249ull;
    };
    auto morton = [&](std::int32_t x, std::int32_t y, std::int32_t z) {
        return spread(std::uint64_t(x)) | spread(std::uint64_t(y)) << 1 | spread(std::uint64_t(z)) << 2;
    };
    // node nd (level ≤ L − 2) is done: so is every region before the end of its range in Morton order
    auto regions_done = [&](const OctreeNode& nd) {
        const int shift = region_level - nd.level;
        if (shift == 0) {
            const glm::ivec3 r(nd.x, nd.y, nd.z), last = glm::min(r + 1, glm::ivec3(regions - 1));
            pending.push({morton(last.x, last.y, last.z), r});
        }
        const std::uint64_t end = (morton(nd.x, nd.y, nd.z) + 1) << (3 * shift);
        while (!pending.empty() && pending.top().first < end) {
            tree.release_fine_samples(pending.top().second);
            pending.pop();
        }
    };
    // The leaves depth first, children in the order c = 0..7, a group of finest siblings at once. Fused with
    // simplify (memory), each node is tried for a collapse as soon as its subtree is done: the children's vertices
    // are then the last ones made, so a collapse takes them back, and the QEFs live on this recursion's stack, not
    // one per vertex. Returns whether node n is a leaf now; out: its QEF, written when it is a leaf with one vertex.
    auto visit = [&](auto& self, std::uint32_t n, QefSlot& out) -> bool {
        OctreeNode& nd = tree.nodes[n];
        if (nd.is_leaf()) {
            if (nd.level == tree.max_level) throw finest_sibling_error(n);
            coarse_leaf(n, fused ? &out.qef : nullptr);
            if (release && nd.level <= region_level) regions_done(nd);
            return true;
        }
        const std::size_t first_vertex = tree.vertices.size();
        QefSlot child_qef[8];
        bool all_leaves = true;
        if (has_finest_children(tree, nd)) {
            finest_group(nd.first_child, child_qef);
        } else {
            for (int c = 0; c < 8; ++c) all_leaves = self(self, nd.first_child + std::uint32_t(c), child_qef[c]) && all_leaves;
        }
        bool collapsed = false;
        if (fused && all_leaves) {
            const Collapse r = collapse_test(tree, nd, fused->tolerance, fused->tau,
                                             [&](int c, std::uint32_t) -> const Qef& { return child_qef[c].qef; });
            if (r.ok) {
                tree.vertices.resize(first_vertex);
                nd.first_child = invalid_index;
                nd.signs = r.signs;
                nd.vertex = invalid_index;
                if (r.has_vertex) {
                    nd.vertex = std::uint32_t(tree.vertices.size());
                    tree.vertices.push_back(r.vertex);
                    out.qef = r.merged.qef;
                }
                ++fused->collapses;
                collapsed = true;
            }
        }
        if (release && nd.level <= region_level) regions_done(nd);
        return collapsed;
    };
    QefSlot root_qef;
    visit(visit, 0, root_qef);
    return crossings;
}
}  // namespace
// END SOLUTION

std::size_t place_vertices(Octree& tree, const VertexParams& params) {
    // BEGIN SOLUTION
    return place_vertices_impl(tree, params, true, nullptr);
    // END SOLUTION
}

std::size_t simplify(Octree& tree, double tolerance, double tau) {
    // BEGIN SOLUTION
    if (tree.coordinates != Coordinates::cartesian)
        throw std::invalid_argument("simplify: only Cartesian octrees are simplified");
    if (tree.qefs.size() != tree.vertices.size())
        throw std::invalid_argument("simplify: tree.qefs must hold the QEF of every vertex (call place_vertices first)");
    std::size_t collapses = 0;
    constexpr std::uint32_t prefetch_distance = 32;  // vertices, about 4 groups of finest leaves
    // children always have larger indices than their parent: one reverse sweep is bottom-up
    for (std::size_t ni = tree.nodes.size(); ni-- > 0;) {
        const OctreeNode nd = tree.nodes[ni];
        if (nd.is_leaf()) continue;
        bool all_leaves = true;
        for (int c = 0; c < 8 && all_leaves; ++c) all_leaves = tree.nodes[nd.first_child + c].is_leaf();
        if (!all_leaves) continue;
        const Collapse r = collapse_test(tree, nd, tolerance, tau, [&](int, std::uint32_t vi) -> const Qef& {
            // Speed: this sweep meets the vertices in decreasing order (place_vertices made them in the order of the
            // nodes); ask for the QEFs a few groups ahead, or each merge waits for main memory
            if (vi >= prefetch_distance) {
                const char* ahead = reinterpret_cast<const char*>(&tree.qefs[vi - prefetch_distance]);
                for (std::size_t line = 0; line < sizeof(Qef); line += 64) __builtin_prefetch(ahead + line);
            }
            return tree.qefs[vi];
        });
        if (!r.ok) continue;
        OctreeNode& parent = tree.nodes[ni];
        parent.first_child = invalid_index;
        parent.vertex = invalid_index;
        parent.signs = r.signs;
        if (r.has_vertex) {
            parent.vertex = std::uint32_t(tree.vertices.size());
            tree.vertices.push_back(r.vertex);
            tree.qefs.push_back(r.merged.qef);
        }
        ++collapses;
    }
    return collapses;
    // END SOLUTION
}


PolygonSoup contour(const Octree& tree, std::vector<PoleRing>* poles) {
    // BEGIN SOLUTION
    // a leaf as the polygons see it: node index, dual vertex (or invalid_index) and level. A finest leaf found
    // through the `finest` grid below has leaf == invalid_index when it has a vertex: the vertex identifies it.
    // `vertex` is first the leaf's first vertex, then (piece()) the vertex of the piece that crosses the edge.
    struct LeafRef {
        std::uint32_t leaf = invalid_index, vertex = invalid_index;
        int level = 0;
        bool found() const { return leaf != invalid_index || vertex != invalid_index; }
        bool same(const LeafRef& o) const {
            return vertex == o.vertex && (vertex != invalid_index || leaf == o.leaf);
        }
    };
    PolygonSoup soup;
    if (poles) poles->clear();
    const bool spherical = tree.coordinates == Coordinates::spherical;
    const std::int32_t n_res = tree.resolution();
    std::vector<std::uint32_t> remap(tree.vertices.size(), invalid_index);
    // Speed: reserve the output (at most one position per dual vertex; a closed triangle mesh has about twice as
    // many faces as vertices, Euler) so it is written once instead of copied while it grows.
    soup.positions.reserve(tree.vertices.size());
    soup.indices.reserve(6 * tree.vertices.size());
    soup.offsets.reserve(2 * tree.vertices.size() + 1);
    prefer_huge_pages(soup.positions);  // Speed: 2 MiB pages for large arrays (lib memory.hpp)
    prefer_huge_pages(soup.indices);
    prefer_huge_pages(soup.offsets);
    // the vertex standing for the piece that crosses cell edge e of the leaf whose first vertex is `first`
    auto piece_vertex = [&](std::uint32_t first, int e) {
        if (first == invalid_index) return first;
        const std::uint32_t n = tree.vertices[first].pieces;
        if (n <= 1) return first;
        for (std::uint32_t k = 0; k < n; ++k)
            if ((tree.vertices[first + k].edges >> e) & 1u) return first + k;
        throw TopologyError("contour: the leaf with vertices " + std::to_string(first) + " .. " +
                            std::to_string(first + n - 1) + " has none whose edges hold its sign-changing edge " +
                            std::to_string(e));
    };
    auto soup_index = [&](std::uint32_t vertex) {
        if (remap[vertex] == invalid_index) {
            remap[vertex] = std::uint32_t(soup.positions.size());
            soup.positions.push_back(tree.vertices[vertex].position);
        }
        return remap[vertex];
    };
    auto soup_vertex = [&](const LeafRef& l) {
        if (l.vertex == invalid_index)
            throw TopologyError("contour: leaf " + std::to_string(l.leaf) + " around a sign-changing edge has no vertex");
        return soup_index(l.vertex);
    };
    auto leaf_ref = [&](std::uint32_t l) { return LeafRef{l, tree.nodes[l].vertex, tree.nodes[l].level}; };
    // The finest leaves by cell index, to reach neighbours at the finest level without descending the tree: a grid
    // over the cells of level L − 1 holding the first child of each node there that has children (memory: 4 bytes
    // for 8 finest cells; their 8 nodes are side by side in the node array).
    BlockGrid<std::uint32_t> parents(invalid_index, std::max(n_res / 2, 1));
    // One depth-first walk fills the grid and sorts the leaves: `groups` holds the first child of every node of
    // level L − 1 whose 8 children are (finest) leaves, `others` every other leaf. Speed: the Cartesian polygons
    // are made a group at a time (finest_group below); spherical trees take every leaf one by one (`others`).
    std::vector<std::uint32_t> groups, others;
    tree.depth_first([&](std::uint32_t n) {
        const OctreeNode& nd = tree.nodes[n];
        if (nd.is_leaf()) {
            others.push_back(n);
            return false;
        }
        if (nd.level + 1 == tree.max_level) parents.slot({nd.x, nd.y, nd.z}) = nd.first_child;
        if (!has_finest_children(tree, nd)) return true;
        const std::uint32_t first = nd.first_child;
        if (spherical)
            for (int c = 0; c < 8; ++c) others.push_back(first + c);
        else
            groups.push_back(first);
        return false;
    });
    // the node of finest cell `cell` when it is a leaf, or null (not a finest leaf, or outside the domain)
    auto finest_leaf = [&](glm::ivec3 cell) -> const OctreeNode* {
        if (spherical) cell.z &= n_res - 1;
        if (cell.x < 0 || cell.y < 0 || cell.z < 0 || cell.x >= n_res || cell.y >= n_res || cell.z >= n_res)
            return nullptr;
        const std::uint32_t first = parents.get({cell.x >> 1, cell.y >> 1, cell.z >> 1});
        if (first == invalid_index) return nullptr;
        const OctreeNode& nd = tree.nodes[first + std::uint32_t((cell.x & 1) | (cell.y & 1) << 1 | (cell.z & 1) << 2)];
        return nd.is_leaf() ? &nd : nullptr;
    };
    // the vertex of the finest leaf in finest cell `cell`, or invalid_index when that cell is not a finest leaf with
    // a vertex (or outside the domain)
    auto finest_vertex = [&](glm::ivec3 cell) {
        const OctreeNode* nd = finest_leaf(cell);
        return nd ? nd->vertex : invalid_index;
    };
    // Speed: the vertex of finest leaf nd's piece crossing its cell edge e (nd.vertex if it has none). A finest leaf
    // whose signs draw one piece and no ambiguous face has one vertex (DualVertex's layout): no need to read it.
    const std::array<CellSurface, 256>& surfaces = plain_surfaces();
    auto finest_piece = [&](const OctreeNode& nd, int e) {
        if (nd.vertex == invalid_index || (surfaces[nd.signs].count == 1 && !has_ambiguous_face[nd.signs]))
            return nd.vertex;
        return piece_vertex(nd.vertex, e);
    };
    auto find_leaf = [&](glm::ivec3 p2) {
        // p2 has odd coordinates: the finest cell containing it is p2 / 2; a finest leaf without a vertex is looked up
        // again by locate() so that the error names it
        const std::uint32_t v = finest_vertex({p2.x >> 1, p2.y >> 1, p2.z >> 1});
        if (v != invalid_index) return LeafRef{invalid_index, v, tree.max_level};
        std::uint32_t l = tree.locate(p2);
        return l == invalid_index ? LeafRef{} : leaf_ref(l);
    };
    // Level 1 of a spherical tree: the 2 φ cells share both their φ faces, so the polygons around the edges at φ = 0
    // and at φ = π join the same 4 vertices; the second takes the other diagonal (the same one would cover the same
    // two triangles twice). Each quad there: its sorted vertices and the diagonal it took.
    std::vector<std::pair<std::array<std::uint32_t, 4>, std::pair<std::uint32_t, std::uint32_t>>> level1_quads;
    // The polygon w[0 .. m) around the edge from lattice point q0 to q0 + span e_a (counter-clockwise about the edge's
    // outward direction: +a when its lower end is inside). A quad is split along the diagonal whose two triangles
    // both face outward (normal · outward direction > 0) when only one of the two does — the other would fold the
    // mesh —, else along the shorter diagonal.
    auto emit_polygon = [&](const std::uint32_t* w, int m, const glm::ivec3& q0, int a, std::int32_t span,
                            bool lower_inside) {
        if (m == 3) {
            soup.add_face({w[0], w[1], w[2]});
        } else {
            const auto& P = soup.positions;
            const glm::dvec3 d02 = P[w[2]] - P[w[0]], d13 = P[w[3]] - P[w[1]];
            bool first = glm::dot(d02, d02) <= glm::dot(d13, d13);  // the diagonal w[0] w[2]
            glm::ivec3 q1 = q0;
            q1[a] += span;
            const glm::dvec3 out = (lower_inside ? 1.0 : -1.0) * (tree.lattice_point(q1) - tree.lattice_point(q0));
            auto faces_out = [&](int i, int j, int k) {
                return glm::dot(glm::cross(P[w[j]] - P[w[i]], P[w[k]] - P[w[i]]), out) > 0.0;
            };
            const bool out02 = faces_out(0, 1, 2) && faces_out(0, 2, 3), out13 = faces_out(0, 1, 3) && faces_out(1, 2, 3);
            if (out02 != out13) first = out02;
            if (spherical && n_res == 2) {
                std::array<std::uint32_t, 4> key{w[0], w[1], w[2], w[3]};
                std::sort(key.begin(), key.end());
                auto diagonal = [](std::uint32_t x, std::uint32_t y) { return std::pair(std::min(x, y), std::max(x, y)); };
                for (const auto& [k, d] : level1_quads)
                    if (k == key) first = d != diagonal(w[0], w[2]);
                level1_quads.push_back({key, first ? diagonal(w[0], w[2]) : diagonal(w[1], w[3])});
            }
            if (first) {
                soup.add_face({w[0], w[1], w[2]});
                soup.add_face({w[0], w[2], w[3]});
            } else {
                soup.add_face({w[0], w[1], w[3]});
                soup.add_face({w[1], w[2], w[3]});
            }
        }
    };
    // The general path for the sign-changing edge e of leaf li (any level): the leaves in the 4 quadrants by find_leaf
    // (locate()), emitted by the first quadrant holding a leaf as small as li, unless a smaller leaf subdivides it.
    auto general_edge = [&](std::uint32_t li, const OctreeNode& nd, const CellEdge& e) {
        const int a = e.a, b = e.b, cax = e.cax, c = e.c, my_b = e.my_b, my_c = e.my_c;
        glm::ivec3 m2 = 2 * tree.corner(nd, c);
        m2[a] += tree.cell_span(nd.level);
        LeafRef around[4];
        bool emit = true;
        for (int k = 0; k < 4 && emit; ++k) {
            if (qb[k] == my_b && qc[k] == my_c) {
                around[k] = LeafRef{li, piece_vertex(nd.vertex, e.edge_in[k]), nd.level};
                continue;
            }
            glm::ivec3 p2 = m2;
            p2[b] += qb[k];
            p2[cax] += qc[k];
            around[k] = find_leaf(p2);
            if (!around[k].found()) emit = false;  // outside the domain
            else if (around[k].level > nd.level) emit = false;  // not minimal here
            else {
                // a leaf with several vertices is a finest one, as this leaf then: the edge is its cell edge edge_in[k]
                around[k].vertex = piece_vertex(around[k].vertex, e.edge_in[k]);
                // emit once: from the first quadrant holding a leaf as small as this one
                bool before_me = false;
                for (int j = 0; j < 4; ++j)
                    if (qb[j] == my_b && qc[j] == my_c) break;
                    else if (j == k) before_me = true;
                if (before_me && around[k].level == nd.level) emit = false;
            }
        }
        if (!emit) return;
        // drop repeated leaves (adaptive trees), orient by the sign at the lower end
        LeafRef poly[4];
        int m = 0;
        for (int k = 0; k < 4; ++k) {
            const LeafRef& l = nd.corner_inside(c) ? around[k] : around[3 - k];
            if (m == 0 || !poly[m - 1].same(l)) poly[m++] = l;
        }
        if (m > 1 && poly[m - 1].same(poly[0])) --m;
        if (m < 3) return;
        std::uint32_t w[4];
        for (int k = 0; k < m; ++k) w[k] = soup_vertex(poly[k]);
        emit_polygon(w, m, tree.corner(nd, c), a, tree.cell_span(nd.level), nd.corner_inside(c));
    };
    // Speed (Cartesian): the 8 finest leaves of a node of level L − 1 as one group. Their corner signs are the 27
    // points of the node's 3×3×3 sub-lattice (bit p = i + 3j + 9k, as in simplify). The group emits the quads of the
    // sign-changing edges whose quadrant-0 cell is one of its leaves: the 4 cells around such an edge are its own
    // leaves or finest leaves of the groups above it along b and c. A sign-changing edge whose quadrant-0 cell lies
    // in a group below is that group's, unless that cell is not a finest leaf with a vertex: then, and wherever a
    // cell around is not one, the general path decides (as the leaf-by-leaf loop below would).
    auto finest_group = [&](std::uint32_t first) {
        std::uint32_t in = 0, v[8];
        const OctreeNode* child_node = &tree.nodes[first];
        for (int child = 0; child < 8; ++child) {
            const OctreeNode& ch = child_node[child];
            in |= simplify_tables.spread[child][ch.signs];
            v[child] = ch.vertex;
        }
        if (in == 0 || in == all_sub_points) return;
        const glm::ivec3 base(tree.nodes[first].x, tree.nodes[first].y, tree.nodes[first].z);  // child 0's cell
        for (int a = 0; a < 3; ++a) {
            const int stride = a == 0 ? 1 : a == 1 ? 3 : 9;
            for (std::uint32_t m = (in ^ (in >> stride)) & edge_starts[a]; m; m &= m - 1) {
                const int p = std::countr_zero(m);
                const GroupEdge& g = group_edges[a][p];
                auto neighbour = [&](int k) { return finest_leaf(base + glm::ivec3(g.d[k][0], g.d[k][1], g.d[k][2])); };
                if (g.child[0] < 0) {  // quadrant 0 is below this group
                    const OctreeNode* below = neighbour(0);
                    if (below && below->vertex != invalid_index) continue;
                    for (int k = 1; k < 4; ++k) {
                        if (g.child[k] < 0) continue;
                        const std::uint32_t li = first + std::uint32_t(g.child[k]);
                        if (v[g.child[k]] != invalid_index) general_edge(li, tree.nodes[li], cell_edges[g.edge[k]]);
                    }
                    continue;
                }
                std::uint32_t around[4];  // the piece vertex of each quadrant's leaf
                bool all_finest = true;
                for (int k = 0; k < 4 && all_finest; ++k) {
                    const OctreeNode* leaf = g.child[k] >= 0 ? &child_node[g.child[k]] : neighbour(k);
                    around[k] = leaf ? finest_piece(*leaf, g.edge[k]) : invalid_index;
                    all_finest = around[k] != invalid_index;
                }
                if (all_finest) {
                    std::uint32_t w[4];
                    const bool lower_inside = (in >> p) & 1u;
                    for (int k = 0; k < 4; ++k) w[k] = soup_index(around[lower_inside ? k : 3 - k]);
                    emit_polygon(w, 4, tree.corner(tree.nodes[first], 0) + sub_offset(p), a, 1, lower_inside);
                } else {
                    const std::uint32_t li = first + std::uint32_t(g.child[0]);
                    if (v[g.child[0]] != invalid_index) general_edge(li, tree.nodes[li], cell_edges[g.edge[0]]);
                }
            }
        }
    };
    for (std::uint32_t first : groups) finest_group(first);
    for (std::uint32_t li : others) {
        const OctreeNode& nd = tree.nodes[li];
        if (nd.vertex == invalid_index) continue;
        const std::int32_t span = tree.cell_span(nd.level);
        const bool finest_leaf = nd.level == tree.max_level;
        const glm::ivec3 cell(nd.x, nd.y, nd.z);
        const EdgeList& changing = changing_edges[nd.signs];
        for (int ei = 0; ei < changing.n; ++ei) {
            const CellEdge& e = cell_edges[changing.e[ei]];
            const int a = e.a, c = e.c;
            const glm::ivec3 q0 = tree.corner(nd, c);
            if (spherical) {
                if (a == 0 && (q0.y == 0 || q0.y == n_res)) continue;  // on the polar axis: a pole ring
                if (a != 0 && q0.x == 0) continue;                     // on the inner sphere: no cells below
            }
            if (finest_leaf) {
                // Speed: where the 4 leaves around the edge are finest (the common case), the leaf in quadrant 0
                // emits the quad; the others only check that it exists. Anything else takes the general path.
                auto quadrant_cell = [&](int k) { return cell + glm::ivec3(e.dx[k], e.dy[k], e.dz[k]); };
                if (e.quadrant != 0) {
                    // the leaf in quadrant 0 is a sibling (it is below this one only along axes where this one is the
                    // upper child): a finest leaf sharing this sign-changing edge, so it has a vertex
                    const int upper_child = (nd.x & 1) | (nd.y & 1) << 1 | (nd.z & 1) << 2;
                    if ((upper_child & e.owner_below) == e.owner_below) continue;
                    if (finest_vertex(quadrant_cell(0)) != invalid_index) continue;
                } else {
                    std::uint32_t v[4] = {nd.vertex, finest_vertex(quadrant_cell(1)), finest_vertex(quadrant_cell(2)),
                                          finest_vertex(quadrant_cell(3))};
                    if (v[1] != invalid_index && v[2] != invalid_index && v[3] != invalid_index) {
                        std::uint32_t w[4];
                        const bool lower_inside = nd.corner_inside(c);
                        for (int k = 0; k < 4; ++k) {
                            const int j = lower_inside ? k : 3 - k;
                            w[k] = soup_index(piece_vertex(v[j], e.edge_in[j]));
                        }
                        emit_polygon(w, 4, tree.corner(nd, c), a, 1, lower_inside);
                        continue;
                    }
                }
            }
            general_edge(li, nd, e);
        }
        // spherical: the radial edge on the polar axis, collected once by the leaf at φ index 0
        if (!spherical || !poles || nd.z != 0) continue;
        for (int pole = 0; pole < 2; ++pole) {
            const bool north = pole == 0;
            if (north ? nd.y != 0 : (std::int32_t(nd.y) + 1) * span != n_res) continue;
            const int c0 = north ? 0 : 2, c1 = c0 | 1;  // lower-φ corners on the axis, inner and outer radius
            if (nd.corner_inside(c0) == nd.corner_inside(c1)) continue;
            glm::ivec3 p2(2 * tree.corner(nd, c0).x + span, north ? 1 : 2 * n_res - 1, 0);
            std::vector<LeafRef> ring;
            bool minimal = true;
            for (std::int32_t k = 0; k < n_res && minimal; ++k) {
                p2.z = 2 * k + 1;
                std::uint32_t l = tree.locate(p2);
                if (l == invalid_index || tree.nodes[l].level > nd.level) minimal = false;
                else if (ring.empty() || ring.back().leaf != l) {
                    // the piece crossing the axis edge: cell edge 0 (north: corners 0, 1) or 1 (south: 2, 3)
                    LeafRef r = leaf_ref(l);
                    r.vertex = piece_vertex(r.vertex, north ? 0 : 1);
                    ring.push_back(r);
                }
            }
            if (!minimal) continue;  // cannot happen without simplification: all ring leaves are finest
            if (ring.size() > 1 && ring.back().same(ring.front())) ring.pop_back();
            // increasing φ is counter-clockwise seen from +Z; outward is +r (±Z) when the inner end is inside
            if (nd.corner_inside(c0) != north) std::reverse(ring.begin(), ring.end());
            PoleRing pr;
            pr.north = north;
            pr.r_lo = tree.lattice_spherical(tree.corner(nd, c0)).r;
            pr.r_hi = tree.lattice_spherical(tree.corner(nd, c1)).r;
            for (const LeafRef& l : ring) pr.ring.push_back(soup_vertex(l));
            poles->push_back(std::move(pr));
        }
    }
    return soup;
    // END SOLUTION
}

PolygonSoup dual_contour_cartesian(const ScalarField& f, const CartesianParams& params, DcStats* stats) {
    // BEGIN SOLUTION
    auto t0 = std::chrono::steady_clock::now();
    Octree tree = build_octree(f, params);
    // place_vertices and simplify in one pass (memory: no QEF per vertex, no second sweep), then the polygons
    // without the samples, which they do not read: the same soup as place_vertices, simplify and contour
    FusedSimplify fused{params.simplify_tolerance * tree.size / tree.resolution(), params.tau};
    const std::size_t crossings = place_vertices_impl(tree, {params.tau, params.crossing_tolerance}, false,
                                                      params.simplify_tolerance > 0.0 ? &fused : nullptr);
    const std::size_t collapses = fused.collapses;
    tree.release_samples();
    PolygonSoup soup = contour(tree);
    if (stats) {
        *stats = DcStats{};
        // build_octree makes only reachable nodes, and each collapse detaches 8 (Speed: no traversal)
        stats->cells = tree.nodes.size() - 8 * collapses;
        stats->leaves = stats->cells - (stats->cells - 1) / 8;  // every inner node has 8 children: 7 I + 1 leaves
        stats->samples = tree.samples();
        stats->crossings = crossings;
        stats->collapses = collapses;
        stats->vertices = soup.n_vertices();
        stats->faces = soup.n_faces();
        stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    return soup;
    // END SOLUTION
}

}  // namespace geolab::dc
