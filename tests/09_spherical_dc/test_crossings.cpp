// Lab 09, Task 2: spherical coordinates, root finding, edge crossings on segments and arcs (handout §3).
#include "helpers.hpp"

using namespace lab09;

namespace {
// A sphere field written here (the tests do not depend on lib's shapes for the exact values).
struct Ball final : ScalarField {
    glm::dvec3 c;
    double r;
    Ball(glm::dvec3 c_, double r_) : c(c_), r(r_) {}
    double value(const glm::dvec3& p) const override { return glm::length(p - c) - r; }
    glm::dvec3 gradient(const glm::dvec3& p) const override { return 3.0 * (p - c) / glm::length(p - c); }  // not unit
    Box bounds() const override { return {c - r, c + r}; }
    double lipschitz() const override { return 1.0; }
};
// The plane x = x0 (f = x − x0), gradient (2, 0, 0) (not unit on purpose).
struct PlaneX final : ScalarField {
    double x0;
    explicit PlaneX(double x) : x0(x) {}
    double value(const glm::dvec3& p) const override { return p.x - x0; }
    glm::dvec3 gradient(const glm::dvec3&) const override { return {2.0, 0.0, 0.0}; }
    Box bounds() const override { return {glm::dvec3(-1.0), glm::dvec3(1.0)}; }
};
// A field with zero gradient everywhere (normals must fall back to the edge direction).
struct FlatGradient final : ScalarField {
    double value(const glm::dvec3& p) const override { return p.y - 0.25; }
    glm::dvec3 gradient(const glm::dvec3&) const override { return glm::dvec3(0.0); }
    Box bounds() const override { return {glm::dvec3(-1.0), glm::dvec3(1.0)}; }
};
}  // namespace

TEST_SUITE("Task 2: spherical coordinates and crossings") {

TEST_CASE("to_spherical and to_cartesian: conventions; phi wrapped into 0..2pi; exact poles" * geolab::points(1) *
          geolab::hint("theta = atan2(sqrt(x2+y2), z) in [0, pi]; phi = atan2(y, x) wrapped into [0, 2pi) (add 2pi "
                       "when negative); r = 0 gives (0,0,0); on the z axis phi = 0; theta == pi gives sin = 0 "
                       "exactly. Handout §3.1.")) {
    Lcg rng(5);
    for (int i = 0; i < 200; ++i) {
        const glm::dvec3 p(rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-3, 3));
        const Spherical s = to_spherical(p);
        const Sph e = sph_of(p);
        INFO("p = " << str(p) << ": got (r, theta, phi) = (" << s.r << ", " << s.theta << ", " << s.phi
                    << "), expected (" << e.r << ", " << e.theta << ", " << e.phi << ")");
        REQUIRE(s.phi >= 0.0);
        REQUIRE(s.phi < 2 * kPi);
        CHECK(std::abs(s.r - e.r) < 1e-12 * e.r);
        CHECK(std::abs(s.theta - e.theta) < 1e-12);
        CHECK(std::abs(s.phi - e.phi) < 1e-12);
        CHECK(glm::length(to_cartesian(s) - p) < 1e-12 * e.r);
    }
    const Spherical o = to_spherical(glm::dvec3(0.0));
    CHECK(o.r == 0.0);
    CHECK(o.theta == 0.0);
    CHECK(o.phi == 0.0);
    const Spherical north = to_spherical({0, 0, 2}), south = to_spherical({0, 0, -2});
    CHECK(north.theta == 0.0);
    CHECK(north.phi == 0.0);
    CHECK(south.theta == kPi);
    CHECK(south.phi == 0.0);
    const Spherical below = to_spherical({1.0, -1e-12, 0.0});  // just below the seam: phi close to 2pi
    CHECK(below.phi > 6.28);
    // the origin with signed zeros is r = 0 too (atan2(0, -0) alone would give theta = pi)
    for (const glm::dvec3 zero : {glm::dvec3(0.0, 0.0, -0.0), glm::dvec3(-0.0, -0.0, -0.0), glm::dvec3(-0.0, 0.0, 0.0)}) {
        const Spherical z = to_spherical(zero);
        INFO("to_spherical" << str(zero) << " (signed zeros) gave (" << z.r << ", " << z.theta << ", " << z.phi
                            << "), expected (0, 0, 0)");
        CHECK(z.r == 0.0);
        CHECK(z.theta == 0.0);
        CHECK(z.phi == 0.0);
    }
    // y so small and negative that atan2(y, x) + 2pi rounds to the double 2pi: phi must still be < 2pi
    for (double y : {-1e-17, -1e-300}) {
        const Spherical w = to_spherical({1.0, y, 0.5});
        INFO("to_spherical(1, " << y << ", 0.5): phi = " << w.phi << " (phi lies in [0, 2pi): "
                                << "wrap 2pi to 0, a value near 0 or just below 2pi)");
        CHECK(w.phi >= 0.0);
        CHECK(w.phi < 2 * kPi);
        CHECK((w.phi < 1e-12 || w.phi > 2 * kPi - 1e-12));
    }
    // theta == 0 and pi are the only special angles: theta = 1 is the plain formula
    for (double th : {1.0, 0.5, 2.0}) {
        const glm::dvec3 c = to_cartesian({2.0, th, 0.7});
        const glm::dvec3 want(2.0 * std::sin(th) * std::cos(0.7), 2.0 * std::sin(th) * std::sin(0.7), 2.0 * std::cos(th));
        INFO("to_cartesian(2, " << th << ", 0.7) gave " << str(c) << ", expected " << str(want));
        CHECK(glm::length(c - want) < 1e-12);
    }
    const glm::dvec3 s_pole = to_cartesian({1.5, pi, 0.7});
    CHECK(s_pole.x == 0.0);
    CHECK(s_pole.y == 0.0);
    CHECK(s_pole.z == -1.5);
    const glm::dvec3 n_pole = to_cartesian({1.5, 0.0, 2.0});
    CHECK(n_pole.x == 0.0);
    CHECK(n_pole.y == 0.0);
    CHECK(n_pole.z == 1.5);
}

