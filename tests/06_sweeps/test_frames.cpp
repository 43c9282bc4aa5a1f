// Lab 06, Task 5: frames. Expected values: the helix's closed forms (Frenet N = (−cos t, −sin t, 0); the rotation-
// minimizing normal turns by −τs = −√2·π against Frenet's over one turn, i.e. ends 2π − √2π = 1.8403023690 rad from
// N toward B), and the RMF's ODE r' = −(r·T')T integrated by RK4 in long double for other curves.
#include "helpers.hpp"

using namespace lab06;

namespace {
const double helix_angle = 2 * pi - std::sqrt(2.0) * pi;  // 1.84030236902...

// The angle in [0, 2π) from the helix's Frenet normal at t = 2π to the RMF normal there (n samples, one turn).
double helix_end_angle(int n) {
    const Path p = helix_path(1, 1, 1, n);
    const RmfResult r = rotation_minimizing_frames(p, {-1, 0, 0});
    REQUIRE_MESSAGE(r.frames.size() == std::size_t(n), "expected " << n << " frames, got " << r.frames.size());
    const glm::dvec3 T = p.tangents.back(), N{-1, 0, 0}, B = glm::cross(T, N), rn = r.frames.back().N;
    double a = std::atan2(glm::dot(rn, B), glm::dot(rn, N));
    return a < 0 ? a + 2 * pi : a;
}
}  // namespace

