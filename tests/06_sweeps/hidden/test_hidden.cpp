// Lab 06 hidden tests: run by the grader, left out of the student release. Same tasks (suites) as the public ones,
// other inputs: larger and random families, other helices (closed form −τ·s), curves checked against the RMF's ODE.
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab06;

namespace {
bool rejects(const Profile& p) {
    try {
        validate_profile(p);
    } catch (const std::invalid_argument&) {
        return true;
    }
    return false;
}
}  // namespace

TEST_SUITE("Task 1: profiles") {
    TEST_CASE("hidden: random profiles — any one loop reversed is rejected; the valid ones accepted" * geolab::points(2) *
              geolab::hidden()) {
        Rng rng(601);
        for (int k = 0; k < 30; ++k) {
            Profile p = star_with_holes(rng, rng.integer(3, 50), rng.integer(0, 6));
            INFO("input: " << str(p));
            CHECK_MESSAGE(!rejects(p), "a valid profile was rejected");
            const int which = rng.integer(-1, int(p.holes.size()) - 1);
            if (which < 0) p.outer = reversed(p.outer);
            else p.holes[std::size_t(which)] = reversed(p.holes[std::size_t(which)]);
            CHECK_MESSAGE(rejects(p), (which < 0 ? std::string("the reversed outer loop") : "reversed hole " + std::to_string(which))
                                          << " was accepted");
        }
    }
    TEST_CASE("hidden: a star with its first point pulled across to (−3; 0) (self-intersecting) is rejected" *
              geolab::points(1) * geolab::hidden()) {
        Rng rng(602);
        for (int k = 0; k < 20; ++k) {
            Loop l = star(rng, rng.integer(6, 30), 1.0, 2.0);
            l[0] = {-3, rng.uniform(-0.2, 0.2)};
            INFO("input: " << str(l));
            CHECK_MESSAGE(rejects({l, {}}), "a self-intersecting loop was accepted");
            l[0] = {1.5, 0};  // back inside: a star again, which is valid ("reject everything" is not the contract)
            CHECK_MESSAGE(!rejects({l, {}}), "a star was rejected");
        }
    }
}

TEST_SUITE("Task 2: triangulation") {
    TEST_CASE("hidden: large polygons with many holes; a spiral; grid profiles with many holes" * geolab::points(3) *
              geolab::builds_on("Task 1") *
              geolab::hidden()) {
        Rng rng(603);
        auto check = [&](const Profile& p) {
            INFO("input: " << str(p));
            const std::string bad = triangulation_problem(p, triangulate(p));
            CHECK_MESSAGE(bad.empty(), "not a triangulation of the region:" << bad);
        };
        for (int k = 0; k < 6; ++k) check(rotated_loops(rng, star_with_holes(rng, rng.integer(100, 300), 8)));
        Loop spiral;  // a thick spiral: outer arm out, inner arm back
        const int n = 120;
        for (int i = 0; i <= n; ++i) {
            const double a = 4 * pi * i / n, r = 1 + 0.5 * a;
            spiral.push_back({r * std::cos(a), r * std::sin(a)});
        }
        for (int i = n; i >= 0; --i) {
            const double a = 4 * pi * i / n, r = 1.6 + 0.5 * a;
            spiral.push_back({r * std::cos(a), r * std::sin(a)});
        }
        if (area_ld(spiral) < 0) spiral = reversed(spiral);
        check({spiral, {}});
        for (int k = 0; k < 60; ++k) check(grid_profile(rng, rng.integer(2, 7), rng.integer(2, 5), rng.integer(4, 20)));
    }
}

TEST_SUITE("Task 3: extrusion") {
    TEST_CASE("hidden: twist up to 80° per step stays closed and unflipped; tilted directions keep V = A·h" *
              geolab::points(3) * geolab::builds_on("Task 1, Task 2") * geolab::hidden()) {
        Rng rng(604);
        for (int k = 0; k < 6; ++k) {
            const Profile p = star_with_holes(rng, rng.integer(4, 12), k % 3);
            const int steps = rng.integer(2, 6);
            const PolygonSoup m = extrude(p, {{0, 0, 1}, steps, steps * 80.0 * pi / 180 * (k % 2 ? 1 : -1), 1.0});
            INFO("input: " << str(p) << ", " << steps << " steps of 80°");
            const auto c = geolab::check_surface(m, {.self_intersections = false});
            CHECK_MESSAGE((c.boundary_edges == 0 && c.misoriented_edges == 0 && c.non_manifold_edges == 0 &&
                           c.euler_characteristic == 2 - 2 * long(p.holes.size())),
                          c.summary());
            const double h = rng.uniform(0.5, 2);
            const PolygonSoup t = extrude(p, {{rng.uniform(-3, 3), rng.uniform(-3, 3), h}, 1, 0.0, 1.0});
            CHECK_MESSAGE(close(double(volume_ld(t)), double(region_area(p)) * h, 1e-11), "tilted prism volume A·h");
        }
    }
}

