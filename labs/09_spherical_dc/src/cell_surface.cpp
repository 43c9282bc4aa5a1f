// Lab 09 — the surface pieces of a cell and the rule for ambiguous faces (given: the tasks use them, they are not
// tasks). Handout §1.1.
#include <cstdint>

#include "geolab/dual_contouring.hpp"

namespace geolab::dc {

namespace {
// The four corners of face (a, s) in cyclic order around it (consecutive corners share a cell edge).
void face_corners(int a, int s, int (&out)[4]) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    const int uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int k = 0; k < 4; ++k) out[k] = (s << a) | (uv[k][0] << b) | (uv[k][1] << c);
}
// The cell edge joining adjacent corners p and q.
int edge_between(int p, int q) {
    for (int e = 0; e < 12; ++e)
        if ((cell_edge_corners[e][0] == p && cell_edge_corners[e][1] == q) ||
            (cell_edge_corners[e][0] == q && cell_edge_corners[e][1] == p))
            return e;
    return -1;
}
}  // namespace

CellSurface cell_surface(std::uint8_t signs, std::uint8_t joins) {
    // union-find over the 12 edges: each face's segment joins the two crossed edges it runs between
    int parent[12];
    for (int e = 0; e < 12; ++e) parent[e] = e;
    auto find = [&](int e) {
        while (parent[e] != e) e = parent[e] = parent[parent[e]];
        return e;
    };
    auto unite = [&](int e, int f) { parent[find(e)] = find(f); };
    auto in = [&](int c) { return (signs >> c) & 1; };
    std::uint16_t crossed = 0;
    for (int e = 0; e < 12; ++e)
        if (in(cell_edge_corners[e][0]) != in(cell_edge_corners[e][1])) crossed |= std::uint16_t(1u << e);
    for (int a = 0; a < 3; ++a)
        for (int s = 0; s < 2; ++s) {
            int fc[4];
            face_corners(a, s, fc);
            int edge[4], n = 0;  // edge[k] joins fc[k] and fc[k + 1]
            for (int k = 0; k < 4; ++k) {
                edge[k] = edge_between(fc[k], fc[(k + 1) % 4]);
                n += (crossed >> edge[k]) & 1;
            }
            if (n == 2) {
                int first = -1;
                for (int k = 0; k < 4; ++k)
                    if ((crossed >> edge[k]) & 1) first < 0 ? (void)(first = edge[k]) : unite(first, edge[k]);
            } else if (n == 4) {
                // ambiguous: cut off each inside corner (separate) or each outside corner (joined); corner fc[k]
                // lies between edge[k − 1] and edge[k]
                const bool joined = (joins >> (2 * a + s)) & 1;
                for (int k = 0; k < 4; ++k)
                    if (bool(in(fc[k])) != joined) unite(edge[(k + 3) % 4], edge[k]);
            }
        }
    CellSurface out;
    int piece_of_root[12];
    for (int e = 0; e < 12; ++e) piece_of_root[e] = -1;
    for (int e = 0; e < 12; ++e) {
        if (!((crossed >> e) & 1)) continue;
        int& k = piece_of_root[find(e)];
        if (k < 0) k = out.count++;
        out.edges[k] |= std::uint16_t(1u << e);
    }
    return out;
}

std::uint8_t face_joins(const Octree& tree, const OctreeNode& leaf) {
    if (!leaf.is_leaf() || leaf.level != tree.max_level || leaf.signs == 0 || leaf.signs == 0xff) return 0;
    const bool spherical = tree.coordinates == Coordinates::spherical;
    const std::int32_t n_res = tree.resolution();
    auto in = [&](int c) { return bool((leaf.signs >> c) & 1); };
    std::uint8_t joins = 0;
    for (int a = 0; a < 3; ++a)
        for (int s = 0; s < 2; ++s) {
            int fc[4];
            face_corners(a, s, fc);
            // ambiguous: inside and outside alternate around the face
            if (in(fc[0]) != in(fc[2]) || in(fc[1]) != in(fc[3]) || in(fc[0]) == in(fc[1])) continue;
            const int p = in(fc[0]) ? 0 : 1;  // the inside diagonal is fc[p], fc[p + 2]
            // in this cell: the far neighbours of fc[p] and fc[p + 2] inside, and one of the other two far corners
            const int flip = 1 << a;
            auto connected = [](bool far_p, bool far_q, bool far_r, bool far_t) { return far_p && far_q && (far_r || far_t); };
            if (!connected(in(fc[p] ^ flip), in(fc[p + 2] ^ flip), in(fc[p + 1] ^ flip), in(fc[(p + 3) % 4] ^ flip)))
                continue;
            // in the cell beyond the face: its far corners are the face's corners one lattice step further out
            const std::int32_t step = s ? 1 : -1;
            auto beyond_inside = [&](int c) {
                glm::ivec3 q = tree.corner(leaf, c);
                q[a] += step;
                return inside(tree.value(q));
            };
            const std::int32_t far_plane = tree.corner(leaf, fc[0])[a] + step;
            const bool wraps = spherical && a == 2;  // φ: the cell beyond the seam is the first one
            if (!wraps && (far_plane < 0 || far_plane > n_res)) continue;  // no cell beyond: the domain's boundary
            if (connected(beyond_inside(fc[p]), beyond_inside(fc[p + 2]), beyond_inside(fc[p + 1]),
                          beyond_inside(fc[(p + 3) % 4])))
                joins |= std::uint8_t(1u << (2 * a + s));
        }
    return joins;
}

}  // namespace geolab::dc
