// Lab 07, Tasks 1-3: primitive distances, tree SDFs, smooth minimum, point membership. Expected values: closed
// forms and the independent references of helpers.hpp.
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab07;

namespace {
// Random points around a primitive (inside, near and outside).
void check_distance_family(const Node& d, double reach, std::uint64_t seed, double tol = 1e-9) {
    Rng rng(seed);
    for (int n = 0; n < 300; ++n) {
        const glm::dvec3 p = rng.point(reach);
        const double want = double(ref_distance(d, p)), got = primitive_distance(d, p);
        INFO(str(d) << " at local point " << str(p) << ": expected distance " << want << ", got " << got);
        CHECK(std::abs(got - want) <= tol * reach);
    }
}
}  // namespace

TEST_SUITE("Task 1: primitives") {
    TEST_CASE("primitive: sphere and box distances at random points (inside; on; outside)" * geolab::points(3) *
              geolab::hint("Box: outside, the length of max(|p| − h, 0); inside, minus the distance to the nearest "
                           "face (the largest of |p|ᵢ − hᵢ). Do not return the 'max' form outside: it is only a bound "
                           "near edges and corners.")) {
        Node s;
        s.shape = Shape::sphere;
        s.size = {0.7, 0, 0};
        check_distance_family(s, 1.5, 1);
        Node b;
        b.shape = Shape::box;
        b.size = {0.5, 1.0, 0.25};
        check_distance_family(b, 2.0, 2);
        // corner region: the distance is Euclidean to the corner, not the max of the slabs
        const glm::dvec3 p(1.5, 2.0, 1.25);
        const double corner = primitive_distance(b, p);
        CHECK_MESSAGE(close(corner, std::sqrt(3.0), 1e-12),
                      "box half extents (0.5, 1, 0.25) at (1.5, 2, 1.25): the nearest point is the corner, distance "
                      "√3, got " << corner);
    }

    TEST_CASE("primitive: cylinder and truncated cones against a search over the meridian outline" * geolab::points(2) *
              geolab::hint("A solid of revolution: work in (ρ, z) = (√(x² + y²), z); the section is a rectangle "
                           "(cylinder) or a trapezoid (cone) whose axis edge is NOT a boundary. Inside, the distance "
                           "is to the nearest of the bottom, the slanted side and the top.")) {
        Node c;
        c.shape = Shape::cylinder;
        c.size = {0.6, 0, 0.9};
        check_distance_family(c, 1.6, 3);
        for (glm::dvec3 sz : {glm::dvec3(0.8, 0.3, 0.7), glm::dvec3(0.0, 0.9, 0.5), glm::dvec3(1.0, 0.0, 1.2)}) {
            Node k;
            k.shape = Shape::cone;
            k.size = sz;
            check_distance_family(k, 1.8, 4);
        }
    }

    TEST_CASE("primitive: torus; half-space and quadric" * geolab::points(2) *
              geolab::hint("Torus: |(√(x² + y²) − R, z)| − r. Half-space z ≤ 0: z. Quadric: q/|∇q| with "
                           "∇q = 2·(QX)ₓᵧ𝓏 — the full 4×4 product, so the linear terms count.")) {
        Node t;
        t.shape = Shape::torus;
        t.size = {1.0, 0.3, 0};
        check_distance_family(t, 1.6, 5);
        Node h;
        h.shape = Shape::halfspace;
        check_distance_family(h, 3.0, 6);
        // a plane as a quadric: 2·(x − 0.5) ≤ 0 i.e. Q with p = 1 (2px), d = −1: q/|∇q| = (2x − 1)/2 = x − 0.5
        Node q;
        q.shape = Shape::quadric;
        q.Q = glm::dmat4(0.0);
        q.Q[3][0] = q.Q[0][3] = 1.0;
        q.Q[3][3] = -1.0;
        Rng rng(7);
        for (int n = 0; n < 50; ++n) {
            const glm::dvec3 p = rng.point(2);
            const double got = primitive_distance(q, p);
            CHECK_MESSAGE(close(got, p.x - 0.5, 1e-12), "the quadric 2x − 1 ≤ 0 (a plane) at "
                                                            << str(p) << ": expected x − 0.5 = " << p.x - 0.5 << ", got " << got);
        }
        // the unit sphere as a quadric: q = |p|² − 1, |∇q| = 2|p|
        Node u;
        u.shape = Shape::quadric;
        u.Q = glm::dmat4(1.0);
        u.Q[3][3] = -1;
        const glm::dvec3 p(0.3, -1.2, 0.9);
        const double want = (glm::dot(p, p) - 1) / (2 * glm::length(p));
        const double got_u = primitive_distance(u, p);
        CHECK_MESSAGE(close(got_u, want, 1e-12), "unit sphere quadric at " << str(p) << ": expected " << want << ", got " << got_u);
        // the unit sphere about (1, 0, 0) as a quadric: q = (x − 1)² + y² + z² − 1 (linear terms count in ∇q)
        Node w;
        w.shape = Shape::quadric;
        w.Q = glm::dmat4(1.0);
        w.Q[3][0] = w.Q[0][3] = -1;
        w.Q[3][3] = 0;
        for (glm::dvec3 x : {glm::dvec3(2.5, 0.5, -0.3), glm::dvec3(1.3, 0, 0), glm::dvec3(0.2, 0.1, 0.4)}) {
            const glm::dvec3 c = x - glm::dvec3(1, 0, 0);
            const double q = glm::dot(c, c) - 1, want2 = q / (2 * glm::length(c));
            const double got = primitive_distance(w, x);
            CHECK_MESSAGE(close(got, want2, 1e-12), "the quadric (x − 1)² + y² + z² − 1 at "
                                                        << str(x) << ": expected q/|∇q| = " << want2 << ", got " << got);
        }
        const double centre = primitive_distance(w, {1, 0, 0});
        CHECK_MESSAGE(centre == -1.0, "at the centre ∇q = 0: return q itself (−1), got " << centre);
    }

    TEST_CASE("primitive: every shape is 1-Lipschitz; zero on its surface and negative exactly inside" *
              geolab::points(2) * geolab::hint("A signed distance never changes faster than the point moves.")) {
        Rng rng(8);
        std::vector<Node> shapes;
        for (Shape s : {Shape::sphere, Shape::box, Shape::cylinder, Shape::cone, Shape::torus}) {
            Node d;
            d.shape = s;
            d.size = s == Shape::torus ? glm::dvec3(0.8, 0.25, 0) : s == Shape::cone ? glm::dvec3(0.7, 0.2, 0.6)
                                                                                      : glm::dvec3(0.7, 0.5, 0.6);
            shapes.push_back(d);
        }
        for (const Node& d : shapes)
            for (int n = 0; n < 400; ++n) {
                const glm::dvec3 p = rng.point(1.5), q = p + 0.05 * rng.unit();
                const double a = primitive_distance(d, p), b = primitive_distance(d, q);
                INFO(str(d) << " at " << str(p) << " and " << str(q) << ": values " << a << ", " << b);
                CHECK(std::abs(a - b) <= glm::length(p - q) * (1 + 1e-9));
                CHECK((a < 0) == (ref_implicit(d, p) < 0));
            }
    }

    TEST_CASE("primitive: an inner node is refused" * geolab::points(1) *
              geolab::hint("Throw std::invalid_argument when the node is not a leaf.")) {
        Node n;
        n.op = Op::unite;
        n.a = 0;
        n.b = 0;
        CHECK_THROWS_AS(primitive_distance(n, glm::dvec3(0.0)), std::invalid_argument);
        // a leaf is no error ("reject everything" is not the contract): the unit sphere's centre is 1 inside
        Node leaf;
        CHECK(primitive_distance(leaf, glm::dvec3(0.0)) == -1.0);
    }
}