TEST_CASE("find_root: brackets the sign change to the tolerance in at most 100 evaluations" * geolab::points(2) *
          geolab::hint("Keep [t0, t1] with inside(g(t0)) == inside(g0) (inside means g <= 0); stop when t1 - t0 < "
                       "tolerance or an iterate moves by less than tolerance/8. Handout §3.2.")) {
    struct Case {
        const char* name;
        double (*g)(double);
        double root;
    };
    const Case cases[] = {
        {"linear 2t - 0.6", [](double t) { return 2 * t - 0.6; }, 0.3},
        {"outside to inside 0.8 - t", [](double t) { return 0.8 - t; }, 0.8},
        {"cubic (t - 0.123)^3", [](double t) { return std::pow(t - 0.123, 3); }, 0.123},
        {"steep exp(40 t) - exp(36)", [](double t) { return std::exp(40 * t) - std::exp(36.0); }, 0.9},
        {"root at the lower end: g(t) = t", [](double t) { return t; }, 0.0},
        {"root near the upper end: g(t) = t - 0.9995", [](double t) { return t - 0.9995; }, 0.9995},
    };
    for (const Case& c : cases)
        for (double tol : {1e-3, 1e-7, 1e-10}) {
            int evals = 0;
            auto g = [&](double t) {
                ++evals;
                return c.g(t);
            };
            const double t = find_root(g, c.g(0.0), c.g(1.0), tol);
            INFO(c.name << ", tolerance " << tol << ": got t = " << t << ", root " << c.root << ", " << evals
                        << " evaluations");
            CHECK(t >= 0.0);
            CHECK(t <= 1.0);
            CHECK(std::abs(t - c.root) <= 2 * tol + 1e-12);
            CHECK(evals <= 100);
        }
}

