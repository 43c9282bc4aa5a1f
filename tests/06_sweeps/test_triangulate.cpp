// Lab 06, Task 2: triangulation. Expected values: the region's area (long double shoelace), the count n + 2h − 2,
// and coverage: sample points of the region each lie in exactly one triangle, points outside it (holes) in none.
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab06;

namespace {
using Tris = std::vector<std::array<std::uint32_t, 3>>;

// Checks count, orientation, total area and coverage of a triangulation of p.
void check_triangulation(const Profile& p, const Tris& t, Rng& rng, int samples = 400) {
    INFO("input: " << str(p));
    const std::vector<glm::dvec2> pts = profile_points(p);
    const std::size_t want_count = pts.size() + 2 * p.holes.size() - 2;
    CHECK_MESSAGE(t.size() == want_count, "expected " << want_count << " triangles (n + 2h − 2 with n = " << pts.size()
                                                      << ", h = " << p.holes.size() << "), got " << t.size());
    LD total = 0;
    for (std::size_t k = 0; k < t.size(); ++k) {
        for (auto i : t[k])
            if (i >= pts.size()) {
                FAIL_CHECK("triangle " << k << " has index " << i << " >= " << pts.size() << " points");
                return;
            }
        const double a = cross2(pts[t[k][0]], pts[t[k][1]], pts[t[k][2]]);
        CHECK_MESSAGE(a > 0, "triangle " << k << " (" << t[k][0] << ", " << t[k][1] << ", " << t[k][2]
                                         << ") is not counter-clockwise (twice its signed area " << a << ")");
        total += (LD)a / 2;
    }
    const double want = double(region_area(p));
    CHECK_MESSAGE(close(double(total), want, 1e-9), "the triangles' areas add up to " << double(total)
                                                                                     << ", the region's area is " << want);
    // Coverage: bounding box samples.
    glm::dvec2 lo(1e300), hi(-1e300);
    for (auto q : pts) lo = glm::min(lo, q), hi = glm::max(hi, q);
    int bad = 0;
    for (int s = 0; s < samples && bad < 3; ++s) {
        const glm::dvec2 q{rng.uniform(lo.x, hi.x), rng.uniform(lo.y, hi.y)};
        int covered = 0;
        bool on_edge = false;
        for (const auto& tr : t) {
            const double c0 = cross2(pts[tr[0]], pts[tr[1]], q), c1 = cross2(pts[tr[1]], pts[tr[2]], q),
                         c2 = cross2(pts[tr[2]], pts[tr[0]], q);
            if (std::min({std::abs(c0), std::abs(c1), std::abs(c2)}) < 1e-12) on_edge = true;
            if (c0 > 0 && c1 > 0 && c2 > 0) ++covered;
        }
        if (on_edge) continue;
        const int want_cover = in_region(p, q) ? 1 : 0;
        if (covered != want_cover) {
            ++bad;
            FAIL_CHECK("the point " << str(q) << " is " << (want_cover ? "inside" : "outside")
                                    << " the region but lies in " << covered << " triangles");
        }
    }
}
}  // namespace

TEST_SUITE("Task 2: triangulation") {
    TEST_CASE("triangulate: convex polygons and a square with a hole" * geolab::points(2) *
              geolab::builds_on("Task 1") *
              geolab::hint("Ear clipping: a vertex is an ear when it is convex (orient2d > 0) and no other vertex lies "
                           "in its triangle; clip it, repeat (handout §3).")) {
        Rng rng(71);
        for (const Profile& p : {Profile{rectangle_loop(0, 0, 1, 1), {}}, Profile{circle_loop({1, 2}, 3, 5), {}},
                                 Profile{circle_loop({0, 0}, 1, 40), {}}, Profile{Loop{{0, 0}, {1, 0}, {0, 1}}, {}},
                                 square_with_hole()})
            check_triangulation(p, triangulate(p), rng);
    }

    TEST_CASE("triangulate: random star-shaped (non-convex) polygons are covered exactly once" * geolab::points(3) *
              geolab::builds_on("Task 1") *
              geolab::hint("A reflex corner is never an ear; an ear's triangle must not contain any other vertex "
                           "(test all of them, with exact orient2d).")) {
        Rng rng(72);
        for (int k = 0; k < 25; ++k) {
            const Profile p{star(rng, rng.integer(4, 60), 0.3, 3.0), {}};
            check_triangulation(p, triangulate(p), rng, 200);
        }
    }

    TEST_CASE("triangulate: profiles with several holes (bridging) are covered exactly once" * geolab::points(3) *
              geolab::builds_on("Task 1") *
              geolab::hint("Bridge each hole into the outer loop from its rightmost vertex to a vertex it sees (the "
                           "nearest crossing of the ray to +x, then the reflex vertices in the triangle), holes by "
                           "decreasing x; the bridge is walked twice (handout §3).")) {
        Rng rng(73);
        for (int k = 0; k < 20; ++k) {
            const Profile p = star_with_holes(rng, rng.integer(6, 40), 1 + k % 5);
            check_triangulation(p, triangulate(p), rng, 200);
        }
        // A hole whose rightmost vertex sees the outer loop only past a reflex notch.
        const Profile notch{Loop{{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 6}, {6, 5.5}, {0, 5}}, {reversed(rectangle_loop(1, 2, 3, 4))}};
        check_triangulation(notch, triangulate(notch), rng);
        // Two holes side by side at the same height (the second's ray meets the first).
        const Profile row{rectangle_loop(0, 0, 10, 3), {reversed(rectangle_loop(1, 1, 2, 2)), reversed(rectangle_loop(4, 1, 5, 2)),
                                                         reversed(rectangle_loop(7, 1, 8, 2))}};
        check_triangulation(row, triangulate(row), rng);
    }

    TEST_CASE("triangulate: combs and collinear points" * geolab::points(2) * geolab::builds_on("Task 1") *
              geolab::hint("Collinear consecutive points (orient2d = 0) are not ears; clip the others first. Deep notches "
                           "need the full containment test.")) {
        Rng rng(74);
        Loop comb{{0, 0}, {10, 0}, {10, 1}};
        for (int i = 9; i >= 1; --i) comb.push_back({double(i), i % 2 ? 5.0 : 1.0}), comb.push_back({i - 0.5, 1.0});
        comb.push_back({0, 1});
        check_triangulation({comb, {}}, triangulate({comb, {}}), rng);
        const Loop mids{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
        check_triangulation({mids, {}}, triangulate({mids, {}}), rng);
        const Profile ring{circle_loop({0, 0}, 2, 48), {reversed(circle_loop({0, 0}, 1.9, 48))}};
        check_triangulation(ring, triangulate(ring), rng);
    }

    TEST_CASE("triangulate: invalid profiles are rejected" * geolab::points(1) * geolab::builds_on("Task 1") *
              geolab::hint("Validate first (validate_profile) and let its std::invalid_argument through.")) {
        Profile p = square_with_hole();
        p.holes[0] = reversed(p.holes[0]);
        CHECK_THROWS_AS(triangulate(p), std::invalid_argument);
        CHECK_THROWS_AS(triangulate({Loop{{0, 0}, {2, 2}, {2, 0}, {0, 2}}, {}}), std::invalid_argument);
        // valid input is no error ("reject everything" is not the contract)
        CHECK(triangulate(square_with_hole()).size() == 8);
    }
}  // TEST_SUITE