TEST_SUITE("Task 5: frames") {
    TEST_CASE("frenet_frames: on the helix N points to the axis; B = T × N; frames orthonormal" * geolab::points(1) *
              geolab::hint("k = Tᵢ₊₁ − Tᵢ₋₁, N = the unit part of k orthogonal to Tᵢ, B = T × N (handout §6).")) {
        const Path p = helix_path(2, 0.5, 1.5, 60);
        const std::vector<Frame> f = frenet_frames(p);
        REQUIRE(f.size() == p.points.size());
        for (std::size_t i = 0; i < f.size(); ++i) {
            const double t = i * 1.5 * 2 * pi / 59;
            glm::dvec3 want{-std::cos(t), -std::sin(t), 0};
            if (i == 0 || i == 59) {  // one-sided at the ends: k = T₁ − T₀ or T₅₉ − T₅₈
                const glm::dvec3 k = i == 0 ? p.tangents[1] - p.tangents[0] : p.tangents[59] - p.tangents[58];
                want = glm::normalize(k - glm::dot(k, p.tangents[i]) * p.tangents[i]);
            }
            INFO("input: helix r 2, h 0.5, 60 samples; sample " << i);
            CHECK_MESSAGE(glm::length(f[i].N - want) < 1e-9,
                          "N: expected " << str(want) << ", got " << str(f[i].N));
            CHECK_MESSAGE(frame_problem(f[i]).empty(), "frame " << i << ":" << frame_problem(f[i]));
            CHECK_MESSAGE(glm::length(f[i].T - p.tangents[i]) < 1e-12, "T must be the path's tangent");
        }
    }

    TEST_CASE("frenet_frames: undefined on straight runs; flipping at an inflection (where RMF does not)" *
              geolab::points(2) *
              geolab::hint("A straight run has k ⟂ T of length 0: return N = B = 0 there. At an inflection the curvature "
                           "changes side, and Frenet's N with it.")) {
        const Path line = polyline_path({{0, 0, 0}, {1, 1, 0}, {2, 2, 0}, {3, 3, 0}}, false);
        for (const Frame& f : frenet_frames(line))
            CHECK_MESSAGE((f.N == glm::dvec3(0.0) && f.B == glm::dvec3(0.0)),
                          "a straight line has no Frenet frame: expected N = B = 0, got N " << str(f.N));
        // a bent line: straight, a corner, straight
        const Path bent = polyline_path({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 1, 0}, {4, 2, 0}, {5, 3, 0}}, false);
        const auto fb = frenet_frames(bent);
        CHECK_MESSAGE(fb[0].N == glm::dvec3(0.0), "sample 0 lies on a straight run: N should be 0, got " << str(fb[0].N));
        CHECK_MESSAGE(glm::length(fb[2].N) > 0.5, "sample 2 is at the corner: N defined, got " << str(fb[2].N));
        // y = sin x: an inflection at x = π
        std::vector<glm::dvec3> pts;
        for (int i = 0; i <= 100; ++i) pts.push_back({0.06 * i, std::sin(0.06 * i), 0});
        const Path s = polyline_path(pts, false);
        const auto fr = frenet_frames(s);
        int flips = 0;
        for (std::size_t i = 1; i < fr.size(); ++i) flips += glm::dot(fr[i].N, fr[i - 1].N) < 0;
        CHECK_MESSAGE(flips >= 1, "y = sin x for x ∈ [0, 6]: Frenet's N should turn over at the inflection at x = π");
        const RmfResult rm = rotation_minimizing_frames(s, {0, 1, 0});
        for (std::size_t i = 1; i < rm.frames.size(); ++i)
            CHECK_MESSAGE(glm::dot(rm.frames[i].N, rm.frames[i - 1].N) > 0.99, "RMF must not flip (sample " << i << ")");
        // The threshold: k's part orthogonal to T of length exactly 1e-9 is a straight run, 1.5e-9 is not.
        for (double e : {1e-9, 1.5e-9}) {
            const Path tiny{{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{1, 0, 0}, {1, 0, 0}, {1, e, 0}}, false};
            const auto ft = frenet_frames(tiny);
            const bool defined = e > 1e-9;
            const bool ok = defined ? glm::length(ft[1].N - glm::dvec3(0, 1, 0)) < 1e-12 : ft[1].N == glm::dvec3(0.0);
            CHECK_MESSAGE(ok, "tangents (1,0,0) (1,0,0) (1," << e << ",0): k at sample 1 is (0, " << e << ", 0), so N should be "
                                                           << (defined ? "(0, 1, 0)" : "0 (|k⊥| ≤ 1e-9)") << ", got " << str(ft[1].N));
        }
        // Two samples are enough for a path.
        const Path two{{{0, 0, 0}, {1, 0, 0}}, {glm::normalize(glm::dvec3(1, -1, 0)), glm::normalize(glm::dvec3(1, 1, 0))}, false};
        const auto f2 = frenet_frames(two);
        REQUIRE(f2.size() == 2);
        for (const Frame& f : f2) {  // both use k = T₁ − T₀ = (0, √2, 0): N is T turned left by 90°
            const glm::dvec3 want{-f.T.y, f.T.x, 0};
            CHECK_MESSAGE(glm::length(f.N - want) < 1e-12, "a two-sample path turning left: N " << str(want) << ", got " << str(f.N));
        }
        CHECK_MESSAGE(rotation_minimizing_frames(two, {0, 0, 1}).frames.size() == 2, "two samples: two RMF frames");
    }

    TEST_CASE("frenet_frames: a closed path wraps around (a coarse trefoil; the regular 12-gon)" * geolab::points(1) *
              geolab::hint("On a closed path sample 0's neighbours are samples n − 1 and 1, and sample n − 1's are n − 2 "
                           "and 0.")) {
        const Path knot = trefoil_path(16, 1.0);  // 16 samples: neighbours far apart, so the wrong ones show
        const auto fk = frenet_frames(knot);
        REQUIRE(fk.size() == 16);
        for (std::size_t i = 0; i < 16; ++i) {
            const glm::dvec3 k = knot.tangents[(i + 1) % 16] - knot.tangents[(i + 15) % 16], t = knot.tangents[i];
            const glm::dvec3 want = glm::normalize(k - glm::dot(k, t) * t);
            CHECK_MESSAGE(glm::length(fk[i].N - want) < 1e-9, "trefoil_path(16), sample " << i << ": N from k = T" << (i + 1) % 16
                                                              << " − T" << (i + 15) % 16 << " is " << str(want) << ", got " << str(fk[i].N));
        }
        std::vector<glm::dvec3> pts;
        for (int i = 0; i < 12; ++i) pts.push_back({2 * std::cos(2 * pi * i / 12), 2 * std::sin(2 * pi * i / 12), 1});
        const auto f = frenet_frames(polyline_path(pts, true));
        REQUIRE(f.size() == 12);
        for (std::size_t i = 0; i < 12; ++i) {
            const glm::dvec3 want = -glm::normalize(glm::dvec3(pts[i].x, pts[i].y, 0));
            CHECK_MESSAGE(glm::length(f[i].N - want) < 1e-9, "sample " << i << ": N expected " << str(want) << ", got " << str(f[i].N));
            CHECK_MESSAGE(frame_problem(f[i]).empty(), "frame " << i << ":" << frame_problem(f[i]));
        }
    }

    TEST_CASE("rotation_minimizing_frames: one helix turn from Frenet's N ends 1.8403023690 rad from N toward B" *
              geolab::points(2) *
              geolab::hint("Double reflection: v₁ = xᵢ₊₁ − xᵢ, r_L = r − (2/c₁)(v₁·r)v₁, t_L likewise, v₂ = Tᵢ₊₁ − t_L, "
                           "r = r_L − (2/c₂)(v₂·r_L)v₂ (Wang et al. 2008; handout §6).")) {
        for (int n : {1025, 2049}) {
            const double got = helix_end_angle(n);
            CHECK_MESSAGE(std::abs(got - helix_angle) < 1e-10, "helix (cos t, sin t, t), " << n << " samples: expected "
                                                                 << helix_angle << " rad, got " << got);
        }
        const RmfResult r = rotation_minimizing_frames(helix_path(1, 1, 1, 200), {-1, 0, 0});
        for (std::size_t i = 0; i < r.frames.size(); ++i)
            CHECK_MESSAGE(frame_problem(r.frames[i]).empty(), "frame " << i << ":" << frame_problem(r.frames[i]));
        CHECK_MESSAGE(r.mismatch == 0.0, "an open path has mismatch 0");
    }

    TEST_CASE("rotation_minimizing_frames: fourth order — the helix error falls about 16× per doubling" *
              geolab::points(2) *
              geolab::hint("Use the path's exact tangents in the second reflection (v₂ = Tᵢ₊₁ − t_L); a first-order "
                           "method (projection) only halves the error.")) {
        double prev = 0;
        for (int n : {24, 48, 96, 192}) {
            const double err = std::abs(helix_end_angle(n) - helix_angle);
            // (a NaN error compares false with everything: no ratio would be checked at all)
            REQUIRE_MESSAGE(std::isfinite(err), n << " samples: the end angle is not a number");
            if (prev > 0) {
                const double ratio = prev / err;
                CHECK_MESSAGE((ratio > 12 && ratio < 21), (n / 2) << " → " << n << " samples: the error fell by " << ratio
                                                                << " (expected about 16; errors " << prev << ", " << err << ")");
            }
            prev = err;
        }
    }

    TEST_CASE("rotation_minimizing_frames: random smooth curves agree with the RMF's ODE (RK4; long double)" *
              geolab::points(2) *
              geolab::hint("The frame must not turn about T: compare with the normal carried by r' = −(r·T')T.")) {
        Rng rng(101);
        int done = 0;
        // Every path stays alive to the end: the grader's recorder memoises a large argument's digest by where its
        // arrays are, so a new path in a freed path's memory could pass as the old one (reported to the lead).
        std::vector<Path> keep;
        keep.reserve(20);
        for (int k = 0; k < 20 && done < 6; ++k) {
            const Fourier c(rng);
            if (c.min_speed() < 0.5) continue;
            ++done;
            const int n = 600;
            const Path& p = keep.emplace_back(c.path(n, false));  // t ∈ [0, π]
            const glm::dvec3 r0 = glm::normalize(glm::cross(p.tangents[0], glm::dvec3(rng.uniform(-1, 1), 1, 0.3)));
            const RmfResult r = rotation_minimizing_frames(p, r0);
            const V3L want = rmf_ode(c.deriv(), 0, (LD)pi, to_ld(r0), 20000);
            const double err = glm::length(r.frames.back().N - to_glm(want));
            CHECK_MESSAGE(err < 1e-7, "random curve " << k << ": the end normal differs from the ODE's " << str(to_glm(want))
                                                      << " by " << err << " (got " << str(r.frames.back().N) << ")");
            for (std::size_t i = 0; i < r.frames.size(); i += 37)
                CHECK_MESSAGE(frame_problem(r.frames[i]).empty(), "frame " << i << ":" << frame_problem(r.frames[i]));
        }
        CHECK(done >= 3);
    }

    TEST_CASE("rotation_minimizing_frames: a closed path's mismatch is measured; then distributed so the frames close" *
              geolab::points(2) *
              geolab::hint("Carry the frame once around (last sample back to sample 0), measure the angle from N₀ about "
                           "T₀, then turn frame i by −mismatch·sᵢ/L about Tᵢ (handout §6).")) {
        const int n = 3000;
        const Path p = trefoil_path(n);
        const glm::dvec3 r0 = glm::normalize(glm::cross(p.tangents[0], glm::dvec3(0, 0, 1)));
        const RmfResult r = rotation_minimizing_frames(p, r0);
        const V3L end = rmf_ode(trefoil_deriv(), 0, 2 * (LD)pi, to_ld(r0), 40000);
        const double want = wrap(angle_about(r0, to_glm(end), p.tangents[0]));
        INFO("input: trefoil knot, " << n << " samples");
        CHECK_MESSAGE(std::abs(r.mismatch - want) < 1e-6, "mismatch: expected " << want << " rad (the ODE), got " << r.mismatch);
        REQUIRE(r.frames.size() == std::size_t(n));
        CHECK_MESSAGE(glm::length(r.frames[0].N - r0) < 1e-12, "frame 0 keeps the initial normal");
        // Distributed: frame i differs from the undistributed RMF by −mismatch·sᵢ/L; carrying the last frame one step
        // further closes with the rotation of the last segment only.
        double L = 0;
        for (int i = 0; i < n; ++i) L += glm::length(p.points[(i + 1) % n] - p.points[i]);
        const glm::dvec3 back = reflect_step(p.points[n - 1], p.tangents[n - 1], r.frames[n - 1].N, p.points[0], p.tangents[0]);
        const double gap = angle_about(r0, back, p.tangents[0]);
        const double last_share = want * glm::length(p.points[0] - p.points[n - 1]) / L;
        CHECK_MESSAGE(std::abs(gap - last_share) < 1e-6, "carrying the last frame back to sample 0 should leave only the last "
                                                         "segment's share " << last_share << " of the mismatch, got " << gap);
        double worst = 0;
        for (int i = 0; i + 1 < n; ++i) {
            const glm::dvec3 nx = reflect_step(p.points[i], p.tangents[i], r.frames[i].N, p.points[i + 1], p.tangents[i + 1]);
            const double step = angle_about(nx, r.frames[i + 1].N, p.tangents[i + 1]);
            const double share = -want * glm::length(p.points[i + 1] - p.points[i]) / L;
            worst = std::max(worst, std::abs(step - share));
        }
        CHECK_MESSAGE(worst < 1e-9, "each step should turn by −mismatch·Δs/L beyond the pure RMF; worst deviation " << worst);
        for (int i = 0; i < n; i += 97) CHECK_MESSAGE(frame_problem(r.frames[i]).empty(), "frame " << i << ":" << frame_problem(r.frames[i]));
        // Few samples: the mismatch is the discrete one, the frame carried by double reflection once around.
        for (int m : {7, 40}) {
            const Path q = trefoil_path(m, 1.3);
            const glm::dvec3 n0 = glm::normalize(glm::cross(q.tangents[0], glm::dvec3(0.2, 0, 1)));
            const RmfResult rq = rotation_minimizing_frames(q, n0);
            glm::dvec3 carried = n0;
            for (int i = 0; i < m; ++i)
                carried = reflect_step(q.points[i], q.tangents[i], carried, q.points[(i + 1) % m], q.tangents[(i + 1) % m]);
            const double mis = angle_about(n0, carried, q.tangents[0]);
            INFO("input: trefoil_path(" << m << ", 1.3)");
            CHECK_MESSAGE(std::abs(rq.mismatch - mis) < 1e-10, "mismatch: expected " << mis << " (the normal carried once "
                                                                "around by double reflection), got " << rq.mismatch);
            double Lq = 0;
            for (int i = 0; i < m; ++i) Lq += glm::length(q.points[(i + 1) % m] - q.points[i]);
            double s = 0, worst_q = 0;
            glm::dvec3 pure = n0;  // the undistributed RMF normal
            for (int i = 1; i < m; ++i) {
                pure = reflect_step(q.points[i - 1], q.tangents[i - 1], pure, q.points[i], q.tangents[i]);
                s += glm::length(q.points[i] - q.points[i - 1]);
                worst_q = std::max(worst_q, std::abs(wrap(angle_about(pure, rq.frames[i].N, q.tangents[i]) + mis * s / Lq)));
            }
            CHECK_MESSAGE(worst_q < 1e-10, "frame i should be the RMF turned by −mismatch·sᵢ/L about Tᵢ; worst deviation " << worst_q);
        }
    }

    TEST_CASE("rotation_minimizing_frames: the initial normal (relative test); a zero v₂ skips the second reflection" *
              geolab::points(1) *
              geolab::hint("N₀ is the initial normal's part orthogonal to T₀, refused when it is no longer than 1e-9 times "
                           "the normal's length; when v₂ = Tᵢ₊₁ − t_L is 0 only the first reflection is made.")) {
        const Path up = polyline_path({{0, 0, 0}, {0, 0, 1}, {0, 0, 2}}, false);  // T = (0, 0, 1) exactly
        CHECK_THROWS_AS(rotation_minimizing_frames(up, {1e-9, 0, 1}), std::invalid_argument);  // orthogonal part 1e-9 · 1
        CHECK_THROWS_AS(rotation_minimizing_frames(up, {1e-4, 0, 1e6}), std::invalid_argument);  // 1e-4 < 1e-9 · 1e6
        for (glm::dvec3 n0 : {glm::dvec3(1.5e-9, 0, 1), glm::dvec3(1e-2, 0, 1e6), glm::dvec3(3, 0, -2)}) {
            const RmfResult r = rotation_minimizing_frames(up, n0);
            CHECK_MESSAGE(glm::length(r.frames[0].N - glm::dvec3(1, 0, 0)) < 1e-12,
                          "initial normal " << str(n0) << ": N₀ should be (1, 0, 0), got " << str(r.frames[0].N));
        }
        // A step sideways (v₁ ⟂ T, T unchanged): t_L = Tᵢ₊₁, so v₂ = 0 and N is only reflected in the bisecting plane.
        const Path side{{{0, 0, 0}, {1, 0, 0}}, {{0, 1, 0}, {0, 1, 0}}, false};
        const RmfResult r = rotation_minimizing_frames(side, {1, 0, 0});
        CHECK_MESSAGE(glm::length(r.frames[1].N - glm::dvec3(-1, 0, 0)) < 1e-15,
                      "points (0,0,0) (1,0,0), both tangents (0,1,0), N₀ (1,0,0): N₁ = the reflection (−1, 0, 0), got "
                          << str(r.frames[1].N));
        // A step almost sideways: t_L is near Tᵢ₊₁ (|v₂|² ≈ 0.08), and the second reflection still counts.
        const Path sharp{{{0, 0, 0}, {1, 0, 0.2}}, {glm::normalize(glm::dvec3(0.3, 1, 0)), glm::normalize(glm::dvec3(0, 1, 0.1))}, false};
        const glm::dvec3 n0 = glm::normalize(glm::cross(sharp.tangents[0], glm::dvec3(0, 0, 1)));
        const glm::dvec3 want = reflect_step(sharp.points[0], sharp.tangents[0], n0, sharp.points[1], sharp.tangents[1]);
        const RmfResult rs = rotation_minimizing_frames(sharp, n0);
        CHECK_MESSAGE(glm::length(rs.frames[1].N - want) < 1e-12, "a sharp step: N₁ expected " << str(want) << " (both "
                                                                  "reflections), got " << str(rs.frames[1].N));
    }

    TEST_CASE("rotation_minimizing_frames: a planar closed curve has mismatch 0; bad input is rejected" * geolab::points(1) *
              geolab::hint("A planar curve's RMF keeps B along the plane's normal. Throw std::invalid_argument for equal "
                           "consecutive points, a normal parallel to T₀, or counts that differ.")) {
        std::vector<glm::dvec3> pts;
        for (int i = 0; i < 50; ++i) pts.push_back({3 * std::cos(2 * pi * i / 50), std::sin(2 * pi * i / 50), 0});
        const RmfResult r = rotation_minimizing_frames(polyline_path(pts, true), {0, 0, 1});
        CHECK_MESSAGE(std::abs(r.mismatch) < 1e-12, "ellipse in the plane z = 0: mismatch should be 0, got " << r.mismatch);
        for (const Frame& f : r.frames) CHECK_MESSAGE(glm::length(f.N - glm::dvec3(0, 0, 1)) < 1e-9, "N should stay (0, 0, 1), got " << str(f.N));
        Path bad = helix_path(1, 1, 1, 10);
        CHECK_THROWS_AS(rotation_minimizing_frames(bad, bad.tangents[0]), std::invalid_argument);
        const auto message = [](const Path& q) {
            try {
                rotation_minimizing_frames(q, {-1, 0, 0});
            } catch (const std::invalid_argument& e) {
                return std::string(e.what());
            }
            return std::string("(nothing thrown)");
        };
        bad.points[4] = bad.points[3];
        const std::string m34 = message(bad);
        CHECK_MESSAGE(m34.find("points 3 and 4") != std::string::npos, "points 3 and 4 equal: the message should name "
                                                                       "'points 3 and 4', got: " << m34);
        Path loop = helix_path(1, 1, 0.9, 10);
        loop.closed = true;
        loop.points[9] = loop.points[0];
        const std::string m90 = message(loop);
        CHECK_MESSAGE(m90.find("points 9 and 0") != std::string::npos, "a closed path whose last point is its first: the "
                                                                       "message should name 'points 9 and 0', got: " << m90);
        Path fewer = helix_path(1, 1, 1, 10);
        fewer.tangents.pop_back();
        CHECK_THROWS_AS(rotation_minimizing_frames(fewer, {-1, 0, 0}), std::invalid_argument);
        CHECK_THROWS_AS(frenet_frames(fewer), std::invalid_argument);
        CHECK_THROWS_AS(frenet_frames(Path{{{0, 0, 0}}, {{1, 0, 0}}, false}), std::invalid_argument);
    }
}  // TEST_SUITE
