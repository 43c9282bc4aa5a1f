// Lab 03, Task 4: rays. Expected roots by bisection in long double (helpers.hpp), never by a quadratic formula.
#include <limits>

#include "helpers.hpp"

using namespace lab03;

namespace {
const double inf = std::numeric_limits<double>::infinity();

void check_roots(double al, double be, double ga, int count, double t0, double t1) {
    const Roots r = solve_quadratic(al, be, ga);
    INFO("solve_quadratic(" << al << ", " << be << ", " << ga << "): expected count " << count << " roots " << t0 << ", "
                            << t1 << "; got count " << r.count << " roots " << r.t0 << ", " << r.t1);
    REQUIRE(r.count == count);
    if (count >= 1) CHECK(close(r.t0, t0, 1e-14, 1e-300));
    if (count >= 1) CHECK(close(r.t1, t1, 1e-14, 1e-300));
}

// The hits must be the given t's (relative 1e-12), sorted, with points on the ray and unit normals ∥ gradient.
void check_hits(const glm::dmat4& Q, const Ray& ray, double t_min, double t_max, const std::vector<double>& want,
                const std::string& what) {
    const auto hits = intersect(Q, ray, t_min, t_max);
    std::ostringstream got;
    for (const Hit& h : hits) got << h.t << " ";
    INFO(what << ", " << str(ray) << ", t in [" << t_min << ", " << t_max << "]: expected " << want.size()
              << " hits, got " << hits.size() << " at t = " << got.str());
    REQUIRE(hits.size() == want.size());
    for (std::size_t i = 0; i < hits.size(); ++i) {
        CHECK(close(hits[i].t, want[i], 1e-12, 1e-12));
        CHECK(glm::length(hits[i].point - (ray.origin + hits[i].t * ray.direction)) <= 1e-12 * (1 + glm::length(hits[i].point)));
        const glm::dvec3 g = glm::dvec3(Q * glm::dvec4(hits[i].point, 1.0));
        if (glm::length(g) > 1e-9) {
            const glm::dvec3 n = glm::normalize(g);
            CHECK_MESSAGE(glm::length(hits[i].normal - n) <= 1e-9,
                          "hit " << i << " at " << str(hits[i].point) << ": the unit normal should be " << str(n)
                                 << " (the normalized gradient of XᵀQX), got " << str(hits[i].normal));
        }
    }
}
glm::dmat4 sphere(glm::dvec3 c, double r) {
    return matrix_of({1, 1, 1, 0, 0, 0, -c.x, -c.y, -c.z, glm::dot(c, c) - r * r});
}
}  // namespace