TEST_CASE("find_crossing: point within the relative tolerance; unit outward normal; at any scale" *
          geolab::points(2) *
          geolab::hint("The tolerance is a fraction of the edge: p = a + t (b - a). The normal is grad f / |grad f| "
                       "(fields need not return unit gradients); with |grad f| = 0, the unit direction from the "
                       "inside end to the outside end. Handout §3.3.")) {
    for (double scale : {1e-4, 1.0, 1e3}) {
        const Ball f(glm::dvec3(0.3, -0.2, 0.1) * scale, 0.8 * scale);
        Lcg rng(17);
        for (int i = 0; i < 30; ++i) {
            // an edge of length 0.1 scale through the surface, in a random direction, either orientation
            const glm::dvec3 n = rng.unit_vector(), d = rng.unit_vector();
            const glm::dvec3 on = f.c + f.r * n;
            glm::dvec3 a = on - 0.05 * scale * d * (glm::dot(d, n) >= 0 ? 1.0 : -1.0) * rng.uniform(0.2, 1.0);
            glm::dvec3 b = a + 0.1 * scale * d * (glm::dot(d, n) >= 0 ? 1.0 : -1.0);
            if (i % 2) std::swap(a, b);
            const double fa = f.value(a), fb = f.value(b);
            if (inside(fa) == inside(fb)) continue;
            const Crossing c = find_crossing(f, a, b, fa, fb, 1e-9);
            // the exact crossing by many bisection steps here
            double lo = 0, hi = 1;
            for (int k = 0; k < 200; ++k) {
                double m = 0.5 * (lo + hi);
                (inside(f.value(a + m * (b - a))) == inside(fa) ? lo : hi) = m;
            }
            const glm::dvec3 exact = a + lo * (b - a);
            INFO("scale " << scale << ", edge " << str(a) << " -> " << str(b) << ": point " << str(c.point)
                          << ", exact " << str(exact) << ", normal " << str(c.normal));
            CHECK(glm::length(c.point - exact) <= 4e-9 * glm::length(b - a));
            CHECK(std::abs(glm::length(c.normal) - 1.0) < 1e-12);
            CHECK(glm::dot(c.normal, glm::normalize(c.point - f.c)) > 1.0 - 1e-9);
        }
    }
    // zero gradient: the edge direction from inside to outside
    const FlatGradient g;
    for (int flip = 0; flip < 2; ++flip) {
        glm::dvec3 a(0.1, 0.0, 0.2), b(0.1, 1.0, 0.2);
        if (flip) std::swap(a, b);
        const Crossing c = find_crossing(g, a, b, g.value(a), g.value(b), 1e-9);
        INFO("f = y - 0.25 with zero gradient, edge " << str(a) << " -> " << str(b) << ": normal " << str(c.normal));
        CHECK(std::abs(c.point.y - 0.25) < 1e-8);
        CHECK(glm::length(c.normal - glm::dvec3(0, 1, 0)) < 1e-12);
    }
}

TEST_CASE("find_crossing_arc: a phi-arc crossing lies on the arc (constant r and theta); not on its chord" *
          geolab::points(2) *
          geolab::hint("Interpolate (r, theta, phi) linearly and map every iterate with to_cartesian, relative to the "
                       "origin: the crossing of a curved edge is on the curve. Handout §3.3, Fig. 3.")) {
    const glm::dvec3 origin(2.0, -1.0, 3.0);
    const double r = 1.3, theta = 1.1;
    for (double x0 : {-0.6, 0.2, 0.9}) {
        // plane x = origin.x + x0 crossing the latitude circle (r, theta) between phi = 0.3 and phi = 2.9
        const PlaneX f(origin.x + x0);
        const Spherical a{r, theta, 0.3}, b{r, theta, 2.9};
        const double fa = f.value(origin + cart_of(a.r, a.theta, a.phi)),
                     fb = f.value(origin + cart_of(b.r, b.theta, b.phi));
        REQUIRE(inside(fa) != inside(fb));
        const Crossing c = find_crossing_arc(f, origin, a, b, fa, fb, 1e-10);
        const Sph s = sph_of(c.point - origin);
        const double phi_star = std::acos(x0 / (r * std::sin(theta)));
        INFO("phi-arc r = " << r << ", theta = " << theta << " about " << str(origin) << ", plane x = " << f.x0
                            << ": got " << str(c.point) << " (r = " << s.r << ", theta = " << s.theta
                            << ", phi = " << s.phi << "), expected phi = " << phi_star);
        CHECK(std::abs(s.r - r) < 1e-9);
        CHECK(std::abs(s.theta - theta) < 1e-9);
        CHECK(std::abs(s.phi - phi_star) < 1e-8);
        CHECK(std::abs(f.value(c.point)) < 1e-8);
        CHECK(glm::length(c.normal - glm::dvec3(1, 0, 0)) < 1e-12);
    }
}

