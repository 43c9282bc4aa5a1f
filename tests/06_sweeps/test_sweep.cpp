// Lab 06, Task 6: sweeps along paths. Expected values: the straight sweep equals extrude's layout, tube volumes
// A·L (Pappus for a tube), lib's check_surface for closedness, orientation, genus and self-intersections.
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab06;

namespace {
// Frames computed here: RMF-like frames by projecting a fixed vector (fine for paths that never point along it).
std::vector<Frame> projected_frames(const Path& p, glm::dvec3 up) {
    std::vector<Frame> f;
    for (auto t : p.tangents) {
        const glm::dvec3 N = glm::normalize(up - glm::dot(up, t) * t);
        f.push_back({t, N, glm::cross(t, N)});
    }
    return f;
}
// A circle of radius R in the plane z = 0 as a closed path, with exact tangents.
Path ring_path(double R, int n) {
    Path p;
    p.closed = true;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * pi * i / n;
        p.points.push_back({R * std::cos(a), R * std::sin(a), 0});
        p.tangents.push_back({-std::sin(a), std::cos(a), 0});
    }
    return p;
}
}  // namespace

TEST_SUITE("Task 6: sweeps") {
    TEST_CASE("sweep: along a straight path it is the extrusion (positions; closed; V = A·h)" * geolab::points(2) *
              geolab::builds_on("Task 1, Task 2") *
              geolab::hint("Point (u, v) of sample i is pointsᵢ + u·Nᵢ + v·Bᵢ; walls as in extrude; caps facing −T₀ "
                           "and +T at the end (handout §7).")) {
        Rng rng(111);
        for (int k = 0; k < 5; ++k) {
            const Profile p = star_with_holes(rng, rng.integer(4, 15), k % 3);
            const int ns = k == 0 ? 2 : rng.integer(2, 7);  // two samples: one step
            std::vector<glm::dvec3> pts;
            for (int i = 0; i < ns; ++i) pts.push_back({0, 0, 0.5 * i});
            const Path path = polyline_path(pts, false);
            const std::vector<Frame> fr(ns, Frame{});
            const PolygonSoup m = sweep(p, path, fr);
            INFO("input: " << str(p) << " along the z-axis, " << ns << " samples, frames T = z, N = x, B = y");
            const auto q = profile_points(p);
            REQUIRE_MESSAGE(m.n_vertices() == q.size() * ns, "expected " << q.size() * ns << " vertices");
            for (int i = 0; i < ns; ++i)
                for (std::size_t j = 0; j < q.size(); ++j)
                    REQUIRE_MESSAGE(glm::length(m.positions[i * q.size() + j] - glm::dvec3(q[j], 0.5 * i)) < 1e-14,
                                    "sample " << i << ", point " << j << ": expected " << str(glm::dvec3(q[j], 0.5 * i)));
            const std::string bad = surface_problem(m, 2 - 2 * long(p.holes.size()), 1);
            CHECK_MESSAGE(bad.empty(), "expected a closed oriented prism:" << bad);
            const double want = double(region_area(p)) * 0.5 * (ns - 1);
            CHECK_MESSAGE(close(double(volume_ld(m)), want, 1e-12), "volume: expected " << want << ", got " << double(volume_ld(m)));
        }
    }

    TEST_CASE("sweep: a closed path gives closed tubes without caps (one torus-like surface per loop)" * geolab::points(2) *
              geolab::builds_on("Task 1") *
              geolab::hint("On a closed path the last sample's ring joins sample 0's; no caps.")) {
        for (int holes : {0, 1}) {
            Profile p{circle_loop({0, 0}, 0.5, 12), {}};
            if (holes) p.holes.push_back(reversed(circle_loop({0.1, 0}, 0.2, 7)));
            const Path path = ring_path(3, 40);
            const PolygonSoup m = sweep(p, path, projected_frames(path, {0, 0, 1}));
            INFO("input: " << str(p) << " around the circle of radius 3, 40 samples");
            CHECK_MESSAGE(m.n_vertices() == 40 * profile_points(p).size(), "expected " << 40 * profile_points(p).size() << " vertices");
            const std::string bad = surface_problem(m, 0, 1 + holes);
            CHECK_MESSAGE(bad.empty(), "expected " << 1 + holes << " closed torus-like surfaces (χ = 0):" << bad);
            // N = z and B = radial: the profile's v is the distance from the circle outward, so the polygonal tube is a
            // polyhedral solid of revolution of the profile moved to (3 + v, u): V = m·sin(2π/m)·∫∫ (3 + v) dA.
            Profile moved{{}, {}};
            for (auto q : p.outer) moved.outer.push_back({3 + q.y, q.x});
            for (const auto& h : p.holes) {
                moved.holes.emplace_back();
                for (auto q : h) moved.holes.back().push_back({3 + q.y, q.x});
            }
            const double want = double(40 * std::sin((LD)2 * pi / 40) * -region_moment_x(moved)), V = double(volume_ld(m));
            CHECK_MESSAGE(close(V, want, 1e-10), "volume: expected " << want << ", got " << V);
        }
    }

    TEST_CASE("sweep: the trefoil knot with rotation-minimizing frames; closed and without self-intersections" *
              geolab::points(3) * geolab::builds_on("Task 1") *
              geolab::hint("Use rotation_minimizing_frames' distributed frames so the tube closes; the volume of a thin "
                           "tube is about the profile's area times the path's length.")) {
        const Path path = trefoil_path(600);
        const Profile p{circle_loop({0, 0}, 0.3, 16), {}};
        // the frames are made here (helpers.hpp), not by your Task 5
        const std::vector<Frame> frames = rmf_frames(path, glm::cross(path.tangents[0], glm::dvec3(0, 0, 1)));
        const PolygonSoup m = sweep(p, path, frames);
        INFO("input: trefoil (600 samples), circle profile r = 0.3 (16 points)");
        const std::string bad = surface_problem(m, 0, 1);
        CHECK_MESSAGE(bad.empty(), "expected a closed, oriented, embedded torus-like tube:" << bad);
        double L = 0;
        for (int i = 0; i < 600; ++i) L += glm::length(path.points[(i + 1) % 600] - path.points[i]);
        const double want = double(area_ld(p.outer)) * L, got = double(volume_ld(m));
        CHECK_MESSAGE(close(got, want, 0.01), "volume: expected about A·L = " << want << ", got " << got);
        // The closing seam is smooth: the last ring and the first differ as much as neighbours do (distributed).
        const std::size_t n = 16;
        double seam = 0, inner = 0;
        for (std::size_t j = 0; j < n; ++j) {
            seam = std::max(seam, glm::length(m.positions[599 * n + j] - m.positions[j]));
            inner = std::max(inner, glm::length(m.positions[300 * n + j] - m.positions[301 * n + j]));
        }
        CHECK_MESSAGE(seam < 3 * inner, "the seam's rings differ by " << seam << " vs " << inner << " between neighbours: "
                                        "a twisted seam (mismatch not distributed?)");
    }

    TEST_CASE("sweep: open helix tube with caps facing −T₀ and +T at the end" * geolab::points(2) *
              geolab::builds_on("Task 1, Task 2") *
              geolab::hint("Start cap: the triangulation reversed; end cap: as it is (with T = N × B the profile is "
                           "counter-clockwise seen from +T).")) {
        const Path path = helix_path(2, 0.4, 2, 120);
        Profile p = square_with_hole();
        for (auto& q : p.outer) q *= 0.2;
        for (auto& q : p.holes[0]) q *= 0.2;
        const std::vector<Frame> frames = rmf_frames(path, {-1, 0, 0});  // made here, not by your Task 5
        const PolygonSoup m = sweep(p, path, frames);
        const std::string bad = surface_problem(m, 0, 1);
        CHECK_MESSAGE(bad.empty(), "expected a closed solid of genus 1:" << bad);
        const std::size_t n = 8, last = 119 * n;
        std::size_t caps = 0, wrong = 0;
        for (std::size_t f = 0; f < m.n_faces(); ++f) {
            const auto fc = m.face(f);
            const bool start = fc[0] < n && fc[1] < n && fc[2] < n, end = fc[0] >= last && fc[1] >= last && fc[2] >= last;
            if (!start && !end) continue;
            ++caps;
            const double d = glm::dot(tri_normal(m, f), start ? path.tangents[0] : path.tangents[119]);
            wrong += start ? d >= 0 : d <= 0;
        }
        CHECK_MESSAGE(caps == 16, "expected 8 + 8 cap triangles, got " << caps);
        CHECK_MESSAGE(wrong == 0, wrong << " cap triangles face into the tube");
    }

    TEST_CASE("check_sweep: a profile wider than the path's radius of curvature is reported; lib confirms" *
              geolab::points(2) * geolab::builds_on("Task 1, Task 2") *
              geolab::hint("Circumradius of each three consecutive samples: |a||b||c| / (2|(b − a) × (c − a)|); compare "
                           "the smallest with the profile's largest distance from (0, 0).")) {
        const Path path = ring_path(2, 48);
        const double R = 2.0;  // the circumradius of three samples of a circle is the circle's radius
        for (double r : {0.5, 1.5, 2.5, 3.0}) {
            const Profile p{circle_loop({0, 0}, r, 10), {}};
            const SweepCheck c = check_sweep(p, path);
            INFO("input: circle profile r = " << r << " around a circle of radius 2 (48 samples)");
            CHECK_MESSAGE(close(c.profile_radius, r, 1e-12), "profile radius: expected " << r << ", got " << c.profile_radius);
            CHECK_MESSAGE(close(c.min_radius_of_curvature, R, 1e-9), "radius of curvature: expected 2, got " << c.min_radius_of_curvature);
            CHECK_MESSAGE(c.self_intersects == (r >= R), "self_intersects: expected " << (r >= R));
            const PolygonSoup m = sweep(p, path, projected_frames(path, {0, 0, 1}));
            const auto sc = geolab::check_surface(m);
            CHECK_MESSAGE((sc.self_intersecting_pairs() > 0) == (r >= R), "lib's check_surface finds " << sc.self_intersecting_pairs() << " intersecting pairs");
        }
        std::vector<glm::dvec3> pts{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
        const SweepCheck s = check_sweep({circle_loop({0, 0}, 5, 8), {}}, polyline_path(pts, false));
        CHECK_MESSAGE((std::isinf(s.min_radius_of_curvature) && !s.self_intersects), "a straight path never self-intersects");
        pts = {{0, 0, 0}, {4, 0, 0}, {4, 1, 0}, {8, 1, 0}};
        const SweepCheck t = check_sweep({circle_loop({0, 0}, 0.6, 8), {}}, polyline_path(pts, false));
        CHECK_MESSAGE(t.at_sample == 1, "the tightest turn of (0,0,0) (4,0,0) (4,1,0) (8,1,0) is at sample 1 (tie: the first), got " << t.at_sample);
        CHECK_MESSAGE(close(t.min_radius_of_curvature, std::sqrt(17.0) / 2, 1e-12), "its circumradius is √17/2, got " << t.min_radius_of_curvature);
        CHECK_MESSAGE(!t.self_intersects, "0.6 < √17/2: no self-intersection reported");
        pts = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 1, 0}};
        const SweepCheck u = check_sweep({circle_loop({0, 0}, 0.6, 8), {}}, polyline_path(pts, false));
        CHECK_MESSAGE(close(u.min_radius_of_curvature, std::sqrt(0.5), 1e-12), "(0,0,0) (1,0,0) (1,1,0) (2,1,0): the "
                                                                               "circumradius √2/2 at sample 1, got " << u.min_radius_of_curvature);
        // An open path's ends are not neighbours: (0,0,0) … (0,0.5,0) ends close to its start (the three samples
        // (0,0.5,0) (0,0,0) (4,0,0) would have circumradius √16.25/2), but only the inner samples' corners count
        // (right angles; the tightest, legs 4 and 3.5 at sample 3, has circumradius √28.25/2).
        pts = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}, {0, 0.5, 0}};
        const SweepCheck o = check_sweep({circle_loop({0, 0}, 0.1, 8), {}}, polyline_path(pts, false));
        CHECK_MESSAGE((close(o.min_radius_of_curvature, std::sqrt(28.25) / 2, 1e-12) && o.at_sample == 3),
                      "the open path (0,0,0) (4,0,0) (4,4,0) (0,4,0) (0,0.5,0): circumradius √28.25/2 at sample 3 (its ends "
                      "have no corner), got " << o.min_radius_of_curvature << " at sample " << o.at_sample);
        // Nor its last sample: (0,4,0) (0,1,0) (1,0.5,0) turns at sample 4 (circumradius √(1.25·13.25)/2), while the
        // last sample with the first as a neighbour would give (0,1,0) (1,0.5,0) (0,0,0), circumradius 0.625.
        pts = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}, {0, 1, 0}, {1, 0.5, 0}};
        const SweepCheck l = check_sweep({circle_loop({0, 0}, 0.1, 8), {}}, polyline_path(pts, false));
        CHECK_MESSAGE((close(l.min_radius_of_curvature, std::sqrt(1.25 * 13.25) / 2, 1e-12) && l.at_sample == 4),
                      "the open path (0,0,0) (4,0,0) (4,4,0) (0,4,0) (0,1,0) (1,0.5,0): circumradius " << std::sqrt(1.25 * 13.25) / 2
                          << " at sample 4, got " << l.min_radius_of_curvature << " at sample " << l.at_sample);
        // A path that comes back near itself is no curvature problem: a coil wound tighter than the profile (pitch
        // 2π·0.05 ≈ 0.31 < the diameter 0.6; radius of curvature ≈ 2). check_sweep sees nothing; the mesh does.
        const Path coil = helix_path(2, 0.05, 3, 300);
        const Profile thick{circle_loop({0, 0}, 0.3, 12), {}};
        const SweepCheck k = check_sweep(thick, coil);
        CHECK_MESSAGE((!k.self_intersects && close(k.min_radius_of_curvature, (4 + 0.0025) / 2, 1e-3)),
                      "a coil of radius 2, pitch 2π·0.05: radius of curvature about 2.00 > 0.3, no local self-intersection; got "
                          << k.min_radius_of_curvature << ", " << k.self_intersects);
        const auto kc = geolab::check_surface(sweep(thick, coil, projected_frames(coil, {0, 0, 1})));
        CHECK_MESSAGE(kc.self_intersecting_pairs() > 0, "the coil's turns overlap: lib's check_surface should find "
                                                        "intersecting face pairs in your sweep, found none");
        // A tie counts: a right-angle corner of legs 3 and 4 has circumradius 5/2 exactly, as far as the profile reaches.
        const Loop diamond{{2.5, 0}, {0, 1}, {-1, 0}, {0, -1}};
        pts = {{0, 0, 0}, {3, 0, 0}, {3, 4, 0}};
        const SweepCheck e = check_sweep({diamond, {}}, polyline_path(pts, false));
        CHECK_MESSAGE((e.min_radius_of_curvature == 2.5 && e.profile_radius == 2.5 && e.self_intersects),
                      "profile radius 2.5 = circumradius 2.5 of (0,0,0) (3,0,0) (3,4,0): self_intersects (≥), got radius "
                          << e.profile_radius << ", circumradius " << e.min_radius_of_curvature << ", " << e.self_intersects);
        // A closed path whose sharpest corner is sample 0 (wrapping: samples n−1, 0, 1).
        pts = {{0, 0, 0}, {0.5, 0.5, 0}, {3, 0.5, 0}, {3, -3, 0}, {-3, -3, 0}, {-3, 0.5, 0}, {-0.5, 0.5, 0}};
        const SweepCheck w = check_sweep({circle_loop({0, 0}, 0.1, 8), {}}, polyline_path(pts, true));
        CHECK_MESSAGE((w.at_sample == 0 && close(w.min_radius_of_curvature, 0.5, 1e-12)),
                      "the closed path (0,0,0) (0.5,0.5,0) (3,0.5,0) (3,−3,0) (−3,−3,0) (−3,0.5,0) (−0.5,0.5,0) turns sharpest "
                      "at sample 0 (circumradius 0.5 with samples 6 and 1), got sample " << w.at_sample << ", radius "
                                                                                        << w.min_radius_of_curvature);
    }

    TEST_CASE("sweep; check_sweep: bad input is rejected" * geolab::points(1) * geolab::builds_on("Task 1, Task 2") *
              geolab::hint("std::invalid_argument for an invalid profile, a frame count that differs from the samples, "
                           "too few samples.")) {
        const Path path = helix_path(1, 1, 1, 10);
        const Profile p{circle_loop({0, 0}, 0.1, 6), {}};
        CHECK_THROWS_AS(sweep(p, path, std::vector<Frame>(9)), std::invalid_argument);
        CHECK_THROWS_AS(sweep({reversed(p.outer), {}}, path, std::vector<Frame>(10)), std::invalid_argument);
        CHECK_THROWS_AS(sweep(p, Path{{{0, 0, 0}}, {{0, 0, 1}}, false}, std::vector<Frame>(1)), std::invalid_argument);
        CHECK_THROWS_AS(check_sweep(p, Path{{{0, 0, 0}}, {{0, 0, 1}}, false}), std::invalid_argument);
        CHECK_THROWS_AS(check_sweep({reversed(p.outer), {}}, path), std::invalid_argument);
        Path two = helix_path(1, 1, 1, 2);
        two.closed = true;
        CHECK_THROWS_AS(sweep(p, two, std::vector<Frame>(2)), std::invalid_argument);
        // valid input is no error ("reject everything" is not the contract)
        CHECK(sweep(p, path, rmf_frames(path, {-1, 0, 0})).n_faces() > 0);
        CHECK_THROWS_AS(check_sweep(p, two), std::invalid_argument);
        // Three samples are enough for a closed path: a triangular ring of three prisms.
        const Path tri = polyline_path({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}}, true);
        const PolygonSoup m = sweep(p, tri, projected_frames(tri, {0, 0, 1}));
        CHECK_MESSAGE((m.n_vertices() == 18 && m.n_faces() == 36), "a closed path of 3 samples and a 6-point profile: 18 "
                                                                    "vertices and 36 triangles, got " << m.n_vertices() << " and " << m.n_faces());
        CHECK_NOTHROW(check_sweep(p, tri));
    }
}  // TEST_SUITE
