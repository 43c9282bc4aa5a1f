// The generated marching-cubes tables (geolab/mc_tables.hpp): every crossed edge in exactly one loop, at most five
// triangles, no fan diagonal between two crossings of one face, outward orientation, and — the point of generating
// them — two cubes that share a face always join its crossings the same way (no crack); the complement-symmetric
// table does not.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <set>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "geolab/mc_tables.hpp"

namespace {
using geolab::mc_edge_corners;
using geolab::McTables;

bool on_face(int e, int axis, int side) {
    return ((mc_edge_corners[e][0] >> axis) & 1) == side && ((mc_edge_corners[e][1] >> axis) & 1) == side;
}
// The edge of the neighbour across the face (axis) that is edge e of this cube: corners moved by one along axis.
int across(int e, int axis) {
    const int a = mc_edge_corners[e][0] ^ (1 << axis), b = mc_edge_corners[e][1] ^ (1 << axis);
    for (int f = 0; f < 12; ++f)
        if ((mc_edge_corners[f][0] == a && mc_edge_corners[f][1] == b) || (mc_edge_corners[f][0] == b && mc_edge_corners[f][1] == a))
            return f;
    return -1;
}
// The segments (unordered pairs of edges) the loops of case cs draw on face (axis, side).
std::set<std::pair<int, int>> segments(const McTables& t, int cs, int axis, int side) {
    std::set<std::pair<int, int>> out;
    int off = 0;
    for (int p = 0; p < t.n_polygons[cs]; ++p) {
        const int n = t.polygon_size[cs][p];
        for (int i = 0; i < n; ++i) {
            const int a = t.polygon_edges[cs][off + i], b = t.polygon_edges[cs][off + (i + 1) % n];
            if (on_face(a, axis, side) && on_face(b, axis, side)) out.insert({std::min(a, b), std::max(a, b)});
        }
        off += n;
    }
    return out;
}
// Number of neighbouring case pairs (A below, B above along some axis, agreeing on the shared corners) whose
// segments on the shared face differ.
int cracks(const McTables& t) {
    int bad = 0;
    for (int axis = 0; axis < 3; ++axis)
        for (int a = 0; a < 256; ++a)
            for (int b = 0; b < 256; ++b) {
                bool agree = true;
                for (int c = 0; c < 8; ++c)
                    if (((c >> axis) & 1) == 1) agree = agree && (((a >> c) & 1) == ((b >> (c ^ (1 << axis))) & 1));
                if (!agree) continue;
                std::set<std::pair<int, int>> sa = segments(t, a, axis, 1), sb;
                for (const auto& [x, y] : segments(t, b, axis, 0)) {
                    const int u = across(x, axis), v = across(y, axis);
                    sb.insert({std::min(u, v), std::max(u, v)});
                }
                bad += sa != sb;
            }
    return bad;
}
glm::dvec3 midpoint(int e) {
    auto corner = [](int c) { return glm::dvec3(c & 1, (c >> 1) & 1, (c >> 2) & 1); };
    return 0.5 * (corner(mc_edge_corners[e][0]) + corner(mc_edge_corners[e][1]));
}
}  // namespace

TEST_CASE("mc tables: each crossed edge in exactly one loop; at most five triangles; fans avoid face diagonals") {
    for (const McTables* t : {&geolab::mc_tables, &geolab::mc_tables_join}) {
        for (int cs = 0; cs < 256; ++cs) {
            std::array<int, 12> seen{};
            int off = 0, tris = 0;
            for (int p = 0; p < t->n_polygons[cs]; ++p) {
                const int n = t->polygon_size[cs][p];
                CHECK(n >= 3);
                for (int i = 0; i < n; ++i) ++seen[t->polygon_edges[cs][off + i]];
                tris += n - 2;
                off += n;
            }
            for (int e = 0; e < 12; ++e) CHECK_MESSAGE(seen[e] == ((t->edge_mask[cs] >> e) & 1), "case " << cs << " edge " << e);
            CHECK(tris == t->n_triangles[cs]);
            CHECK(t->n_triangles[cs] <= 5);
            for (int i = 0; i < t->n_triangles[cs]; ++i)
                for (int m = 0; m < 3; ++m) {
                    const int a = t->triangles[cs][3 * i + m], b = t->triangles[cs][3 * i + (m + 1) % 3];
                    // An edge of a triangle that joins two crossings of one face must be a loop segment.
                    bool shares = false;
                    for (int axis = 0; axis < 3; ++axis)
                        for (int side = 0; side < 2; ++side)
                            if (on_face(a, axis, side) && on_face(b, axis, side) &&
                                !segments(*t, cs, axis, side).count({std::min(a, b), std::max(a, b)}))
                                shares = true;
                    CHECK_MESSAGE(!shares, "case " << cs << ": a fan diagonal joins edges " << a << " and " << b << " on one face");
                }
        }
    }
}

TEST_CASE("mc tables: one inside corner gives one triangle facing away from it") {
    for (int c = 0; c < 8; ++c) {
        const int cs = 1 << c;
        REQUIRE(geolab::mc_tables.n_triangles[cs] == 1);
        const glm::dvec3 a = midpoint(geolab::mc_tables.triangles[cs][0]), b = midpoint(geolab::mc_tables.triangles[cs][1]),
                         d = midpoint(geolab::mc_tables.triangles[cs][2]);
        const glm::dvec3 corner(c & 1, (c >> 1) & 1, (c >> 2) & 1);
        CHECK_MESSAGE(glm::dot(glm::cross(b - a, d - a), a - corner) > 0, "corner " << c << ": the triangle faces the inside corner");
    }
}

TEST_CASE("mc tables: the consistent tables never crack; the complement-symmetric one does") {
    CHECK(cracks(geolab::mc_tables) == 0);
    CHECK(cracks(geolab::mc_tables_join) == 0);
    CHECK(cracks(geolab::mc_tables_complement) > 0);
}
