// Lab 05, Tasks 5 and 6: tensor-product patches and the Utah teapot. Expected values from the tensor-product
// Bernstein form in long double (helpers.hpp); the teapot from lib's reader of data/teapot.bpt.
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab05;

namespace {
// A patch with a collapsed u = 0 edge (a cone-like cap): the row i = 0 is one point.
BezierPatch cap() {
    BezierPatch S{2, 3, {}};
    for (int i = 0; i <= 2; ++i)
        for (int j = 0; j <= 3; ++j) {
            const double r = i, a = j * pi / 6;
            S.points.push_back({r * std::cos(a), r * std::sin(a), 2.0 - 0.5 * i * i});
        }
    return S;
}
}  // namespace

TEST_SUITE("Task 5: tensor-product patches") {
    TEST_CASE("patch point: Σ B_i(u) B_j(v) P_ij with i along u; j along v; for degrees 1..4 × 1..4" *
              geolab::points(2) * geolab::builds_on("Task 1") *
              geolab::hint("P_ij = points[i (degree_v + 1) + j]; de Casteljau in u on each column j (P_0j .. P_nj), "
                           "then in v on the results. A 2 × 3 patch tells u from v.")) {
        Rng rng(40);
        for (int du = 1; du <= 4; ++du)
            for (int dv = 1; dv <= 4; ++dv) {
                const BezierPatch S = random_patch(rng, du, dv);
                for (auto [u, v] : {std::pair{0.0, 0.0}, {0.25, 0.75}, {0.5, 0.125}, {1.0, 0.3}, {0.9, 1.0}}) {
                    const glm::dvec3 want = D(ref_patch(S, u, v)), got = patch_point(S, u, v);
                    INFO("degrees " << du << " × " << dv << " at (u, v) = (" << u << ", " << v << "): expected "
                                    << str(want) << ", got " << str(got));
                    CHECK(close3(got, want, 1e-13, 3));
                }
            }
        // corners are control points: S(1, 0) = P_(n,0)
        const BezierPatch S = random_patch(rng, 2, 3);
        CHECK(patch_point(S, 1, 0) == S.points[2 * 4 + 0]);
        CHECK(patch_point(S, 0, 1) == S.points[3]);
        BezierPatch bad = S;
        bad.points.pop_back();
        CHECK_THROWS_AS(patch_point(bad, 0.5, 0.5), std::invalid_argument);
        const BezierPatch flat_v{1, 0, {{0, 0, 0}, {1, 0, 0}}};  // degree 0 in v (2 points: the count fits)
        CHECK_THROWS_AS(patch_point(flat_v, 0.5, 0.5), std::invalid_argument);
        CHECK_THROWS_AS(patch_du(flat_v, 0.5, 0.5), std::invalid_argument);
        CHECK_THROWS_AS(patch_dv(flat_v, 0.5, 0.5), std::invalid_argument);
    }

    TEST_CASE("patch derivatives: S_u and S_v" * geolab::points(2) * geolab::builds_on("Task 1, Task 2") *
              geolab::hint("S_u: the u-derivative of each column's curve, then de Casteljau in v; S_v: the points of "
                           "the columns at u, then the derivative of that curve in v.")) {
        Rng rng(41);
        for (int du = 1; du <= 4; ++du)
            for (int dv = 1; dv <= 4; ++dv) {
                const BezierPatch S = random_patch(rng, du, dv);
                for (auto [u, v] : {std::pair{0.0, 0.5}, {0.3, 0.7}, {1.0, 1.0}, {0.5, 0.0}}) {
                    const glm::dvec3 wu = D(ref_patch(S, u, v, 1, 0)), wv = D(ref_patch(S, u, v, 0, 1));
                    const glm::dvec3 gu = patch_du(S, u, v), gv = patch_dv(S, u, v);
                    INFO("degrees " << du << " × " << dv << " at (" << u << ", " << v << "): S_u expected " << str(wu)
                                    << ", got " << str(gu) << "; S_v expected " << str(wv) << ", got " << str(gv));
                    CHECK(close3(gu, wu, 1e-12, 12));
                    CHECK(close3(gv, wv, 1e-12, 12));
                }
            }
    }

    TEST_CASE("patch normal: unit; along S_u × S_v; the limit at a collapsed edge" * geolab::points(2) *
              geolab::builds_on("Task 1, Task 2") *
              geolab::hint("Where S_u × S_v = 0 (a collapsed edge) take the limit moving into the patch: the first-"
                           "order term, or a point moved slightly inside (handout §6). Never NaN.")) {
        Rng rng(42);
        for (int rep = 0; rep < 20; ++rep) {
            const BezierPatch S = random_patch(rng, 1 + rep % 3, 1 + rep / 7);
            const double u = rng.uniform(0, 1), v = rng.uniform(0, 1);
            const V3L c = cross(ref_patch(S, u, v, 1, 0), ref_patch(S, u, v, 0, 1));
            const glm::dvec3 want = D((1 / norm(c)) * c), got = patch_normal(S, u, v);
            INFO("random patch at (" << num(u) << ", " << num(v) << "): expected " << str(want) << ", got " << str(got));
            CHECK(close3(got, want, 1e-10));
        }
        // the cap's collapsed edge moved to u = 1 (rows reversed) and to v = 0 / v = 1 (transposed): the limit
        // normal must come from inside the patch on every side
        BezierPatch Cu1{2, 3, {}}, Cv0{3, 2, {}}, Cv1{3, 2, {}};
        const BezierPatch C0 = cap();
        for (int i = 2; i >= 0; --i)
            for (int j = 0; j <= 3; ++j) Cu1.points.push_back(C0.points[i * 4 + j]);
        for (int j = 0; j <= 3; ++j)
            for (int i = 0; i <= 2; ++i) Cv0.points.push_back(C0.points[i * 4 + j]);
        for (int j = 0; j <= 3; ++j)
            for (int i = 2; i >= 0; --i) Cv1.points.push_back(C0.points[i * 4 + j]);
        struct Side {
            const char* name;
            const BezierPatch* S;
            double u, v, du, dv;
        };
        const Side sides[] = {{"collapsed u = 1", &Cu1, 1.0, 0.4, -1e-5, 0.0},
                              {"collapsed v = 0", &Cv0, 0.4, 0.0, 0.0, 1e-5},
                              {"collapsed v = 1", &Cv1, 0.6, 1.0, 0.0, -1e-5}};
        for (const auto& sd : sides) {
            const glm::dvec3 n0 = patch_normal(*sd.S, sd.u, sd.v), want = ref_normal(*sd.S, sd.u, sd.v);
            INFO(sd.name << ": normal at the edge " << str(n0) << ", expected the limit from inside " << str(want));
            REQUIRE(std::isfinite(n0.x + n0.y + n0.z));
            CHECK(close3(n0, want, 1e-9));
        }
        // a corner where S_u, S_v and S_uv all vanish (P00 = P01 = P10 = P11): the normal from just inside
        BezierPatch flat{3, 3, {}};
        for (int i = 0; i <= 3; ++i)
            for (int j = 0; j <= 3; ++j)
                flat.points.push_back({std::max(i, 1) - 1.0, std::max(j, 1) - 1.0, 0.1 * i * j});
        {
            const glm::dvec3 n0 = patch_normal(flat, 0, 0);
            const V3L c = cross(ref_patch(flat, 1e-3, 1e-3, 1, 0), ref_patch(flat, 1e-3, 1e-3, 0, 1));
            INFO("corner with S_u = S_v = S_uv = 0: normal " << str(n0) << ", just inside " << str(D((1 / norm(c)) * c)));
            REQUIRE(std::isfinite(n0.x + n0.y + n0.z));
            CHECK(glm::dot(n0, D((1 / norm(c)) * c)) >= 0.99);
            // the same corner at (1, 1): rows and columns reversed
            BezierPatch rev{3, 3, {}};
            for (int i = 3; i >= 0; --i)
                for (int j = 3; j >= 0; --j) rev.points.push_back(flat.points[i * 4 + j]);
            const glm::dvec3 n1 = patch_normal(rev, 1, 1);
            const V3L c1 = cross(ref_patch(rev, 1 - 1e-3, 1 - 1e-3, 1, 0), ref_patch(rev, 1 - 1e-3, 1 - 1e-3, 0, 1));
            INFO("the corner at (1, 1): normal " << str(n1) << ", just inside " << str(D((1 / norm(c1)) * c1)));
            REQUIRE(std::isfinite(n1.x + n1.y + n1.z));
            CHECK(glm::dot(n1, D((1 / norm(c1)) * c1)) >= 0.99);
        }
        CHECK_THROWS_AS(patch_normal(BezierPatch{0, 1, {{0, 0, 0}, {1, 0, 0}}}, 0.5, 0.5), std::invalid_argument);
        // the cap at scale 1 and 1/10 (a first-order term shorter than 1 is as good as any other)
        for (double scale : {1.0, 0.1}) {
            BezierPatch C = cap();
            for (auto& p : C.points) p *= scale;
            for (double v : {0.0, 0.3, 0.5, 0.75, 1.0}) {
                const glm::dvec3 n0 = patch_normal(C, 0, v), want = ref_normal(C, 0, v);
                INFO("cap (scale " << scale << ") with a collapsed u = 0 edge, v = " << v << ": normal " << str(n0)
                                   << ", expected the limit from inside " << str(want));
                REQUIRE(std::isfinite(n0.x));
                CHECK(std::abs(glm::length(n0) - 1) <= 1e-12);
                CHECK(close3(n0, want, 1e-9));
            }
        }
    }

    TEST_CASE("patch normal where S_u × S_v counts as 0: the threshold; the first-order term with S_uu and S_vv; "
              "σ at ½; the 1e-6 step; a point patch" *
              geolab::points(2) *
              geolab::builds_on("Task 1, Task 2") *
              geolab::hint("|S_u × S_v| ≤ 1e-12 (|S_u| + |S_v|)² counts as 0. Then the direction of (σ_u S_uu + σ_v S_uv) × "
                           "S_v + S_u × (σ_u S_uv + σ_v S_vv), σ = +1 for a parameter ≤ ½, else −1; if that is exactly 0, "
                           "the normal at (u + σ_u 1e-6, v + σ_v 1e-6); if that is 0 too, (0, 0, 1) (handout §6).")) {
        // The threshold: a bilinear patch with S_u = (1, 0, 0), S_v = (1, ε, 0) at (0, 0), so |S_u × S_v| = ε against
        // 1e-12 (1 + 1)² = 4e-12, and S_uv = (0, 0, 5): above the threshold the normal is (0, 0, 1); at or below it
        // the first-order term S_uv × S_v + S_u × S_uv = (−5ε, 0, 0) gives (−1, 0, 0).
        for (auto [eps, want] : {std::pair{6e-12, glm::dvec3(0, 0, 1)}, {2e-12, glm::dvec3(-1, 0, 0)}}) {
            const BezierPatch B{1, 1, {{0, 0, 0}, {1, eps, 0}, {1, 0, 0}, {2, eps, 5}}};
            const glm::dvec3 got = patch_normal(B, 0, 0);
            INFO("|S_u × S_v| = " << eps << " (threshold 4e-12): expected " << str(want) << ", got " << str(got));
            CHECK(close3(got, want, 1e-12));
        }
        // A fold: S = (u + v, (2u − 1) v + v², u² + 2uv) has S_u = S_v = (1, 0, 1) at (½, 0). With σ = (+1, +1)
        // (u = ½ counts as the lower half): (S_uu + S_uv) × S_v + S_u × (S_uv + S_vv) = (−2, 2, 2); the other side
        // of the fold (σ_u = −1) would give (2, 2, −2). Transposed (u and v swapped) at (0, ½): the opposite normal.
        auto fold = [](int a, int b) -> glm::dvec3 {
            if (a == 1 && b == 0) return {1, 0, 0};
            if (a == 0 && b == 1) return {1, -1, 0};
            if (a == 1 && b == 1) return {0, 2, 2};
            if (a == 0 && b == 2) return {0, 1, 0};
            if (a == 2 && b == 0) return {0, 0, 1};
            return {0, 0, 0};
        };
        const BezierPatch F = patch_from_power(2, 2, fold);
        const BezierPatch Ft = patch_from_power(2, 2, [&](int a, int b) { return fold(b, a); });
        const glm::dvec3 wf = glm::dvec3(-1, 1, 1) / std::sqrt(3.0);
        const glm::dvec3 nf = patch_normal(F, 0.5, 0), nft = patch_normal(Ft, 0, 0.5);
        INFO("fold at (½, 0): expected " << str(wf) << " (numerically " << str(ref_normal(F, 0.5, 0)) << "), got "
                                         << str(nf) << "; transposed at (0, ½): expected " << str(-wf) << ", got " << str(nft));
        CHECK(close3(nf, wf, 1e-12));
        CHECK(close3(ref_normal(F, 0.5, 0), wf, 1e-9));  // the test's own limit agrees with the formula
        CHECK(close3(nft, -wf, 1e-12));
        // Corners where S_u ∥ S_v ≠ 0 (P_10 − P_00 = d, P_01 − P_00 = 2d, and likewise at the other corners) on a
        // random bicubic: S_uu and S_vv enter the first-order term; σ points into the patch from each corner.
        Rng rng(45);
        for (int rep = 0; rep < 3; ++rep) {
            BezierPatch S = random_patch(rng, 3, 3, 2);
            for (auto& p : S.points) p = {std::round(p.x * 8) / 8, std::round(p.y * 8) / 8, std::round(p.z * 8) / 8};
            const glm::dvec3 d{0.5, -0.25 + rep, 1};
            auto P = [&](int i, int j) -> glm::dvec3& { return S.points[i * 4 + j]; };
            P(1, 0) = P(0, 0) + d, P(0, 1) = P(0, 0) + 2.0 * d;        // corner (0, 0)
            P(2, 0) = P(3, 0) - d, P(3, 1) = P(3, 0) + 2.0 * d;        // corner (1, 0)
            P(1, 3) = P(0, 3) + 2.0 * d, P(0, 2) = P(0, 3) - d;        // corner (0, 1)
            P(2, 3) = P(3, 3) - 2.0 * d, P(3, 2) = P(3, 3) - d;        // corner (1, 1)
            for (auto [u, v] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {1.0, 1.0}}) {
                const glm::dvec3 got = patch_normal(S, u, v), want = ref_normal(S, u, v);
                INFO("bicubic " << rep << ", corner (" << u << ", " << v << ") with S_u ∥ S_v: expected the limit "
                                << str(want) << ", got " << str(got));
                CHECK(close3(got, want, 1e-9));
            }
        }
        // S_u = S_v = 0 at the corner (P_00 = P_01 = P_10): the first-order term is 0 too, so the normal at
        // (1e-6, 1e-6) — exactly there, not at another small step
        BezierPatch flat{3, 3, {}};
        for (int i = 0; i <= 3; ++i)
            for (int j = 0; j <= 3; ++j) flat.points.push_back({std::max(i, 1) - 1.0, std::max(j, 1) - 1.0, 0.1 * i * j});
        const V3L c6 = cross(ref_patch(flat, 1e-6L, 1e-6L, 1, 0), ref_patch(flat, 1e-6L, 1e-6L, 0, 1));
        const glm::dvec3 w6 = D((1 / norm(c6)) * c6), n6 = patch_normal(flat, 0, 0);
        INFO("corner with S_u = S_v = 0: expected the normal at (1e-6, 1e-6) " << str(w6) << ", got " << str(n6));
        CHECK(close3(n6, w6, 1e-8));
        // a patch collapsed to a point: (0, 0, 1); to a line: some unit vector
        const BezierPatch dot_patch{2, 1, std::vector<glm::dvec3>(6, glm::dvec3(1, -2, 3))};
        CHECK(patch_normal(dot_patch, 0.3, 0.7) == glm::dvec3(0, 0, 1));
        BezierPatch line_patch{2, 2, {}};
        for (int i = 0; i <= 2; ++i)
            for (int j = 0; j <= 2; ++j) line_patch.points.push_back(double(i + 2 * j) * glm::dvec3(1, 2, 3));
        for (auto [u, v] : {std::pair{0.0, 0.0}, {0.5, 0.5}, {1.0, 0.25}}) {
            const glm::dvec3 nl = patch_normal(line_patch, u, v);
            INFO("patch collapsed to a line, (" << u << ", " << v << "): " << str(nl));
            REQUIRE(std::isfinite(nl.x + nl.y + nl.z));
            CHECK(std::abs(glm::length(nl) - 1) <= 1e-12);
        }
    }

    TEST_CASE("tessellation: vertex order; the weld rule (earliest border vertex within weld_tol); collapsed edges" *
              geolab::points(2) *
              geolab::builds_on("Task 1, Task 2") *
              geolab::hint("Patches in order, samples i-major. A border sample within weld_tol (distance ≤ weld_tol) of "
                           "an earlier border vertex IS the earliest such vertex; interior samples are always new. "
                           "Drop a triangle with two equal vertices (handout §6).")) {
        // the expected mesh, vertex by vertex and triangle by triangle, from an independent tessellation
        auto check_mesh = [](const char* what, const std::vector<BezierPatch>& ps, int n, double tol, bool flip) {
            const PatchMesh got = tessellate_patches(ps, n, tol, flip);
            const std::string diff = compare_mesh(got, expected_tessellation(ps, n, tol, flip), ps, n, flip);
            INFO(what << ", n = " << n << ", weld_tol " << tol << (flip ? ", flipped" : "") << ": " << diff);
            CHECK(diff.empty());
        };
        auto square = [](double x0, double x1, double y0 = 0, double y1 = 1) {
            return BezierPatch{1, 1, {{x0, y0, 0}, {x0, y1, 0}, {x1, y0, 0}, {x1, y1, 0}}};
        };
        // distance exactly weld_tol welds, on either side in x; a chain welds to the earliest vertex
        check_mesh("unit square and one 0.25 to its right (weld_tol 0.25)", {square(0, 1), square(1.25, 2.25)}, 1, 0.25,
                   false);
        check_mesh("unit square and one 0.25 to its left", {square(0, 1), square(-1.25, -0.25)}, 1, 0.25, false);
        check_mesh("chain: C's left corners within 0.25 of A's and of B's (A earlier)",
                   {square(0, 1), square(1.375, 2.375), square(1.1875, 3)}, 1, 0.25, false);
        check_mesh("the same, n = 2", {square(0, 1), square(1.375, 2.375), square(1.1875, 3)}, 2, 0.25, false);
        // diagonal offsets: within weld_tol although x + y + z differs by more than weld_tol (√3 · 0.125 ≈ 0.217 ≤ 0.25
        // with x + y + z 0.375 apart; √3 ≤ 2 with 3 apart); both directions
        auto moved = [](BezierPatch S, const glm::dvec3& d) {
            for (auto& p : S.points) p += d;
            return S;
        };
        check_mesh("square and one moved by (1/8, 1/8, 1/8) past its right edge",
                   {square(0, 1), moved(square(1, 2), {0.125, 0.125, 0.125})}, 1, 0.25, false);
        check_mesh("square and one moved by (−1/8, −1/8, −1/8) past its left edge",
                   {square(0, 1), moved(square(-1, 0), {-0.125, -0.125, -0.125})}, 2, 0.25, false);
        check_mesh("large squares, offset (1, 1, 1), weld_tol 2",
                   {square(0, 10, 0, 10), moved(square(10, 20, 0, 10), {1, 1, 1})}, 1, 2.0, false);
        check_mesh("large squares, offset (−1, −1, −1), weld_tol 2",
                   {square(0, 10, 0, 10), moved(square(-10, 0, 0, 10), {-1, -1, -1})}, 1, 2.0, false);
        // interior samples are never welded (B's corner lies on A's centre sample)
        check_mesh("B's corner on A's interior sample", {square(0, 2, 0, 2), square(1, 3, 1, 3)}, 2, 1e-9, false);
        // weld_tol = 0 welds equal positions only
        check_mesh("squares 1e-15 apart at weld_tol 0", {square(0, 1), square(1 + 1e-15, 2)}, 1, 0.0, false);
        // collapsed edges on each side: one vertex, no triangle with a repeated vertex, the limit normal
        BezierPatch Cu1{2, 3, {}}, Cv0{3, 2, {}}, Cv1{3, 2, {}};
        const BezierPatch C0 = cap();
        for (int i = 2; i >= 0; --i)
            for (int j = 0; j <= 3; ++j) Cu1.points.push_back(C0.points[i * 4 + j]);
        for (int j = 0; j <= 3; ++j)
            for (int i = 0; i <= 2; ++i) Cv0.points.push_back(C0.points[i * 4 + j]);
        for (int j = 0; j <= 3; ++j)
            for (int i = 2; i >= 0; --i) Cv1.points.push_back(C0.points[i * 4 + j]);
        check_mesh("cap collapsed at u = 0", {C0}, 4, 1e-9, false);
        check_mesh("cap collapsed at u = 1", {Cu1}, 4, 1e-9, false);
        check_mesh("cap collapsed at v = 0", {Cv0}, 4, 1e-9, true);
        check_mesh("cap collapsed at v = 1", {Cv1}, 3, 1e-9, false);
        check_mesh("all four caps", {C0, Cu1, Cv0, Cv1}, 2, 1e-9, true);
        // a patch of degree 30 in u (the basis at high degree)
        BezierPatch high{30, 1, {}};
        for (int i = 0; i <= 30; ++i)
            for (int j = 0; j <= 1; ++j) high.points.push_back({double(i), double(j), std::sin(i * 0.3)});
        check_mesh("degree 30 × 1", {high}, 5, 1e-9, false);
    }

    TEST_CASE("tessellation: (n + 1)² samples per patch; 2n² triangles turning like S_u × S_v; borders shared" *
              geolab::points(2) *
              geolab::builds_on("Task 1") *
              geolab::hint("Triangles (i,j)(i+1,j)(i+1,j+1) and (i,j)(i+1,j+1)(i,j+1); weld only border samples closer "
                           "than weld_tol; flip reverses triangles and normals.")) {
        Rng rng(43);
        BezierPatch S{3, 2, {}};  // a gently curved 3 × 2 patch over the (u, v) grid (no folds)
        for (int i = 0; i <= 3; ++i)
            for (int j = 0; j <= 2; ++j) S.points.push_back({i + rng.uniform(-0.2, 0.2), 1.5 * j, rng.uniform(-0.4, 0.4)});
        for (int n : {1, 2, 5}) {
            const PatchMesh m = tessellate_patches({S}, n, 1e-9, false);
            INFO("one 3 × 2 patch, n = " << n << ": " << m.soup.n_vertices() << " vertices, " << m.soup.n_faces()
                                         << " faces");
            REQUIRE(m.soup.n_vertices() == std::size_t((n + 1) * (n + 1)));
            REQUIRE(m.soup.n_faces() == std::size_t(2 * n * n));
            REQUIRE(m.normals.size() == m.soup.n_vertices());
            CHECK(m.soup.is_triangle_soup());
            for (int i = 0; i <= n; ++i)
                for (int j = 0; j <= n; ++j) {
                    const glm::dvec3 p = D(ref_patch(S, LD(i) / n, LD(j) / n));
                    bool found = false;
                    for (std::size_t k = 0; k < m.soup.n_vertices(); ++k)
                        if (close3(m.soup.positions[k], p, 1e-12, 3)) found = true;
                    INFO("sample (" << i << ", " << j << ") = " << str(p) << " is a vertex");
                    CHECK(found);
                }
            for (std::size_t f = 0; f < m.soup.n_faces(); ++f) {
                const auto t = m.soup.face(f);
                const glm::dvec3 a = m.soup.positions[t[0]], b = m.soup.positions[t[1]], c = m.soup.positions[t[2]];
                const glm::dvec3 fn = glm::cross(b - a, c - a);
                const glm::dvec3 vn = m.normals[t[0]] + m.normals[t[1]] + m.normals[t[2]];
                INFO("face " << f << ": its normal " << str(fn) << " should agree with its vertices' " << str(vn));
                CHECK(glm::dot(fn, vn) > 0);
            }
            // each vertex normal is the patch's unit normal there; the triangles' total area is the grid's
            for (std::size_t k = 0; k < m.soup.n_vertices(); ++k) {
                const glm::dvec3 p = m.soup.positions[k];
                for (int i = 0; i <= n; ++i)
                    for (int j = 0; j <= n; ++j)
                        if (close3(D(ref_patch(S, LD(i) / n, LD(j) / n)), p, 1e-12, 3)) {
                            const V3L c = cross(ref_patch(S, LD(i) / n, LD(j) / n, 1, 0), ref_patch(S, LD(i) / n, LD(j) / n, 0, 1));
                            INFO("vertex " << k << " = sample (" << i << ", " << j << "): normal expected "
                                           << str(D((1 / norm(c)) * c)) << ", got " << str(m.normals[k]));
                            CHECK(close3(m.normals[k], D((1 / norm(c)) * c), 1e-9));
                        }
            }
            LD want_area = 0, got_area = 0;
            auto g = [&](int i, int j) { return ref_patch(S, LD(i) / n, LD(j) / n); };
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j)
                    want_area += norm(cross(g(i + 1, j) - g(i, j), g(i + 1, j + 1) - g(i, j))) / 2 +
                                 norm(cross(g(i + 1, j + 1) - g(i, j), g(i, j + 1) - g(i, j))) / 2;
            for (std::size_t f = 0; f < m.soup.n_faces(); ++f) {
                const auto t = m.soup.face(f);
                got_area += norm(cross(L(m.soup.positions[t[1]]) - L(m.soup.positions[t[0]]),
                                       L(m.soup.positions[t[2]]) - L(m.soup.positions[t[0]]))) / 2;
            }
            INFO("total triangle area: expected " << double(want_area) << " (the two triangles of every grid cell), got "
                                                  << double(got_area));
            CHECK(std::abs(double(got_area - want_area)) <= 1e-10 * double(want_area));
            const PatchMesh fl = tessellate_patches({S}, n, 1e-9, true);
            REQUIRE(fl.soup.n_faces() == m.soup.n_faces());
            CHECK(fl.normals[0] == -m.normals[0]);
        }
        // two halves of one patch (split at u = 1/2 by hand) share n + 1 border vertices
        BezierPatch L = S, R = S;
        for (int j = 0; j <= 2; ++j) {
            glm::dvec3 c[4];
            for (int i = 0; i <= 3; ++i) c[i] = S.points[i * 3 + j];
            const glm::dvec3 a1 = 0.5 * (c[0] + c[1]), a2 = 0.5 * (c[1] + c[2]), a3 = 0.5 * (c[2] + c[3]);
            const glm::dvec3 b1 = 0.5 * (a1 + a2), b2 = 0.5 * (a2 + a3), m = 0.5 * (b1 + b2);
            const glm::dvec3 l[4] = {c[0], a1, b1, m}, r[4] = {m, b2, a3, c[3]};
            for (int i = 0; i <= 3; ++i) L.points[i * 3 + j] = l[i], R.points[i * 3 + j] = r[i];
        }
        const int n = 4;
        const PatchMesh two = tessellate_patches({L, R}, n, 1e-9, false);
        INFO("two halves of a patch at n = 4: expected " << (2 * n + 1) * (n + 1) << " vertices, got "
                                                          << two.soup.n_vertices());
        CHECK(two.soup.n_vertices() == std::size_t((2 * n + 1) * (n + 1)));
        CHECK(two.soup.n_faces() == std::size_t(4 * n * n));
        // weld_tol = 0 welds bitwise-equal border samples (the shared border's samples are exact here)
        const PatchMesh exact = tessellate_patches({L, R}, n, 0.0, false);
        CHECK(exact.soup.n_vertices() == std::size_t((2 * n + 1) * (n + 1)));
        CHECK_THROWS_AS(tessellate_patches({S}, 0, 1e-9, false), std::invalid_argument);
        CHECK_THROWS_AS(tessellate_patches({S}, 2, -1.0, false), std::invalid_argument);
        BezierPatch high{30, 1, {}};  // degree 30 is allowed
        for (int i = 0; i <= 30; ++i)
            for (int j = 0; j <= 1; ++j) high.points.push_back({double(i), double(j), std::sin(i * 0.3)});
        CHECK(tessellate_patches({high}, 2, 1e-9, false).soup.n_vertices() == 9);
    }
}