TEST_SUITE("Task 4: rays") {
    TEST_CASE("rays: solve_quadratic on two; none; double; linear and degenerate equations" * geolab::points(2) *
              geolab::hint("Δ < 0: none; Δ = 0: one (t0 = t1); α = 0: the linear root −γ/β; α = β = 0: none. Sort the "
                           "two roots.")) {
        check_roots(1, -3, 2, 2, 1, 2);
        check_roots(-1, 0, 4, 2, -2, 2);
        check_roots(2, 2, -12, 2, -3, 2);
        check_roots(1, 0, 1, 0, 0, 0);
        check_roots(1, -2, 1, 1, 1, 1);
        check_roots(4, 4, 1, 1, -0.5, -0.5);
        check_roots(0, 2, -4, 1, 2, 2);
        check_roots(0, -4, -2, 1, -0.5, -0.5);
        check_roots(0, 0, 1, 0, 0, 0);
        check_roots(0, 0, 0, 0, 0, 0);
        // Δ = β² − 4αγ counts as 0 when |Δ| <= 1e-12 (β² + 4|αγ|): here β² + 4|αγ| = 8 (about), Δ = −4δ
        check_roots(1, 2, 1 + 1e-13, 1, -1, -1);    // Δ = −4e-13: within the tolerance, a double root
        check_roots(1, 2, 1 + 1.9e-12, 1, -1, -1);  // Δ = −7.6e-12 <= 8e-12: still a double root
        check_roots(1, 2, 1 + 2.1e-12, 0, 0, 0);    // Δ = −8.4e-12 > 8e-12: no root
        check_roots(2, 0, 0, 1, 0, 0);              // Δ = 0 and the tolerance 0: the double root t = 0
        check_roots(1, 2, 1 + 1e-9, 0, 0, 0);
        check_roots(-3, 6, -3 * (1 - 1e-13), 1, 1, 1);  // the same with α < 0 and Δ > 0 within the tolerance
    }

    TEST_CASE("rays: solve_quadratic keeps the small root when β² ≫ 4αγ (no cancellation)" * geolab::points(3) *
              geolab::hint("(−β + √Δ)/(2α) subtracts two nearly equal numbers when |β| ≫ |αγ|: compute the root of larger "
                           "magnitude q/α with q = −(β + sign(β)√Δ)/2 first, and the other as γ/q.")) {
        struct C {
            double al, be, ga;
        };
        int naive_fails = 0;  // test self-check: the cases are hard (the textbook formula fails most of them)
        for (const C& c : {C{1, -1e8, 1}, C{1, 1e8, 1}, C{1, -2, 1e-12}, C{3, 7e5, -2}, C{1e-20, -1, 1}, C{-1e-12, 1, 1},
                           C{2.5, -1e7, 3.25}}) {
            const RayPoly p{c.al, c.be, c.ga};
            const double small_guess = -c.ga / c.be;  // only to place the bracket; the root comes from bisection
            const double lo = small_guess - std::abs(small_guess) * 0.5 - 1e-300, hi = small_guess + std::abs(small_guess) * 0.5;
            const double want = double(bisect(p, std::min(lo, hi), std::max(lo, hi)));
            // the case is hard: the textbook formula misses this root by more than 1e-9 relative
            const double naive = naive_near_root(c.al, c.be, c.ga);
            if (!close(naive, want, 1e-9)) ++naive_fails;
            const Roots r = solve_quadratic(c.al, c.be, c.ga);
            INFO("solve_quadratic(" << c.al << ", " << c.be << ", " << c.ga << "): the small root is " << want
                                    << " (bisection in long double); got roots " << r.t0 << ", " << r.t1);
            REQUIRE(r.count == 2);
            const double got = std::abs(r.t0) < std::abs(r.t1) ? r.t0 : r.t1;
            CHECK(close(got, want, 1e-12));
        }
        CHECK_MESSAGE(naive_fails >= 4, "test self-check: the textbook formula fails only " << naive_fails << " of 7 cases");
    }

    TEST_CASE("rays: intersect a sphere; sorted; with unit normals along the gradient and the (t_min; t_max) window" *
              geolab::points(3) *
              geolab::hint("α = DᵀQD, β = 2 DᵀQX, γ = XᵀQX with X = (origin, 1), D = (direction, 0) — D has a 0, not a 1, "
                           "in its last entry. Keep only roots inside [t_min, t_max]; normal = normalize((Q X)_xyz).")) {
        const glm::dmat4 S = sphere({1, 2, 3}, 2);
        check_hits(S, {{1, 2, -3}, {0, 0, 1}}, 0, inf, {4, 8}, "sphere centre (1,2,3) radius 2");
        check_hits(S, {{1, 2, -3}, {0, 0, 2}}, 0, inf, {2, 4}, "sphere centre (1,2,3) radius 2, direction of length 2");
        check_hits(S, {{1, 2, 3}, {0, 0, 1}}, 0, inf, {2}, "sphere centre (1,2,3) radius 2, from the centre");
        check_hits(S, {{1, 2, 3}, {0, 0, 1}}, -inf, inf, {-2, 2}, "sphere centre (1,2,3) radius 2, the whole line");
        check_hits(S, {{1, 2, -3}, {0, 0, 1}}, 5, 10, {8}, "sphere centre (1,2,3) radius 2, window [5, 10]");
        check_hits(S, {{1, 2, -3}, {0, 0, 1}}, 0, 3, {}, "sphere centre (1,2,3) radius 2, window [0, 3]");
        check_hits(S, {{4, 2, -3}, {0, 0, 1}}, 0, inf, {}, "sphere centre (1,2,3) radius 2, a miss");
        check_hits(-1.0 * S, {{1, 2, -3}, {0, 0, 1}}, 0, inf, {4, 8}, "−(sphere): same hits, normals inward (gradient)");
        check_hits(to_glm(canonical(QuadricType::hyperboloid_one_sheet, 1, 1, 1)), {{-3, 0, 0}, {1, 0, 0}}, 0, inf,
                   {2, 4}, "x² + y² − z² = 1");
        check_hits(S, {{1, 2, -3}, {0, 0, 1}}, 4, 4, {4}, "sphere centre (1,2,3) radius 2, window [4, 4] at the root");
        check_hits(S, {{1, 2, -3}, {0, 0, 1}}, 5, 5, {}, "sphere centre (1,2,3) radius 2, window [5, 5]");
        CHECK_THROWS_AS(intersect(S, {{0, 0, 0}, {0, 0, 0}}, 0, 1), std::invalid_argument);
        CHECK_THROWS_AS(intersect(S, {{0, 0, 0}, {0, 0, 1}}, 2, 1), std::invalid_argument);
        // through a cone's apex: XᵀQX has a double root there and the gradient is zero: normal (0, 0, 0)
        const glm::dmat4 K = to_glm(canonical(QuadricType::real_cone, 1, 1, 1));
        const auto apex = intersect(K, {{0, 0, -2}, {0, 0, 1}}, 0, inf);
        INFO("x² + y² = z² along its axis from (0, 0, -2): one hit at the apex t = 2 with normal (0, 0, 0); got "
             << apex.size() << " hits" << (apex.empty() ? std::string() : ", normal " + str(apex[0].normal)));
        REQUIRE(apex.size() == 1);
        CHECK(apex[0].t == 2.0);
        CHECK(apex[0].normal == glm::dvec3(0.0));
    }

    TEST_CASE("rays: tangent rays give one hit; rays starting on the surface hit at t = 0" * geolab::points(2) *
              geolab::hint("Δ = 0 is one (double) hit, not two and not none. A ray starting on the surface has γ = 0: "
                           "with the stable formula the root γ/q is exactly 0.")) {
        const glm::dmat4 S = sphere({0, 0, 0}, 1);
        check_hits(S, {{1, 0, 5}, {0, 0, -1}}, 0, inf, {5}, "unit sphere, tangent at (1,0,0)");
        check_hits(S, {{0, -3, 2}, {0, 1, 0}}, -inf, inf, {}, "unit sphere, passing above it");
        check_hits(S, {{0, 0, 1}, {0, 0, -1}}, 0, inf, {0, 2}, "unit sphere, from its north pole inwards");
        check_hits(S, {{0, 0, 1}, {0, 0, 1}}, 0, inf, {0}, "unit sphere, from its north pole outwards");
        check_hits(S, {{0, 0, 1}, {1, 0, 0}}, -inf, inf, {0}, "unit sphere, from its north pole along the tangent plane");
        check_hits(to_glm(canonical(QuadricType::real_elliptic_cylinder, 2, 1, 1)), {{2, 0, 0}, {0, 0, 1}}, -inf, inf, {},
                   "x²/4 + y² = 1, a ray lying in the surface (no isolated hits)");
    }

    TEST_CASE("rays: α = 0 (a ray parallel to a paraboloid's axis or a cone's generator) has one hit" *
              geolab::points(2) *
              geolab::hint("When DᵀQD = 0 the equation is linear: t = −γ/β. Do not divide by α.")) {
        const glm::dmat4 P = to_glm(canonical(QuadricType::elliptic_paraboloid, 1, 1, 1));  // z = x² + y²
        check_hits(P, {{0.3, 0.4, -2}, {0, 0, 1}}, 0, inf, {2.25}, "z = x² + y², up the axis direction");
        check_hits(P, {{0.3, 0.4, 5}, {0, 0, -2}}, 0, inf, {2.375}, "z = x² + y², down, direction of length 2");
        const glm::dmat4 K = to_glm(canonical(QuadricType::real_cone, 1, 1, 1));  // x² + y² = z²
        check_hits(K, {{2, 0, 0}, {-1, 0, 1}}, 0, inf, {1}, "x² + y² = z², parallel to a generator");
        const glm::dmat4 C = to_glm(canonical(QuadricType::parabolic_cylinder, 1, 1, 0.5));  // x² − z = 0
        check_hits(C, {{0.5, 7, 3}, {0, 0, -1}}, 0, inf, {2.75}, "x² = z, down the z axis");
    }

    TEST_CASE("rays: intersect_in_box keeps the hits inside the box (unbounded surfaces clipped)" * geolab::points(2) *
              geolab::hint("Clip the ray to the box with the slab method (per axis: the t range inside lo..hi; a zero "
                           "direction component is either always or never inside), start at t ≥ 0, then intersect.")) {
        const glm::dmat4 planes = to_glm(canonical(QuadricType::real_parallel_planes, 1, 1, 1));  // x² = 1
        const Box3 box{{-2, -2, -2}, {2, 2, 2}};
        auto ts = [](const std::vector<Hit>& hs) {
            std::vector<double> t;
            for (const Hit& h : hs) t.push_back(h.t);
            return t;
        };
        struct C {
            Ray ray;
            std::vector<double> want;
            const char* what;
        };
        for (const C& c : {C{{{-5, 0, 0}, {1, 0, 0}}, {4, 6}, "through both planes"},
                           C{{{-5, 3, 0}, {1, 0, 0}}, {}, "the planes are hit at y = 3, outside the box"},
                           C{{{0, 0, 0}, {1, 0, 0}}, {1}, "from inside the box: only t >= 0"},
                           C{{{0, 0, 0}, {-0.5, 0, 0}}, {2}, "from inside the box, backwards, direction length 0.5"},
                           C{{{-5, 0, 0}, {1, 0.5, 0}}, {4}, "the second plane is hit at y = 3, outside the box"},
                           C{{{-5, 0, 3}, {1, 0, 0}}, {}, "z = 3 is outside the box for the whole ray"},
                           C{{{0, 0, 0}, {2, 0, 0}}, {0.5}, "from inside the box, direction length 2: t = 0.5"},
                           C{{{-5, -2, 0}, {1, 0, 0}}, {4, 6}, "along the box's face y = -2 (the box is closed)"},
                           C{{{-5, 0, 2}, {1, 0, 0}}, {4, 6}, "along the box's face z = 2 (the box is closed)"},
                           C{{{-5, -2, 0}, {1, -0.0, 0}}, {4, 6}, "along the face y = -2, direction y = -0.0"},
                           C{{{-5, 2, 0}, {1, -0.0, 0}}, {4, 6}, "along the face y = 2, direction y = -0.0"}}) {
            const auto got = ts(intersect_in_box(planes, c.ray, box));
            INFO("x² = 1 in the box [-2, 2]³, " << c.what << ", " << str(c.ray) << ": expected " << c.want.size()
                                                  << " hits, got " << got.size());
            REQUIRE(got.size() == c.want.size());
            for (std::size_t i = 0; i < got.size(); ++i) CHECK(close(got[i], c.want[i], 1e-12));
        }
        const glm::dmat4 hyp = to_glm(canonical(QuadricType::hyperbolic_cylinder, 1, 1, 1));  // x² − y² = 1
        const auto got = ts(intersect_in_box(hyp, {{-1.5, -5, 0}, {0, 1, 0}}, {{-2, -1, -1}, {2, 1, 1}}));
        INFO("x² − y² = 1 at x = −1.5 meets y = ±√1.25 = ±1.118, both outside |y| <= 1: got " << got.size() << " hits");
        CHECK(got.empty());
        CHECK_THROWS_AS(intersect_in_box(planes, {{0, 0, 0}, {1, 0, 0}}, {{1, -1, -1}, {-1, 1, 1}}), std::invalid_argument);
        // a flat box (lo.z = hi.z) is a box: the ray in its plane sees the planes x = ±1
        const auto flat = ts(intersect_in_box(planes, {{-5, 0, 0}, {1, 0, 0}}, {{-2, -2, 0}, {2, 2, 0}}));
        CHECK_MESSAGE(flat.size() == 2, "x² = 1 in the flat box [-2, 2]² × [0, 0], ray along x in z = 0: expected 2 hits, got "
                                            << flat.size());
        // a ray that meets the box in one point (its edge y = z = 2) where the sphere |x| = 3 touches it
        const glm::dmat4 S3 = sphere({0, 0, 0}, 3);
        const auto touch = ts(intersect_in_box(S3, {{1, 3, 1}, {0, -1, 1}}, box));
        INFO("|x| = 3 and the ray (1, 3, 1) + t (0, -1, 1): tangent at (1, 2, 2) at t = 1, the one point of the ray in "
             "the box [-2, 2]³: expected 1 hit, got " << touch.size());
        REQUIRE(touch.size() == 1);
        CHECK(touch[0] == 1.0);
    }
}  // TEST_SUITE
