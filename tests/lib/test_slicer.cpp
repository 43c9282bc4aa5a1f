// Tests of SliceRasterizer (geolab/render/slicer.hpp): the rules its header promises, checked against exact
// computations on small lattice coordinates (where float and the rasterizer's fixed point are exact): the fill
// rule is the perturbation (ε, ε²), the slab test is (lo, hi] with ties by the perturbation of the depth rank,
// XOR accumulates, corners snap to the sub-pixel lattice, and bad arguments are errors.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "geolab/predicates.hpp"
#include "geolab/render/slicer.hpp"

using geolab::render::SliceRasterizer;

namespace {

constexpr float inf = std::numeric_limits<float>::infinity();

// The camera that maps (x, y, z) to the window pixels (x, y) of a w × h image and keeps z as the depth.
glm::dmat4 window_camera(int w, int h) {
    glm::dmat4 m(1.0);
    m[0][0] = 2.0 / w;
    m[1][1] = 2.0 / h;
    m[3][0] = -1.0;
    m[3][1] = -1.0;
    return m;
}

// orient2d(a, b, q) with q moved by (ε, ε²).
int orient_moved(glm::dvec2 a, glm::dvec2 b, glm::dvec2 q) {
    if (const int o = geolab::orient2d(a, b, q)) return o;
    if (a.y != b.y) return a.y > b.y ? 1 : -1;
    return b.x > a.x ? 1 : -1;
}

// Whether the pixel centre q moved by (ε, ε²) lies in the projection of triangle t.
bool covers(const std::array<glm::dvec3, 3>& t, glm::dvec2 q) {
    const glm::dvec2 a(t[0]), b(t[1]), c(t[2]);
    if (geolab::orient2d(a, b, c) == 0) return false;
    const int s0 = orient_moved(a, b, q), s1 = orient_moved(b, c, q), s2 = orient_moved(c, a, q);
    return s0 == s1 && s1 == s2;
}

// Whether the point (q, z) lies above t's plane along +depth, ties by the perturbation whose components shrink in
// the order x, y with the depth at place `rank` (exact here: lattice coordinates, small numbers).
bool above(const std::array<glm::dvec3, 3>& t, glm::dvec2 q, double z, int rank) {
    const glm::dvec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
    double s = glm::dot(n, glm::dvec3(q, z) - t[0]);
    if (s == 0) {
        const double order[3][3] = {{n.z, n.x, n.y}, {n.x, n.z, n.y}, {n.x, n.y, n.z}};
        for (double c : order[rank])
            if (c != 0) {
                s = c;
                break;
            }
    }
    return (s > 0) == (n.z > 0);
}

std::string picture(const std::vector<std::uint8_t>& img, int w, int h) {
    std::ostringstream s;
    for (int y = h - 1; y >= 0; --y) {
        for (int x = 0; x < w; ++x) s << int(img[std::size_t(y * w + x)]);
        s << "\n";
    }
    return s.str();
}

std::string str(const std::array<glm::dvec3, 3>& t) {
    std::ostringstream s;
    for (const auto& p : t) s << "(" << p.x << ", " << p.y << ", " << p.z << ") ";
    return s.str();
}

}  // namespace

TEST_CASE("SliceRasterizer: coverage follows the fill rule (ε, ε²) on lattice triangles; shared edges once") {
    const int w = 12, h = 10;
    SliceRasterizer r(w, h);
    CHECK(r.subpixel_bits() >= 4);
    MESSAGE("sub-pixel bits: " << r.subpixel_bits());
    std::mt19937 rng(12);
    // half-pixels: corners on pixel centres and on pixel edges, inside the image (GL clips triangles that reach
    // outside, and the corners it makes on the border snap to the lattice: see the next test)
    std::uniform_int_distribution<int> cx(0, 2 * w), cy(0, 2 * h);
    for (int n = 0; n < 300; ++n) {
        std::array<glm::dvec3, 3> t;
        for (auto& p : t) p = {cx(rng) / 2.0, cy(rng) / 2.0, 0.0};
        if (n % 10 == 0) t[2] = t[0] + 2.0 * (t[1] - t[0]);  // zero area: covers nothing
        r.clear();
        r.set_triangles(t, window_camera(w, h));
        r.draw_xor(0, 1, -inf, inf);
        const auto img = r.read();
        std::vector<std::uint8_t> want(img.size());
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) want[std::size_t(y * w + x)] = covers(t, {x + 0.5, y + 0.5});
        INFO("triangle " << str(t) << "\ngot\n" << picture(img, w, h) << "expected\n" << picture(want, w, h));
        CHECK(img == want);
    }
    // a fan around a pixel centre: every centre of its square is covered once, the XOR leaves no hole
    std::vector<glm::dvec3> fan;
    const glm::dvec3 c(5.5, 4.5, 0), ring[6] = {{1.5, 1.5, 0}, {9.5, 0.5, 0}, {10.5, 4.5, 0}, {9.5, 8.5, 0}, {2.5, 9.5, 0}, {0.5, 4.5, 0}};
    for (int i = 0; i < 6; ++i) fan.insert(fan.end(), {c, ring[i], ring[(i + 1) % 6]});
    r.clear();
    r.set_triangles(fan, window_camera(w, h));
    r.draw_xor(0, 6, -inf, inf);
    const auto img = r.read();
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            int n = 0;
            for (int i = 0; i < 6; ++i) n += covers({c, ring[i], ring[(i + 1) % 6]}, {x + 0.5, y + 0.5});
            CHECK_MESSAGE(n <= 1, "pixel (" << x << ", " << y << ") in " << n << " triangles of the fan");
            CHECK_MESSAGE(int(img[std::size_t(y * w + x)]) == n, "pixel (" << x << ", " << y << ")");
        }
}

