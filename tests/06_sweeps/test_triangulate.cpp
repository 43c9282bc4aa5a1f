// Lab 06, Task 2: triangulation. Any triangulation of the region is right (the bridges and the order of the ears
// are yours to choose), so the tests check what every right one has, exactly (helpers.hpp: triangulation_problem):
// the count n + 2h − 2, counter-clockwise triangles, each loop edge used once as it runs, each diagonal once each
// way; together these mean the triangles cover the region exactly once. Profiles: fixed ones, random star-shaped
// ones, and grid profiles full of ties and collinear points, every loop started at a random point.
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab06;

namespace {
using Tris = std::vector<std::array<std::uint32_t, 3>>;

// Checks a triangulation of p exactly (helpers.hpp: triangulation_problem) and its total area.
void check_triangulation(const Profile& p, const Tris& t) {
    INFO("input: " << str(p));
    const std::string bad = triangulation_problem(p, t);
    CHECK_MESSAGE(bad.empty(), "not a triangulation of the region:" << bad);
    const std::vector<glm::dvec2> pts = profile_points(p);
    LD total = 0;
    for (const auto& tr : t)
        if (tr[0] < pts.size() && tr[1] < pts.size() && tr[2] < pts.size()) total += (LD)cross2(pts[tr[0]], pts[tr[1]], pts[tr[2]]) / 2;
    const double want = double(region_area(p));
    CHECK_MESSAGE(close(double(total), want, 1e-9), "the triangles' areas add up to " << double(total)
                                                                                     << ", the region's area is " << want);
}
}  // namespace