TEST_SUITE("Task 6: the Utah teapot") {
    TEST_CASE("teapot: shared patch edges agree within 1e-12" * geolab::points(2) * geolab::builds_on("Task 1") *
              geolab::hint("Neighbouring patches share their border control points; your patch_point must give the "
                           "same points along the shared border.")) {
        const auto& T = teapot();
        REQUIRE(T.size() == 32);
        // borders as control-point lists: u = 0, u = 1 (rows), v = 0, v = 1 (columns), with their parameters
        struct Border {
            int patch, kind;
            std::vector<glm::dvec3> pts;
        };
        std::vector<Border> borders;
        for (int p = 0; p < 32; ++p)
            for (int kind = 0; kind < 4; ++kind) {
                Border b{p, kind, {}};
                for (int k = 0; k < 4; ++k) {
                    const int i = kind == 0 ? 0 : kind == 1 ? 3 : k, j = kind == 2 ? 0 : kind == 3 ? 3 : k;
                    b.pts.push_back(T[p].points[i * 4 + j]);
                }
                borders.push_back(b);
            }
        auto at = [&](const Border& b, double s) {
            const double u = b.kind == 0 ? 0 : b.kind == 1 ? 1 : s, v = b.kind == 2 ? 0 : b.kind == 3 ? 1 : s;
            return patch_point(T[b.patch], u, v);
        };
        // (points that agree because they are all the same prove nothing): a patch passes through its corners
        for (int p = 0; p < 32; ++p) {
            const glm::dvec3 c = patch_point(T[p], 0, 0);
            CHECK_MESSAGE(glm::length(c - T[p].points[0]) <= 1e-12, "patch " << p << " at (0, 0): expected its corner "
                                                                            << str(T[p].points[0]) << ", got " << str(c));
        }
        int shared = 0;
        for (std::size_t a = 0; a < borders.size(); ++a)
            for (std::size_t b = a + 1; b < borders.size(); ++b) {
                if (borders[a].patch == borders[b].patch) continue;
                const bool same = borders[a].pts == borders[b].pts;
                auto rev = borders[b].pts;
                std::reverse(rev.begin(), rev.end());
                const bool reversed = borders[a].pts == rev;
                if (!same && !reversed) continue;
                if (borders[a].pts.front() == borders[a].pts.back() && borders[a].pts[1] == borders[a].pts[0]) continue;
                ++shared;
                for (int k = 0; k <= 16; ++k) {
                    const double s = k / 16.0;
                    const glm::dvec3 pa = at(borders[a], s), pb = at(borders[b], same ? s : 1 - s);
                    INFO("patches " << borders[a].patch << " and " << borders[b].patch << " share a border: at s = "
                                    << s << " " << str(pa) << " vs " << str(pb));
                    CHECK(glm::length(pa - pb) <= 1e-12);
                }
            }
        INFO("shared borders found: " << shared);
        CHECK(shared >= 40);
    }

    TEST_CASE("teapot: normals everywhere; vertical at the lid's top and the bottom's centre" * geolab::points(2) *
              geolab::builds_on("Task 1, Task 2") *
              geolab::hint("Patches 20–23 (lid) and 28–31 (bottom) collapse their u = 0 edge to one point: S_u × S_v "
                           "= 0 there. The normal is the limit from inside the patch.")) {
        const auto& T = teapot();
        for (int p = 0; p < 32; ++p)
            for (int i = 0; i <= 8; ++i)
                for (int j = 0; j <= 8; ++j) {
                    const glm::dvec3 nrm = patch_normal(T[p], i / 8.0, j / 8.0);
                    INFO("patch " << p << " at (" << i / 8.0 << ", " << j / 8.0 << "): normal " << str(nrm));
                    REQUIRE(std::isfinite(nrm.x + nrm.y + nrm.z));
                    CHECK(std::abs(glm::length(nrm) - 1) <= 1e-12);
                }
        for (int p : {20, 21, 22, 23, 28, 29, 30, 31})
            for (double v : {0.0, 0.5, 1.0}) {
                const glm::dvec3 nrm = patch_normal(T[p], 0, v);
                INFO("patch " << p << " at its collapsed corner (0, " << v << "): normal " << str(nrm)
                              << " should be vertical");
                CHECK(std::abs(std::abs(nrm.z) - 1) <= 1e-9);
                const V3L c = cross(ref_patch(T[p], 1e-4, v, 1, 0), ref_patch(T[p], 1e-4, v, 0, 1));
                CHECK(glm::dot(nrm, D(c)) > 0);  // the same side as the normals just inside
            }
    }

    TEST_CASE("teapot: samples inside each patch's convex hull; the body's normals point in (file order)" *
              geolab::points(2) * geolab::builds_on("Task 1") *
              geolab::hint("S_u × S_v of the file's patches points into the teapot; tessellate with flip = true for "
                           "outward normals.")) {
        const auto& T = teapot();
        Rng rng(44);
        std::vector<glm::dvec3> dirs;
        for (int k = 0; k < 64; ++k) {
            glm::dvec3 d{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
            dirs.push_back(glm::normalize(d));
        }
        for (int p = 0; p < 32; ++p)
            for (int i = 0; i <= 6; ++i)
                for (int j = 0; j <= 6; ++j) {
                    const glm::dvec3 x = patch_point(T[p], i / 6.0, j / 6.0);
                    for (const auto& d : dirs) {
                        double support = -1e300;
                        for (const auto& q : T[p].points) support = std::max(support, glm::dot(d, q));
                        INFO("patch " << p << " sample (" << i << ", " << j << ") = " << str(x)
                                      << " outside its control points' hull along " << str(d));
                        CHECK(glm::dot(d, x) <= support + 1e-12);
                    }
                }
        // body patches 4–11: flip = true gives outward normals (away from the z axis)
        std::vector<BezierPatch> body(T.begin() + 4, T.begin() + 12);
        const PatchMesh m = tessellate_patches(body, 6, 1e-9, true);
        int outward = 0;
        for (std::size_t k = 0; k < m.soup.n_vertices(); ++k) {
            const glm::dvec3 p = m.soup.positions[k];
            outward += glm::dot(m.normals[k], glm::dvec3(p.x, p.y, 0)) > 0;
        }
        INFO("body tessellated with flip = true: " << outward << " of " << m.soup.n_vertices() << " normals outward");
        CHECK(outward == int(m.soup.n_vertices()));
    }
}
