// Lab 07 hidden tests: run by the grader, left out of the student release. Same tasks (suites), same independent
// references (helpers.hpp), other inputs.
#include "../helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab07;

TEST_SUITE("Task 1: primitives") {
    TEST_CASE("primitive hidden: thin and large shapes; far points" * geolab::points(3) * geolab::hidden() *
              geolab::hint("Nothing is rounded to a fixed tolerance: sizes from 1e-3 to 1e3 behave alike.")) {
        Rng rng(101);
        for (double s : {1e-3, 1.0, 1e3}) {
            for (Shape sh : {Shape::box, Shape::cylinder, Shape::cone, Shape::torus, Shape::sphere}) {
                Node d;
                d.shape = sh;
                d.size = sh == Shape::torus ? glm::dvec3(s, 0.1 * s, 0) : sh == Shape::cone ? glm::dvec3(0.05 * s, s, 2 * s)
                                                                                           : glm::dvec3(s, 0.05 * s, 2 * s);
                for (int n = 0; n < 60; ++n) {
                    const glm::dvec3 p = rng.point(5 * s);
                    const double want = double(ref_distance(d, p)), got = primitive_distance(d, p);
                    INFO(str(d) << " at " << str(p) << ": expected " << want << ", got " << got);
                    CHECK(std::abs(got - want) <= 1e-9 * s);
                }
            }
        }
    }
}

TEST_SUITE("Task 2: signed distances") {
    TEST_CASE("sdf hidden: nested trees under rotations agree with min/max of the leaves" * geolab::points(3) *
              geolab::builds_on("Task 1") *
              geolab::hidden() * geolab::hint("Recurse over the tree; each leaf in its own coordinates.")) {
        Rng rng(102);
        for (int n = 0; n < 20; ++n) {
            const glm::dmat4 M1 = rigid(rng), M2 = rigid(rng), M3 = rigid(rng);
            const Tree a = leaf(Shape::torus, {0.7, 0.2, 0}, M1), b = leaf(Shape::box, {0.4, 0.5, 0.3}, M2),
                       c = leaf(Shape::cone, {0.5, 0.1, 0.6}, M3);
            const Tree t = op(Op::subtract, op(Op::unite, a, b), c);
            for (int k = 0; k < 20; ++k) {
                const glm::dvec3 x = rng.point(2);
                const double da = double(ref_distance(a.nodes[0], to_local(M1, x)));
                const double db = double(ref_distance(b.nodes[0], to_local(M2, x)));
                const double dc = double(ref_distance(c.nodes[0], to_local(M3, x)));
                const double want = std::max(std::min(da, db), -dc);
                const double got = sdf(t, x);
                INFO("(torus ∪ box) − cone, random rigid motions, at " << str(x) << ": expected " << want << ", got " << got);
                CHECK(std::abs(got - want) <= 1e-9);
            }
        }
        Tree bad = leaf(Shape::sphere, {1, 0, 0});
        bad.root = 3;
        CHECK_THROWS_AS(sdf(bad, glm::dvec3(0)), std::invalid_argument);
    }
}

TEST_SUITE("Task 3: point membership") {
    TEST_CASE("classify hidden: random trees of moved primitives against the definition" * geolab::points(3) *
              geolab::builds_on("Task 1") *
              geolab::hidden() * geolab::hint("Points far from every surface are in or out exactly as the set says.")) {
        Rng rng(103);
        for (int n = 0; n < 15; ++n) {
            const Tree a = leaf(Shape::cylinder, {0.4, 0.4, 0.8}, rigid(rng, 0.5));
            const Tree b = leaf(Shape::sphere, {0.7, 0, 0}, rigid(rng, 0.5));
            const Tree c = leaf(Shape::box, {0.5, 0.6, 0.4}, rigid(rng, 0.5));
            const Tree t = op(Op::intersect, op(Op::unite, a, c), op(Op::subtract, c, b));
            for (int k = 0; k < 40; ++k) {
                const glm::dvec3 x = rng.point(1.5);
                const Membership m = classify(t, x, 1e-9);
                INFO("random tree " << n << " at " << str(x) << ": got " << str(m));
                CHECK(m != Membership::on);
                CHECK((m == Membership::in) == ref_inside(t, x));
            }
        }
    }
}

