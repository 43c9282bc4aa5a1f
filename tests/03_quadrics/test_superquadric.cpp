// Lab 03, Task 5: superquadrics. Expected values from Barr's F written out in long double, closed forms for the sphere
// and the octahedron, and a numerical integral of the cross-sections for the volume (helpers.hpp).
#include <limits>

#include "helpers.hpp"

using namespace lab03;

namespace {
// ∇F in long double, analytically from F (away from the coordinate planes).
glm::dvec3 grad_F(const Superquadric& s, const glm::dvec3& p) {
    const LD x = LD(p.x) / s.radii.x, y = LD(p.y) / s.radii.y, z = LD(p.z) / s.radii.z, e1 = s.e1, e2 = s.e2;
    const LD u = std::pow(std::abs(x), 2 / e2) + std::pow(std::abs(y), 2 / e2);
    const LD k = (e2 / e1) * std::pow(u, e2 / e1 - 1) * (2 / e2);
    auto d = [](LD v, LD e) { return (v < 0 ? -1 : 1) * std::pow(std::abs(v), e - 1); };
    return {double(k * d(x, 2 / e2) / s.radii.x), double(k * d(y, 2 / e2) / s.radii.y),
            double((2 / e1) * d(z, 2 / e1) / s.radii.z)};
}
const double exps[] = {0.25, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0};
}  // namespace