TEST_SUITE("Task 2: triangulation") {
    TEST_CASE("triangulate: convex polygons and a square with a hole" * geolab::points(1) *
              geolab::builds_on("Task 1") *
              geolab::hint("Ear clipping: a vertex is an ear when it is convex (orient2d > 0) and no other vertex lies "
                           "in its triangle; clip it, repeat (handout §3).")) {
        for (const Profile& p : {Profile{rectangle_loop(0, 0, 1, 1), {}}, Profile{circle_loop({1, 2}, 3, 5), {}},
                                 Profile{circle_loop({0, 0}, 1, 40), {}}, Profile{Loop{{0, 0}, {1, 0}, {0, 1}}, {}},
                                 square_with_hole()})
            check_triangulation(p, triangulate(p));
    }

    TEST_CASE("triangulate: random star-shaped (non-convex) polygons; started anywhere" * geolab::points(2) *
              geolab::builds_on("Task 1") *
              geolab::hint("A reflex corner is never an ear; an ear's triangle must not contain any other vertex "
                           "(test all of them, with exact orient2d). The loop's first point is not special.")) {
        Rng rng(72);
        for (int k = 0; k < 25; ++k) {
            const Profile p = rotated_loops(rng, {star(rng, rng.integer(4, 60), 0.3, 3.0), {}});
            check_triangulation(p, triangulate(p));
        }
    }

    TEST_CASE("triangulate: profiles with several holes (bridging); every loop started anywhere" * geolab::points(3) *
              geolab::builds_on("Task 1") *
              geolab::hint("Bridge each hole into the polygon from its rightmost vertex M to the nearest vertex P that M "
                           "sees (no edge of the polygon or of any hole in the way) and whose corner opens towards M; "
                           "holes by decreasing rightmost x; the bridge is walked twice (handout §3).")) {
        Rng rng(73);
        for (int k = 0; k < 30; ++k) {
            const Profile p = rotated_loops(rng, star_with_holes(rng, rng.integer(6, 40), 1 + k % 6));
            check_triangulation(p, triangulate(p));
        }
        // A hole whose rightmost vertex sees the outer loop only past a reflex notch.
        const Profile notch{Loop{{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 6}, {6, 5.5}, {0, 5}}, {reversed(rectangle_loop(1, 2, 3, 4))}};
        check_triangulation(notch, triangulate(notch));
        // Three holes side by side at the same height (a hole is in the way of the next one's bridge).
        const Profile row{rectangle_loop(0, 0, 10, 3), {reversed(rectangle_loop(1, 1, 2, 2)), reversed(rectangle_loop(4, 1, 5, 2)),
                                                         reversed(rectangle_loop(7, 1, 8, 2))}};
        check_triangulation(row, triangulate(row));
        // A triangular hole whose first point is its rightmost (and the only one that sees out past the hole itself).
        const Profile tip{rectangle_loop(0, 0, 10, 10), {Loop{{8, 5}, {2, 2}, {2, 8}}}};
        check_triangulation(tip, triangulate(tip));
        // A hole in a pocket of another hole: the pocket's mouth is the only way out.
        // A chevron whose rightmost point (1, 0) sees one vertex only: the outer loop's first, (10, 0), straight ahead
        // (the others are behind the chevron; its notch (−2, 0) lies on the same line, behind the rightmost point).
        const Profile chevron{Loop{{10, 0}, {-10, 10}, {-10, -10}}, {Loop{{1, 0}, {-4, -6}, {-2, 0}, {-4, 6}}}};
        check_triangulation(chevron, triangulate(chevron));
        const Profile pocket{rectangle_loop(0, 0, 12, 12),
                             {reversed(Loop{{2, 2}, {10, 2}, {10, 10}, {2, 10}, {2, 7}, {8, 7}, {8, 5}, {2, 5}}),
                              reversed(rectangle_loop(1, 5.5, 7, 6.5))}};
        check_triangulation(pocket, triangulate(pocket));
    }

    TEST_CASE("triangulate: grid profiles — holes level with each other and with the outer loop; collinear points" *
              geolab::points(2) * geolab::builds_on("Task 1") *
              geolab::hint("Ties everywhere: a bridge must not pass through a vertex (a point on the segment blocks it "
                           "too), and a vertex used by an earlier bridge appears twice in the polygon: join at the copy "
                           "whose corner opens towards the hole.")) {
        Rng rng(75);
        for (int k = 0; k < 40; ++k) {
            const Profile p = grid_profile(rng, rng.integer(1, 5), rng.integer(1, 4), rng.integer(1, 8));
            check_triangulation(p, triangulate(p));
        }
        // Found by a random search: (16, 4) is reflex and joined by several bridges; each must join the right copy.
        const Profile copies{Loop{{17, 20}, {16, 20}, {16, 5}, {16, 4}, {4, 4}, {0, 4}, {0, 1}, {0, 0}, {16, 0}, {20, 0}, {20, 20}},
                             {Loop{{17, 18}, {17, 19}, {18, 19}, {19, 19}, {19, 18}, {19, 17}, {18, 17}, {17, 17}},
                              Loop{{15, 3}, {15, 2}, {15, 1}, {14, 1}, {13, 1}, {13, 2}, {13, 3}, {14, 3}},
                              Loop{{17, 10}, {18, 11}, {19, 10}, {18, 9}},
                              Loop{{1, 2.5}, {3, 2.5}, {3, 2}, {1, 2}},
                              Loop{{5, 1}, {5, 3}, {7, 3}, {7, 1}},
                              Loop{{17, 6.5}, {19, 6.5}, {19, 6}, {17, 6}},
                              Loop{{18, 3}, {19, 2}, {18, 1}, {17, 2}},
                              Loop{{10, 2}, {11, 2}, {11, 1}, {9, 1}, {9, 3}, {10, 3}},
                              Loop{{17, 13}, {17, 15}, {19, 15}, {19, 13}}}};
        check_triangulation(copies, triangulate(copies));
    }

    TEST_CASE("triangulate: combs; collinear points; a loop starting at a straight corner" * geolab::points(2) *
 geolab::builds_on("Task 1") *
              geolab::hint("Collinear consecutive points (orient2d = 0) are not ears; clip the others first. Deep notches "
                           "need the full containment test, with points on the triangle's edges counted as inside.")) {
        Loop comb{{0, 0}, {10, 0}, {10, 1}};
        for (int i = 9; i >= 1; --i) comb.push_back({double(i), i % 2 ? 5.0 : 1.0}), comb.push_back({i - 0.5, 1.0});
        comb.push_back({0, 1});
        check_triangulation({comb, {}}, triangulate({comb, {}}));
        const Loop mids{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
        for (std::size_t k = 0; k < mids.size(); ++k) check_triangulation({rotated(mids, k), {}}, triangulate({rotated(mids, k), {}}));
        const Loop straight_first{{1, 0}, {2, 0}, {1, 2}, {0, 0}};  // the triangle (0,0) (2,0) (1,2), starting mid-edge
        check_triangulation({straight_first, {}}, triangulate({straight_first, {}}));
        // (2, 2) is reflex and lies on the segment (0, 4)–(4, 0): the corner at (0, 0) is not an ear
        const Loop notched{{0, 0}, {4, 0}, {4, 4}, {2, 2}, {0, 4}};
        for (std::size_t k = 0; k < notched.size(); ++k)
            check_triangulation({rotated(notched, k), {}}, triangulate({rotated(notched, k), {}}));
        const Profile ring{circle_loop({0, 0}, 2, 48), {reversed(circle_loop({0, 0}, 1.9, 48))}};
        check_triangulation(ring, triangulate(ring));
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

