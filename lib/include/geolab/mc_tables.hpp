#pragma once
//! \file mc_tables.hpp
//! Marching-cubes case tables, GENERATED at compile time by walking the cube's faces (nothing typed in).
//!
//! Cube numbering. Corner c (0..7) sits at offset (c & 1, (c >> 1) & 1, (c >> 2) & 1) from the cube's lowest
//! corner: bit 0 is x, bit 1 is y, bit 2 is z. Edge e (0..11) joins mc_edge_corners[e][0] (the lower end) and
//! mc_edge_corners[e][1]; edges 0–3 run along x, 4–7 along y, 8–11 along z (e / 4 is the axis).
//! A case index has bit c set when corner c is INSIDE.
//!
//! The generator. On each of the six faces the crossed edges (an inside and an outside end) are joined by
//! segments; the segments of the six faces close into loops (every crossed edge lies on two faces), and each loop
//! is one polygon, fanned into triangles from its first vertex (the loop starts at a vertex whose fan has no
//! diagonal between two crossings of one face). A face with 2 crossed edges has one segment. A
//! face with 4 (inside corners on a diagonal: the ambiguous face) is resolved by ONE fixed rule that looks only at
//! the face's four corners, so the two cubes sharing a face always join its crossings the same way and the
//! surface has no crack:
//!   - McRule::separate_inside: the two inside corners are cut off separately (the outside is connected across
//!     the face). The default; it matches "ambiguous means outside".
//!   - McRule::join_inside: the two inside corners are connected across the face.
//! McRule::complement_symmetric is the classic 15-case table that is NOT consistent: a case with more than four
//! inside corners reuses its complement's triangles (flipped), which amounts to separating the outside corners —
//! the opposite rule — in those cubes only; a face shared by a cube of either kind gets two different segment
//! pairs and the surface cracks there. Kept for the handout's figure and the tests that show the crack.
//!
//! Orientation: each segment runs, seen from outside the cube, with the inside corners on its right (the loops
//! are built inside-on-the-left and then reversed); each triangle (a, b, c) has its right-hand normal (b − a) × (c − a)
//! pointing OUT of the inside region (towards the outside corners).
#include <array>
#include <cstdint>

