// Lab 05, Task 7: glyph outlines (DejaVu Sans through lib's FreeType reader). Expected areas: closed forms and
// the shoelace area of finely sampled outlines in long double; flattening checked against the curve itself.
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab05;

namespace {
QuadSegment line(glm::dvec2 a, glm::dvec2 b) { return {a, 0.5 * (a + b), b}; }
std::vector<QuadSegment> reversed(const std::vector<QuadSegment>& c) {
    std::vector<QuadSegment> r;
    for (auto it = c.rbegin(); it != c.rend(); ++it) r.push_back({(*it)[2], (*it)[1], (*it)[0]});
    return r;
}
}  // namespace

TEST_SUITE("Task 7: glyphs") {
    TEST_CASE("contour area: exact from the control points; signed by orientation" * geolab::points(2) *
              geolab::hint("Green: A = ½ ∮ x dy − y dx; for a quadratic segment the integral is a closed form in the "
                           "cross products of its control points (handout §8). Counter-clockwise is positive.")) {
        const std::vector<QuadSegment> square{line({0, 0}, {1, 0}), line({1, 0}, {1, 1}), line({1, 1}, {0, 1}),
                                              line({0, 1}, {0, 0})};
        const double a_sq = contour_area(square);
        INFO("unit square, counter-clockwise: expected 1, got " << num(a_sq));
        CHECK(a_sq == 1.0);
        CHECK(contour_area(reversed(square)) == -1.0);
        // the parabolic arch (0,0) (1,2) (2,0) over its chord: area 2/3 · base 2 · height 1, clockwise
        const std::vector<QuadSegment> arch{{glm::dvec2(0, 0), glm::dvec2(1, 2), glm::dvec2(2, 0)}, line({2, 0}, {0, 0})};
        const double a = contour_area(arch);
        INFO("parabolic arch, clockwise: expected −4/3, got " << num(a));
        CHECK(std::abs(a + 4.0 / 3.0) <= 1e-15);
        // translation does not change the area
        std::vector<QuadSegment> moved = arch;
        for (auto& s : moved)
            for (auto& p : s) p += glm::dvec2(1000.5, -250.25);
        CHECK(std::abs(contour_area(moved) + 4.0 / 3.0) <= 1e-9);
        CHECK_THROWS_AS(contour_area({}), std::invalid_argument);
    }

    TEST_CASE("flatten: the prescribed uniform steps per segment; every chord within tol of the curve" *
              geolab::points(2) * geolab::builds_on("Task 1") *
              geolab::hint("m = max(1, ceil(sqrt(|P0 − 2P1 + P2| / (4 tol)))) steps per segment; the points C(k/m) for "
                           "k = 0..m−1 (the next segment starts where this one ends).")) {
        for (char32_t ch : {U'S', U'g', U'@'}) {
            const GlyphOutline& g = glyph(ch);
            for (double tol : {8.0, 1.0, 0.05}) {
                for (const auto& c : g.contours) {
                    const Poly2 poly = flatten_contour(c, tol);
                    std::size_t idx = 0;
                    for (std::size_t s = 0; s < c.size(); ++s) {
                        const double dd = glm::length(c[s][0] - 2.0 * c[s][1] + c[s][2]);
                        const int m = std::max(1, int(std::ceil(std::sqrt(dd / (4 * tol)))));
                        for (int k = 0; k < m; ++k, ++idx) {
                            REQUIRE(idx < poly.size());
                            const glm::dvec2 want = quad_at(c[s], LD(k) / m);
                            INFO("glyph U+" << std::hex << unsigned(ch) << std::dec << ", tol " << tol << ", segment "
                                            << s << ", step " << k << " of " << m << ": expected " << str(want)
                                            << ", got " << str(poly[idx]));
                            CHECK(glm::length(poly[idx] - want) <= 1e-9);
                            const glm::dvec2 next = poly[(idx + 1) % poly.size()];
                            for (int q = 1; q < 8; ++q) {
                                const glm::dvec2 x = quad_at(c[s], (k + q / 8.0L) / m);
                                CHECK(seg_dist(x, poly[idx], next) <= tol * (1 + 1e-9));
                            }
                        }
                    }
                    CHECK(idx == poly.size());
                }
            }
        }
        // straight segments need one step each: the polygon is the corners
        const std::vector<QuadSegment> square{line({0, 0}, {1, 0}), line({1, 0}, {1, 1}), line({1, 1}, {0, 1}),
                                              line({0, 1}, {0, 0})};
        const Poly2 sq = flatten_contour(square, 0.01);
        INFO("unit square of straight segments at tol 0.01: expected its 4 corners, got " << str(sq));
        CHECK(sq == Poly2{{0, 0}, {1, 0}, {1, 1}, {0, 1}});
        CHECK_THROWS_AS(flatten_contour({}, 1.0), std::invalid_argument);
        CHECK_THROWS_AS(flatten_contour(glyph(U'S').contours[0], 0.0), std::invalid_argument);
    }

    TEST_CASE("glyph area: holes subtract; agrees with a finely sampled outline" * geolab::points(1) *
              geolab::hint("|Σ contour_area|: TrueType's outer contours are clockwise, holes counter-clockwise.")) {
        for (char32_t ch : {U'O', U'o', U'B', U'e', U'8', U'i'}) {
            const GlyphOutline& g = glyph(ch);
            LD want = 0;
            for (const auto& c : g.contours) want += sampled_area(c, 4000);
            want = std::abs(want);
            const double got = glyph_area(g);
            INFO("DejaVu Sans U+" << std::hex << unsigned(ch) << std::dec << ": expected about " << double(want)
                                  << " font units², got " << num(got));
            CHECK(std::abs(got - double(want)) <= 1e-6 * double(want));
        }
        CHECK(glyph_area(glyph(U' ')) == 0.0);
    }
}
