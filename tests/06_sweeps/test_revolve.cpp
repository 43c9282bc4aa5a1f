// Lab 06, Task 4: revolution. Expected values: the polyhedral solid of revolution in closed form (each ring is a
// regular polygon, so the volume is m·sin θ·∫∫ r dA and each band's area is m·(rₐ + r_b)·sin(θ/2)·slant, θ the
// segment angle), Pappus's limits 48π and 96π for the issue's profile, and lib's check_surface.
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab06;

namespace {
// The issue's profile: the 4×4 square with a 2×2 hole, centre 2 from the axis (r ∈ [0, 4]).
Profile issue_profile() { return square_with_hole({2, 0}); }

// Exact volume and area of the revolved polyhedron (clipped profile p, all x ≥ 0), m segments over angle a.
LD poly_volume(const Profile& p, int m, double a) { return m * std::sin((LD)a / m) * region_moment_x(p); }
LD poly_area(const Profile& p, int m, double a, bool caps) {
    const LD th = (LD)a / m;
    LD s = 0;
    auto band = [&](const Loop& l) {
        for (std::size_t i = 0; i < l.size(); ++i) {
            const auto u = l[i], v = l[(i + 1) % l.size()];
            const LD dz = (LD)v.y - u.y, dr = ((LD)v.x - u.x) * std::cos(th / 2);
            s += m * ((LD)u.x + v.x) * std::sin(th / 2) * std::sqrt(dz * dz + dr * dr);
        }
    };
    band(p.outer);
    for (const auto& h : p.holes) band(h);
    if (caps) s += 2 * region_area(p);
    return s;
}
std::size_t poles(const PolygonSoup& m) {
    std::size_t k = 0;
    for (auto q : m.positions) k += q.x == 0 && q.y == 0;
    return k;
}
}  // namespace

