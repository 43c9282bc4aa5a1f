// Lab 09 — task 4: dual vertices, simplification and polygons; the Cartesian one-shot function.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"

namespace geolab::dc {

std::size_t place_vertices(Octree& tree, const VertexParams& params) {
    // BEGIN SOLUTION
    tree.vertices.clear();
    const bool spherical = tree.coordinates == Coordinates::spherical;
    const std::int32_t n_res = tree.resolution();
    std::size_t crossings = 0;
    const std::vector<std::uint32_t> leaves = tree.leaves();
    // finest edges are shared by 4 leaves: compute each crossing once, keyed by the edge's doubled midpoint
    BlockGrid<std::uint32_t> edge_crossing(invalid_index, 2 * n_res + 1);
    std::vector<Crossing> computed;
    // Speed: in the conservative band about half the leaves are cut by the surface, each with about one new crossing;
    // reserving that much avoids most copies of these large arrays while they grow.
    tree.vertices.reserve(leaves.size() / 2);
    computed.reserve(leaves.size() / 2);
    // Hermite data and vertex of leaf li, given its corner lattice points q and samples v
    auto place = [&](std::uint32_t li, const glm::ivec3 (&q)[8], const double (&v)[8]) {
        OctreeNode& nd = tree.nodes[li];
        nd.vertex = invalid_index;
        nd.signs = 0;
        for (int c = 0; c < 8; ++c) nd.signs |= std::uint8_t(inside(v[c]) << c);
        if (nd.signs == 0 || nd.signs == 0xff) return;
        // Hermite data on the 12 edges: corner c → c | (1 << a) for the corners c with bit a clear
        Qef qef;
        for (int a = 0; a < 3; ++a)
            for (int c = 0; c < 8; ++c) {
                if (c & (1 << a)) continue;
                const int d = c | (1 << a);
                if (inside(v[c]) == inside(v[d])) continue;
                // the radial edge on the polar axis appears twice (φ-lower and φ-upper corners): count it once
                if (spherical && a == 0 && (c & 4) && (q[c].y == 0 || q[c].y == n_res)) continue;
                std::uint32_t* cached = nullptr;
                if (nd.level == tree.max_level) {
                    glm::ivec3 m2 = 2 * tree.canonical(q[c]);
                    m2[a] += 1;
                    cached = &edge_crossing.slot(m2);
                    if (*cached != invalid_index) {
                        qef.add(computed[*cached].point, computed[*cached].normal);
                        continue;
                    }
                }
                Crossing x = spherical ? find_crossing_arc(*tree.field, tree.origin, tree.lattice_spherical(q[c]),
                                                           tree.lattice_spherical(q[d]), v[c], v[d],
                                                           params.crossing_tolerance)
                                       : find_crossing(*tree.field, tree.lattice_point(q[c]),
                                                       tree.lattice_point(q[d]), v[c], v[d],
                                                       params.crossing_tolerance);
                qef.add(x.point, x.normal);
                ++crossings;
                if (cached) {
                    *cached = std::uint32_t(computed.size());
                    computed.push_back(x);
                }
            }
        if (qef.count == 0) return;  // only degenerate edges changed sign (cannot happen with canonical samples)
        glm::dvec3 x = qef.solve(params.tau);
        // keep the vertex in its cell
        if (!spherical) {
            x = glm::clamp(x, tree.lattice_point(q[0]), tree.lattice_point(q[7]));
        } else {
            Spherical lo = tree.lattice_spherical(q[0]), hi = tree.lattice_spherical(q[7]);
            Spherical s = to_spherical(x - tree.origin);
            s.r = std::clamp(s.r, lo.r, hi.r);
            s.theta = std::clamp(s.theta, lo.theta, hi.theta);
            // φ relative to the cell's lower bound, in [0, 2π): inside when ≤ the cell's width
            double w = hi.phi - lo.phi, d = std::fmod(s.phi - lo.phi + 4.0 * pi, 2.0 * pi);
            if (d > w) d = (d - w < 2.0 * pi - d) ? w : 0.0;
            s.phi = lo.phi + d;
            x = tree.spherical_point(s);
        }
        nd.vertex = std::uint32_t(tree.vertices.size());
        tree.vertices.push_back({x, qef});
    };
    for (std::size_t i = 0; i < leaves.size(); ++i) {
        const OctreeNode& nd = tree.nodes[leaves[i]];
        glm::ivec3 q[8];
        double v[8];
        // Speed: finest leaves come as 8 siblings in a row (depth-first order); their 8 × 8 corners are the 27
        // points of the parent's 3×3×3 sub-lattice. Look those up once, not 64 times: the sample cache is large
        // and its look-ups (a hash probe when the block changes, then the value) often miss the processor caches.
        bool group = nd.level == tree.max_level && ((nd.x | nd.y | nd.z) & 1) == 0 && i + 8 <= leaves.size() &&
                     leaves[i + 7] == leaves[i] + 7;
        if (!group) {
            for (int c = 0; c < 8; ++c) q[c] = tree.corner(nd, c), v[c] = tree.value(q[c]);
            place(leaves[i], q, v);
            continue;
        }
        const glm::ivec3 base = tree.corner(nd, 0);
        double sub[27];  // sub[l + 3 j + 9 k] = f(base + (l, j, k))
        for (int k = 0; k < 3; ++k)
            for (int j = 0; j < 3; ++j)
                for (int l = 0; l < 3; ++l) sub[l + 3 * j + 9 * k] = tree.value(base + glm::ivec3(l, j, k));
        for (int child = 0; child < 8; ++child) {
            const glm::ivec3 o(child & 1, (child >> 1) & 1, child >> 2);
            for (int c = 0; c < 8; ++c) {
                const glm::ivec3 p = o + glm::ivec3(c & 1, (c >> 1) & 1, c >> 2);
                q[c] = base + p;
                v[c] = sub[p.x + 3 * p.y + 9 * p.z];
            }
            place(leaves[i + child], q, v);
        }
        i += 7;
    }
    return crossings;
    // END SOLUTION
}

std::size_t simplify(Octree& tree, double tolerance, double tau) {
    // BEGIN SOLUTION
    if (tree.coordinates != Coordinates::cartesian)
        throw std::invalid_argument("simplify: only Cartesian octrees are simplified");
    // are the corners in `mask` (bit c = corner c) connected through cube edges?
    auto connected = [](int mask) {
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
    };
    std::size_t collapses = 0;
    // children always have larger indices than their parent: one reverse sweep is bottom-up
    for (std::size_t ni = tree.nodes.size(); ni-- > 0;) {
        OctreeNode nd = tree.nodes[ni];
        if (nd.is_leaf()) continue;
        bool all_leaves = true;
        for (int c = 0; c < 8 && all_leaves; ++c) all_leaves = tree.nodes[nd.first_child + c].is_leaf();
        if (!all_leaves) continue;
        // (1) the parent's corner signs form one sheet
        const std::int32_t s = tree.cell_span(nd.level);
        const glm::ivec3 base = tree.corner(nd, 0);
        // inside at the sub-lattice point base + (i, j, k) h, (i, j, k) ∈ {0,1,2}³: a corner of the child
        // (min(i,1), min(j,1), min(k,1)), whose sign configuration place_vertices recorded
        auto sign_at = [&](int i, int j, int k) {
            const int ci = std::min(i, 1), cj = std::min(j, 1), ck = std::min(k, 1);
            const OctreeNode& child = tree.nodes[nd.first_child + ci + 2 * cj + 4 * ck];
            return child.corner_inside((i - ci) + 2 * (j - cj) + 4 * (k - ck));
        };
        int in_mask = 0;
        for (int c = 0; c < 8; ++c)
            if (sign_at(2 * (c & 1), (c & 2), (c & 4) / 2)) in_mask |= 1 << c;
        if (!connected(in_mask) || !connected(~in_mask & 0xff)) continue;
        // (2) every sub-lattice point (i, j, k) ∈ {0,1,2}³ with a 1 agrees with a corner of the parent's
        //     edge / face / cell it is the centre of: the corners obtained by replacing each 1 with 0 or 2
        bool safe = true;
        for (int i = 0; i < 3 && safe; ++i)
            for (int j = 0; j < 3 && safe; ++j)
                for (int k = 0; k < 3 && safe; ++k) {
                    if (i != 1 && j != 1 && k != 1) continue;
                    bool sm = sign_at(i, j, k), agrees = false;
                    for (int c = 0; c < 8 && !agrees; ++c) {
                        int ci = i == 1 ? 2 * (c & 1) : i, cj = j == 1 ? (c & 2) : j, ck = k == 1 ? (c & 4) / 2 : k;
                        agrees = sign_at(ci, cj, ck) == sm;
                    }
                    safe = agrees;
                }
        if (!safe) continue;
        // (3) the merged QEF fits well and its minimiser lies in the cell
        Qef merged;
        for (int c = 0; c < 8; ++c) {
            std::uint32_t vi = tree.nodes[nd.first_child + c].vertex;
            if (vi != invalid_index) merged.merge(tree.vertices[vi].qef);
        }
        std::uint32_t new_vertex = invalid_index;
        if (merged.count > 0) {
            if (in_mask == 0 || in_mask == 0xff) continue;  // a surface the coarse corners cannot see
            glm::dvec3 x = merged.solve(tau);
            glm::dvec3 lo = tree.lattice_point(base), hi = tree.lattice_point(base + glm::ivec3(s));
            double slack = 1e-9 * tree.size;
            if (glm::any(glm::lessThan(x, lo - slack)) || glm::any(glm::greaterThan(x, hi + slack))) continue;
            if (std::sqrt(std::max(0.0, merged.error(x)) / merged.count) > tolerance) continue;
            new_vertex = std::uint32_t(tree.vertices.size());
            tree.vertices.push_back({glm::clamp(x, lo, hi), merged});
        } else if (in_mask != 0 && in_mask != 0xff) {
            continue;  // sign changes without crossings: leave it alone
        }
        tree.nodes[ni].first_child = invalid_index;
        tree.nodes[ni].vertex = new_vertex;
        tree.nodes[ni].signs = std::uint8_t(in_mask);
        ++collapses;
    }
    return collapses;
    // END SOLUTION
}

PolygonSoup contour(const Octree& tree, std::vector<PoleRing>* poles) {
    // BEGIN SOLUTION
    // a leaf as the polygons see it: node index, dual vertex (or invalid_index) and level. A finest leaf found
    // through the `finest` grid below has leaf == invalid_index when it has a vertex: the vertex identifies it.
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
    // Speed: the dual vertices' positions copied in one sequential pass into a compact array. The polygons reach
    // them in a scattered order, and each DualVertex (position + QEF) is 136 bytes: gathering positions from there
    // costs a cache miss per vertex, from here mostly cache hits.
    std::vector<glm::dvec3> position(tree.vertices.size());
    for (std::size_t i = 0; i < position.size(); ++i) position[i] = tree.vertices[i].position;
    auto soup_vertex = [&](const LeafRef& l) {
        if (l.vertex == invalid_index)
            throw TopologyError("contour: leaf " + std::to_string(l.leaf) + " around a sign-changing edge has no vertex");
        if (remap[l.vertex] == invalid_index) {
            remap[l.vertex] = std::uint32_t(soup.positions.size());
            soup.positions.push_back(position[l.vertex]);
        }
        return remap[l.vertex];
    };
    auto leaf_ref = [&](std::uint32_t l) { return LeafRef{l, tree.nodes[l].vertex, tree.nodes[l].level}; };
    // quadrants around an edge along axis a, counter-clockwise seen from +a: (−,−), (+,−), (+,+), (−,+) in (b, c)
    static constexpr int qb[4] = {-1, +1, +1, -1}, qc[4] = {-1, -1, +1, +1};
    const std::vector<std::uint32_t> leaves = tree.leaves();
    // finest leaves by cell index: neighbours at the finest level without descending the tree. Speed: the grid
    // holds their vertex (4 bytes a cell), so that the (large) node array is not read again for them.
    constexpr std::uint32_t not_finest = invalid_index, no_vertex = invalid_index - 1;
    BlockGrid<std::uint32_t> finest(not_finest, n_res);
    for (std::uint32_t li : leaves) {
        const OctreeNode& nd = tree.nodes[li];
        if (nd.level == tree.max_level) finest.slot({nd.x, nd.y, nd.z}) = nd.vertex == invalid_index ? no_vertex : nd.vertex;
    }
    auto find_leaf = [&](glm::ivec3 p2) {
        // p2 has odd coordinates: the finest cell containing it is p2 / 2 (φ wrapped)
        glm::ivec3 cell(p2.x >> 1, p2.y >> 1, p2.z >> 1);
        if (spherical) cell.z &= n_res - 1;
        if (cell.x >= 0 && cell.y >= 0 && cell.z >= 0 && cell.x < n_res && cell.y < n_res && cell.z < n_res) {
            const std::uint32_t v = finest.get(cell);
            if (v != not_finest && v != no_vertex) return LeafRef{invalid_index, v, tree.max_level};
        }
        std::uint32_t l = tree.locate(p2);
        return l == invalid_index ? LeafRef{} : leaf_ref(l);
    };
    for (std::uint32_t li : leaves) {
        const OctreeNode& nd = tree.nodes[li];
        if (nd.vertex == invalid_index) continue;
        const std::int32_t span = tree.cell_span(nd.level);
        glm::ivec3 q[8];
        for (int c = 0; c < 8; ++c) q[c] = tree.corner(nd, c);
        for (int a = 0; a < 3; ++a) {
            const int b = (a + 1) % 3, cax = (a + 2) % 3;
            for (int c = 0; c < 8; ++c) {
                if (c & (1 << a)) continue;
                const int d = c | (1 << a);
                if (nd.corner_inside(c) == nd.corner_inside(d)) continue;
                const glm::ivec3 q0 = q[c];
                if (spherical) {
                    if (a == 0 && (q0.y == 0 || q0.y == n_res)) continue;  // on the polar axis: a pole ring
                    if (a != 0 && q0.x == 0) continue;                     // on the inner sphere: no cells below
                }
                // this leaf's quadrant: the edge is on its upper side along b → the leaf is on the − side
                const int my_b = (c & (1 << b)) ? -1 : +1, my_c = (c & (1 << cax)) ? -1 : +1;
                glm::ivec3 m2 = 2 * q0;
                m2[a] += span;
                LeafRef around[4];
                bool emit = true;
                for (int k = 0; k < 4 && emit; ++k) {
                    if (qb[k] == my_b && qc[k] == my_c) {
                        around[k] = LeafRef{li, nd.vertex, nd.level};
                        continue;
                    }
                    glm::ivec3 p2 = m2;
                    p2[b] += qb[k];
                    p2[cax] += qc[k];
                    around[k] = find_leaf(p2);
                    if (!around[k].found()) emit = false;  // outside the domain
                    else if (around[k].level > nd.level) emit = false;  // not minimal here
                    else {
                        // emit once: from the first quadrant holding a leaf as small as this one
                        bool before_me = false;
                        for (int j = 0; j < 4; ++j)
                            if (qb[j] == my_b && qc[j] == my_c) break;
                            else if (j == k) before_me = true;
                        if (before_me && around[k].level == nd.level) emit = false;
                    }
                }
                if (!emit) continue;
                // drop repeated leaves (adaptive trees), orient by the sign at the lower end
                LeafRef poly[4];
                int m = 0;
                for (int k = 0; k < 4; ++k) {
                    const LeafRef& l = nd.corner_inside(c) ? around[k] : around[3 - k];
                    if (m == 0 || !poly[m - 1].same(l)) poly[m++] = l;
                }
                if (m > 1 && poly[m - 1].same(poly[0])) --m;
                if (m < 3) continue;
                std::uint32_t w[4];
                for (int k = 0; k < m; ++k) w[k] = soup_vertex(poly[k]);
                if (m == 3) {
                    soup.add_face({w[0], w[1], w[2]});
                } else {  // split along the shorter diagonal
                    const auto& P = soup.positions;
                    if (glm::distance(P[w[0]], P[w[2]]) <= glm::distance(P[w[1]], P[w[3]])) {
                        soup.add_face({w[0], w[1], w[2]});
                        soup.add_face({w[0], w[2], w[3]});
                    } else {
                        soup.add_face({w[0], w[1], w[3]});
                        soup.add_face({w[1], w[2], w[3]});
                    }
                }
            }
        }
        // spherical: the radial edge on the polar axis, collected once by the leaf at φ index 0
        if (!spherical || !poles || nd.z != 0) continue;
        for (int pole = 0; pole < 2; ++pole) {
            const bool north = pole == 0;
            if (north ? nd.y != 0 : (std::int32_t(nd.y) + 1) * span != n_res) continue;
            const int c0 = north ? 0 : 2, c1 = c0 | 1;  // lower-φ corners on the axis, inner and outer radius
            if (nd.corner_inside(c0) == nd.corner_inside(c1)) continue;
            glm::ivec3 p2(2 * q[c0].x + span, north ? 1 : 2 * n_res - 1, 0);
            std::vector<LeafRef> ring;
            bool minimal = true;
            for (std::int32_t k = 0; k < n_res && minimal; ++k) {
                p2.z = 2 * k + 1;
                std::uint32_t l = tree.locate(p2);
                if (l == invalid_index || tree.nodes[l].level > nd.level) minimal = false;
                else if (ring.empty() || ring.back().leaf != l) ring.push_back(leaf_ref(l));
            }
            if (!minimal) continue;  // cannot happen without simplification: all ring leaves are finest
            if (ring.size() > 1 && ring.back().same(ring.front())) ring.pop_back();
            // increasing φ is counter-clockwise seen from +Z; outward is +r (±Z) when the inner end is inside
            if (nd.corner_inside(c0) != north) std::reverse(ring.begin(), ring.end());
            PoleRing pr;
            pr.north = north;
            pr.r_lo = tree.lattice_spherical(q[c0]).r;
            pr.r_hi = tree.lattice_spherical(q[c1]).r;
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
    std::size_t crossings = place_vertices(tree, {params.tau, params.crossing_tolerance});
    std::size_t collapses = 0;
    if (params.simplify_tolerance > 0.0)
        collapses = simplify(tree, params.simplify_tolerance * tree.size / tree.resolution(), params.tau);
    PolygonSoup soup = contour(tree);
    if (stats) {
        *stats = DcStats{};
        stats->cells = tree.reachable_nodes();
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
