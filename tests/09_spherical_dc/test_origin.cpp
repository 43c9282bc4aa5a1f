// Lab 09, Tasks 8-9: the origin of the spherical octree (handout §6): Welzl's smallest enclosing sphere and the
// eq. (6) correction that moves the origin off the surface.
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab09;

namespace {
void check_encloses(const std::vector<glm::dvec3>& pts, const Sphere& s, double scale) {
    std::size_t outside = 0;
    double worst = 0;
    for (const auto& p : pts) {
        const double d = glm::length(p - s.center) - s.radius;
        if (d > 1e-9 * scale) ++outside;
        worst = std::max(worst, d);
    }
    CHECK_MESSAGE(outside == 0, outside << " points outside the sphere (worst by " << worst << ")");
}
}  // namespace

TEST_SUITE("Task 8: smallest enclosing sphere") {

TEST_CASE("minimal_enclosing_sphere: known configurations" * geolab::points(2) *
          geolab::hint("Welzl: a point outside the current sphere lies on the boundary of the smallest sphere of "
                       "the points so far. The support set has 1-4 points; an obtuse triangle's sphere is the one of "
                       "its longest side, not its circumsphere. Handout §6.1.")) {
    const double s3 = std::sqrt(3.0);
    struct Case {
        const char* name;
        std::vector<glm::dvec3> pts;
        glm::dvec3 center;
        double radius;
    };
    const glm::dvec3 o(1.5, -2.0, 0.5);
    const double a = 0.8;  // tetrahedron (±1,±1,±1) with an even number of minus signs, edge 2√2 a
    const std::vector<Case> cases = {
        {"one point", {o}, o, 0.0},
        {"two points", {o, o + glm::dvec3(0.6, 0.0, 0.8)}, o + glm::dvec3(0.3, 0.0, 0.4), 0.5},
        {"equilateral triangle, side 1", {o, o + glm::dvec3(1, 0, 0), o + glm::dvec3(0.5, s3 / 2, 0)},
         o + glm::dvec3(0.5, s3 / 6, 0), 1 / s3},
        {"obtuse triangle (sphere of the longest side)", {o, o + glm::dvec3(2, 0, 0), o + glm::dvec3(1.0, 0.3, 0.2)},
         o + glm::dvec3(1, 0, 0), 1.0},
        {"regular tetrahedron", {o + a * glm::dvec3(1, 1, 1), o + a * glm::dvec3(1, -1, -1),
                                 o + a * glm::dvec3(-1, 1, -1), o + a * glm::dvec3(-1, -1, 1)},
         o, a * s3},
        {"regular tetrahedron plus its centre and edge midpoints",
         {o + a * glm::dvec3(1, 1, 1), o, o + a * glm::dvec3(1, 0, 0), o + a * glm::dvec3(1, -1, -1),
          o + a * glm::dvec3(0, 1, 0), o + a * glm::dvec3(-1, 1, -1), o + a * glm::dvec3(0, 0, -1),
          o + a * glm::dvec3(-1, -1, 1)},
         o, a * s3},
        {"octahedron vertices", {o + glm::dvec3(1, 0, 0), o - glm::dvec3(1, 0, 0), o + glm::dvec3(0, 1, 0),
                                 o - glm::dvec3(0, 1, 0), o + glm::dvec3(0, 0, 1), o - glm::dvec3(0, 0, 1)},
         o, 1.0},
    };
    for (const Case& c : cases) {
        const Sphere s = minimal_enclosing_sphere(c.pts);
        INFO(c.name << ": got centre " << str(s.center) << " radius " << s.radius << ", expected centre "
                    << str(c.center) << " radius " << c.radius);
        CHECK(std::abs(s.radius - c.radius) < 1e-9);
        CHECK(glm::length(s.center - c.center) < 1e-7);
        check_encloses(c.pts, s, 1.0);
    }
    // many points on a unit sphere (including 6 axis points) and inside it: the unit sphere itself
    Lcg rng(21);
    std::vector<glm::dvec3> pts;
    for (int i = 0; i < 300; ++i) pts.push_back(o + (i % 3 ? 1.0 : rng.uniform(0.0, 0.99)) * rng.unit_vector());
    for (int k = 0; k < 6; ++k) {
        glm::dvec3 e(0.0);
        e[k / 2] = k % 2 ? -1.0 : 1.0;
        pts.push_back(o + e);
    }
    const Sphere s = minimal_enclosing_sphere(pts);
    INFO("306 points on and in the unit sphere about " << str(o) << ": got centre " << str(s.center) << " radius "
                                                       << s.radius);
    CHECK(std::abs(s.radius - 1.0) < 1e-9);
    CHECK(glm::length(s.center - o) < 1e-6);
    check_encloses(pts, s, 1.0);
    // a third point 1e-4 or 1e-7 of the radius outside the sphere of the other two (diameter 2R), in every input
    // order: every point must be enclosed to 1e-9 of R at every size and far from the origin (containment
    // tolerances relative to the cloud's size, not to its distance from the origin)
    for (double R : {1e-9, 1.0, 1e3})
        for (const glm::dvec3 c : {glm::dvec3(0.0), glm::dvec3(1e6, -2e6, 5e5)}) {
            if (R < 1e-3 && glm::length(c) > 0) continue;  // 1e-9 far from the origin is below the rounding
            for (double excess : {1e-4, 1e-7}) {
                std::vector<glm::dvec3> three = {c + glm::dvec3(R, 0, 0), c + glm::dvec3(0, R * (1 + excess), 0),
                                                 c - glm::dvec3(R, 0, 0)};
                // the circumcircle: centre (0, y0, 0) with R^2 + y0^2 = (R (1 + excess) - y0)^2
                const double yt = R * (1 + excess), y0 = (yt * yt - R * R) / (2 * yt);
                std::sort(three.begin(), three.end(), [](const glm::dvec3& p, const glm::dvec3& q) {
                    return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z);
                });
                do {
                    const Sphere t = minimal_enclosing_sphere(three);
                    INFO("points (+-R, 0, 0) and (0, R (1 + " << excess << "), 0) about " << str(c) << ", R = " << R
                         << ", given in the order " << str(three[0]) << " " << str(three[1]) << " " << str(three[2])
                         << ": got centre " << str(t.center) << " radius " << t.radius << ", expected radius "
                         << std::sqrt(R * R + y0 * y0));
                    CHECK(std::abs(t.radius - std::sqrt(R * R + y0 * y0)) < 1e-9 * R);
                    check_encloses(three, t, R);
                } while (std::next_permutation(three.begin(), three.end(), [](const glm::dvec3& p, const glm::dvec3& q) {
                    return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z);
                }));
            }
            // a regular tetrahedron (all four points on the sphere) of the same size: radius R sqrt(3)
            const std::vector<glm::dvec3> tet = {c + R * glm::dvec3(1, 1, 1), c + R * glm::dvec3(1, -1, -1),
                                                 c + R * glm::dvec3(-1, 1, -1), c + R * glm::dvec3(-1, -1, 1)};
            const Sphere u = minimal_enclosing_sphere(tet);
            INFO("regular tetrahedron R (+-1, +-1, +-1) about " << str(c) << ", R = " << R << ": got centre "
                 << str(u.center) << " radius " << u.radius << ", expected " << R * std::sqrt(3.0));
            CHECK(std::abs(u.radius - R * std::sqrt(3.0)) < 1e-9 * R);
            CHECK(glm::length(u.center - c) < 1e-9 * R);
        }
    const Sphere e = minimal_enclosing_sphere({});
    CHECK(e.radius == 0.0);
}

