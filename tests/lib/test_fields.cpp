// Tests of the signed fields: geolab/field.hpp, geolab/implicits.hpp, geolab/mesh_field.hpp.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "geolab/field.hpp"
#include "geolab/fixtures.hpp"
#include "geolab/implicits.hpp"
#include "geolab/io.hpp"
#include "geolab/mesh_field.hpp"
#include "geolab/models.hpp"

namespace {

using geolab::FieldPtr;
using glm::dvec3;

std::string str(const dvec3& v) {
    std::ostringstream s;
    s.precision(17);
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}

dvec3 random_in(std::mt19937& rng, const geolab::Box& b) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    return b.lo + dvec3(u(rng), u(rng), u(rng)) * (b.hi - b.lo);
}

geolab::Box grown(const geolab::Box& b, double factor) {
    dvec3 c = b.center(), h = 0.5 * factor * b.size();
    return {c - h, c + h};
}

dvec3 central_difference(const geolab::ScalarField& f, const dvec3& p, double h) {
    dvec3 g;
    for (int i = 0; i < 3; ++i) {
        dvec3 e(0.0);
        e[i] = h;
        g[i] = (f.value(p + e) - f.value(p - e)) / (2 * h);
    }
    return g;
}

// Every named implicit, plus the primitives with unusual parameters and the transforms.
std::vector<std::pair<std::string, FieldPtr>> all_fields() {
    std::vector<std::pair<std::string, FieldPtr>> out;
    for (const auto& name : geolab::implicit_names()) out.emplace_back(name, geolab::named_implicit(name));
    out.emplace_back("tilted cylinder", geolab::cylinder({0.1, -0.2, 0.3}, {1, 2, 3}, 0.4, 0.6));
    out.emplace_back("off-centre torus", geolab::torus({0.2, 0.1, -0.1}, 0.7, 0.1));
    out.emplace_back("translated box", geolab::translated(geolab::box({0, 0, 0}, {0.3, 0.2, 0.1}), {0.5, 0.5, 0}));
    out.emplace_back("scaled torus", geolab::scaled(geolab::named_implicit("torus"), 0.5));
    out.emplace_back("box cut by a halfspace",
                     geolab::csg_intersection(geolab::named_implicit("cube"), geolab::halfspace({0, 0, 0}, {1, 1, 1})));
    return out;
}

// The icosphere of radius 1 from the fixtures, and its longest edge.
double longest_edge(const geolab::PolygonSoup& soup) {
    double e = 0;
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        auto vs = soup.face(f);
        for (std::size_t i = 0; i < vs.size(); ++i)
            e = std::max(e, glm::length(soup.positions[vs[i]] - soup.positions[vs[(i + 1) % vs.size()]]));
    }
    return e;
}

geolab::PolygonSoup without_face(const geolab::PolygonSoup& soup, std::size_t skip) {
    geolab::PolygonSoup out;
    out.positions = soup.positions;
    for (std::size_t f = 0; f < soup.n_faces(); ++f)
        if (f != skip) out.add_face(soup.face(f));
    return out;
}

// Every face reversed (an inward-oriented closed mesh, like CGAL's head).
geolab::PolygonSoup flipped_all(const geolab::PolygonSoup& soup) {
    geolab::PolygonSoup out;
    out.positions = soup.positions;
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        auto vs = soup.face(f);
        std::vector<std::uint32_t> r(vs.rbegin(), vs.rend());
        out.add_face(r);
    }
    return out;
}

double brute_force_distance(const geolab::PolygonSoup& soup, const dvec3& p) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        auto vs = soup.face(f);
        for (std::size_t i = 1; i + 1 < vs.size(); ++i) {
            dvec3 q = geolab::closest_point_on_triangle(p, soup.positions[vs[0]], soup.positions[vs[i]],
                                                        soup.positions[vs[i + 1]]);
            best = std::min(best, glm::dot(q - p, q - p));
        }
    }
    return std::sqrt(best);
}

}  // namespace