TEST_SUITE("Task 2: signed distances") {
    TEST_CASE("smooth_min: the pinned polynomial formula; min where |a − b| ≥ k; at most k/4 below" *
              geolab::points(2) *
              geolab::hint("h = clamp(1/2 + (b − a)/(2k), 0, 1), smin = b(1 − h) + a h − k h (1 − h); k ≤ 0 throws.")) {
        const double s0 = smooth_min(0.0, 0.0, 1.0), s1 = smooth_min(0.1, 0.3, 0.4);
        CHECK_MESSAGE(close(s0, -0.25, 1e-15), "smin(0, 0, 1) = −1/4, got " << s0);
        CHECK_MESSAGE(close(s1, 0.1 * 0.75 + 0.3 * 0.25 - 0.4 * 0.75 * 0.25, 1e-15),
                      "smin(0.1, 0.3, 0.4): h = 0.75, expected 0.075, got " << s1);
        Rng rng(11);
        for (int n = 0; n < 500; ++n) {
            const double a = rng.uniform(-2, 2), b = rng.uniform(-2, 2), k = rng.uniform(0.01, 1.5);
            const double s = smooth_min(a, b, k);
            INFO("smin(" << a << ", " << b << ", " << k << ") = " << s);
            if (std::abs(a - b) >= k) CHECK(s == std::min(a, b));
            CHECK(s <= std::min(a, b) + 1e-15);
            CHECK(s >= std::min(a, b) - k / 4 - 1e-15);
            CHECK(std::abs(s - smooth_min(b, a, k)) <= 1e-14);
        }
        CHECK_THROWS_AS(smooth_min(0, 1, 0), std::invalid_argument);
        CHECK_THROWS_AS(smooth_min(0, 1, -1), std::invalid_argument);
    }

    TEST_CASE("sdf: two unit cubes offset by 0.5 — union min; intersection max; difference max(a; −b)" *
              geolab::points(3) * geolab::builds_on("Task 1") *
              geolab::hint("A − B is max(a, −b): inside A and outside B. max(a, b) would be the intersection.")) {
        const Tree A = unit_cube_at(glm::dvec3(0.0)), B = unit_cube_at(glm::dvec3(0.5));
        Rng rng(12);
        for (int n = 0; n < 400; ++n) {
            const glm::dvec3 x = rng.point(1.0) + glm::dvec3(0.75);
            const double a = double(ref_distance(A.nodes[0], x - glm::dvec3(0.5)));
            const double b = double(ref_distance(B.nodes[0], x - glm::dvec3(1.0)));
            INFO("cubes [0,1]³ and [0.5,1.5]³ at " << str(x) << ": a = " << a << ", b = " << b);
            CHECK(close(sdf(op(Op::unite, A, B), x), std::min(a, b), 1e-12));
            CHECK(close(sdf(op(Op::intersect, A, B), x), std::max(a, b), 1e-12));
            CHECK(close(sdf(op(Op::subtract, A, B), x), std::max(a, -b), 1e-12));
            CHECK(close(sdf(op(Op::subtract, B, A), x), std::max(b, -a), 1e-12));
        }
    }

    TEST_CASE("sdf: transformed leaves — rigid motions keep distances exact; M⁻¹ maps the point" * geolab::points(3) *
              geolab::builds_on("Task 1") *
              geolab::hint("Evaluate the primitive at M⁻¹x (the point in the leaf's coordinates), and multiply by "
                           "min_stretch(M) so that scaled leaves still give world distances.")) {
        Rng rng(13);
        for (int n = 0; n < 40; ++n) {
            const glm::dmat4 M = rigid(rng, 2.0);
            const double s = rng.uniform(0.3, 3.0);
            const Tree t = leaf(Shape::sphere, {0.5, 0, 0}, M * scale(glm::dvec3(s)));
            const glm::dvec3 c(M[3]);
            for (int k = 0; k < 10; ++k) {
                const glm::dvec3 x = c + rng.point(3.0);
                const double want = glm::length(x - c) - 0.5 * s;
                const double got = sdf(t, x);
                INFO("sphere radius 0.5 scaled by " << s << " and moved to " << str(c) << ", at " << str(x)
                                                     << ": expected " << want << ", got " << got);
                CHECK(close(got, want, 1e-10));
            }
            // a box under a rigid motion: the distance of the local point
            const Tree b = leaf(Shape::box, {0.3, 0.6, 0.2}, M);
            const glm::dvec3 x = c + rng.point(1.5);
            const double want = double(ref_distance(b.nodes[0], to_local(M, x)));
            const double got = sdf(b, x);
            CHECK_MESSAGE(close(got, want, 1e-10), "box (0.3, 0.6, 0.2) moved rigidly, at " << str(x) << ": expected "
                                                                                             << want << ", got " << got);
        }
        // a non-uniform scaling: a lower bound of the distance, with the right sign
        const Tree e = leaf(Shape::sphere, {1, 0, 0}, scale({2, 1, 0.5}));
        for (glm::dvec3 x : {glm::dvec3(3, 0, 0), glm::dvec3(0, 0, 1.5), glm::dvec3(1.9, 0, 0)}) {
            const double v = sdf(e, x);
            const double true_gap = x.z != 0 ? x.z - 0.5 : x.x - 2;  // on the axes the distance is along the axis
            CHECK_MESSAGE((std::abs(v) <= std::abs(true_gap) * (1 + 1e-12) && (v < 0) == (true_gap < 0)),
                          "ellipsoid (2, 1, 0.5) at " << str(x) << ": the value must be a bound of the distance "
                                                      << true_gap << " with its sign, got " << v);
        }
    }

    TEST_CASE("sdf: min/max is exact outside a union but only a bound inside and near edges" * geolab::points(2) *
              geolab::builds_on("Task 1") *
              geolab::hint("Union = min(a, b) exactly; the test also shows where that is not the true distance.")) {
        // Two overlapping unit spheres at (±0.5, 0, 0); at the origin the true distance to the surface is the
        // distance to the circle where the spheres meet: √(1 − 0.25) = 0.866..., but min(a, b) = −0.5.
        const Tree u = op(Op::unite, leaf(Shape::sphere, {1, 0, 0}, translate({-0.5, 0, 0})),
                          leaf(Shape::sphere, {1, 0, 0}, translate({0.5, 0, 0})));
        const double v = sdf(u, glm::dvec3(0.0));
        CHECK_MESSAGE(close(v, -0.5, 1e-14), "union of unit spheres at (±0.5, 0, 0), at the origin: min(a, b) = −0.5, got " << v);
        CHECK_MESSAGE(std::abs(v) < std::sqrt(0.75), "the value there is a bound: |min| = 0.5 < the true distance 0.866");
        // Outside the union min is exact: points far on the x axis
        CHECK(close(sdf(u, {3, 0, 0}), 1.5, 1e-14));
        // A box minus a box at an edge: max(a, −b) underestimates the distance to the re-entrant edge.
        const Tree d = op(Op::subtract, leaf(Shape::box, glm::dvec3(1.0)), leaf(Shape::box, glm::dvec3(1.0), translate({1, 1, 0})));
        const glm::dvec3 x(0.2, 0.2, 0.0);  // outside A − B, inside B near its corner edge at (0, 0, z)
        const double w = sdf(d, x);
        CHECK_MESSAGE(close(w, 0.2, 1e-14), "box [−1,1]³ minus the box [0,2]×[0,2]×[−1,1] at (0.2, 0.2, 0): max(a, −b) = 0.2, got " << w);
        CHECK_MESSAGE(w < std::sqrt(0.08) - 1e-6, "and that is less than the true distance √0.08 to the edge");
    }

    TEST_CASE("sdf: blend nodes use smooth_min of the children's values" * geolab::points(1) *
              geolab::builds_on("Task 1") *
              geolab::hint("Op::blend: smooth_min(a, b, k) with the node's k.")) {
        const Tree a = leaf(Shape::sphere, {0.5, 0, 0}, translate({-0.4, 0, 0}));
        const Tree b = leaf(Shape::sphere, {0.5, 0, 0}, translate({0.4, 0, 0}));
        const Tree t = op(Op::blend, a, b, 0.3);
        Rng rng(14);
        for (int n = 0; n < 100; ++n) {
            const glm::dvec3 x = rng.point(1.2);
            const double da = glm::length(x - glm::dvec3(-0.4, 0, 0)) - 0.5, db = glm::length(x - glm::dvec3(0.4, 0, 0)) - 0.5;
            const double h = std::clamp(0.5 + (db - da) / 0.6, 0.0, 1.0);
            const double want = db * (1 - h) + da * h - 0.3 * h * (1 - h);
            const double got = sdf(t, x);
            CHECK_MESSAGE(close(got, want, 1e-12), "blend k = 0.3 of spheres at (±0.4, 0, 0) at " << str(x)
                                                                                        << ": expected " << want << ", got " << got);
        }
    }

    TEST_CASE("sdf (prepared): reads each leaf's prepared stretch and inverse; never M" * geolab::points(2) *
              geolab::builds_on("Task 1") *
              geolab::hint("On a PreparedTree a leaf's value is stretch · primitive_distance(leaf, inverse · x): "
                           "prepare() computed both once; recomputing them from M for every sample is what made the "
                           "polygonization slow.")) {
        // a rotated, non-uniformly scaled box minus a moved sphere; then every leaf's M overwritten with 0
        const glm::dmat4 Mb = rotate(30, {1, 2, 0}) * scale({2, 1, 1.5}), Ms = translate({0.8, 0.3, 0});
        const Tree t = op(Op::subtract, leaf(Shape::box, {0.5, 0.6, 0.4}, Mb), leaf(Shape::sphere, {0.5, 0, 0}, Ms));
        PreparedTree p = prepare(t);
        for (PreparedNode& n : p.nodes) n.node.M = glm::dmat4(0.0);
        Rng rng(15);
        for (int n = 0; n < 100; ++n) {
            const glm::dvec3 x = rng.point(1.5);
            const double db = double(ref_distance(t.nodes[0], to_local(Mb, x)));  // min_stretch(Mb) = 1
            const double ds = double(ref_distance(t.nodes[1], to_local(Ms, x)));
            const double want = std::max(db, -ds), got = sdf(p, x);
            INFO("box (0.5, 0.6, 0.4) rotated 30° about (1, 2, 0) and scaled by (2, 1, 1.5) (stretch 1) minus a sphere r = 0.5 "
                 "at (0.8, 0.3, 0), every node's M set to 0 after prepare(), at " << str(x) << ": expected " << want << ", got " << got);
            CHECK(close(got, want, 1e-10));
        }
        // the stretch is the prepared one: doubled, the leaf's values double
        PreparedTree s = prepare(leaf(Shape::sphere, {1, 0, 0}, translate({1, 0, 0})));
        s.nodes[0].stretch = 2.0;
        const double doubled = sdf(s, {4, 0, 0});
        CHECK_MESSAGE(close(doubled, 4.0, 1e-14), "unit sphere at (1, 0, 0) with its prepared stretch set to 2, "
                                                  "at (4, 0, 0): 2 · 2 = 4, got " << doubled);
    }
}