TEST_SUITE("Task 4: spans in a primitive") {
    TEST_CASE("spans hidden: random rays through every primitive; far origins; short and long directions" *
              geolab::points(3) * geolab::hidden() *
              geolab::hint("t is in the direction's units; a far origin must not lose the roots (stable quadratic).")) {
        Rng rng(104);
        std::vector<Node> shapes;
        for (Shape s : {Shape::sphere, Shape::box, Shape::cylinder, Shape::cone, Shape::torus}) {
            Node d;
            d.shape = s;
            d.size = s == Shape::torus ? glm::dvec3(0.9, 0.35, 0) : s == Shape::cone ? glm::dvec3(0.2, 0.8, 0.7)
                                                                                      : glm::dvec3(0.8, 0.6, 0.5);
            shapes.push_back(d);
        }
        for (const Node& d : shapes)
            for (int n = 0; n < 40; ++n) {
                const glm::dvec3 dir = rng.unit();
                const double far = n % 2 ? 1e3 : 3;
                const double len = n % 3 == 0 ? 1e-2 : n % 3 == 1 ? 1.0 : 50.0;
                const Ray r{-far * dir + 0.6 * rng.point(1), dir * len};
                const auto got = spans_of(d, r);
                const double c = far / len;
                const std::string e = check_spans(got, [&](double t) { return ref_implicit(d, r.origin + t * r.direction) <= 0; },
                                                  c - 3 / len, c + 3 / len, 1e-6 / len + 1e-9 * c);
                INFO(str(d) << ", " << str(r) << ": " << e);
                CHECK(e.empty());
            }
    }
}

TEST_SUITE("Task 5: combining interval lists") {
    TEST_CASE("ray_spans hidden: random trees along random rays against the definition" * geolab::points(3) *
              geolab::builds_on("Task 4") *
              geolab::hidden() * geolab::hint("Combine the children's lists at every inner node.")) {
        Rng rng(105);
        SpanLists lists;  // reused by every ray of every tree
        for (int n = 0; n < 25; ++n) {
            const Tree a = leaf(Shape::torus, {0.7, 0.25, 0}, rigid(rng, 0.4));
            const Tree b = leaf(Shape::box, {0.5, 0.4, 0.6}, rigid(rng, 0.4) * scale({1.5, 0.7, 1}));
            const Tree c = leaf(Shape::cone, {0.6, 0.0, 0.8}, rigid(rng, 0.4));
            const Tree t = op(Op::subtract, op(Op::unite, a, b), op(Op::intersect, c, b));
            const PreparedTree p = prepare(t);
            for (int k = 0; k < 10; ++k) {
                const Ray r{rng.point(3), rng.unit()};
                const auto got = tree_spans(p, r, lists);
                const std::string e = check_spans(got, [&](double s) { return ref_inside(t, r.origin + s * r.direction); }, -8, 8, 1e-6);
                INFO("random tree " << n << ", " << str(r) << ": " << e);
                CHECK(e.empty());
            }
        }
    }
    TEST_CASE("ray_spans hidden: skipping by boxes never changes the spans (lines grazing the boxes too)" *
              geolab::points(2) *
              geolab::builds_on("Task 4") * geolab::hidden() *
              geolab::hint("A node's box holds its whole solid: a line that misses it has no span there. Skip only "
                           "on line_meets_box, and for ∩ and − only after an empty A.")) {
        Rng rng(107);
        SpanLists pruned, full;
        for (int n = 0; n < 20; ++n) {
            const Tree a = leaf(Shape::box, {0.5, 0.3, 0.4}, rigid(rng, 0.8));
            const Tree b = leaf(Shape::cylinder, {0.3, 0.3, 0.6}, rigid(rng, 0.8) * scale({1, 1.5, 1}));
            const Tree c = leaf(Shape::sphere, {0.45, 0, 0}, rigid(rng, 0.8));
            const Tree d = leaf(Shape::cone, {0.4, 0.1, 0.5}, rigid(rng, 0.8));
            const Tree t = op(Op::unite, op(Op::subtract, op(Op::unite, a, b), c), op(Op::intersect, d, c));
            const PreparedTree p = prepare(t);
            PreparedTree unbounded = p;  // every box all of space: nothing is skipped
            for (PreparedNode& q : unbounded.nodes) {
                q.lo = glm::dvec3(-inf);
                q.hi = glm::dvec3(inf);
            }
            for (int k = 0; k < 40; ++k) {
                // half the lines aimed at a corner of some node's box, where skipping is closest to wrong
                const PreparedNode& q = p.nodes[std::size_t(k) % p.nodes.size()];
                const glm::dvec3 corner((k & 1) ? q.lo.x : q.hi.x, (k & 2) ? q.lo.y : q.hi.y, (k & 4) ? q.lo.z : q.hi.z);
                const glm::dvec3 dir = rng.unit();
                const Ray r = k % 2 ? Ray{corner - 3.0 * dir, dir} : Ray{rng.point(2), dir};
                const auto got = tree_spans(p, r, pruned), want = tree_spans(unbounded, r, full);
                bool same = got.size() == want.size();
                for (std::size_t i = 0; same && i < got.size(); ++i)
                    same = got[i].t0 == want[i].t0 && got[i].t1 == want[i].t1 && got[i].n0 == want[i].n0 && got[i].n1 == want[i].n1;
                INFO("random tree " << n << ", " << str(r) << ": with the prepared boxes " << str(got)
                                    << ", with every box infinite " << str(want));
                CHECK(same);
            }
        }
    }

    TEST_CASE("combine hidden: unbounded spans and coincident ends" * geolab::points(2) * geolab::hidden() *
              geolab::hint("±inf are ordinary ends; equal ends in A and B are applied together.")) {
        const glm::dvec3 z(0, 0, 1);
        const std::vector<Span> all{{-inf, inf, glm::dvec3(0), glm::dvec3(0)}}, a{{1, 2, -z, z}}, b{{-inf, 1, glm::dvec3(0), z}};
        auto d = combined(Op::subtract, all, a);
        REQUIRE_MESSAGE(d.size() == 2, "ℝ − [1, 2]: (−inf, 1] and [2, inf), got " << str(d));
        CHECK(d[0].t0 == -inf);
        CHECK(d[1].t1 == inf);
        CHECK_MESSAGE(glm::length(d[0].n1 - z) < 1e-15, "the end at 1 comes from B's entry normal −z, negated: +z");
        auto u = combined(Op::unite, a, b);
        REQUIRE_MESSAGE(u.size() == 1, "(−inf, 1] ∪ [1, 2] = (−inf, 2], got " << str(u));
        CHECK(u[0].t1 == 2);
        CHECK(combined(Op::intersect, a, b).empty());
        CHECK(combined(Op::subtract, a, a).empty());
    }
}

