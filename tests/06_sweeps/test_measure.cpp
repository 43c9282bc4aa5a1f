// Lab 06, Task 7: measures. Expected values: closed forms (cube, tetrahedron, box areas), long double sums, and
// Pappus's theorems written out (V = angle·A·x̄, lateral area = angle·Σ|e|·x_mid) for the profile.
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab06;

namespace {
// The axis-aligned box [lo, hi] as 6 quads (outward), or 12 triangles.
PolygonSoup box(glm::dvec3 lo, glm::dvec3 hi, bool quads) {
    PolygonSoup m;
    for (int i = 0; i < 8; ++i) m.positions.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
    const std::uint32_t f[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : f) {
        if (quads) m.add_face({q[0], q[1], q[2], q[3]});
        else m.add_face({q[0], q[1], q[2]}), m.add_face({q[0], q[2], q[3]});
    }
    return m;
}
PolygonSoup flipped(PolygonSoup m) {
    PolygonSoup r;
    r.positions = m.positions;
    for (std::size_t f = 0; f < m.n_faces(); ++f) {
        std::vector<std::uint32_t> v(m.face(f).begin(), m.face(f).end());
        std::reverse(v.begin(), v.end());
        r.add_face(v);
    }
    return r;
}
}  // namespace

TEST_SUITE("Task 7: measures") {
    TEST_CASE("mesh_volume: boxes and tetrahedra; triangles and quads; negative when turned inside out" *
              geolab::points(2) *
              geolab::hint("Divergence theorem: V = Σ det(a, b, c)/6 over the triangles (a polygon as a fan from its "
                           "first vertex); reversed faces give −V (handout §8).")) {
        Rng rng(121);
        for (int k = 0; k < 10; ++k) {
            const glm::dvec3 lo{rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)};
            const glm::dvec3 hi = lo + glm::dvec3{rng.uniform(0.1, 3), rng.uniform(0.1, 3), rng.uniform(0.1, 3)};
            const double want = (hi.x - lo.x) * (hi.y - lo.y) * (hi.z - lo.z);
            for (bool quads : {false, true}) {
                const PolygonSoup b = box(lo, hi, quads);
                INFO("input: box " << str(lo) << " – " << str(hi) << (quads ? " (quads)" : " (triangles)"));
                CHECK_MESSAGE(close(mesh_volume(b), want, 1e-12), "expected " << want << ", got " << mesh_volume(b));
                CHECK_MESSAGE(close(mesh_volume(flipped(b)), -want, 1e-12), "turned inside out: expected " << -want);
            }
        }
        PolygonSoup t;
        t.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        for (auto f : {std::array<std::uint32_t, 3>{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}) t.add_face({f[0], f[1], f[2]});
        CHECK_MESSAGE(close(mesh_volume(t), 1.0 / 6, 1e-15), "unit corner tetrahedron: expected 1/6, got " << mesh_volume(t));
        CHECK_MESSAGE(mesh_volume(PolygonSoup{}) == 0.0, "an empty mesh has volume 0");
        // An open mesh (one triangle that does not use vertex 0): the sum taken about the FIRST vertex, as the contract says.
        PolygonSoup open;
        open.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        open.add_face({1, 2, 3});
        CHECK_MESSAGE(close(mesh_volume(open), 1.0 / 6, 1e-15), "one triangle (1, 0, 0) (0, 1, 0) (0, 0, 1) about vertex 0 "
                                                                 "(0, 0, 0): expected 1/6, got " << mesh_volume(open));
    }

    TEST_CASE("mesh_volume: far from the origin (coordinates ~1e6) the volume keeps its digits" * geolab::points(1) *
              geolab::hint("Take the points relative to the first vertex before the determinants: det(a, b, c) with "
                           "|a| ~ 1e6 cancels ~12 digits.")) {
        for (double off : {1e5, 1e6, 3e7}) {
            const glm::dvec3 lo{off, -off, off};
            const PolygonSoup b = box(lo, lo + glm::dvec3{1, 2, 0.5}, false);
            INFO("input: box of volume 1 at " << str(lo));
            CHECK_MESSAGE(close(mesh_volume(b), 1.0, 1e-6), "expected 1, got " << mesh_volume(b));
        }
    }

    TEST_CASE("mesh_area: boxes; quads; a regular polygon's fan" * geolab::points(1) *
              geolab::hint("Σ |(b − a) × (c − a)| / 2 over the fan triangles of each face.")) {
        Rng rng(122);
        for (int k = 0; k < 8; ++k) {
            const glm::dvec3 lo{rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)};
            const glm::dvec3 d{rng.uniform(0.1, 3), rng.uniform(0.1, 3), rng.uniform(0.1, 3)};
            const double want = 2 * (d.x * d.y + d.y * d.z + d.z * d.x);
            for (bool quads : {false, true}) {
                const double got = mesh_area(box(lo, lo + d, quads));
                CHECK_MESSAGE(close(got, want, 1e-12), "box " << str(d) << (quads ? " (quads)" : "") << ": expected " << want << ", got " << got);
            }
        }
        PolygonSoup disk;
        std::vector<std::uint32_t> idx;
        for (int i = 0; i < 30; ++i) {
            disk.positions.push_back({std::cos(2 * pi * i / 30), std::sin(2 * pi * i / 30), 1.0});
            idx.push_back(std::uint32_t(i));
        }
        disk.add_face(idx);
        const double want = 15 * std::sin(2 * pi / 30);
        CHECK_MESSAGE(close(mesh_area(disk), want, 1e-13), "a regular 30-gon of circumradius 1: expected " << want << ", got " << mesh_area(disk));
    }

    TEST_CASE("pappus: the issue's profile gives V = 48π and lateral area 96π; partial angles scale" * geolab::points(2) *
              geolab::builds_on("Task 1") *
              geolab::hint("V = angle · ∫∫ x dA = angle · (1/6) Σ (xᵢ + xᵢ₊₁)(xᵢ yᵢ₊₁ − xᵢ₊₁ yᵢ) over all loops (holes "
                           "clockwise subtract); lateral area = angle · Σ |e| · x at e's midpoint, holes included.")) {
        const Profile p = square_with_hole({2, 0});
        const Pappus full = pappus(p, 2 * pi);
        CHECK_MESSAGE(close(full.volume, 48 * pi, 1e-14), "volume: expected 48π = " << 48 * pi << ", got " << full.volume);
        CHECK_MESSAGE(close(full.lateral_area, 96 * pi, 1e-14), "lateral area: expected 96π = " << 96 * pi << ", got " << full.lateral_area);
        const Pappus q = pappus(p, pi / 3);
        CHECK_MESSAGE(close(q.volume, 8 * pi, 1e-14), "angle π/3: expected 8π, got " << q.volume);
        const Pappus h = pappus(p, 0.5);
        CHECK_MESSAGE(close(h.volume, 12.0, 1e-14), "angle 0.5: expected V = 0.5 · 12 · 2 = 12, got " << h.volume);
        Rng rng(123);
        for (int k = 0; k < 8; ++k) {
            const Profile s = star_with_holes(rng, rng.integer(4, 20), k % 3);
            Profile t{shifted(s.outer, {3.2, 1}), {}};
            for (const auto& h : s.holes) t.holes.push_back(shifted(h, {3.2, 1}));
            const double a = rng.uniform(0.1, 2 * pi);
            const Pappus got = pappus(t, a);
            const double wantV = a * double(region_moment_x(t));
            LD lat = 0;
            auto add = [&](const Loop& l) {
                for (std::size_t i = 0; i < l.size(); ++i) lat += glm::length(l[(i + 1) % l.size()] - l[i]) * ((LD)l[i].x + l[(i + 1) % l.size()].x) / 2;
            };
            add(t.outer);
            for (const auto& h : t.holes) add(h);
            INFO("input: " << str(t) << ", angle " << a);
            CHECK_MESSAGE(close(got.volume, wantV, 1e-12), "volume: expected " << wantV << ", got " << got.volume);
            CHECK_MESSAGE(close(got.lateral_area, double(a * lat), 1e-12), "lateral area: expected " << double(a * lat) << ", got " << got.lateral_area);
        }
    }

    TEST_CASE("pappus: bad input is rejected" * geolab::points(1) * geolab::builds_on("Task 1") *
              geolab::hint("std::invalid_argument for a point with x < 0, an angle ≤ 0, an invalid profile.")) {
        CHECK_THROWS_AS(pappus(square_with_hole({1, 0}), 1.0), std::invalid_argument);
        CHECK_THROWS_AS(pappus(square_with_hole({3, 0}), 0.0), std::invalid_argument);
        Profile q = square_with_hole({3, 0});
        q.holes[0] = reversed(q.holes[0]);
        CHECK_THROWS_AS(pappus(q, 1.0), std::invalid_argument);
        // valid input is no error ("reject everything" is not the contract)
        CHECK(pappus(square_with_hole({3, 0}), 1.0).volume > 0);
    }
}  // TEST_SUITE