TEST_SUITE("Task 4: revolution") {
    TEST_CASE("revolve: the issue's square with a hole at offset 2 — V → 48π; A → 96π (Pappus); closed" *
              geolab::points(3) * geolab::builds_on("Task 1") *
              geolab::hint("(r, z) ↦ (r cos φ, r sin φ, z); the outer edge on the axis makes no faces; a point on the "
                           "axis is one pole vertex; the outer loop gives a sphere-like surface, the hole a torus "
                           "(handout §5).")) {
        const Profile p = issue_profile();
        for (int m : {16, 64, 512}) {
            const PolygonSoup mesh = revolve(p, {m, 2 * pi});
            INFO("input: " << str(p) << " revolved fully in " << m << " segments");
            const double V = double(volume_ld(mesh)), wantV = double(poly_volume(p, m, 2 * pi)), wantA = double(poly_area(p, m, 2 * pi, false));
            CHECK_MESSAGE(close(V, wantV, 1e-11), "volume: expected " << wantV << " (the polyhedron; 48π = " << 48 * pi
                                                                      << " in the limit), got " << V);
            LD area = 0;
            for (std::size_t f = 0; f < mesh.n_faces(); ++f) area += glm::length(tri_normal(mesh, f)) / 2;
            CHECK_MESSAGE(close(double(area), wantA, 1e-11),
                          "area: expected " << wantA << " (96π = " << 96 * pi << " in the limit), got " << double(area));
            const std::string bad = surface_problem(mesh, 2, 2, m <= 64);
            CHECK_MESSAGE(bad.empty(), "expected a sphere-like outer surface and a torus inside (χ = 2, 2 components):" << bad);
            CHECK_MESSAGE(mesh.n_vertices() == 2 + 6 * std::size_t(m),
                          "expected 2 poles + 6 rings of " << m << " = " << 2 + 6 * m << " vertices, got " << mesh.n_vertices());
        }
        const PolygonSoup fine = revolve(p, {4096, 2 * pi});
        CHECK_MESSAGE(close(double(volume_ld(fine)), 48 * pi, 1e-5), "4096 segments: volume should be 48π to 1e-5");
    }

    TEST_CASE("revolve: a full revolution shares its seam (no duplicated ring; no boundary)" * geolab::points(2) *
              geolab::builds_on("Task 1") *
              geolab::hint("For a full turn the ring has `segments` vertices and the last segment joins back to ring "
                           "index 0: never add a ring at φ = 2π.")) {
        Rng rng(91);
        for (int k = 0; k < 6; ++k) {
            const Profile p0 = star_with_holes(rng, rng.integer(4, 12), k % 3);
            const Profile p{shifted(p0.outer, {4, 0}), {}};
            Profile ph = p;
            for (const auto& h : p0.holes) ph.holes.push_back(shifted(h, {4, 0}));
            const int m = rng.integer(3, 40);
            const PolygonSoup mesh = revolve(ph, {m, 2 * pi});
            INFO("input: " << str(ph) << " revolved fully in " << m << " segments");
            const std::size_t n = profile_points(ph).size();
            CHECK_MESSAGE(mesh.n_vertices() == n * m, "expected " << n << " rings of " << m << " = " << n * m
                                                                  << " vertices, got " << mesh.n_vertices());
            const std::string bad = surface_problem(mesh, 0, 1 + ph.holes.size(), m <= 20);
            CHECK_MESSAGE(bad.empty(), "expected " << 1 + ph.holes.size() << " closed torus-like surfaces (the outer loop's "
                                       "and one per hole; χ = 0):" << bad);
            CHECK_MESSAGE(close(double(volume_ld(mesh)), double(poly_volume(ph, m, 2 * pi)), 1e-10),
                          "volume: expected " << double(poly_volume(ph, m, 2 * pi)) << ", got " << double(volume_ld(mesh)));
        }
    }

    TEST_CASE("revolve: a profile touching the axis closes at single pole vertices without degenerate triangles" *
              geolab::points(2) * geolab::builds_on("Task 1") *
              geolab::hint("An edge with one end on the axis gives ONE triangle per segment (pole, ring, ring); both ends "
                           "on the axis: no faces.")) {
        for (int n : {3, 8, 33}) {
            Loop half;  // the right half of a unit disk, from the south pole to the north pole
            for (int i = 0; i <= n; ++i) {
                const double a = -pi / 2 + pi * i / n;
                half.push_back({i == 0 || i == n ? 0.0 : std::cos(a), std::sin(a)});
            }
            const Profile p{half, {}};
            for (int m : {3, 7, 48}) {
                const PolygonSoup mesh = revolve(p, {m, 2 * pi});
                INFO("input: half disk with " << n + 1 << " points, " << m << " segments");
                CHECK_MESSAGE(poles(mesh) == 2, "expected exactly 2 vertices on the axis (the poles), got " << poles(mesh));
                CHECK_MESSAGE(mesh.n_vertices() == 2 + std::size_t(n - 1) * m, "expected " << 2 + (n - 1) * m << " vertices");
                CHECK_MESSAGE(mesh.n_faces() == 2 * std::size_t(n - 1) * m, "expected " << 2 * (n - 1) * m << " triangles");
                const std::string bad = surface_problem(mesh, 2, 1);
                CHECK_MESSAGE(bad.empty(), "expected a closed sphere-like surface:" << bad);
                CHECK_MESSAGE(close(double(volume_ld(mesh)), double(poly_volume(p, m, 2 * pi)), 1e-10), "volume");
            }
        }
    }

    TEST_CASE("revolve: partial revolutions are closed by two caps" * geolab::points(2) *
              geolab::builds_on("Task 1, Task 2") *
              geolab::hint("Rings get segments + 1 vertices (φ = 0 and φ = angle both); the cap at φ = 0 is the "
                           "triangulation as it is, the one at φ = angle reversed (or the other way: check the normals).")) {
        Rng rng(92);
        std::vector<Profile> ps = {issue_profile(), {rectangle_loop(0, 0, 1, 2), {}}};
        for (int k = 0; k < 3; ++k) {
            const Profile s = star_with_holes(rng, rng.integer(5, 12), k);
            Profile t{shifted(s.outer, {3.5, 0}), {}};
            for (const auto& h : s.holes) t.holes.push_back(shifted(h, {3.5, 0}));
            ps.push_back(t);
        }
        for (const auto& p : ps)
            for (double a : {0.3, pi / 2, pi, 5.0}) {
                const int m = 9;
                const PolygonSoup mesh = revolve(p, {m, a});
                INFO("input: " << str(p) << " revolved by " << a << " rad in " << m << " segments");
                const std::string bad = surface_problem(mesh, 2 - 2 * long(p.holes.size()), 1);
                CHECK_MESSAGE(bad.empty(), "expected a closed oriented solid of genus " << p.holes.size() << ":" << bad);
                std::size_t want_v = 0;  // rings of segments + 1, one vertex per pole
                for (auto q : profile_points(clip_to_axis(p))) want_v += q.x == 0 ? 1 : m + 1;
                CHECK_MESSAGE(mesh.n_vertices() == want_v, "expected " << want_v << " vertices (rings of " << m + 1
                                                                      << " at φ = 0 .. angle), got " << mesh.n_vertices());
                const double V = double(volume_ld(mesh)), want = double(poly_volume(p, m, a));
                CHECK_MESSAGE(close(V, want, 1e-10), "volume: expected " << want << ", got " << V);
                LD area = 0;
                for (std::size_t f = 0; f < mesh.n_faces(); ++f) area += glm::length(tri_normal(mesh, f)) / 2;
                CHECK_MESSAGE(close(double(area), double(poly_area(p, m, a, true)), 1e-10),
                              "area: expected " << double(poly_area(p, m, a, true)) << " (bands + two caps), got " << double(area));
            }
    }

    TEST_CASE("clip_to_axis: profiles crossing the axis are cut at x = 0; revolve uses the cut profile" *
              geolab::points(2) * geolab::builds_on("Task 1") *
              geolab::hint("Sutherland–Hodgman against x ≥ 0: keep inside points, add the crossing point (x exactly 0) "
                           "of each edge that crosses; drop consecutive duplicates (handout §5).")) {
        const Profile rect{rectangle_loop(-1, 0, 2, 1), {}};
        const Profile c = clip_to_axis(rect);
        CHECK_MESSAGE(close(double(area_ld(c.outer)), 2.0, 1e-14), "[-1, 2] × [0, 1] clipped: area 2, got " << double(area_ld(c.outer)));
        const PolygonSoup cyl = revolve(rect, {24, 2 * pi});
        CHECK_MESSAGE(surface_problem(cyl, 2, 1).empty(), "the clipped rectangle revolves to a closed cylinder: "
                                                              << surface_problem(cyl, 2, 1));
        CHECK_MESSAGE(close(double(volume_ld(cyl)), double(24 * std::sin(2 * pi / 24) * 2.0), 1e-11), "cylinder volume");
        CHECK_MESSAGE(poles(cyl) == 2, "the cylinder's caps meet the axis in 2 poles, got " << poles(cyl));
        Rng rng(93);
        for (int k = 0; k < 10; ++k) {
            const Loop l = shifted(star(rng, rng.integer(3, 30), 0.5, 2.0), {rng.uniform(-1.5, 1.5), rng.uniform(-1, 1)});
            Loop mirror;
            for (auto q : l) mirror.push_back({-q.x, q.y});
            mirror = reversed(mirror);
            INFO("input: " << str(l));
            const bool right = std::any_of(l.begin(), l.end(), [](auto q) { return q.x > 0; });
            const bool left = std::any_of(l.begin(), l.end(), [](auto q) { return q.x < 0; });
            if (!right || !left) continue;
            const Profile a = clip_to_axis({l, {}}), b = clip_to_axis({mirror, {}});
            for (auto q : a.outer) CHECK_MESSAGE(q.x >= 0, "a clipped point has x = " << q.x);
            const double sum = double(area_ld(a.outer) + area_ld(b.outer)), want = double(area_ld(l));
            CHECK_MESSAGE(close(sum, want, 1e-12, 1), "the parts at x ≥ 0 and x ≤ 0 should add up to the area " << want
                                                                                                             << ", got " << sum);
            for (auto q : l)
                if (q.x > 0) CHECK_MESSAGE(std::find(a.outer.begin(), a.outer.end(), q) != a.outer.end(),
                                           "the point " << str(q) << " (x > 0) is missing from the clipped loop");
        }
        const Profile cone{Loop{{0, 0}, {1.5, 0}, {0, 2}}, {}};  // three points, two on the axis: a cone
        const PolygonSoup cm = revolve(cone, {20, 2 * pi});
        CHECK_MESSAGE(surface_problem(cm, 2, 1).empty(), "a right triangle on the axis revolves to a closed cone: "
                                                             << surface_problem(cm, 2, 1));
        CHECK_MESSAGE(close(double(volume_ld(cm)), double(poly_volume(cone, 20, 2 * pi)), 1e-11), "cone volume");
        // The unit square [−1, 1] × [0, 1] with points on the axis, started at each point in turn: the clipped loop
        // keeps no repeated point (also where the loop's last point and the first crossing are the same point).
        const Loop across{{-1, 1}, {-1, 0}, {0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (std::size_t k = 0; k < across.size(); ++k) {
            const Profile pk{rotated(across, k), {}};
            const Profile ck = clip_to_axis(pk);
            INFO("input: " << str(pk));
            CHECK_MESSAGE(ck.outer.size() == 4, "expected the 4 corners of [0, 1] × [0, 1], got " << str(ck.outer));
            CHECK_MESSAGE(close(double(area_ld(ck.outer)), 1.0, 1e-15), "clipped area: expected 1, got " << double(area_ld(ck.outer)));
            const PolygonSoup mk = revolve(pk, {12, 2 * pi});
            CHECK_MESSAGE(surface_problem(mk, 2, 1).empty(), "a closed cylinder expected: " << surface_problem(mk, 2, 1));
        }
        const Profile inside = square_with_hole({3, 0});
        const Profile same = clip_to_axis(inside);
        CHECK_MESSAGE((same.outer == inside.outer && same.holes == inside.holes), "a profile at x > 0 comes back unchanged");
    }

    TEST_CASE("revolve; clip_to_axis: bad input is rejected" * geolab::points(1) * geolab::builds_on("Task 1, Task 2") *
              geolab::hint("std::invalid_argument for segments < 3, angle ≤ 0 or > 2π, a hole reaching the axis, a "
                           "profile with nothing at x ≥ 0, an invalid profile.")) {
        const Profile p = issue_profile();
        CHECK_THROWS_AS(revolve(p, {2, 2 * pi}), std::invalid_argument);
        CHECK_THROWS_AS(revolve(p, {8, 0.0}), std::invalid_argument);
        CHECK_THROWS_AS(revolve(p, {8, 7.0}), std::invalid_argument);
        CHECK_THROWS_AS(clip_to_axis(square_with_hole({0.5, 0})), std::invalid_argument);
        CHECK_THROWS_AS(clip_to_axis({rectangle_loop(-3, 0, -1, 1), {}}), std::invalid_argument);
        CHECK_THROWS_AS(clip_to_axis({rectangle_loop(-3, 0, 0, 1), {}}), std::invalid_argument);  // touches the axis only
        CHECK_THROWS_AS(clip_to_axis({Loop{{-1, 0}, {0, 0}, {0, 1}, {0, 2}, {-1, 2}}, {}}), std::invalid_argument);  // 3 points on it
        CHECK_THROWS_AS(clip_to_axis({rectangle_loop(-3, -3, 3, 3), {reversed(rectangle_loop(0, 0, 1, 1))}}),
                        std::invalid_argument);  // a hole touching the axis
        // The angle: |angle − 2π| ≤ 1e-12 is a full turn (seam shared), else (0, 2π) a partial one.
        const Profile ring{rectangle_loop(2, 0, 3, 1), {}};
        CHECK_MESSAGE(revolve(ring, {8, 2 * pi + 0.5e-12}).n_vertices() == 32, "2π + 0.5e-12 is a full revolution: 4 rings of 8");
        CHECK_MESSAGE(revolve(ring, {8, 2 * pi - 0.5e-12}).n_vertices() == 32, "2π − 0.5e-12 is a full revolution: 4 rings of 8");
        CHECK_MESSAGE(revolve(ring, {8, 2 * pi - 1.5e-12}).n_vertices() == 36, "2π − 1.5e-12 is a partial revolution: 4 rings of 9");
        CHECK_THROWS_AS(revolve(ring, {8, 2 * pi + 1.5e-12}), std::invalid_argument);
        Profile q = issue_profile();
        q.holes[0] = reversed(q.holes[0]);
        CHECK_THROWS_AS(revolve(q, {8, 2 * pi}), std::invalid_argument);
        // valid input is no error ("reject everything" is not the contract)
        CHECK(revolve(p, {8, 2 * pi}).n_faces() > 0);
    }
}  // TEST_SUITE