TEST_CASE("SliceRasterizer: triangles reaching out of the image still cover each centre of a closed fan once") {
    // Quads split along a diagonal through pixel centres, reaching far outside the image: GL clips them, and its
    // new corners may tilt the diagonal by a sub-pixel step, but both halves of a shared edge tilt alike, so each
    // pixel centre inside the quad is covered exactly once.
    const int w = 10, h = 8;
    SliceRasterizer r(w, h);
    std::mt19937 rng(56);
    std::uniform_int_distribution<int> out(-40, 40);
    for (int n = 0; n < 40; ++n) {
        const glm::dvec3 lo(-out(rng) / 2.0 - 20.5, -out(rng) / 2.0 - 20.5, 0), hi(w + out(rng) / 2.0 + 20.5, 3.5 + (n % 4), 0);
        const glm::dvec3 a = lo, b(hi.x, lo.y, 0), c = hi, d(lo.x, hi.y, 0);
        const std::vector<glm::dvec3> quad = {a, b, c, a, c, d};
        r.clear();
        r.set_triangles(quad, window_camera(w, h));
        r.draw_xor(0, 2, -inf, inf);
        const auto img = r.read();
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                CHECK_MESSAGE(img[std::size_t(y * w + x)] == (y + 0.5 < hi.y), "quad " << lo.x << " " << lo.y << " – " << hi.x << " " << hi.y << ", pixel (" << x << ", " << y << ")");
    }
}

TEST_CASE("SliceRasterizer: the slab test keeps depths in (lo; hi]; ties by the depth rank") {
    const int w = 9, h = 8;
    SliceRasterizer r(w, h);
    std::mt19937 rng(34);
    std::uniform_int_distribution<int> cx(0, 2 * w), cy(0, 2 * h), depth(0, 12);
    for (int rank = 0; rank < 3; ++rank) {
        r.set_depth_rank(rank);
        CHECK(r.depth_rank() == rank);
        for (int n = 0; n < 60; ++n) {
            std::array<glm::dvec3, 3> t;
            for (auto& p : t) p = {cx(rng) / 2.0, cy(rng) / 2.0, depth(rng) / 2.0};
            const double lo = depth(rng) / 2.0 - 0.5, hi = lo + 1.0;  // bounds on half-voxels: many exact ties
            r.clear();
            r.set_triangles(t, window_camera(w, h));
            r.draw_xor(0, 1, float(lo), float(hi));
            const auto img = r.read();
            std::vector<std::uint8_t> want(img.size());
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    const glm::dvec2 q(x + 0.5, y + 0.5);
                    want[std::size_t(y * w + x)] = covers(t, q) && above(t, q, hi, rank) && !above(t, q, lo, rank);
                }
            INFO("rank " << rank << ", triangle " << str(t) << ", slab (" << lo << ", " << hi << "]\ngot\n" << picture(img, w, h)
                         << "expected\n" << picture(want, w, h));
            CHECK(img == want);
        }
    }
    // a level triangle exactly at a bound belongs to the slab below it: (lo, hi] includes hi
    const std::vector<glm::dvec3> level = {{0, 0, 2.5}, {9, 0, 2.5}, {0, 8, 2.5}};
    r.clear();
    r.set_triangles(level, window_camera(w, h));
    r.draw_xor(0, 1, 2.5f, 3.5f);
    CHECK(r.read()[0] == 0);
    r.draw_xor(0, 1, 1.5f, 2.5f);
    CHECK(r.read()[0] == 1);
    r.draw_xor(0, 1, -inf, 2.5f);  // lo = −∞: everything up to hi
    CHECK(r.read()[0] == 0);
}

