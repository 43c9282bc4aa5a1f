#pragma once
// Lab 02 test inputs: procedural cell lists (tetrahedra, hexahedra, prisms, pyramids, general polyhedra). Every
// cell's faces are counter-clockwise seen from outside it (geolab/halfface/cells.hpp).
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "geolab/halfface/cells.hpp"

namespace lab02 {

using geolab::halfface::CellList;
using geolab::halfface::CellType;

struct Fixture {
    std::string name;
    CellList cells;
};

namespace fx {

inline CellList single_tet() {
    CellList c;
    c.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    c.add_tet(0, 1, 2, 3);
    return c;
}

// Two tetrahedra sharing the face (0 1 2): apex 3 above, apex 4 below.
inline CellList two_tets() {
    CellList c;
    c.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.3, 0.3, 1}, {0.3, 0.3, -1}};
    c.add_tet(0, 1, 2, 3);
    c.add_tet(0, 2, 1, 4);
    return c;
}

// The 8 corners of the cube [0,s]^3 starting at index `base` in binary order: corner i = (i&1, i>>1&1, i>>2&1)·s.
inline void add_cube_corners(CellList& c, glm::dvec3 origin, double s) {
    for (int i = 0; i < 8; ++i) c.positions.push_back(origin + s * glm::dvec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
}

// The Kuhn (Freudenthal) split of a cube with binary corner numbering b[0..7] into 6 tetrahedra around the
// diagonal b[0]-b[7]: one tet per permutation of the axes (all positively oriented).
inline void add_kuhn_cube(CellList& c, const std::array<std::uint32_t, 8>& b, std::int32_t label = 0) {
    static const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (const auto& p : perms) {
        const int i1 = 1 << p[0], i2 = i1 | (1 << p[1]);
        // the path 0 -> i1 -> i2 -> 7; orientation follows the permutation's parity
        const bool even = (p[0] == 0 && p[1] == 1) || (p[0] == 1 && p[1] == 2) || (p[0] == 2 && p[1] == 0);
        if (even)
            c.add_tet(b[0], b[i1], b[i2], b[7], label);
        else
            c.add_tet(b[0], b[i2], b[i1], b[7], label);
    }
}

inline CellList kuhn_cube() {
    CellList c;
    add_cube_corners(c, {0, 0, 0}, 1.0);
    add_kuhn_cube(c, {0, 1, 2, 3, 4, 5, 6, 7});
    return c;
}

// Grid vertices (n+1)^3 of [0,n·h]^3; index of (i,j,k).
inline std::uint32_t grid_index(int n, int i, int j, int k) { return std::uint32_t((k * (n + 1) + j) * (n + 1) + i); }
inline void add_grid_vertices(CellList& c, int n, double h, double jitter = 0.0) {
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                glm::dvec3 p(i * h, j * h, k * h);
                const bool interior = i > 0 && j > 0 && k > 0 && i < n && j < n && k < n;
                if (interior && jitter > 0) {  // deterministic jitter of interior vertices
                    const double s = std::sin(12.9898 * i + 78.233 * j + 37.719 * k) * 43758.5453;
                    const double r = s - std::floor(s);
                    p += jitter * h * glm::dvec3(r - 0.5, std::fmod(r * 7.0, 1.0) - 0.5, std::fmod(r * 13.0, 1.0) - 0.5);
                }
                c.positions.push_back(p);
            }
}
inline std::array<std::uint32_t, 8> grid_cube(int n, int i, int j, int k) {
    std::array<std::uint32_t, 8> b{};
    for (int t = 0; t < 8; ++t) b[t] = grid_index(n, i + (t & 1), j + ((t >> 1) & 1), k + ((t >> 2) & 1));
    return b;
}

// n^3 cubes, each split into 6 Kuhn tetrahedra (6 n^3 tets; conforming because every cube uses the same diagonal
// direction). Interior vertices jittered by `jitter`·h.
inline CellList tet_grid(int n, double jitter = 0.0) {
    CellList c;
    add_grid_vertices(c, n, 1.0 / n, jitter);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) add_kuhn_cube(c, grid_cube(n, i, j, k));
    return c;
}

// n^3 hexahedra.
inline CellList hex_grid(int n) {
    CellList c;
    add_grid_vertices(c, n, 1.0 / n);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const auto b = grid_cube(n, i, j, k);
                const std::array<std::uint32_t, 8> v{b[0], b[1], b[3], b[2], b[4], b[5], b[7], b[6]};
                c.add_hex(v);
            }
    return c;
}