namespace geolab {

//! How a face with two diagonal inside corners is split (see the file comment).
enum class McRule : int { separate_inside, join_inside, complement_symmetric };

//! The two corners of each edge, lower corner first.
inline constexpr std::array<std::array<int, 2>, 12> mc_edge_corners{{{0, 1}, {2, 3}, {4, 5}, {6, 7},  // along x
                                                                     {0, 2}, {1, 3}, {4, 6}, {5, 7},  // along y
                                                                     {0, 4}, {1, 5}, {2, 6}, {3, 7}}};  // along z

//! The tables of one rule: for each of the 256 cases, the edges crossed (bit e of edge_mask) and the triangles
//! as triples of edge numbers, triangles[case][0 .. 3·n_triangles[case]).
struct McTables {
    std::array<std::uint16_t, 256> edge_mask{};
    std::array<std::uint8_t, 256> n_triangles{};
    std::array<std::array<std::int8_t, 15>, 256> triangles{};
    //! The loops (polygons) before triangulation: n_polygons[case], sizes, and the edges in order.
    std::array<std::uint8_t, 256> n_polygons{};
    std::array<std::array<std::uint8_t, 4>, 256> polygon_size{};
    std::array<std::array<std::int8_t, 12>, 256> polygon_edges{};
};

namespace mc_detail {

//! The edge joining corners a and b (adjacent corners), or −1.
constexpr int edge_of(int a, int b) {
    for (int e = 0; e < 12; ++e)
        if ((mc_edge_corners[e][0] == a && mc_edge_corners[e][1] == b) ||
            (mc_edge_corners[e][0] == b && mc_edge_corners[e][1] == a))
            return e;
    return -1;
}

//! True when edges e1 and e2 lie on one face of the cube (their four corners agree in one coordinate).
constexpr bool share_face(int e1, int e2) {
    const int c[4] = {mc_edge_corners[e1][0], mc_edge_corners[e1][1], mc_edge_corners[e2][0], mc_edge_corners[e2][1]};
    for (int axis = 0; axis < 3; ++axis) {
        const int bit = (c[0] >> axis) & 1;
        bool same = true;
        for (int i = 1; i < 4; ++i) same = same && ((c[i] >> axis) & 1) == bit;
        if (same) return true;
    }
    return false;
}

//! The four corners of face (axis, side) in counter-clockwise order seen from outside the cube.
constexpr std::array<int, 4> face_corners(int axis, int side) {
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    // (u, v) = (0,0), (1,0), (1,1), (0,1) in the axes b, c: counter-clockwise around e_b × e_c = e_axis.
    const int uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    std::array<int, 4> out{};
    for (int k = 0; k < 4; ++k) {
        const int i = side == 1 ? k : (4 - k) % 4;  // reversed on the side whose outward normal is −e_axis
        out[k] = (side << axis) | (uv[i][0] << b) | (uv[i][1] << c);
    }
    return out;
}

//! Tables for the cases whose ambiguous faces all follow `separate` (true: separate the inside corners).
constexpr void build_case(McTables& t, int cs, bool separate) {
    // next[e] = the crossed edge that follows e on its loop (−1: not crossed).
    std::array<int, 12> next{};
    for (int& n : next) n = -1;
    std::uint16_t mask = 0;
    for (int e = 0; e < 12; ++e)
        if (((cs >> mc_edge_corners[e][0]) & 1) != ((cs >> mc_edge_corners[e][1]) & 1)) mask |= std::uint16_t(1u << e);
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const auto fc = face_corners(axis, side);
            // Walking counter-clockwise, edge k joins fc[k] and fc[k+1]. "leave" = inside → outside, "enter" =
            // outside → inside. The loop is first built from each leave edge to an enter edge (inside on the left), then reversed.
            int leave[2] = {-1, -1}, enter[2] = {-1, -1}, nl = 0, ne = 0;
            for (int k = 0; k < 4; ++k) {
                const bool in0 = (cs >> fc[k]) & 1, in1 = (cs >> fc[(k + 1) % 4]) & 1;
                if (in0 && !in1) leave[nl++] = k;
                if (!in0 && in1) enter[ne++] = k;
            }
            auto edge = [&](int k) { return edge_of(fc[k], fc[(k + 1) % 4]); };
            if (nl == 1) {
                next[edge(leave[0])] = edge(enter[0]);
            } else if (nl == 2) {
                // Leave edges and enter edges alternate around the face. Separate the inside corners:
                // each leave edge joins the enter edge just BEFORE it (cutting its inside corner off); join them:
                // each leave edge joins the enter edge just AFTER it (cutting the outside corner off).
                for (int i = 0; i < 2; ++i) {
                    const int l = leave[i];
                    const int target = separate ? (l + 3) % 4 : (l + 1) % 4;
                    next[edge(l)] = edge(target);
                }
            }
        }
    t.edge_mask[cs] = mask;
    int n_tri = 0, n_poly = 0, n_pe = 0;
    std::array<bool, 12> used{};
    for (int e0 = 0; e0 < 12; ++e0) {
        if (next[e0] < 0 || used[e0]) continue;
        int loop[12] = {}, n = 0;
        for (int e = e0; !used[e]; e = next[e]) {
            used[e] = true;
            loop[n++] = e;
        }
        for (int i = 0, j = n - 1; i < j; ++i, --j) {  // walk it backwards: the inside on the right, normals out
            const int x = loop[i];
            loop[i] = loop[j];
            loop[j] = x;
        }
        // The fan's apex: the first vertex none of whose diagonals joins two crossings on one face (both ends of
        // such a diagonal lie on an ambiguous face shared with the next cube, which could have the same
        // diagonal: four triangles on one edge). Some apex always qualifies (checked by the tests of lib).
        int apex = 0;
        for (int k = 0; k < n; ++k) {
            bool ok = true;
            for (int i = 2; i + 1 < n; ++i) ok = ok && !share_face(loop[k], loop[(k + i) % n]);
            if (ok) {
                apex = k;
                break;
            }
        }
        int rotated[12] = {};
        for (int i = 0; i < n; ++i) rotated[i] = loop[(apex + i) % n];
        for (int i = 0; i < n; ++i) loop[i] = rotated[i];
        t.polygon_size[cs][n_poly++] = std::uint8_t(n);
        for (int i = 0; i < n; ++i) t.polygon_edges[cs][n_pe++] = std::int8_t(loop[i]);
        for (int i = 1; i + 1 < n; ++i) {
            t.triangles[cs][3 * n_tri + 0] = std::int8_t(loop[0]);
            t.triangles[cs][3 * n_tri + 1] = std::int8_t(loop[i]);
            t.triangles[cs][3 * n_tri + 2] = std::int8_t(loop[i + 1]);
            ++n_tri;
        }
    }
    t.n_polygons[cs] = std::uint8_t(n_poly);
    t.n_triangles[cs] = std::uint8_t(n_tri);
    for (int i = 3 * n_tri; i < 15; ++i) t.triangles[cs][i] = -1;
    for (int i = n_pe; i < 12; ++i) t.polygon_edges[cs][i] = -1;
}

constexpr int popcount8(int x) {
    int n = 0;
    for (; x; x &= x - 1) ++n;
    return n;
}

constexpr McTables make(McRule rule) {
    McTables t{};
    for (int cs = 0; cs < 256; ++cs) {
        if (rule == McRule::complement_symmetric && popcount8(cs) > 4) {
            // The complement's polygons (separate_inside for the complement = join_inside here), reversed.
            McTables c{};
            build_case(c, 255 - cs, true);
            t.edge_mask[cs] = c.edge_mask[255 - cs];
            t.n_triangles[cs] = c.n_triangles[255 - cs];
            t.n_polygons[cs] = c.n_polygons[255 - cs];
            t.polygon_size[cs] = c.polygon_size[255 - cs];
            for (int i = 0; i < 15; ++i) t.triangles[cs][i] = c.triangles[255 - cs][i];
            for (int i = 0; i + 2 < 15; i += 3)
                if (t.triangles[cs][i] >= 0) {
                    const auto x = t.triangles[cs][i + 1];
                    t.triangles[cs][i + 1] = t.triangles[cs][i + 2];
                    t.triangles[cs][i + 2] = x;
                }
            int off = 0;
            for (int p = 0; p < t.n_polygons[cs]; ++p) {  // each loop reversed
                const int n = t.polygon_size[cs][p];
                for (int i = 0; i < n; ++i) t.polygon_edges[cs][off + i] = c.polygon_edges[255 - cs][off + n - 1 - i];
                off += n;
            }
            for (int i = off; i < 12; ++i) t.polygon_edges[cs][i] = -1;
        } else {
            build_case(t, cs, rule != McRule::join_inside);
        }
    }
    return t;
}

}  // namespace mc_detail

//! The consistent table (ambiguous faces: inside corners separated). Use this one.
inline constexpr McTables mc_tables = mc_detail::make(McRule::separate_inside);
//! The consistent table with the other rule (ambiguous faces: inside corners joined).
inline constexpr McTables mc_tables_join = mc_detail::make(McRule::join_inside);
//! The inconsistent, complement-symmetric 15-case table (cracks; for the handout and its tests only).
inline constexpr McTables mc_tables_complement = mc_detail::make(McRule::complement_symmetric);

//! The tables of a rule.
constexpr const McTables& mc_tables_for(McRule rule) {
    return rule == McRule::separate_inside ? mc_tables : rule == McRule::join_inside ? mc_tables_join
                                                                                    : mc_tables_complement;
}

}  // namespace geolab