TEST_CASE("SliceRasterizer: XOR accumulates; consecutive slabs flip each crossing once") {
    const int w = 16, h = 16;
    SliceRasterizer r(w, h);
    // two tilted triangles over each other, depths from 1.3 to 6.1
    const std::vector<glm::dvec3> tris = {{1.2, 1.1, 1.3}, {14.7, 2.3, 3.9}, {3.3, 14.9, 6.1},
                                          {0.4, 15.2, 2.2}, {15.6, 0.3, 5.7}, {14.1, 13.8, 1.9}};
    r.set_triangles(tris, window_camera(w, h));
    CHECK(r.triangle_count() == 2);
    r.draw_xor(0, 2, -inf, inf);
    const auto all = r.read();
    r.clear();
    for (int k = 0; k < 8; ++k) r.draw_xor(0, 2, k == 0 ? -inf : k - 0.5f, k + 0.5f);  // slabs cover everything
    CHECK(r.read() == all);
    // where both triangles cover a pixel centre, the XOR cleared it
    const std::array<glm::dvec3, 3> t0 = {tris[0], tris[1], tris[2]}, t1 = {tris[3], tris[4], tris[5]};
    int both = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const bool c0 = covers(t0, {x + 0.5, y + 0.5}), c1 = covers(t1, {x + 0.5, y + 0.5});
            both += c0 && c1;
            CHECK_MESSAGE(all[std::size_t(y * w + x)] == (c0 != c1), "pixel (" << x << ", " << y << ")");
        }
    CHECK(both > 20);
    r.draw_xor(0, 2, -inf, inf);
    for (auto p : r.read()) CHECK(p == 0);
}

TEST_CASE("SliceRasterizer: corners snap to the sub-pixel lattice before coverage and depth") {
    const int w = 8, h = 8;
    SliceRasterizer r(w, h);
    const double step = std::ldexp(1.0, -r.subpixel_bits());
    // a rectangle whose left edge lies a quarter step right of the pixel centres x = 2.5: snapped onto them,
    // the fill rule covers column 2; a full step right, it does not
    for (const auto& [off, covered] : {std::pair{0.25 * step, true}, std::pair{step, false}}) {
        const double x0 = 2.5 + off;
        const std::vector<glm::dvec3> rect = {{x0, 1.0, 0}, {6.0, 1.0, 0}, {6.0, 7.0, 0}, {x0, 1.0, 0}, {6.0, 7.0, 0}, {x0, 7.0, 0}};
        r.clear();
        r.set_triangles(rect, window_camera(w, h));
        r.draw_xor(0, 2, -inf, inf);
        const auto img = r.read();
        for (int y = 1; y < 7; ++y) CHECK_MESSAGE(img[std::size_t(y * w + 2)] == covered, "left edge at x = 2.5 + " << off << ", row " << y);
        CHECK(img[std::size_t(3 * w + 3)] == 1);
        CHECK(img[std::size_t(3 * w + 6)] == 0);
    }
}

TEST_CASE("SliceRasterizer: bad arguments are errors") {
    CHECK_THROWS_AS(SliceRasterizer(0, 4), std::invalid_argument);
    CHECK_THROWS_AS(SliceRasterizer(4, 9000), std::invalid_argument);
    SliceRasterizer r(4, 4);
    const std::vector<glm::dvec3> two = {{0, 0, 0}, {1, 0, 0}};
    CHECK_THROWS_AS(r.set_triangles(two, glm::dmat4(1.0)), std::invalid_argument);
    const std::vector<glm::dvec3> tri = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    glm::dmat4 perspective(1.0);
    perspective[2][3] = -1.0;
    CHECK_THROWS_AS(r.set_triangles(tri, perspective), std::invalid_argument);
    const std::vector<glm::dvec3> far = {{0, 0, 0}, {1e39, 0, 0}, {0, 1, 0}};
    CHECK_THROWS_AS(r.set_triangles(far, glm::dmat4(1.0)), std::invalid_argument);
    const std::vector<glm::dvec3> nan = {{0, 0, 0}, {std::nan(""), 0, 0}, {0, 1, 0}};
    CHECK_THROWS_AS(r.set_triangles(nan, glm::dmat4(1.0)), std::invalid_argument);
    r.set_triangles(tri, glm::dmat4(1.0));
    CHECK_THROWS_AS(r.draw_xor(1, 1, 0, 1), std::out_of_range);
    CHECK_THROWS_AS(r.draw_xor(0, 2, 0, 1), std::out_of_range);
    CHECK_THROWS_AS(r.draw_xor(0, 1, std::nanf(""), 1), std::invalid_argument);
    CHECK_THROWS_AS(r.set_depth_rank(3), std::invalid_argument);
    CHECK_THROWS_AS(r.set_depth_rank(-1), std::invalid_argument);
    r.draw_xor(1, 0, 0, 1);  // nothing to draw is fine
    CHECK(r.read().size() == 16);
}