TEST_SUITE("Task 5: superquadrics") {
    TEST_CASE("superquadrics: spow is sign(x)·|x|^e; never NaN" * geolab::points(1) *
              geolab::hint("std::pow of a negative base with a non-integer exponent is NaN: take the power of |x| and put "
                           "the sign back (std::copysign).")) {
        struct C {
            double x, e, want;
        };
        for (const C& c : {C{-8, 1.0 / 3, -2}, C{8, 1.0 / 3, 2}, C{-2, 2, -4}, C{0, 0.5, 0}, C{-0.0, 3, 0}, C{3, 1, 3},
                           C{-0.0625, 0.25, -0.5}, C{0.0625, 0.5, 0.25}, C{-1, 7.5, -1}}) {
            const double got = spow(c.x, c.e);
            CHECK_MESSAGE(close(got, c.want, 1e-14, 1e-300), "spow(" << c.x << ", " << c.e << "): expected " << c.want
                                                                      << ", got " << got);
        }
        const double tiny = spow(-1e-300, 0.1);
        CHECK_MESSAGE((std::isfinite(tiny) && tiny < 0), "spow(-1e-300, 0.1) must be finite and negative, got " << tiny);
    }

    TEST_CASE("superquadrics: inside_outside is Barr's F (sphere; octahedron; double cone; and in general)" *
              geolab::points(2) *
              geolab::hint("F = (|x/a1|^(2/ε₂) + |y/a2|^(2/ε₂))^(ε₂/ε₁) + |z/a3|^(2/ε₁); take absolute values before "
                           "the powers. Reject radii or exponents <= 0 with std::invalid_argument.")) {
        const glm::dvec3 p{0.3, -0.7, 1.1};
        CHECK(close(inside_outside({{1, 1, 1}, 1, 1}, p), 0.09 + 0.49 + 1.21, 1e-14));
        CHECK(close(inside_outside({{2, 3, 4}, 1, 1}, p), 0.09 / 4 + 0.49 / 9 + 1.21 / 16, 1e-14));
        CHECK(close(inside_outside({{1, 1, 1}, 2, 2}, p), 2.1, 1e-14));
        CHECK(close(inside_outside({{1, 1, 1}, 2, 1}, p), std::sqrt(0.58) + 1.1, 1e-14));
        Rng rng(51);
        for (int n = 0; n < 60; ++n) {
            const Superquadric s{{rng.uniform(0.5, 2), rng.uniform(0.5, 2), rng.uniform(0.5, 2)}, exps[n % 7], exps[(n / 7) % 7]};
            const glm::dvec3 x{rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2)};
            const double want = double(F_ld(s, x)), got = inside_outside(s, x);
            CHECK_MESSAGE(close(got, want, 1e-12), str(s) << " at " << str(x) << ": expected " << want << ", got " << got);
        }
        CHECK_THROWS_AS(inside_outside({{1, 1, 1}, 0, 1}, p), std::invalid_argument);
        CHECK_THROWS_AS(inside_outside({{1, -1, 1}, 1, 1}, p), std::invalid_argument);
        CHECK_THROWS_AS(inside_outside({{0, 1, 1}, 1, 1}, p), std::invalid_argument);
        CHECK_THROWS_AS(inside_outside({{1, 0, 1}, 1, 1}, p), std::invalid_argument);
        CHECK_THROWS_AS(inside_outside({{1, 1, 0}, 1, 1}, p), std::invalid_argument);
        CHECK_THROWS_AS(inside_outside({{1, 1, 1}, 1, 0}, p), std::invalid_argument);
    }

    TEST_CASE("superquadrics: superquadric_point lies on F = 1 in the right octant for all angles and exponents" *
              geolab::points(2) *
              geolab::hint("Use spow for every cos and sin raised to ε: cos ω < 0 for |ω| > π/2, sin η < 0 in the south. "
                           "A plain pow gives NaN there.")) {
        Rng rng(52);
        for (double e1 : exps)
            for (double e2 : exps)
                for (int n = 0; n < 6; ++n) {
                    const Superquadric s{{rng.uniform(0.5, 2), rng.uniform(0.5, 2), rng.uniform(0.5, 2)}, e1, e2};
                    const double eta = rng.uniform(-pi / 2, pi / 2), om = rng.uniform(-pi, pi);
                    const glm::dvec3 x = superquadric_point(s, eta, om);
                    INFO(str(s) << ", eta = " << eta << ", omega = " << om << ": got " << str(x));
                    REQUIRE((std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z)));
                    CHECK(close(double(F_ld(s, x)), 1.0, 1e-11));
                    CHECK(((x.x < 0) == (std::cos(eta) * std::cos(om) < 0) || std::abs(x.x) < 1e-12));
                    CHECK(((x.y < 0) == (std::cos(eta) * std::sin(om) < 0) || std::abs(x.y) < 1e-12));
                    CHECK(((x.z < 0) == (std::sin(eta) < 0) || std::abs(x.z) < 1e-12));
                }
        const glm::dvec3 e = superquadric_point({{2, 3, 4}, 1, 1}, 0.3, -2.0);
        const glm::dvec3 want{2 * std::cos(0.3) * std::cos(-2.0), 3 * std::cos(0.3) * std::sin(-2.0), 4 * std::sin(0.3)};
        CHECK_MESSAGE(glm::length(e - want) <= 1e-14, "ellipsoid (2,3,4) at eta 0.3, omega -2: expected " << str(want) << ", got " << str(e));
    }

    TEST_CASE("superquadrics: superquadric_normal is the unit outward normal (∥ ∇F)" * geolab::points(2) *
              geolab::hint("n ∝ (spow(cos η, 2−ε₁) spow(cos ω, 2−ε₂)/a1, spow(cos η, 2−ε₁) spow(sin ω, 2−ε₂)/a2, "
                           "spow(sin η, 2−ε₁)/a3), normalized; divide by the radii, do not multiply.")) {
        Rng rng(53);
        for (double e1 : {0.25, 0.5, 1.0, 1.5, 2.0})
            for (double e2 : {0.25, 0.5, 1.0, 1.5, 2.0})
                for (int n = 0; n < 4; ++n) {
                    const Superquadric s{{rng.uniform(0.5, 2), rng.uniform(0.5, 2), rng.uniform(0.5, 2)}, e1, e2};
                    // away from the coordinate planes, where F has kinks or flat spots
                    double eta = rng.uniform(0.15, pi / 2 - 0.15), om = rng.uniform(0.15, pi / 2 - 0.15);
                    if (n & 1) eta = -eta;
                    if (n & 2) om = om - pi;
                    const glm::dvec3 x = superquadric_point(s, eta, om);
                    const glm::dvec3 want = glm::normalize(grad_F(s, x));
                    const glm::dvec3 got = superquadric_normal(s, eta, om);
                    CHECK_MESSAGE(glm::length(got - want) <= 1e-9, str(s) << ", eta = " << eta << ", omega = " << om
                                                                          << ": expected " << str(want) << " (∇F normalized), got "
                                                                          << str(got));
                }
    }

    TEST_CASE("superquadrics: the exact volume from Beta functions" * geolab::points(2) *
              geolab::hint("V = 2 a1 a2 a3 ε₁ ε₂ B(ε₁/2 + 1, ε₁) B(ε₂/2, ε₂/2), B(x, y) = Γ(x)Γ(y)/Γ(x+y) "
                           "(std::tgamma, or std::lgamma for large arguments).")) {
        CHECK(close(superquadric_volume({{1, 1, 1}, 1, 1}), 4 * pi / 3, 1e-13));
        CHECK(close(superquadric_volume({{2, 3, 0.5}, 1, 1}), 4 * pi, 1e-13));
        CHECK(close(superquadric_volume({{1, 1, 1}, 2, 2}), 4.0 / 3, 1e-13));
        CHECK(close(superquadric_volume({{1.5, 1, 2}, 2, 2}), 4.0, 1e-13));
        for (double e1 : {0.3, 0.7, 1.5, 2.5})
            for (double e2 : {0.4, 1.0, 1.8, 3.0}) {
                const Superquadric s{{1.2, 0.8, 1.5}, e1, e2};
                const double want = double(volume_by_integral(s)), got = superquadric_volume(s);
                CHECK_MESSAGE(close(got, want, 1e-7), str(s) << ": the integral of the cross-sections is " << want
                                                             << ", got " << got);
            }
        CHECK_THROWS_AS(superquadric_volume({{1, 1, 1}, -1, 1}), std::invalid_argument);
    }

    TEST_CASE("superquadrics: intersect_superquadric finds the first crossing (sphere; octahedron; general)" *
              geolab::points(3) *
              geolab::hint("Clip the ray to the bounding box, step along it until F − 1 (or F^(ε₁/2) − 1) changes sign, "
                           "then bisect to 1e-12 relative. From inside, the first crossing is the exit.")) {
        const double inf = std::numeric_limits<double>::infinity();
        struct C {
            Superquadric s;
            Ray ray;
            double want;  // NaN: no hit
            const char* what;
        };
        const double nan = std::numeric_limits<double>::quiet_NaN();
        for (const C& c : {C{{{1, 1, 1}, 1, 1}, {{0, 0, -5}, {0, 0, 1}}, 4, "unit sphere, up the z axis"},
                           C{{{2, 2, 2}, 1, 1}, {{0.6, 0.8, 0}, {0, 0, 1}}, std::sqrt(3.0), "radius-2 sphere, from inside"},
                           C{{{1, 1, 1}, 2, 2}, {{-5, 0.2, 0.1}, {1, 0, 0}}, 4.3, "octahedron |x|+|y|+|z| = 1"},
                           C{{{1, 1, 1}, 2, 2}, {{-5, 0.2, 0.1}, {2, 0, 0}}, 2.15, "octahedron, direction of length 2"},
                           C{{{1, 1, 1}, 1, 1}, {{0.9, 0.9, -5}, {0, 0, 1}}, nan, "unit sphere, through the box's corner: miss"},
                           C{{{1, 1, 1}, 1, 1}, {{3, 0, -5}, {0, 0, 1}}, nan, "unit sphere, outside the box: miss"}}) {
            const auto got = intersect_superquadric(c.s, c.ray, 0, inf);
            INFO(str(c.s) << ", " << str(c.ray) << " (" << c.what << "): expected "
                          << (std::isnan(c.want) ? std::string("no hit") : "t = " + std::to_string(c.want)) << ", got "
                          << (got ? "t = " + std::to_string(got->t) : std::string("no hit")));
            REQUIRE(got.has_value() == !std::isnan(c.want));
            if (got) {
                CHECK(close(got->t, c.want, 1e-9));
                CHECK(glm::length(got->point - (c.ray.origin + got->t * c.ray.direction)) <= 1e-9);
            }
        }
        CHECK_FALSE(intersect_superquadric({{1, 1, 1}, 1, 1}, {{0, 0, -5}, {0, 0, 1}}, 0, 3.5).has_value());
        {  // a window [4, 4] holding the crossing point itself; [5, 5] holds none (and neither throws)
            const auto at4 = intersect_superquadric({{1, 1, 1}, 1, 1}, {{0, 0, -5}, {0, 0, 1}}, 4, 4);
            CHECK_MESSAGE((at4.has_value() && close(at4->t, 4.0, 1e-9)),
                          "unit sphere, ray (0,0,-5) + t (0,0,1), t in [4, 4]: the ray is on the surface at t = 4");
            CHECK_FALSE(intersect_superquadric({{1, 1, 1}, 1, 1}, {{0, 0, -5}, {0, 0, 1}}, 5, 5).has_value());
        }
        {  // leaving from just inside: the crossing is at the very end of the clipped interval
            const auto out = intersect_superquadric({{1, 1, 1}, 1, 1}, {{1 - 1e-4, 0, 0}, {1, 0, 0}}, 0, inf);
            INFO("unit sphere, ray (1 - 1e-4, 0, 0) + t (1, 0, 0): leaves at t = 1e-4; got "
                 << (out ? "t = " + std::to_string(out->t) : std::string("no hit")));
            REQUIRE(out.has_value());
            CHECK(close(out->t, 1e-4, 1e-9, 1e-4));
        }
        {  // a short chord (0.089 long) seen from 500 away: bracket on the clipped interval, not from the origin
            const double off = 0.999;
            const auto far = intersect_superquadric({{1, 1, 1}, 1, 1}, {{0, off, -500}, {0, 0, 1}}, 0, inf);
            const double want = double(500 - std::sqrt(1 - LD(off) * off));
            INFO("unit sphere, ray (0, 0.999, -500) + t (0, 0, 1): enters at t = " << want << ", got "
                 << (far ? "t = " + std::to_string(far->t) : std::string("no hit")));
            REQUIRE(far.has_value());
            CHECK(close(far->t, want, 1e-9));
        }
        {  // a sample of the march lands exactly on the surface (g = 0) and the next one is inside: the crossing is
           // there (radius 2^20, origin 2^-12 above the pole, t in [0, 0.25]: samples at t = k 2^-12)
            const double r = 1048576.0;
            const auto on = intersect_superquadric({{r, r, r}, 1, 1}, {{0, 0, r + 0x1p-12}, {0, 0, -1}}, 0, 0.25);
            INFO("sphere of radius 2^20, ray (0, 0, 2^20 + 2^-12) + t (0, 0, -1), t in [0, 0.25]: enters at t = 2^-12; got "
                 << (on ? "t = " + std::to_string(on->t) : std::string("no hit")));
            REQUIRE(on.has_value());
            CHECK(close(on->t, 0x1p-12, 1e-9, 1.0));
        }
        {  // from (1, 1, 0), where F = 2 exactly, towards the centre
            const auto in = intersect_superquadric({{1, 1, 1}, 1, 1}, {{1, 1, 0}, {-1, -1, 0}}, 0, inf);
            const double want = 1 - std::sqrt(0.5);
            INFO("unit sphere, ray (1, 1, 0) + t (-1, -1, 0): enters at t = " << want << ", got "
                 << (in ? "t = " + std::to_string(in->t) : std::string("no hit")));
            REQUIRE(in.has_value());
            CHECK(close(in->t, want, 1e-9));
        }
        for (auto [e1, e2] : {std::pair{2.0, 1.0}, std::pair{3.0, 0.5}, std::pair{1.0, 1.0}}) {  // the poles' normals
            const Superquadric s{{1.2, 0.7, 0.9}, e1, e2};
            const auto top = intersect_superquadric(s, {{0, 0, 4}, {0, 0, -1}}, 0, inf);
            INFO(str(s) << ", ray down the z axis: the hit is the north pole (0, 0, 0.9) with normal (0, 0, 1); got "
                        << (top ? "normal " + str(top->normal) : std::string("no hit")));
            REQUIRE(top.has_value());
            CHECK(close(top->t, 3.1, 1e-9));
            CHECK(glm::length(top->normal - glm::dvec3(0, 0, 1)) <= 1e-9);
        }
        CHECK_THROWS_AS(intersect_superquadric({{1, 1, 1}, 1, 1}, {{0, 0, -5}, {0, 0, 0}}, 0, 1), std::invalid_argument);
        Rng rng(54);
        for (int n = 0; n < 40; ++n) {
            const Superquadric s{{rng.uniform(0.5, 2), rng.uniform(0.5, 2), rng.uniform(0.5, 2)}, exps[n % 7], exps[(n * 3) % 7]};
            const glm::dvec3 aim{rng.uniform(-0.1, 0.1) * s.radii.x, rng.uniform(-0.1, 0.1) * s.radii.y, rng.uniform(-0.1, 0.1) * s.radii.z};
            const glm::dvec3 o = aim + 6.0 * rng.unit();
            const Ray ray{o, aim - o};
            const auto got = intersect_superquadric(s, ray, 0, inf);
            INFO(str(s) << ", " << str(ray) << " (aimed inside): got " << (got ? "t = " + std::to_string(got->t) : std::string("no hit")));
            REQUIRE(got.has_value());
            CHECK(std::abs(double(F_ld(s, got->point)) - 1) <= 1e-7 * std::max(1.0, 2 / std::min(s.e1, s.e2)));
            const glm::dvec3 gw = glm::normalize(grad_F(s, got->point));
            const bool near_plane = std::abs(got->point.x) < 1e-3 || std::abs(got->point.y) < 1e-3 || std::abs(got->point.z) < 1e-3;
            if (!near_plane)
                CHECK_MESSAGE(glm::length(got->normal - gw) <= 1e-6,
                              "the hit's normal should be ∇F normalized, " << str(gw) << ", got " << str(got->normal));
            for (int k = 0; k < 400; ++k)  // nothing crossed before: F stays > 1 up to the hit
                CHECK(F_ld(s, ray.origin + got->t * (k / 400.0) * ray.direction) > 1);
        }
    }
}  // TEST_SUITE