// A cube cut into two prisms by the diagonal plane x = y, with a pyramid on top of each (the top square split
// along the same diagonal is not a quad: so the pyramids sit on the prisms' quad side faces x = 1 and y = 1).
inline CellList prisms_and_pyramids() {
    CellList c;
    add_cube_corners(c, {0, 0, 0}, 1.0);
    c.positions.push_back({1.5, 0.5, 0.5});  // 8: apex beyond x = 1
    c.positions.push_back({0.5, 1.5, 0.5});  // 9: apex beyond y = 1
    // prism A: bottom (0,1,3) (counter-clockwise seen from +z), top (4,5,7)
    const std::array<std::uint32_t, 6> a{0, 1, 3, 4, 5, 7};
    c.add_prism(a);
    // prism B: bottom (0,3,2), top (4,7,6)
    const std::array<std::uint32_t, 6> b{0, 3, 2, 4, 7, 6};
    c.add_prism(b);
    // pyramid on x = 1 (corners 1,3,7,5), counter-clockwise seen from the apex at +x
    const std::array<std::uint32_t, 5> p{1, 3, 7, 5, 8};
    c.add_pyramid(p);
    // pyramid on y = 1 (corners 3,2,6,7) seen from +y
    const std::array<std::uint32_t, 5> q{3, 2, 6, 7, 9};
    c.add_pyramid(q);
    return c;
}

// The unit cube split into 6 pyramids with their apex at the centre (vertex 8).
inline CellList cube_of_pyramids() {
    CellList c;
    add_cube_corners(c, {0, 0, 0}, 1.0);
    c.positions.push_back({0.5, 0.5, 0.5});
    // each face of the cube, counter-clockwise seen from the centre (= clockwise seen from outside the cube)
    const std::uint32_t faces[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (const auto& f : faces) {
        const std::array<std::uint32_t, 5> p{f[0], f[1], f[2], f[3], 8};
        c.add_pyramid(p);
    }
    return c;
}

// General polyhedra: a hexagonal prism (two hexagons, six quads) glued to a cube-like cell with a pentagon? Here:
// a hexagonal prism (cell 0) and a hexagonal pyramid on its top hexagon (cell 1).
inline CellList hexagonal_prism_and_pyramid() {
    CellList c;
    for (int z = 0; z < 2; ++z)
        for (int i = 0; i < 6; ++i) {
            const double a = 2 * 3.14159265358979323846 * i / 6;
            c.positions.push_back({std::cos(a), std::sin(a), double(z)});
        }
    c.positions.push_back({0, 0, 2});  // 12: apex
    std::vector<std::uint32_t> bottom{5, 4, 3, 2, 1, 0}, top{6, 7, 8, 9, 10, 11};
    c.add_face(bottom);
    c.add_face(top);
    for (std::uint32_t i = 0; i < 6; ++i) {
        const std::uint32_t j = (i + 1) % 6;
        std::vector<std::uint32_t> side{i, j, j + 6, i + 6};
        c.add_face(side);
    }
    c.close_cell();
    std::vector<std::uint32_t> base{11, 10, 9, 8, 7, 6};
    c.add_face(base);
    for (std::uint32_t i = 0; i < 6; ++i) {
        std::vector<std::uint32_t> side{6 + i, 6 + (i + 1) % 6, 12};
        c.add_face(side);
    }
    c.close_cell();
    return c;
}

}  // namespace fx

// Fixtures with stored connectivity (tests/02_halfface/data): small enough to keep as data.
inline std::vector<Fixture> stored_fixtures() {
    return {{"single tet", fx::single_tet()},
            {"two tets", fx::two_tets()},
            {"Kuhn cube (6 tets)", fx::kuhn_cube()},
            {"tet grid 2", fx::tet_grid(2, 0.3)},
            {"tet grid 3", fx::tet_grid(3, 0.3)},
            {"hex grid 2", fx::hex_grid(2)},
            {"prisms and pyramids", fx::prisms_and_pyramids()},
            {"cube of 6 pyramids", fx::cube_of_pyramids()},
            {"hexagonal prism and pyramid", fx::hexagonal_prism_and_pyramid()}};
}

}  // namespace lab02