TEST_CASE("minimal_enclosing_sphere: random point sets match a brute-force search" * geolab::points(3) *
          geolab::hint("The result must contain every point AND be the smallest such sphere (the brute force tries "
                       "every support set of <= 4 points). A sphere from the bounding box or a centroid is not "
                       "minimal. Handout §6.1.")) {
    Lcg rng(1234);
    for (int trial = 0; trial < 40; ++trial) {
        const int n = 5 + trial % 11;
        std::vector<glm::dvec3> pts;
        glm::dvec3 shift(rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5));
        double scale = std::pow(10.0, rng.uniform(-2, 2));
        // tiny and huge clouds about the origin: any tolerance must be relative to the scale
        if (trial % 10 == 9) scale = 1e-6, shift = glm::dvec3(0.0);
        if (trial % 10 == 8) scale = 1e5, shift = glm::dvec3(0.0);
        for (int i = 0; i < n; ++i) {
            glm::dvec3 p(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
            if (trial % 4 == 1) p *= glm::dvec3(1.0, 0.2, 0.05);  // flat clouds
            if (trial % 4 == 2) p = glm::normalize(p);           // on a sphere
            pts.push_back(shift + scale * p);
        }
        const Sphere s = minimal_enclosing_sphere(pts);
        const Sphere b = brute_force_enclosing_sphere(pts, 1e-10 * scale);
        INFO("trial " << trial << ": " << n << " points, scale " << scale << "; got radius " << s.radius
                      << ", brute force " << b.radius);
        check_encloses(pts, s, scale);
        CHECK(s.radius <= b.radius * (1 + 1e-9) + 1e-12 * scale);
        CHECK(s.radius >= b.radius * (1 - 1e-9) - 1e-12 * scale);
    }
}

}  // TEST_SUITE