TEST_SUITE("Task 6: ray casting") {
    TEST_CASE("first_hit hidden: a box minus an equal moved box; a sphere seen from inside" * geolab::points(2) *
              geolab::builds_on("Task 4, Task 5") *
              geolab::hidden() * geolab::hint("Rays starting inside report the exit with the outward normal.")) {
        const glm::dmat4 M = rotate(33, glm::normalize(glm::dvec3(1, 2, 3))) * scale({1, 2, 0.5});
        const Tree b = leaf(Shape::box, glm::dvec3(1.0), M);
        Rng rng(106);
        const PreparedTree bb = prepare(op(Op::subtract, b, b));
        SpanLists lists;
        for (int n = 0; n < 50; ++n) {
            const Ray r{rng.point(4), rng.unit()};
            CHECK_MESSAGE(!first_hit(bb, r, -100, lists).has_value(), "a box minus itself: no hit, " << str(r));
        }
        const Tree s = leaf(Shape::sphere, {2, 0, 0}, translate({1, 1, 1}));
        for (int n = 0; n < 50; ++n) {
            const glm::dvec3 d = rng.unit();
            const auto h = first_hit(s, Ray{{1, 1, 1}, d}, 0);
            REQUIRE(h.has_value());
            CHECK(close(h->t, 2, 1e-12));
            CHECK(glm::length(h->normal - d) < 1e-12);
        }
    }
}

TEST_SUITE("Task 7: meshes and volumes") {
    TEST_CASE("mesh hidden: sphere minus a moved sphere and a torus: volumes converge" * geolab::points(2) *
              geolab::builds_on("Task 1, Task 2") *
              geolab::hidden() * geolab::hint("The mesh must be closed and outward: pad the box.")) {
        // sphere r = 1 minus a sphere r = 1 centred at distance 1: the lens removed has volume 5π/12
        const Tree t = op(Op::subtract, leaf(Shape::sphere, {1, 0, 0}), leaf(Shape::sphere, {1, 0, 0}, translate({1, 0, 0})));
        const double want = 4 * pi / 3 - 5 * pi / 12;
        const double v = volume(mesh_tree(t, 40));
        CHECK_MESSAGE(std::abs(v - want) < 0.02 * want, "sphere minus sphere: expected " << want << ", got " << v);
        const Tree tor = leaf(Shape::torus, {1, 0.3, 0}, rotate(40, {1, 0, 0}));
        const double wt = 2 * pi * pi * 1 * 0.09;
        const double vt = volume(mesh_tree(tor, 48));
        CHECK_MESSAGE(std::abs(vt - wt) < 0.03 * wt, "torus R = 1, r = 0.3: expected 2π²Rr² = " << wt << ", got " << vt);
    }
}