TEST_SUITE("Task 3: point membership") {
    TEST_CASE("classify: the logo's points in; on and out" * geolab::points(2) * geolab::builds_on("Task 1") *
              geolab::hint("Leaves: on when |d| ≤ tol; combine with the three-valued rules of the header.")) {
        const Tree t = logo();
        Rng rng(21);
        int counts[3] = {0, 0, 0};
        for (int n = 0; n < 600; ++n) {
            const glm::dvec3 x = rng.point(1.4);
            const Membership m = classify(t, x, 1e-9);
            counts[int(m)]++;
            if (m != Membership::on) {
                INFO("logo at " << str(x) << ": got " << str(m));
                CHECK((m == Membership::in) == ref_inside(t, x));
            }
        }
        CHECK_MESSAGE(counts[1] == 0, "random points are almost never on the surface, got " << counts[1] << " 'on'");
        // points on the surface: a face of the cube away from the holes and the sphere's cut
        for (glm::dvec3 x : {glm::dvec3(1, 0.7, 0.0), glm::dvec3(0.7, -1, 0.2), glm::dvec3(-0.2, 0.7, 1.0)}) {
            const Membership m = classify(t, x, 1e-9);
            CHECK_MESSAGE(m == Membership::on, "logo at " << str(x) << " (on a face of the cube): got " << str(m));
        }
        // a point on the wall of the z hole (radius 0.55): on
        const glm::dvec3 w(0.55, 0, 0.8);
        const Membership mw = classify(t, w, 1e-9);
        CHECK_MESSAGE(mw == Membership::on, "logo at " << str(w) << " on the z hole's wall: got " << str(mw));
        CHECK(classify(t, {0.8, 0.8, 0.1}, 1e-9) == Membership::in);
        CHECK(classify(t, {0, 0, 0}, 1e-9) == Membership::out);
        CHECK(classify(t, {0.95, 0.95, 0.95}, 1e-9) == Membership::out);  // cut off by the sphere
    }

    TEST_CASE("classify: the tolerance is relative to the scene's size" * geolab::points(3) *
              geolab::builds_on("Task 1, Task 2") *
              geolab::hint("tol = rel_tol · scene_size(t): the same scene scaled by 1000 classifies the same points "
                           "(scaled) the same way.")) {
        for (double s : {1e-3, 1.0, 1e3}) {
            const Tree t = op(Op::subtract, leaf(Shape::box, glm::dvec3(s)), leaf(Shape::sphere, {0.8 * s, 0, 0}));
            const double size = scene_size(t);
            // just outside the box by 1e-4 of the size: on with rel_tol 1e-3, out with rel_tol 1e-5
            const glm::dvec3 x(s + 1e-4 * size, 0.95 * s, 0.95 * s);
            const Membership loose = classify(t, x, 1e-3), tight = classify(t, x, 1e-5);
            CHECK_MESSAGE(loose == Membership::on, "box ±" << s << " minus a sphere, a point 1e-4·size outside the box, rel_tol 1e-3: expected on, got " << str(loose));
            CHECK_MESSAGE(tight == Membership::out, "the same with rel_tol 1e-5: expected out, got " << str(tight));
            const glm::dvec3 y(0.9 * s, 0.9 * s, 0.9 * s);
            CHECK(classify(t, y, 1e-9) == Membership::in);
            CHECK(classify(t, glm::dvec3(0.1 * s), 1e-9) == Membership::out);
            const glm::dvec3 z(0.8 * s, 0, 0);  // on the sphere, inside the box
            const Membership mz = classify(t, z, 1e-9);
            CHECK_MESSAGE(mz == Membership::on, "on the subtracted sphere: got " << str(mz));
        }
        CHECK_THROWS_AS(classify(leaf(Shape::sphere, {1, 0, 0}), glm::dvec3(0.0), -1.0), std::invalid_argument);
        CHECK_MESSAGE(classify(leaf(Shape::sphere, {1, 0, 0}), glm::dvec3(0.0), 0.0) == Membership::in,
                      "rel_tol = 0 is allowed (only exact zeros are on)");
        CHECK(classify(leaf(Shape::sphere, {1, 0, 0}), glm::dvec3(1, 0, 0), 0.0) == Membership::on);
    }

    TEST_CASE("classify: the three-valued rules at shared faces (touching union; equal subtraction)" *
              geolab::points(3) * geolab::builds_on("Task 1, Task 2") *
              geolab::hint("Union: in if either is in, out if both out, else on. Difference: out if A out or B in; in "
                           "if A in and B out; else on.")) {
        const Tree a = unit_cube_at({0, 0, 0}), b = unit_cube_at({1, 0, 0});
        const glm::dvec3 face(1.0, 0.5, 0.5);
        CHECK_MESSAGE(classify(op(Op::unite, a, b), face, 1e-9) == Membership::on,
                      "cubes [0,1]³ and [1,2]×[0,1]² touching at x = 1: the shared face's point is 'on' by the rule");
        CHECK_MESSAGE(classify(op(Op::intersect, a, b), face, 1e-9) == Membership::on, "their intersection there: on");
        CHECK_MESSAGE(classify(op(Op::subtract, a, b), face, 1e-9) == Membership::on, "a − b there: on");
        CHECK_MESSAGE(classify(op(Op::subtract, a, a), glm::dvec3(0.5), 1e-9) == Membership::out, "a cube minus itself at its centre: out");
        CHECK_MESSAGE(classify(op(Op::subtract, a, a), glm::dvec3(1, 0.5, 0.5), 1e-9) == Membership::on, "a cube minus itself on its face: on");
        CHECK(classify(op(Op::unite, a, b), {0.5, 0.5, 0.5}, 1e-9) == Membership::in);
        CHECK_MESSAGE(classify(op(Op::unite, a, b), {0, 0.5, 0.5}, 1e-9) == Membership::on,
                      "union: on a's face x = 0 and outside b: on");
        CHECK(classify(op(Op::intersect, a, b), {0, 0.5, 0.5}, 1e-9) == Membership::out);
        // a blend node classifies by its own value: (0, 0.4, 0) is outside both spheres but inside their blend
        const Tree s1 = leaf(Shape::sphere, {0.5, 0, 0}, translate({-0.4, 0, 0})), s2 = leaf(Shape::sphere, {0.5, 0, 0}, translate({0.4, 0, 0}));
        CHECK_MESSAGE(classify(op(Op::blend, s1, s2, 0.3), {0, 0.4, 0}, 1e-9) == Membership::in,
                      "blend k = 0.3 of spheres r = 0.5 at (±0.4, 0, 0) at (0, 0.4, 0): smin = −0.0093: in");
        CHECK(classify(op(Op::unite, s1, s2), {0, 0.4, 0}, 1e-9) == Membership::out);
        CHECK(classify(op(Op::blend, s1, s2, 0.3), {0, 0.45, 0}, 1e-9) == Membership::out);
        CHECK(classify(op(Op::intersect, a, b), {0.5, 0.5, 0.5}, 1e-9) == Membership::out);
        CHECK(classify(op(Op::subtract, a, b), {1.5, 0.5, 0.5}, 1e-9) == Membership::out);
        CHECK(classify(op(Op::subtract, b, a), {1.5, 0.5, 0.5}, 1e-9) == Membership::in);
        CHECK(classify(op(Op::unite, a, b), {1.5, 0.5, 0.5}, 1e-9) == Membership::in);
    }
}
