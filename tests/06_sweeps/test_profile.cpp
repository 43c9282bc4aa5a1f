// Lab 06, Task 1: profiles. Expected values: the shoelace sum in long double, and profiles invalid by construction.
#include "helpers.hpp"

using namespace lab06;

namespace {
// validate_profile must throw std::invalid_argument whose message contains `word`.
void expect_rejected(const Profile& p, const std::string& why, const std::string& word) {
    INFO("input: " << str(p) << " (" << why << ")");
    bool threw = false;
    try {
        validate_profile(p);
    } catch (const std::invalid_argument& e) {
        threw = true;
        const std::string msg = e.what();
        CHECK_MESSAGE(msg.find(word) != std::string::npos,
                      "the message should name the problem with the word '" << word << "'; got: " << msg);
    }
    CHECK_MESSAGE(threw, "validate_profile accepted an invalid profile: " << why);
}
}  // namespace

TEST_SUITE("Task 1: profiles") {
    TEST_CASE("signed_area: squares; triangles and random star polygons; positive counter-clockwise" *
              geolab::points(2) *
              geolab::hint("Shoelace: ½ Σ (xᵢ yᵢ₊₁ − xᵢ₊₁ yᵢ), the last point joined to the first (handout §2).")) {
        CHECK_MESSAGE(signed_area(rectangle_loop(0, 0, 4, 3)) == doctest::Approx(12.0),
                      "4×3 rectangle counter-clockwise: expected 12");
        CHECK_MESSAGE(signed_area(reversed(rectangle_loop(0, 0, 4, 3))) == doctest::Approx(-12.0),
                      "4×3 rectangle clockwise: expected -12");
        CHECK_MESSAGE(signed_area(Loop{{0, 0}, {1, 0}, {0, 1}}) == doctest::Approx(0.5), "unit right triangle: 0.5");
        CHECK_MESSAGE(signed_area(Loop{{0, 0}, {1, 0}}) == 0.0, "two points: area 0");
        CHECK_MESSAGE(signed_area(Loop{}) == 0.0, "no points: area 0");
        Rng rng(61);
        for (int k = 0; k < 20; ++k) {
            const Loop l = shifted(star(rng, rng.integer(3, 40), 0.5, 3.0), {rng.uniform(-100, 100), rng.uniform(-100, 100)});
            const double want = double(area_ld(l)), got = signed_area(l), got_r = signed_area(reversed(l));
            CHECK_MESSAGE(close(got, want, 1e-11, 10), "star polygon " << str(l) << ": expected " << want << ", got " << got);
            CHECK_MESSAGE(close(got_r, -want, 1e-11, 10), "the same polygon reversed: expected " << -want << ", got " << got_r);
        }
    }

    TEST_CASE("validate_profile: valid profiles pass (convex; star-shaped; with one and several holes)" *
              geolab::points(2) *
              geolab::hint("Accept an outer loop that is counter-clockwise and holes that are clockwise, strictly inside "
                           "and apart; use exact orient2d (geolab/predicates.hpp) for the intersection tests.")) {
        std::vector<Profile> ok = {{rectangle_loop(0, 0, 1, 1), {}}, square_with_hole(), square_with_hole({2, 0}),
                                   {circle_loop({0, 0}, 1, 64), {reversed(circle_loop({0.2, 0}, 0.3, 12))}}};
        Rng rng(62);
        for (int k = 0; k < 10; ++k) ok.push_back(star_with_holes(rng, rng.integer(5, 30), k % 4));
        for (int k = 0; k < 10; ++k) ok.push_back(grid_profile(rng, rng.integer(1, 4), rng.integer(1, 3), rng.integer(0, 6)));
        // the line of edge 0 passes through the end (5, 5) of edge 3, whose other end (1, 3) is in edge 0's box
        ok.push_back({Loop{{0, 0}, {4, 4}, {6, 4}, {5, 5}, {1, 3}, {-1, 3}}, {}});
        ok.push_back({reversed(Loop{{0, 0}, {4, 4}, {6, 4}, {5, 5}, {1, 3}, {-1, 3}}), {}});  // made counter-clockwise below
        for (auto& q : ok)
            if (area_ld(q.outer) < 0) q.outer = reversed(q.outer);
        for (const auto& p : ok) {
            INFO("input: " << str(p));
            CHECK_NOTHROW(validate_profile(p));
        }
        // (a validator that accepts everything passes the above): a bow tie is no profile
        CHECK_THROWS_AS(validate_profile({Loop{{0, 0}, {2, 2}, {2, 0}, {0, 2}}, {}}), std::invalid_argument);
    }

    TEST_CASE("validate_profile: a loop with the wrong orientation is rejected; the outer loop and each hole" *
              geolab::points(2) *
              geolab::hint("The outer loop must have positive signed area, every hole negative: check EVERY loop's sign "
                           "and say 'wrong orientation' (handout §2).")) {
        Profile p = square_with_hole();
        p.outer = reversed(p.outer);
        expect_rejected(p, "outer loop clockwise", "orientation");
        Profile q = square_with_hole();
        q.holes[0] = reversed(q.holes[0]);
        expect_rejected(q, "hole counter-clockwise", "orientation");
        Rng rng(63);
        Profile r = star_with_holes(rng, 20, 3);
        REQUIRE(r.holes.size() == 3);
        r.holes[2] = reversed(r.holes[2]);
        expect_rejected(r, "the third hole counter-clockwise", "orientation");
        expect_rejected({reversed(circle_loop({0, 0}, 1, 9)), {}}, "a clockwise circle", "orientation");
    }

    TEST_CASE("validate_profile: self-intersecting; degenerate and non-finite loops are rejected" * geolab::points(2) *
              geolab::hint("Test every pair of non-adjacent edges with exact orient2d, including touching (a vertex on an "
                           "edge); also fewer than 3 points, equal consecutive points, NaN or inf, zero area.")) {
        expect_rejected({Loop{{0, 0}, {2, 2}, {2, 0}, {0, 2}}, {}}, "a bow tie", "edges 0 and 2 meet");
        expect_rejected({Loop{{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}, {}}, "a vertex touching another edge", "edges 0 and 2 meet");
        expect_rejected({Loop{{2, 3}, {2, 0}, {5, -1}, {4, 0}, {0, 0}}, {}}, "the end of edge 0 on edge 3", "edges 0 and 3 meet");
        expect_rejected({Loop{{0, 0}, {4, 0}, {2, 0}, {2, 3}}, {}}, "an edge folding back on the previous one", "edges 0 and 2 meet");
        expect_rejected({Loop{{0, 0}, {4, 0}, {4, 2}, {3, 2}, {3, 0.5}, {1, 0}, {1, 3}, {0, 3}}, {}},
                        "edge 4 ending on edge 0", "edges 0 and 4 meet");
        expect_rejected({Loop{{0, 0}, {4, 0}, {3, 0}, {1, 0}, {1, 2}}, {}}, "edge 2 lying along edge 0 (folded back)",
                        "edges 0 and 2 meet");
        expect_rejected({Loop{{0, 0}, {0, 4}, {0, 3}, {0, 1}, {2, 1}}, {}}, "edge 2 lying along the vertical edge 0 (folded back)",
                        "edges 0 and 2 meet");
        expect_rejected({Loop{{0, 0}, {1, 0}, {1, 2}, {3, 2}, {3, 0}, {2, 0}, {1, 0}, {0.5, -1}}, {}},
                        "edges 0 and 5 on one line, touching end to end at (1, 0)", "edges 0 and 5 meet");
        expect_rejected({Loop{{0, 0}, {0, 1}, {-2, 1}, {-2, 3}, {0, 3}, {0, 2}, {0, 1}, {1, 0.5}}, {}},
                        "vertical edges 0 and 5 on one line, touching end to end at (0, 1)", "edges 0 and 5 meet");
        expect_rejected({Loop{{0, 0}, {1, 0}}, {}}, "two points", "2 vertices (at least 3)");
        expect_rejected({Loop{{0, 0}}, {}}, "one point", "1 vertices (at least 3)");
        expect_rejected({Loop{{0, 0}, {1, 0}, {1, 0}, {0, 1}}, {}}, "two equal consecutive points", "vertices 1 and 2 are equal");
        expect_rejected({Loop{{0, 0}, {1, 0}, {0, 1}, {0, 0}}, {}}, "the last point equal to the first", "vertices 3 and 0 are equal");
        expect_rejected({Loop{{3, 3}, {3, 3}, {1, 0}, {0, 1}}, {}}, "the first two points equal", "vertices 0 and 1 are equal");
        expect_rejected({Loop{{0, 0}, {1, 0}, {std::nan(""), 1}}, {}}, "a NaN coordinate", "vertex 2 is not finite");
        expect_rejected({Loop{{std::nan(""), 0}, {1, 0}, {1, 1}}, {}}, "a NaN coordinate first", "vertex 0 is not finite");
        expect_rejected({Loop{{0, 0}, {1, 0}, {INFINITY, 1}}, {}}, "an infinite coordinate", "vertex 2 is not finite");
        Profile p = square_with_hole();
        p.holes[0] = {{-1, -1}, {1, 1}, {1, -1}, {-1, 1}};
        expect_rejected(p, "a self-intersecting hole", "hole 0");
    }

    TEST_CASE("validate_profile: holes outside; crossing; touching or nested are rejected" * geolab::points(1) *
              geolab::hint("A hole must lie strictly inside the outer loop and apart from every other hole: no edge of "
                           "one loop may meet an edge of another, and no hole may lie inside another.")) {
        Profile p = square_with_hole();
        p.holes[0] = reversed(rectangle_loop(5, 5, 6, 6));
        expect_rejected(p, "a hole outside the outer loop", "hole 0");
        p.holes[0] = reversed(rectangle_loop(1, 1, 3, 3));
        expect_rejected(p, "a hole crossing the outer loop", "hole 0");
        p.holes[0] = reversed(rectangle_loop(0, 0, 2, 1));
        expect_rejected(p, "a hole touching the outer loop along an edge", "hole 0");
        p.holes[0] = reversed(rectangle_loop(-1, -3, 1, -1));
        expect_rejected(p, "a hole crossing the outer loop's first edge (its first vertex inside)", "hole 0");
        Profile q{rectangle_loop(-4, -4, 4, 4), {reversed(rectangle_loop(-3, -3, 3, 3)), reversed(rectangle_loop(-1, -1, 1, 1))}};
        expect_rejected(q, "a hole inside another hole", "hole 1");
        Profile r{rectangle_loop(-4, -4, 4, 4), {reversed(rectangle_loop(-3, -1, 1, 1)), reversed(rectangle_loop(0, -2, 2, 2))}};
        expect_rejected(r, "two holes crossing", "hole 1");
        // The outer loop with a thin spike down from its top edge to (−0.7, 0.9), piercing one edge of a hole only.
        const Loop spiked{{-4, -4}, {4, -4}, {4, 4}, {-0.6, 4}, {-0.7, 0.9}, {-0.8, 4}, {-4, 4}};
        expect_rejected({spiked, {reversed(rectangle_loop(-1, -1, 1, 1))}}, "the spike crosses the hole's edge 0 only", "hole 0");
        expect_rejected({spiked, {Loop{{-0.2, 1.2}, {-0.5, -1}, {-1.5, 1.2}}}}, "the spike crosses the triangular hole's "
                                                                                  "edge 2 (last to first) only", "hole 0");
        expect_rejected({spiked, {Loop{{-1.5, 1.2}, {-0.2, 1.2}, {-0.5, -1}}}}, "the spike crosses the triangular hole's "
                                                                                  "edge 0 only", "hole 0");
        expect_rejected({rectangle_loop(-4, -4, 4, 4), {reversed(rectangle_loop(-1, -1, 1, 1)), Loop{{1.2, 0.7}, {0.7, 1.2}, {2, 2}}}},
                        "a triangular hole cutting a corner of hole 0 with its edge 0 only", "hole 1");
    }
}  // TEST_SUITE