TEST_SUITE("Task 9: origin correction") {

TEST_CASE("correct_origin: starting exactly on the surface; the path leaves it in a few bounded steps" *
          geolab::points(2) *
          geolab::hint("Eq. (6): x += s * delta * unit * grad f / |grad f| until s * f(x) >= margin * unit. A step "
                       "is delta * unit long whatever |grad f| is; on the surface (f = 0) pick the side whose probe "
                       "has the larger |f|. Handout §6.2.")) {
    const FieldPtr sphere = geolab::sphere({0, 0, 0}, 1.0), box = geolab::box({0, 0, 0}, {1.0, 0.8, 0.6});
    const std::pair<const ScalarField*, glm::dvec3> starts[] = {
        {sphere.get(), {1.0, 0.0, 0.0}}, {sphere.get(), {0.0, 0.0, -1.0}}, {box.get(), {0.3, 0.8, 0.1}}};
    for (auto [f, x0] : starts) {
        REQUIRE(f->value(x0) == 0.0);
        OriginParams op;
        op.unit = 0.05;
        const auto path = correct_origin(*f, x0, op);
        INFO("start " << str(x0) << " on the " << (f == sphere.get() ? "unit sphere" : "box") << ", unit 0.05: "
                      << path.size() << " positions, last " << (path.empty() ? "-" : str(path.back())));
        REQUIRE(path.size() >= 2);
        CHECK(path.front() == x0);
        CHECK(path.size() <= 4);
        for (std::size_t i = 1; i < path.size(); ++i) {
            CHECK(std::abs(glm::length(path[i] - path[i - 1]) - op.delta * op.unit) < 1e-9);
            CHECK(glm::length(path[i] - x0) <= i * op.delta * op.unit + 1e-9);
        }
        CHECK(std::abs(f->value(path.back())) >= op.margin * op.unit);
    }
}

TEST_CASE("correct_origin: moves to the nearer side along the gradient; stops at once when far enough" *
          geolab::points(1) *
          geolab::hint("s = sign f(x0): slightly outside goes further out (+grad f), slightly inside goes in "
                       "(-grad f). |f(x0)| >= margin * unit returns {x0}. Handout §6.2.")) {
    const FieldPtr f = geolab::sphere({0.2, -0.1, 0.3}, 0.9);
    OriginParams op;
    op.unit = 0.02;
    for (double off : {0.3, -0.3, 0.01, -0.01}) {
        const glm::dvec3 dir = glm::normalize(glm::dvec3(1.0, 2.0, -0.5));
        const glm::dvec3 x0 = glm::dvec3(0.2, -0.1, 0.3) + (0.9 + off * op.unit) * dir;
        const auto path = correct_origin(*f, x0, op);
        INFO("start at f = " << f->value(x0) << " (" << off << " unit): " << path.size() << " positions, last f = "
                             << (path.empty() ? 0.0 : f->value(path.back())));
        REQUIRE(path.size() >= 2);
        const double fe = f->value(path.back());
        if (off > 0) CHECK(fe >= op.margin * op.unit);
        else CHECK(fe <= -op.margin * op.unit);
        for (std::size_t i = 1; i < path.size(); ++i) {
            const glm::dvec3 step = path[i] - path[i - 1];
            CHECK(glm::dot(glm::normalize(step), (off > 0 ? 1.0 : -1.0) * dir) > 1 - 1e-9);
        }
    }
    const glm::dvec3 far(0.2, -0.1, 0.3 + 0.9 + 2.5 * op.unit);
    const auto path = correct_origin(*f, far, op);
    INFO("start at f = 2.5 unit (margin 2): " << path.size() << " positions");
    REQUIRE(path.size() == 1);
    CHECK(path[0] == far);
    // |f| reaching margin * unit exactly counts as far enough, at the start and after a step: f = z, unit 1/8,
    // delta * unit = 0.1875, margin * unit = 0.25 (every number exact in binary)
    struct Plane final : ScalarField {
        double value(const glm::dvec3& p) const override { return p.z; }
        glm::dvec3 gradient(const glm::dvec3&) const override { return {0.0, 0.0, 1.0}; }
        Box bounds() const override { return {glm::dvec3(-1.0), glm::dvec3(1.0)}; }
    } plane;
    OriginParams eighth;
    eighth.unit = 0.125;
    for (double z0 : {0.25, -0.25, 0.0625, -0.0625}) {
        const glm::dvec3 x0(0.1, -0.2, z0);
        const auto exact = correct_origin(plane, x0, eighth);
        const std::size_t want = std::abs(z0) == 0.25 ? 1 : 2;
        INFO("f = z from z = " << z0 << ", margin * unit = 0.25, delta * unit = 0.1875: " << exact.size()
                               << " positions, last " << str(exact.back()) << "; expected " << want
                               << " (|f| >= margin * unit stops, equality included)");
        CHECK(exact.size() == want);
        CHECK(std::abs(exact.back().z) == 0.25);
    }
}

TEST_CASE("correct_origin: where grad f vanishes the step goes to the best of the 6 axis probes at delta times unit" *
          geolab::points(1) *
          geolab::hint("|grad f| < 1e-12: probe x +- delta * unit * e for the 6 axis directions e and step to the probe "
                       "with the largest s * f (s = the side we move to). The probe distance matters: a field can grow "
                       "fastest along one axis near x and along another farther away. Handout §6.")) {
    // f = s0 (c + A max(x, 0)^4 + B max(y, 0)^2 + h max(z, 0)^2 + g z): zero gradient at the origin when g = 0.
    // With h = 0, +X wins beyond d* = sqrt(B / A) = 0.05 and +Y below it; with h = 0.01, +Z wins at both distances.
    // |grad f| = g exactly at the origin: 1e-12 and 1.5e-12 are not below 1e-12, so the step follows the gradient.
    struct Probe final : ScalarField {
        double sign = 1.0, g = 0.0, h = 0.0;
        double value(const glm::dvec3& p) const override {
            const double x = std::max(p.x, 0.0), y = std::max(p.y, 0.0), z = std::max(p.z, 0.0);
            return sign * (0.01 + x * x * x * x + 0.0025 * y * y + h * z * z + g * p.z);
        }
        glm::dvec3 gradient(const glm::dvec3& p) const override {
            const double x = std::max(p.x, 0.0), y = std::max(p.y, 0.0), z = std::max(p.z, 0.0);
            return sign * glm::dvec3(4.0 * x * x * x, 0.005 * y, 2.0 * h * z + g);
        }
        Box bounds() const override { return {glm::dvec3(-1.0), glm::dvec3(1.0)}; }
    };
    int checked = 0;
    for (double sign : {1.0, -1.0})
        for (double g : {0.0, 1e-13, 1e-12, 1.5e-12, 1e-11})
            for (double step : {0.035, 0.07})
                for (double h : {0.0, 0.01}) {
                Probe f;
                f.sign = sign;
                f.g = g;
                f.h = h;
                OriginParams op;
                op.unit = step / op.delta;
                const glm::dvec3 x0(0.0);
                const auto path = correct_origin(f, x0, op);
                // the expected first position: the best probe (|grad f| < 1e-12), or one step along s grad f
                glm::dvec3 want(0.0, 0.0, step * (g > 0 ? 1.0 : 0.0));
                const char* rule = "one step along s * grad f / |grad f|";
                if (glm::length(f.gradient(x0)) < 1e-12) {
                    rule = "the axis probe with the largest s * f";
                    double best = -1e300;
                    for (int a = 0; a < 3; ++a)
                        for (double e : {1.0, -1.0}) {
                            glm::dvec3 q(0.0);
                            q[a] = e * step;
                            if (sign * f.value(q) > best) best = sign * f.value(q), want = q;
                        }
                }
                INFO("f = " << (sign > 0 ? "" : "-") << "(0.01 + max(x,0)^4 + 0.0025 max(y,0)^2 + " << h
                            << " max(z,0)^2 + " << g << " z) from the origin, delta * unit = " << step << ": expected " << rule << " "
                            << str(want) << ", got " << (path.size() > 1 ? str(path[1]) : std::string("no step")));
                REQUIRE(path.size() >= 2);
                CHECK(path[0] == x0);
                CHECK(glm::length(path[1] - want) < 1e-12);
                ++checked;
            }
    CHECK(checked == 40);
}

TEST_CASE("correct_origin: exactly on the surface where grad f vanishes: the side comes from the probe at delta times unit" *
          geolab::points(1) *
          geolab::hint("f(x0) = 0 and |grad f| < 1e-12: n = the axis probe at distance delta * unit with the largest f "
                       "(as for s = 1), then s = +1 if |f(x0 + delta unit n)| > |f(x0 - delta unit n)| else -1. The probe "
                       "distance decides which axis wins here. Handout §6.")) {
    // f = max(x,0)^4 - 10 max(-x,0)^4 + 0.0025 max(y,0)^2: f(0) = 0, grad f(0) = 0. Probing at d < 0.05, +Y wins
    // (and then s = +1); at d > 0.05, +X wins (and then s = -1: f falls faster along -x).
    struct Flat final : ScalarField {
        double value(const glm::dvec3& p) const override {
            const double xp = std::max(p.x, 0.0), xm = std::max(-p.x, 0.0), y = std::max(p.y, 0.0);
            return xp * xp * xp * xp - 10.0 * xm * xm * xm * xm + 0.0025 * y * y;
        }
        glm::dvec3 gradient(const glm::dvec3& p) const override {
            const double xp = std::max(p.x, 0.0), xm = std::max(-p.x, 0.0), y = std::max(p.y, 0.0);
            return {4.0 * xp * xp * xp + 40.0 * xm * xm * xm, 0.005 * y, 0.0};
        }
        Box bounds() const override { return {glm::dvec3(-1.0), glm::dvec3(1.0)}; }
    } f;
    auto best_probe = [&](const glm::dvec3& x, double s, double d) {
        glm::dvec3 best(0.0);
        double best_v = -1e300;
        for (int a = 0; a < 3; ++a)
            for (double e : {1.0, -1.0}) {
                glm::dvec3 q(0.0);
                q[a] = e;
                if (s * f.value(x + s * d * q) > best_v) best_v = s * f.value(x + s * d * q), best = q;
            }
        return best;
    };
    for (double step : {0.03, 0.035, 0.07, 0.1}) {
        OriginParams op;
        op.unit = step / op.delta;
        const glm::dvec3 x0(0.0);
        const glm::dvec3 n = best_probe(x0, 1.0, step);
        const double s = std::abs(f.value(x0 + step * n)) > std::abs(f.value(x0 - step * n)) ? 1.0 : -1.0;
        const glm::dvec3 want = x0 + s * step * best_probe(x0, s, step);
        const auto path = correct_origin(f, x0, op);
        INFO("f = max(x,0)^4 - 10 max(-x,0)^4 + 0.0025 max(y,0)^2 from the origin, delta * unit = " << step
             << ": the probe gives n = " << str(n) << ", side s = " << s << ", first step to " << str(want) << "; got "
             << (path.size() > 1 ? str(path[1]) : std::string("no step")));
        REQUIRE(path.size() >= 2);
        CHECK(glm::length(path[1] - want) < 1e-12);
    }
}

TEST_CASE("dual_contour_spherical: the default r_max from an off-centre origin covers every corner of bounds()" *
          geolab::points(1) * geolab::whole_chain() *
          geolab::hint("r_max = 0 means 1.05 x the largest distance from the (corrected) origin to the 8 corners of "
                       "bounds(): corner c takes hi.x when bit 0 of c is set, hi.y for bit 1, hi.z for bit 2. From an "
                       "origin off the centre the farthest corner can be any of the 8. Handout §6.2.")) {
    // a box with unequal half extents (bounds are not a cube) and origins in every octant of it
    const glm::dvec3 centre(0.3, -0.2, 0.1), half(0.9, 0.6, 0.45);
    const FieldPtr f = geolab::box(centre, half);
    const Box b = f->bounds();
    for (int oct = 0; oct < 8; ++oct) {
        const glm::dvec3 off(oct & 1 ? 0.45 : -0.45, oct & 2 ? 0.3 : -0.3, oct & 4 ? 0.2 : -0.2);
        SphericalParams p;
        p.max_level = 3;
        p.origin = centre + off;
        DcStats st;
        (void)dual_contour_spherical(*f, p, &st);
        double far = 0;
        int far_corner = -1;
        for (int c = 0; c < 8; ++c) {
            const glm::dvec3 q(c & 1 ? b.hi.x : b.lo.x, c & 2 ? b.hi.y : b.lo.y, c & 4 ? b.hi.z : b.lo.z);
            if (glm::length(q - st.origin) > far) far = glm::length(q - st.origin), far_corner = c;
        }
        INFO("box about " << str(centre) << " half extents " << str(half) << ", origin " << str(st.origin)
             << ": the farthest corner of bounds() is corner " << far_corner << " at " << far << ", expected r_max "
             << 1.05 * far << ", got " << st.r_max);
        CHECK(std::abs(st.r_max - 1.05 * far) <= 1e-12 * far);
    }
}

TEST_CASE("correct_origin: unit <= 0 throws std::invalid_argument" * geolab::points(1) *
          geolab::hint("dual_contour_spherical fills unit in; a direct call must pass a positive length.")) {
    const FieldPtr f = geolab::sphere({0, 0, 0}, 1.0);
    OriginParams op;
    op.unit = 0.1;
    const auto path = correct_origin(*f, {1.0, 0.0, 0.0}, op);
    REQUIRE(path.size() >= 2);
    op.unit = 0.0;
    CHECK_THROWS_AS(correct_origin(*f, {1.0, 0.0, 0.0}, op), std::invalid_argument);
    op.unit = -1.0;
    CHECK_THROWS_AS(correct_origin(*f, {1.0, 0.0, 0.0}, op), std::invalid_argument);
}

TEST_CASE("dual_contour_spherical: an origin on the surface is corrected and the mesh stays closed" *
          geolab::points(1) * geolab::whole_chain() *
          geolab::hint("Radii about an origin ON the surface degenerate (the paper's diverging vertices): apply "
                       "correct_origin first and use its last position; DcStats::origin_path records it. "
                       "Handout §6.2.")) {
    const FieldPtr f = geolab::sphere({0, 0, 0}, 0.8);
    SphericalParams p;
    p.max_level = 5;
    p.origin = glm::dvec3(0.0, 0.8, 0.0);
    DcStats st;
    const PolygonSoup s = dual_contour_spherical(*f, p, &st);
    const double unit = 1.6 / 32;
    INFO("sphere r = 0.8, origin (0, 0.8, 0) on the surface, level 5: path of " << st.origin_path.size()
                                                                               << " positions, origin "
                                                                               << str(st.origin));
    REQUIRE(st.origin_path.size() >= 2);
    CHECK(st.origin_path.front() == glm::dvec3(0.0, 0.8, 0.0));
    CHECK(st.origin_path.back() == st.origin);
    // the default unit: the largest extent of bounds() / 2^L (here 1.6 / 32), steps of delta = 1.5 units
    for (std::size_t i = 1; i < st.origin_path.size(); ++i) {
        const double step = glm::length(st.origin_path[i] - st.origin_path[i - 1]);
        INFO("step " << i << " is " << step << " long, expected 1.5 * " << unit);
        CHECK(std::abs(step - 1.5 * unit) < 1e-9 * unit);
    }
    // the default shell: r_max = 1.05 x the distance from the origin to the farthest corner of bounds()
    double far = 0;
    for (int c = 0; c < 8; ++c)
        far = std::max(far, glm::length(glm::dvec3(c & 1 ? 0.8 : -0.8, c & 2 ? 0.8 : -0.8, c & 4 ? 0.8 : -0.8) - st.origin));
    CHECK(st.r_min == 0.0);
    CHECK(std::abs(st.r_max - 1.05 * far) < 1e-12 * far);
    CHECK(std::abs(f->value(st.origin)) >= 2.0 * unit * (1 - 1e-9));
    LAB09_CHECK_CLOSED_MANIFOLD(s, "sphere, corrected origin");
    CHECK(std::abs(enclosed_volume(s) - sphere_volume(0.8)) < 0.02 * sphere_volume(0.8));
    // bounds that are not a cube (extents 1.8, 1.2, 0.9): the unit is the LARGEST extent / 2^L
    const glm::dvec3 centre(0.3, -0.2, 0.1), half(0.9, 0.6, 0.45);
    const FieldPtr box = geolab::box(centre, half);
    SphericalParams q;
    q.max_level = 4;
    q.origin = centre + glm::dvec3(0.9, 0.1, 0.05);  // on the +x face
    DcStats sb;
    (void)dual_contour_spherical(*box, q, &sb);
    const double box_unit = 1.8 / 16;
    INFO("box about " << str(centre) << " half extents " << str(half) << ", origin on its +x face, level 4: path of "
                      << sb.origin_path.size() << " positions");
    REQUIRE(sb.origin_path.size() >= 2);
    for (std::size_t i = 1; i < sb.origin_path.size(); ++i) {
        const double step = glm::length(sb.origin_path[i] - sb.origin_path[i - 1]);
        INFO("step " << i << " is " << step << " long, expected 1.5 * " << box_unit);
        CHECK(std::abs(step - 1.5 * box_unit) < 1e-9 * box_unit);
    }
}

}  // TEST_SUITE