TEST_SUITE("fields") {
    // ---- field.hpp -------------------------------------------------------------------------------------------

    TEST_CASE("Box: diagonal, centre, size") {
        geolab::Box b{{-1, 0, 2}, {1, 2, 3}};
        CHECK(b.diagonal() == doctest::Approx(3.0));
        CHECK(b.center() == dvec3(0, 1, 2.5));
        CHECK(b.size() == dvec3(2, 2, 1));
        CHECK(geolab::Box{}.diagonal() == 0.0);
    }

    TEST_CASE("ScalarField: default gradient is a central difference") {
        // f = x² + 2y² + z³ − 1 has ∇f = (2x, 4y, 3z²)
        struct Poly : geolab::ScalarField {
            double value(const dvec3& p) const override { return p.x * p.x + 2 * p.y * p.y + p.z * p.z * p.z - 1; }
            geolab::Box bounds() const override { return {dvec3(-2), dvec3(2)}; }
        } f;
        for (dvec3 p : {dvec3(0.3, -0.2, 0.5), dvec3(1, 1, 1), dvec3(-0.7, 0.1, -0.4)}) {
            dvec3 g = f.gradient(p), expect(2 * p.x, 4 * p.y, 3 * p.z * p.z);
            INFO("at " << str(p) << ": got " << str(g) << ", expected " << str(expect));
            CHECK(glm::length(g - expect) < 1e-7);
        }
        CHECK(f.lipschitz() == 0.0);
    }

    // ---- implicits.hpp: analytic values ----------------------------------------------------------------------

    TEST_CASE("implicit sphere: values") {
        FieldPtr s = geolab::sphere({1, 2, 3}, 0.5);
        CHECK(s->value({1, 2, 3}) == doctest::Approx(-0.5));
        CHECK(s->value({1, 2, 4}) == doctest::Approx(0.5));
        CHECK(s->value({1.5, 2, 3}) == doctest::Approx(0.0));
        CHECK(s->lipschitz() == 1.0);
        CHECK(s->bounds().lo == dvec3(0.5, 1.5, 2.5));
        CHECK(glm::length(s->gradient({1, 2, 3})) == doctest::Approx(1.0));  // centre: some unit vector
    }

    TEST_CASE("implicit torus: values") {
        FieldPtr t = geolab::torus({0, 0, 0}, 1.0, 0.25);
        CHECK(t->value({1, 0, 0}) == doctest::Approx(-0.25));  // on the core circle
        CHECK(t->value({0, -1, 0}) == doctest::Approx(-0.25));
        CHECK(t->value({0, 0, 0}) == doctest::Approx(0.75));  // the hole's centre
        CHECK(t->value({0, 0, 1}) == doctest::Approx(std::sqrt(2.0) - 0.25));
        CHECK(t->value({1.25, 0, 0}) == doctest::Approx(0.0));
        CHECK(t->value({1, 0, 0.25}) == doctest::Approx(0.0));
        CHECK(t->bounds().hi == dvec3(1.25, 1.25, 0.25));
    }

    TEST_CASE("implicit box: exact distance, sharp and rounded") {
        FieldPtr b = geolab::box({0, 0, 0}, {1, 2, 3});
        CHECK(b->value({0, 0, 0}) == doctest::Approx(-1.0));
        CHECK(b->value({0.5, 0, 0}) == doctest::Approx(-0.5));
        CHECK(b->value({2, 0, 0}) == doctest::Approx(1.0));
        CHECK(b->value({2, 3, 0}) == doctest::Approx(std::sqrt(2.0)));  // off an edge
        CHECK(b->value({2, 3, 4}) == doctest::Approx(std::sqrt(3.0)));  // off a corner
        CHECK(b->value({-1, 2, -3}) == doctest::Approx(0.0));
        FieldPtr r = geolab::box({0, 0, 0}, dvec3(1), 0.25);
        CHECK(r->value({1, 0, 0}) == doctest::Approx(0.0));  // face centres stay
        CHECK(r->value({0, 0, 0}) == doctest::Approx(-1.0));
        dvec3 corner_dir = glm::normalize(dvec3(1));
        CHECK(r->value(dvec3(0.75) + 0.25 * corner_dir) == doctest::Approx(0.0));  // rounded corner
        CHECK(r->value(dvec3(1)) == doctest::Approx(std::sqrt(3.0) * 0.25 - 0.25));
    }

    TEST_CASE("implicit cylinder and halfspace: values") {
        FieldPtr c = geolab::cylinder({0, 0, 0}, {0, 0, 2}, 0.5, 1.0);
        CHECK(c->value({0, 0, 0}) == doctest::Approx(-0.5));
        CHECK(c->value({0, 0, 0.9}) == doctest::Approx(-0.1));
        CHECK(c->value({1, 0, 0}) == doctest::Approx(0.5));
        CHECK(c->value({0, 0, -3}) == doctest::Approx(2.0));
        CHECK(c->value({0, 1.5, 2}) == doctest::Approx(std::sqrt(2.0)));
        FieldPtr cx = geolab::cylinder({0, 0, 0}, {1, 0, 0}, 0.5, 1.0);
        CHECK(cx->value({0.9, 0, 0}) == doctest::Approx(-0.1));
        CHECK(cx->bounds().hi.x == doctest::Approx(1.0));
        CHECK(cx->bounds().hi.y == doctest::Approx(0.5));
        FieldPtr h = geolab::halfspace({0, 0, 1}, {0, 0, 3});
        CHECK(h->value({5, 5, 0}) == doctest::Approx(-1.0));
        CHECK(h->value({5, 5, 3}) == doctest::Approx(2.0));
        CHECK(h->gradient({1, 2, 3}) == dvec3(0, 0, 1));
    }

    TEST_CASE("implicit primitives: invalid parameters throw") {
        CHECK_THROWS_AS(geolab::sphere({0, 0, 0}, 0.0), std::invalid_argument);
        CHECK_THROWS_AS(geolab::torus({0, 0, 0}, 0.3, 0.5), std::invalid_argument);
        CHECK_THROWS_AS(geolab::box({0, 0, 0}, {1, 0, 1}), std::invalid_argument);
        CHECK_THROWS_AS(geolab::box({0, 0, 0}, {1, 1, 1}, 1.5), std::invalid_argument);
        CHECK_THROWS_AS(geolab::cylinder({0, 0, 0}, {0, 0, 0}, 1, 1), std::invalid_argument);
        CHECK_THROWS_AS(geolab::halfspace({0, 0, 0}, {0, 0, 0}), std::invalid_argument);
        CHECK_THROWS_AS(geolab::csg_union(nullptr, geolab::sphere({0, 0, 0}, 1)), std::invalid_argument);
        CHECK_THROWS_AS(geolab::smooth_union(geolab::sphere({0, 0, 0}, 1), geolab::sphere({1, 0, 0}, 1), 0.0),
                        std::invalid_argument);
        CHECK_THROWS_AS(geolab::scaled(geolab::sphere({0, 0, 0}, 1), -1.0), std::invalid_argument);
    }

    TEST_CASE("implicit primitives: exact distance (p − f ∇f lands on the surface, |∇f| = 1)") {
        std::mt19937 rng(7);
        std::vector<std::pair<std::string, FieldPtr>> prims = {
            {"sphere", geolab::sphere({0.1, 0.2, 0.3}, 0.7)},
            {"torus", geolab::torus({0, 0, 0.1}, 0.6, 0.2)},
            {"box", geolab::box({0, 0, 0}, {0.5, 0.3, 0.2})},
            {"rounded box", geolab::box({0, 0, 0}, {0.5, 0.3, 0.2}, 0.1)},
            {"cylinder", geolab::cylinder({0, 0, 0}, {1, 1, 0}, 0.3, 0.5)},
        };
        for (const auto& [name, f] : prims) {
            geolab::Box region = grown(f->bounds(), 2.0);
            int bad = 0;
            std::string first;
            for (int i = 0; i < 500; ++i) {
                dvec3 p = random_in(rng, region);
                dvec3 g = f->gradient(p);
                dvec3 foot = p - f->value(p) * g;
                if (std::abs(glm::length(g) - 1) > 1e-12 || std::abs(f->value(foot)) > 1e-9) {
                    if (bad++ == 0) first = str(p) + " f=" + std::to_string(f->value(foot)) + " at the foot";
                }
            }
            INFO(name << ": first failure at " << first);
            CHECK(bad == 0);
        }
    }

    // ---- implicits.hpp: gradients, Lipschitz, bounds, registry -----------------------------------------------

    TEST_CASE("implicits: analytic gradients match central differences") {
        std::mt19937 rng(11);
        for (const auto& [name, f] : all_fields()) {
            geolab::Box region = grown(f->bounds(), 1.5);
            if (!std::isfinite(region.diagonal())) continue;
            int bad = 0;
            std::string first;
            for (int i = 0; i < 400; ++i) {
                dvec3 p = random_in(rng, region);
                dvec3 g = f->gradient(p), fd = central_difference(*f, p, 1e-7);
                // skip stencils that straddle a kink (min/max switch or medial set): there fd depends on h
                if (glm::length(fd - central_difference(*f, p, 1e-6)) > 1e-6) continue;
                if (glm::length(g - fd) > 1e-5 && bad++ == 0)
                    first = "at " + str(p) + ": analytic " + str(g) + ", finite differences " + str(fd);
            }
            INFO(name << ": " << bad << " mismatches; first " << first);
            CHECK(bad == 0);
        }
    }

    TEST_CASE("implicits: Lipschitz bound holds on random pairs") {
        std::mt19937 rng(13);
        for (const auto& [name, f] : all_fields()) {
            double L = f->lipschitz();
            REQUIRE_MESSAGE(L > 0.0, name << " reports no Lipschitz constant");
            geolab::Box region = grown(f->bounds(), 2.0);
            if (!std::isfinite(region.diagonal())) continue;
            double worst = 0;
            for (int i = 0; i < 2000; ++i) {
                dvec3 p = random_in(rng, region),
                      q = i % 2 ? random_in(rng, region) : p + 1e-3 * random_in(rng, region);
                double ratio = std::abs(f->value(p) - f->value(q)) / glm::length(p - q);
                worst = std::max(worst, ratio);
            }
            INFO(name << ": worst |f(p) − f(q)| / |p − q| = " << worst << ", L = " << L);
            CHECK(worst <= L * (1 + 1e-9));
        }
    }

    TEST_CASE("implicits: bounds contain the surface (f > 0 on a shell just outside bounds)") {
        std::mt19937 rng(17);
        for (const auto& [name, f] : all_fields()) {
            geolab::Box b = f->bounds();
            if (!std::isfinite(b.diagonal())) continue;
            geolab::Box shell = grown(b, 1.02);
            int bad = 0;
            for (int i = 0; i < 3000; ++i) {
                dvec3 p = random_in(rng, shell);
                int axis = i % 3;
                p[axis] = (i / 3) % 2 ? shell.hi[axis] : shell.lo[axis];  // on a face of the shell
                if (f->value(p) <= 0) ++bad;
            }
            INFO(name << ": " << bad << " shell points with f ≤ 0");
            CHECK(bad == 0);
        }
    }

    TEST_CASE("implicits: CSG sign tables") {
        // A = sphere at −0.5, B = sphere at +0.5 (radius 0.7): sample points in A only, B only, both, neither
        FieldPtr A = geolab::sphere({-0.5, 0, 0}, 0.7), B = geolab::sphere({0.5, 0, 0}, 0.7);
        struct Row {
            const char* where;
            dvec3 p;
            bool in_a, in_b;
        };
        const Row rows[] = {{"A only", {-1, 0, 0}, true, false},
                            {"B only", {1, 0, 0}, false, true},
                            {"both", {0, 0, 0}, true, true},
                            {"neither", {0, 2, 0}, false, false}};
        FieldPtr U = geolab::csg_union(A, B), I = geolab::csg_intersection(A, B), D = geolab::csg_difference(A, B);
        FieldPtr S = geolab::smooth_union(A, B, 0.1);
        for (const Row& r : rows) {
            INFO(r.where << " at " << str(r.p));
            REQUIRE((A->value(r.p) < 0) == r.in_a);
            REQUIRE((B->value(r.p) < 0) == r.in_b);
            CHECK((U->value(r.p) < 0) == (r.in_a || r.in_b));
            CHECK((I->value(r.p) < 0) == (r.in_a && r.in_b));
            CHECK((D->value(r.p) < 0) == (r.in_a && !r.in_b));
            CHECK((S->value(r.p) < 0) == (r.in_a || r.in_b));
        }
        // the values themselves
        dvec3 p(0.2, 0.3, -0.1);
        double a = A->value(p), b = B->value(p);
        CHECK(U->value(p) == std::min(a, b));
        CHECK(I->value(p) == std::max(a, b));
        CHECK(D->value(p) == std::max(a, -b));
    }

    TEST_CASE("implicits: smooth union is min away from the blend and within k/4 below it") {
        std::mt19937 rng(19);
        const double k = 0.3;
        FieldPtr A = geolab::sphere({-0.4, 0, 0}, 0.5), B = geolab::box({0.4, 0, 0}, dvec3(0.4));
        FieldPtr S = geolab::smooth_union(A, B, k);
        for (int i = 0; i < 2000; ++i) {
            dvec3 p = random_in(rng, {dvec3(-1.5), dvec3(1.5)});
            double a = A->value(p), b = B->value(p), m = std::min(a, b), s = S->value(p);
            INFO("at " << str(p) << ": a=" << a << " b=" << b << " smin=" << s);
            CHECK(s <= m + 1e-15);
            CHECK(s >= m - k / 4 - 1e-15);
            if (std::abs(a - b) >= k) CHECK(s == doctest::Approx(m).epsilon(1e-14));
        }
    }

    TEST_CASE("implicits: translated and scaled") {
        FieldPtr t = geolab::translated(geolab::sphere({0, 0, 0}, 1), {2, 0, 0});
        CHECK(t->value({2, 0, 0}) == doctest::Approx(-1));
        CHECK(t->bounds().lo == dvec3(1, -1, -1));
        FieldPtr s = geolab::scaled(geolab::box({0, 0, 0}, dvec3(1)), 3.0);
        CHECK(s->value({0, 0, 0}) == doctest::Approx(-3));  // still a distance
        CHECK(s->value({4, 0, 0}) == doctest::Approx(1));
        CHECK(s->bounds().hi == dvec3(3));
        CHECK(s->lipschitz() == 1.0);
    }

    TEST_CASE("implicits: registry names, shapes contain the origin's expected side, unknown name throws") {
        auto names = geolab::implicit_names();
        for (const char* must : {"sphere", "torus", "box", "cube", "csg", "blob"})
            CHECK_MESSAGE(std::find(names.begin(), names.end(), must) != names.end(), "missing " << must);
        for (const auto& n : names) {
            FieldPtr f = geolab::named_implicit(n);
            REQUIRE(f);
            geolab::Box b = f->bounds();
            INFO(n);
            CHECK(b.lo.x >= -1.0);
            CHECK(b.hi.x <= 1.0);
            bool hollow_at_origin = n == "torus" || n == "box_minus_sphere" || n == "csg";
            CHECK((f->value({0, 0, 0}) > 0) == hollow_at_origin);
        }
        try {
            geolab::named_implicit("teapot-of-doom");
            FAIL("no exception");
        } catch (const std::invalid_argument& e) {
            std::string what = e.what();
            CHECK(what.find("teapot-of-doom") != std::string::npos);
            for (const auto& n : names) CHECK_MESSAGE(what.find(n) != std::string::npos, what);
        }
    }

    // ---- mesh_field.hpp: building blocks ---------------------------------------------------------------------

    TEST_CASE("closest_point_on_triangle: every Voronoi region and degenerate triangles") {
        dvec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
        CHECK(geolab::closest_point_on_triangle({-1, -1, 1}, a, b, c) == a);
        CHECK(geolab::closest_point_on_triangle({2, -0.5, 0}, a, b, c) == b);
        CHECK(geolab::closest_point_on_triangle({-0.1, 3, 0}, a, b, c) == c);
        CHECK(geolab::closest_point_on_triangle({0.5, -1, 2}, a, b, c) == dvec3(0.5, 0, 0));
        CHECK(geolab::closest_point_on_triangle({-1, 0.25, 0}, a, b, c) == dvec3(0, 0.25, 0));
        dvec3 q = geolab::closest_point_on_triangle({1, 1, 5}, a, b, c);
        CHECK(glm::length(q - dvec3(0.5, 0.5, 0)) < 1e-15);
        CHECK(glm::length(geolab::closest_point_on_triangle({0.2, 0.3, -4}, a, b, c) - dvec3(0.2, 0.3, 0)) < 1e-15);
        // degenerate: collinear and a point triangle
        q = geolab::closest_point_on_triangle({0.5, 1, 0}, a, b, dvec3(2, 0, 0));
        CHECK(glm::length(q - dvec3(0.5, 0, 0)) < 1e-15);
        CHECK(geolab::closest_point_on_triangle({3, 3, 3}, a, a, a) == a);
        // random points: nothing on the triangle is closer (sampled)
        std::mt19937 rng(3);
        std::uniform_real_distribution<double> u(-2, 2), w(0, 1);
        for (int i = 0; i < 200; ++i) {
            dvec3 p(u(rng), u(rng), u(rng)), A(u(rng), u(rng), u(rng)), B(u(rng), u(rng), u(rng)),
                C(u(rng), u(rng), u(rng));
            double d = glm::length(geolab::closest_point_on_triangle(p, A, B, C) - p);
            for (int s = 0; s < 50; ++s) {
                double x = w(rng), y = w(rng);
                if (x + y > 1) x = 1 - x, y = 1 - y;
                CHECK(d <= glm::length(A + x * (B - A) + y * (C - A) - p) + 1e-12);
            }
        }
    }

    TEST_CASE("triangle_solid_angle: octant, sign, sum over a closed mesh") {
        dvec3 a(1, 0, 0), b(0, 1, 0), c(0, 0, 1);
        CHECK(geolab::triangle_solid_angle({0, 0, 0}, a, b, c) == doctest::Approx(std::numbers::pi / 2));
        CHECK(geolab::triangle_solid_angle({0, 0, 0}, a, c, b) == doctest::Approx(-std::numbers::pi / 2));
        CHECK(geolab::triangle_solid_angle({5, 5, 0}, a, b, dvec3(2, 2, 0)) == 0.0);  // in the plane, outside
        auto cube = geolab::fixtures::cube(true);
        for (dvec3 p : {dvec3(0, 0, 0), dvec3(0.9, -0.5, 0.3), dvec3(3, 0, 0)}) {
            double sum = 0;
            for (std::size_t f = 0; f < cube.n_faces(); ++f) {
                auto vs = cube.face(f);
                sum += geolab::triangle_solid_angle(p, cube.positions[vs[0]], cube.positions[vs[1]],
                                                    cube.positions[vs[2]]);
            }
            bool inside = std::abs(p.x) < 1 && std::abs(p.y) < 1 && std::abs(p.z) < 1;
            INFO("at " << str(p));
            CHECK(sum == doctest::Approx(inside ? 4 * std::numbers::pi : 0.0));
        }
    }

    // ---- mesh_field.hpp: MeshField ---------------------------------------------------------------------------

    TEST_CASE("MeshField: invalid soups throw") {
        CHECK_THROWS_AS(geolab::MeshField(geolab::PolygonSoup{}), std::invalid_argument);
        geolab::PolygonSoup bad = geolab::fixtures::tetrahedron();
        bad.add_face({0, 1, 9});
        CHECK_THROWS_AS(geolab::MeshField{bad}, std::invalid_argument);
    }

    TEST_CASE("MeshField: cube of quads (fan triangulation), values, gradient, bounds") {
        geolab::MeshField f(geolab::fixtures::cube(false));
        CHECK(f.n_triangles() == 12);
        CHECK(f.value({0, 0, 0}) == doctest::Approx(-1));
        CHECK(f.value({0.5, 0.2, -0.9}) == doctest::Approx(-0.1));
        CHECK(f.value({2, 0, 0}) == doctest::Approx(1));
        CHECK(f.value({2, 2, 0}) == doctest::Approx(std::sqrt(2.0)));
        CHECK(f.value({2, 2, 2}) == doctest::Approx(std::sqrt(3.0)));
        CHECK(glm::length(f.gradient({0.5, 0.2, -0.9}) - dvec3(0, 0, -1)) < 1e-12);
        CHECK(glm::length(f.gradient({2, 2, 0}) - glm::normalize(dvec3(1, 1, 0))) < 1e-12);
        CHECK(glm::length(f.gradient({1, 0.3, 0.2}) - dvec3(1, 0, 0)) < 1e-12);  // on the surface: the normal
        CHECK(f.bounds().hi == dvec3(1.05));
        CHECK(f.lipschitz() == 1.0);
        dvec3 q;
        CHECK(f.unsigned_distance({0.5, 3, 0.5}, &q) == doctest::Approx(2));
        CHECK(glm::length(q - dvec3(0.5, 1, 0.5)) < 1e-12);
    }

    TEST_CASE("MeshField: icosphere(4) ≈ |p| − 1, winding number 1 inside / 0 outside") {
        auto soup = geolab::fixtures::icosphere(4);
        geolab::MeshField f(soup);
        double e = longest_edge(soup);
        double tol = e * e / 4;  // > the sagitta e²/8 of a chord, the largest gap between mesh and sphere
        std::mt19937 rng(23);
        for (int i = 0; i < 500; ++i) {
            dvec3 p = random_in(rng, {dvec3(-2), dvec3(2)});
            double expect = glm::length(p) - 1, got = f.value(p);
            INFO("at " << str(p) << ": MeshField " << got << ", |p| − 1 = " << expect << ", tol " << tol);
            CHECK(std::abs(got - expect) < tol);
            if (std::abs(expect) > 2 * tol) {
                CHECK(std::abs(f.winding_number(p) - (expect < 0 ? 1.0 : 0.0)) < 0.1);
                CHECK(glm::length(f.gradient(p) - glm::normalize(p)) < 0.1);
            }
        }
    }

    TEST_CASE("MeshField: fast winding number matches the exact sum") {
        for (auto soup :
             {geolab::fixtures::icosphere(4), geolab::fixtures::torus(48, 24), geolab::fixtures::grid(20, 20)}) {
            geolab::MeshField f(soup);
            std::mt19937 rng(29);
            double worst = 0, mean = 0;
            const int n = 300;
            for (int i = 0; i < n; ++i) {
                dvec3 p = random_in(rng, grown(f.bounds(), 1.5));
                double err = std::abs(f.winding_number(p) - f.winding_number_exact(p));
                worst = std::max(worst, err);
                mean += err / n;
            }
            INFO(f.n_triangles() << " triangles: |fast − exact| worst " << worst << ", mean " << mean);
            CHECK(worst < 0.1);
            CHECK(mean < 0.02);
        }
    }

    TEST_CASE("MeshField: sign stays right far from a hole") {
        auto full = geolab::fixtures::icosphere(3);
        const std::size_t removed = 17;
        auto soup = without_face(full, removed);
        auto vs = full.face(removed);
        dvec3 hole = (full.positions[vs[0]] + full.positions[vs[1]] + full.positions[vs[2]]) / 3.0;
        geolab::MeshField f(soup);
        std::mt19937 rng(31);
        int checked = 0;
        for (int i = 0; i < 1000; ++i) {
            dvec3 p = random_in(rng, {dvec3(-1.5), dvec3(1.5)});
            double r = glm::length(p);
            if (glm::length(p - hole) < 0.5 || std::abs(r - 1) < 0.05) continue;
            ++checked;
            INFO("at " << str(p) << ", winding number " << f.winding_number(p));
            CHECK((f.value(p) < 0) == (r < 1));
        }
        CHECK(checked > 500);
        // the winding number of an open sphere is fractional only near the hole
        CHECK(std::abs(f.winding_number({0, 0, 0}) - 1.0) < 0.1);
    }

    TEST_CASE("MeshField: sign_may_jump tells open or misoriented meshes from closed ones; CSG passes it on") {
        const auto closed = geolab::fixtures::icosphere(2);
        CHECK_FALSE(geolab::MeshField(closed).sign_may_jump());
        CHECK_FALSE(geolab::MeshField(geolab::fixtures::cube(false)).sign_may_jump());   // quads
        CHECK_FALSE(geolab::MeshField(geolab::fixtures::torus()).sign_may_jump());
        CHECK_FALSE(geolab::MeshField(geolab::fixtures::two_components()).sign_may_jump());
        CHECK(geolab::MeshField(without_face(closed, 5)).sign_may_jump());                // a hole
        CHECK(geolab::MeshField(geolab::fixtures::grid(3, 3)).sign_may_jump());           // a sheet
        CHECK(geolab::MeshField(geolab::fixtures::flip_face(closed, 7)).sign_may_jump()); // misoriented face
        // inward-oriented: the boundary still cancels
        CHECK_FALSE(geolab::MeshField(flipped_all(closed)).sign_may_jump());
        // unwelded (every face has its own copies of its vertices, as read from STL): matched by position
        geolab::PolygonSoup unwelded;
        for (std::size_t f = 0; f < closed.n_faces(); ++f) {
            const auto vs = closed.face(f);
            const auto first = static_cast<std::uint32_t>(unwelded.positions.size());
            for (std::uint32_t v : vs) unwelded.positions.push_back(closed.positions[v]);
            unwelded.add_face({first, first + 1, first + 2});
        }
        CHECK_FALSE(geolab::MeshField(unwelded).sign_may_jump());
        // fields built from others keep the flag; analytic ones have none
        const FieldPtr open = std::make_shared<geolab::MeshField>(without_face(closed, 5));
        const FieldPtr ball = geolab::sphere(dvec3(0.0), 0.5);
        CHECK_FALSE(ball->sign_may_jump());
        CHECK(geolab::csg_union(ball, open)->sign_may_jump());
        CHECK(geolab::translated(open, dvec3(1, 0, 0))->sign_may_jump());
        CHECK_FALSE(geolab::scaled(ball, 2.0)->sign_may_jump());
    }

    TEST_CASE("MeshField: BVH distance equals brute force") {
        std::vector<geolab::PolygonSoup> soups = {geolab::fixtures::icosphere(3), geolab::fixtures::torus(),
                                                  geolab::fixtures::grid(7, 5), geolab::fixtures::cube(false)};
        // a random triangle soup: overlapping, intersecting, some slivers
        geolab::PolygonSoup random_soup;
        std::mt19937 rng(37);
        std::uniform_real_distribution<double> u(-1, 1), s(-0.2, 0.2);
        for (std::uint32_t t = 0; t < 300; ++t) {
            dvec3 c(u(rng), u(rng), u(rng));
            for (int k = 0; k < 3; ++k) random_soup.positions.push_back(c + dvec3(s(rng), s(rng), s(rng)));
            random_soup.add_face({3 * t, 3 * t + 1, 3 * t + 2});
        }
        soups.push_back(random_soup);
        for (const auto& soup : soups) {
            geolab::MeshField f(soup);
            for (int i = 0; i < 300; ++i) {
                dvec3 p = random_in(rng, grown(f.bounds(), 2.0));
                double bvh = f.unsigned_distance(p), brute = brute_force_distance(soup, p);
                INFO(soup.n_faces() << " faces, at " << str(p) << ": BVH " << bvh << ", brute force " << brute);
                CHECK(std::abs(bvh - brute) <= 1e-12 * std::max(brute, 1e-300));
                CHECK(std::abs(f.value(p)) == bvh);
            }
        }
    }

    TEST_CASE("MeshField: real models — inside negative, outside positive, distance exact" * doctest::timeout(60)) {
        for (const char* name : {"bunny00", "head", "lion", "ChineseDragon-10kv"}) {
            auto path = geolab::model_path(name);
            if (!path) {
                MESSAGE("model " << name << " not fetched (run tools/fetch_models.sh); skipped");
                continue;
            }
            geolab::PolygonSoup soup;
            try {
                soup = geolab::read_mesh(*path);
            } catch (const std::exception& e) {
                MESSAGE("could not read " << name << " (" << e.what() << "); skipped");
                continue;
            }
            geolab::MeshField f(soup);
            double diag = f.bounds().diagonal();
            INFO(name << ": " << f.n_triangles() << " triangles");
            // far points are outside
            for (dvec3 dir : {dvec3(1, 0, 0), dvec3(0, -1, 0), dvec3(0.3, 0.4, 1)})
                CHECK(f.value(f.bounds().center() + diag * glm::normalize(dir)) > 0);
            // the orientation (the CGAL head is inward-oriented): the sign of the enclosed volume
            double volume = 0;
            for (std::size_t fi = 0; fi < soup.n_faces(); ++fi) {
                auto vs = soup.face(fi);
                for (std::size_t i = 1; i + 1 < vs.size(); ++i)
                    volume +=
                        glm::dot(soup.positions[vs[0]], glm::cross(soup.positions[vs[i]], soup.positions[vs[i + 1]]));
            }
            const double outward = volume < 0 ? -1.0 : 1.0;
            // just behind / in front of random faces: inside / outside (holes and thin parts excepted: allow 2%)
            std::mt19937 rng(41);
            std::uniform_int_distribution<std::size_t> pick(0, soup.n_faces() - 1);
            int wrong = 0, tested = 0;
            for (int i = 0; i < 200; ++i) {
                auto vs = soup.face(pick(rng));
                dvec3 a = soup.positions[vs[0]], b = soup.positions[vs[1]], c = soup.positions[vs[2]];
                dvec3 n = glm::cross(b - a, c - a);
                if (glm::length(n) == 0) continue;
                n = outward * glm::normalize(n);
                dvec3 centroid = (a + b + c) / 3.0;
                double eps = 1e-3 * diag;
                ++tested;
                if (!(f.value(centroid - eps * n) < 0) || !(f.value(centroid + eps * n) > 0)) ++wrong;
            }
            CHECK_MESSAGE(wrong <= tested / 50, wrong << " of " << tested << " face-offset points have the wrong sign");
            // distance equals brute force on a few points
            for (int i = 0; i < 5; ++i) {
                dvec3 p = random_in(rng, f.bounds());
                double brute = brute_force_distance(soup, p);
                CHECK(std::abs(f.unsigned_distance(p) - brute) <= 1e-12 * brute);
            }
        }
    }

}  // TEST_SUITE