TEST_CASE("find_crossing_arc: theta-arcs keep r and phi; radial edges keep the direction" * geolab::points(1) *
          geolab::hint("Only the parameter that differs between the ends changes along the edge: a meridian "
                       "(theta-arc) keeps r and phi; a radial edge keeps theta and phi. Where grad f = 0 the normal "
                       "is the unit direction along the edge from its inside end to its outside end. Handout §3.3.")) {
    const glm::dvec3 origin(-0.5, 0.25, 0.1);
    const Ball f(origin + glm::dvec3(0.0, 0.0, 0.6), 1.0);  // a sphere whose centre is off the origin
    // theta-arc at r = 1.2, phi = 0.8, from the north pole (inside) to theta = 2.5 (outside)
    {
        const Spherical a{1.2, 0.0, 0.8}, b{1.2, 2.5, 0.8};
        const double fa = f.value(origin + cart_of(a.r, a.theta, a.phi)),
                     fb = f.value(origin + cart_of(b.r, b.theta, b.phi));
        REQUIRE(inside(fa) != inside(fb));
        const Crossing c = find_crossing_arc(f, origin, a, b, fa, fb, 1e-10);
        const Sph s = sph_of(c.point - origin);
        INFO("theta-arc: got " << str(c.point) << " (r = " << s.r << ", theta = " << s.theta << ", phi = " << s.phi
                               << "), f = " << f.value(c.point));
        CHECK(std::abs(s.r - 1.2) < 1e-9);
        CHECK(std::abs(s.phi - 0.8) < 1e-9);
        CHECK(std::abs(f.value(c.point)) < 1e-8);
        CHECK(std::abs(glm::length(c.normal) - 1.0) < 1e-12);
        CHECK(glm::dot(c.normal, c.point - f.c) > 0.0);
    }
    // radial edge at (theta, phi) = (2.0, 4.0) from r = 0.05 to r = 2.5
    {
        const Spherical a{0.05, 2.0, 4.0}, b{2.5, 2.0, 4.0};
        const double fa = f.value(origin + cart_of(a.r, a.theta, a.phi)),
                     fb = f.value(origin + cart_of(b.r, b.theta, b.phi));
        REQUIRE(inside(fa) != inside(fb));
        const Crossing c = find_crossing_arc(f, origin, a, b, fa, fb, 1e-10);
        const Sph s = sph_of(c.point - origin);
        INFO("radial edge: got " << str(c.point) << " (r = " << s.r << ", theta = " << s.theta
                                 << ", phi = " << s.phi << "), f = " << f.value(c.point));
        CHECK(std::abs(s.theta - 2.0) < 1e-9);
        CHECK(std::abs(s.phi - 4.0) < 1e-9);
        CHECK(std::abs(f.value(c.point)) < 1e-8);
        CHECK(glm::dot(c.normal, c.point - f.c) > 0.0);
    }
    // zero gradient (f = y - 0.25): the normal is the unit direction along the edge from its inside end to its
    // outside end; on an arc of angle w the tangent and the chord agree within w / 2
    const FlatGradient flat;
    const glm::dvec3 o0(0.0);
    struct Arc {
        Spherical a, b;
        double angle;  // the arc's angle (0 for a radial edge)
        const char* what;
    } arcs[] = {{{0.8, 0.9, 0.2}, {0.8, 0.9, 1.4}, 1.2, "phi-arc r = 0.8, theta = 0.9, phi 0.2 -> 1.4 (inside -> outside)"},
                {{0.8, 0.9, 1.4}, {0.8, 0.9, 0.2}, 1.2, "phi-arc r = 0.8, theta = 0.9, phi 1.4 -> 0.2 (outside -> inside)"},
                {{0.9, 0.1, 1.2}, {0.9, 1.6, 1.2}, 1.5, "theta-arc r = 0.9, phi = 1.2, theta 0.1 -> 1.6"},
                {{0.1, 1.3, 1.5}, {0.9, 1.3, 1.5}, 0.0, "radial edge theta = 1.3, phi = 1.5, r 0.1 -> 0.9"}};
    for (const Arc& arc : arcs) {
        const glm::dvec3 pa = cart_of(arc.a.r, arc.a.theta, arc.a.phi), pb = cart_of(arc.b.r, arc.b.theta, arc.b.phi);
        const double fa = flat.value(pa), fb = flat.value(pb);
        REQUIRE(inside(fa) != inside(fb));
        const Crossing c = find_crossing_arc(flat, o0, arc.a, arc.b, fa, fb, 1e-10);
        const glm::dvec3 chord = glm::normalize(inside(fa) ? pb - pa : pa - pb);
        INFO(std::string(arc.what) << ", |grad f| = 0: normal " << str(c.normal) << ", chord from inside to outside "
                                   << str(chord));
        CHECK(std::abs(c.point.y - 0.25) < 1e-9);
        CHECK(std::abs(glm::length(c.normal) - 1.0) < 1e-9);
        CHECK(glm::dot(c.normal, chord) >= std::cos(0.5 * arc.angle) - 1e-9);
    }
}

}  // TEST_SUITE