TEST_SUITE("Task 4: revolution") {
    TEST_CASE("hidden: random profiles crossing the axis revolve to closed solids; partial turns of axis-touching "
              "profiles with holes" * geolab::points(3) * geolab::builds_on("Task 1, Task 2") * geolab::hidden()) {
        Rng rng(605);
        int done = 0;
        for (int k = 0; k < 40 && done < 8; ++k) {
            const Profile p{shifted(star(rng, rng.integer(3, 25), 1.0, 2.0), {rng.uniform(-0.8, 0.8), 0}), {}};
            const Profile c = clip_to_axis(p);
            int on_axis = 0;
            for (auto q : c.outer) on_axis += q.x == 0;
            if (on_axis != 2) continue;  // one crossing pair (a star can cross the axis more often)
            ++done;
            const int m = rng.integer(5, 30);
            const PolygonSoup mesh = revolve(p, {m, 2 * pi});
            INFO("input: " << str(p) << ", " << m << " segments");
            const std::string bad = surface_problem(mesh, 2, 1, m < 16);
            CHECK_MESSAGE(bad.empty(), "expected a closed sphere-like solid:" << bad);
            const double want = double(m * std::sin((LD)2 * pi / m) * region_moment_x(c));
            CHECK_MESSAGE(close(double(volume_ld(mesh)), want, 1e-10), "volume " << double(volume_ld(mesh)) << " vs " << want);
        }
        CHECK(done >= 4);
        Profile q{Loop{{0, -3}, {3, -3}, {3, 3}, {0, 3}}, {reversed(rectangle_loop(1, -2, 2, -1)), reversed(rectangle_loop(1, 1, 2, 2))}};
        for (double a : {1.0, 4.0}) {
            const PolygonSoup mesh = revolve(q, {10, a});
            const std::string bad = surface_problem(mesh, -2, 1);
            CHECK_MESSAGE(bad.empty(), "partial turn " << a << " of a profile on the axis with 2 holes: genus 2 expected:" << bad);
        }
    }
}

TEST_SUITE("Task 5: frames") {
    TEST_CASE("hidden: helices of other radii and pitches end at −τ·s from Frenet's N" * geolab::points(2) * geolab::hidden()) {
        for (auto [r, h, turns] : {std::tuple{1.0, 0.5, 1.0}, std::tuple{2.0, 0.3, 2.5}, std::tuple{0.5, 2.0, 0.75},
                                   std::tuple{3.0, -1.0, 1.0}}) {
            const int n = 1500 + int(10 * r);  // different sizes: see the public test on random curves
            const Path p = helix_path(r, h, turns, n);
            const RmfResult res = rotation_minimizing_frames(p, {-1, 0, 0});
            const double T = turns * 2 * pi, want = wrap(-h / std::sqrt(r * r + h * h) * T);
            const glm::dvec3 N{-std::cos(T), -std::sin(T), 0};
            const double got = angle_about(N, res.frames.back().N, p.tangents.back());
            INFO("input: helix r " << r << ", h " << h << ", " << turns << " turns, " << n << " samples");
            CHECK_MESSAGE(std::abs(wrap(got - want)) < 1e-8, "expected " << want << " rad from N toward B, got " << got);
        }
    }
    TEST_CASE("hidden: closed random curves — mismatch against the ODE; frames close up" * geolab::points(2) * geolab::hidden()) {
        Rng rng(606);
        int done = 0;
        std::vector<Path> keep;  // alive to the end (see the public test on random curves)
        keep.reserve(30);
        for (int k = 0; k < 30 && done < 4; ++k) {
            const Fourier c(rng);
            if (c.min_speed() < 0.7) continue;
            ++done;
            const int n = 2500;
            const Path& p = keep.emplace_back(c.path(n, true));
            const glm::dvec3 r0 = glm::normalize(glm::cross(p.tangents[0], glm::dvec3(0.3, 1, -0.2)));
            const RmfResult res = rotation_minimizing_frames(p, r0);
            const double want = wrap(angle_about(r0, to_glm(rmf_ode(c.deriv(), 0, 2 * (LD)pi, to_ld(r0), 40000)), p.tangents[0]));
            CHECK_MESSAGE(std::abs(wrap(res.mismatch - want)) < 1e-6, "curve " << k << ": mismatch " << res.mismatch << " vs ODE " << want);
            const glm::dvec3 back = reflect_step(p.points[n - 1], p.tangents[n - 1], res.frames[n - 1].N, p.points[0], p.tangents[0]);
            CHECK_MESSAGE(std::abs(angle_about(r0, back, p.tangents[0])) < std::abs(want) * 0.01 + 1e-9,
                          "the frames do not close up: the mismatch was not distributed");
        }
        CHECK(done >= 2);
    }
}

TEST_SUITE("Task 6: sweeps") {
    TEST_CASE("hidden: the trefoil with a holed profile; check_sweep on helices (curvature radius (r² + h²)/r)" *
              geolab::points(3) * geolab::builds_on("Task 1") * geolab::hidden()) {
        const Path path = trefoil_path(500, 1.5);
        const Profile p{circle_loop({0, 0}, 0.4, 12), {reversed(circle_loop({0, 0}, 0.2, 8))}};
        // the frames are made here (helpers.hpp), not by your Task 5
        const std::vector<Frame> frames = rmf_frames(path, glm::cross(path.tangents[0], glm::dvec3(1, 0, 0)));
        const PolygonSoup m = sweep(p, path, frames);
        const std::string bad = surface_problem(m, 0, 2);
        CHECK_MESSAGE(bad.empty(), "a hollow trefoil tube: two embedded torus-like surfaces expected:" << bad);
        for (auto [rad, h] : {std::pair{1.0, 0.5}, std::pair{2.0, 1.0}, std::pair{0.5, 0.5}}) {
            const Path hp = helix_path(rad, h, 1, 400);
            const double R = (rad * rad + h * h) / rad;
            for (double pr : {0.8 * R, 1.2 * R}) {
                const SweepCheck c = check_sweep({circle_loop({0, 0}, pr, 9), {}}, hp);
                INFO("input: helix r " << rad << ", h " << h << "; profile radius " << pr);
                CHECK_MESSAGE(close(c.min_radius_of_curvature, R, 1e-3), "radius of curvature: expected about " << R << ", got " << c.min_radius_of_curvature);
                CHECK_MESSAGE(c.self_intersects == (pr > R), "self_intersects should be " << (pr > R));
            }
        }
    }
}

TEST_SUITE("Task 7: measures") {
    TEST_CASE("hidden: volumes don't depend on where the solid is; areas of random boxes' triangle soups" * geolab::points(3) *
              geolab::hidden()) {
        Rng rng(607);
        for (int k = 0; k < 6; ++k) {
            PolygonSoup m;
            // a random convex-ish closed mesh: an octahedron with random radii
            const double a = rng.uniform(0.5, 2), b = rng.uniform(0.5, 2), c = rng.uniform(0.5, 2);
            m.positions = {{a, 0, 0}, {-a, 0, 0}, {0, b, 0}, {0, -b, 0}, {0, 0, c}, {0, 0, -c}};
            for (auto f : {std::array<std::uint32_t, 3>{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}})
                m.add_face({f[0], f[1], f[2]});
            const double want = 4.0 / 3 * a * b * c;
            const glm::dvec3 off{rng.uniform(-1e6, 1e6), rng.uniform(-1e6, 1e6), rng.uniform(-1e6, 1e6)};
            PolygonSoup moved = m;
            for (auto& q : moved.positions) q += off;
            CHECK_MESSAGE(close(mesh_volume(m), want, 1e-12), "octahedron: expected " << want << ", got " << mesh_volume(m));
            CHECK_MESSAGE(close(mesh_volume(moved), want, 1e-7), "moved by " << str(off) << ": expected " << want << ", got " << mesh_volume(moved));
            const double face = glm::length(glm::cross(glm::dvec3(-a, b, 0), glm::dvec3(-a, 0, c))) / 2;
            CHECK_MESSAGE(close(mesh_area(moved), 8 * face, 1e-9), "area: expected " << 8 * face << ", got " << mesh_area(moved));
        }
    }
}
