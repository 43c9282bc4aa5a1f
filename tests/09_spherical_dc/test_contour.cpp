// Lab 09, Tasks 4-6: dual vertices, simplification, polygons on the Cartesian octree (handout §5).
#include <bit>
#include <bitset>

#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab09;

namespace {
Octree tree_with_vertices(const ScalarField& f, int level) {
    Octree t = given_octree(f, level);  // not your build_octree: Task 3's bugs cost Task 3's points only
    place_vertices(t, {});
    return t;
}
std::size_t leaves_with_vertex(const Octree& t) {
    std::size_t n = 0;
    for (std::uint32_t li : tree_shape(t).leaves) n += t.nodes[li].vertex != invalid_index;
    return n;
}
}  // namespace

TEST_SUITE("Task 4: vertex placement") {

TEST_CASE("place_vertices: a vertex in exactly the leaves whose corners change sign; f <= 0 inside" *
          geolab::points(2) * geolab::builds_on("Task 1, Task 2") *
          geolab::hint("A leaf gets a vertex iff its 8 corner samples are not all on one side, where inside means "
                       "f <= 0 (a sample that is exactly 0 is inside: the lattice box here has zeros on its faces). "
                       "One QEF plane per sign-changing edge; each finest edge's crossing computed once. Record "
                       "every leaf's corner signs in OctreeNode::signs. Handout §5.1.")) {
    const LatticeBox lbox(4, 0.05, {3, 4, 5}, {12, 11, 10});
    const FieldPtr ball = geolab::sphere({0.05, 0.1, -0.07}, 0.66);
    const std::pair<const ScalarField*, const char*> fields[] = {{&lbox, "box with faces on lattice planes, level 4"},
                                                                 {ball.get(), "sphere r = 0.66, level 4"}};
    for (auto [f, name] : fields) {
        Octree t = given_octree(*f, 4);
        const std::size_t crossings = place_vertices(t, {});
        INFO(name);
        if (f == &lbox) {  // the fixture really has exact zeros at lattice points
            std::size_t zeros = 0;
            for (int i = 0; i <= 16; ++i)
                for (int k = 0; k <= 16; ++k) zeros += t.value({i, 7, k}) == 0.0 && t.value({i, 11, k}) == 0.0;
            REQUIRE(zeros > 0);
        }
        std::size_t wrong = 0, with_vertex = 0;
        std::ostringstream first;
        for (std::uint32_t li : tree_shape(t).leaves) {
            const OctreeNode& nd = t.nodes[li];
            const int in = inside_corners(t, nd);
            const bool should = in > 0 && in < 8, has = nd.vertex != invalid_index;
            with_vertex += has;
            bool ok = should == has;
            if (ok && has) {
                REQUIRE(nd.vertex < t.vertices.size());
                ok = qef_of(t, nd.vertex).count == sign_changing_edges(t, nd);
            }
            if (!ok && wrong++ < 3)
                first << "\n  leaf (" << nd.x << ", " << nd.y << ", " << nd.z << ") level " << int(nd.level) << ": "
                      << in << " inside corners (f <= 0), " << sign_changing_edges(t, nd)
                      << " sign-changing edges, vertex " << (has ? "yes" : "no")
                      << (has ? ", qef.count " + std::to_string(qef_of(t, nd.vertex).count) : std::string());
        }
        CHECK_MESSAGE(wrong == 0, wrong << " leaves have a wrong vertex / QEF" << first.str());
        std::ostringstream first_signs;
        const std::size_t bad_signs = wrong_signs(t, first_signs);
        CHECK_MESSAGE(bad_signs == 0, bad_signs << " leaves have OctreeNode::signs that do not match their corners "
                                                   "(bit c = corner c inside; every leaf, with a vertex or not)"
                                                << first_signs.str());
        CHECK(with_vertex > 0);
        CHECK(t.vertices.size() == with_vertex);
        CHECK_MESSAGE(crossings == sign_changing_finest_edges(t),
                      "place_vertices returned " << crossings << " crossings; distinct sign-changing edges: "
                                                 << sign_changing_finest_edges(t));
    }
}

TEST_CASE("place_vertices: a coarse leaf's signs are its 8 corners' even where its centre disagrees" *
          geolab::points(1) * geolab::builds_on("Task 1, Task 2") *
          geolab::hint("OctreeNode::signs is bit c = inside(value(corner(n, c))) for every leaf. A shortcut that "
                       "decides a coarse leaf from one sample at its centre holds only for a Lipschitz field with a "
                       "known constant (lipschitz() > 0) whose sign cannot jump (!sign_may_jump()). Handout §5.1.")) {
    // f = −5 within 0.1 of the centre of child 0 of the root, +5 elsewhere: no corner of that level-1 leaf is
    // inside, its centre is; |f| = 5 exceeds Lf times its half diagonal (0.87), the shortcut's condition
    struct Pocket : geolab::ScalarField {
        double lf;
        bool jumps;
        Pocket(double l, bool j) : lf(l), jumps(j) {}
        double value(const glm::dvec3& p) const override {
            return glm::length(p - glm::dvec3(-0.5)) < 0.1 ? -5.0 : 5.0;
        }
        geolab::Box bounds() const override { return {glm::dvec3(-1.0), glm::dvec3(1.0)}; }
        double lipschitz() const override { return lf; }
        bool sign_may_jump() const override { return jumps; }
    };
    const Pocket fields[] = {{1.0, true}, {0.0, false}};
    for (const Pocket& f : fields) {
        INFO("a pocket inside a coarse leaf, lipschitz() = " << f.lf << ", sign_may_jump() = " << f.jumps);
        Octree t;
        t.init_cartesian(f, 3, glm::dvec3(-1.0), 2.0);
        t.split(0);  // 8 leaves of level 1 (the finest level is 3)
        REQUIRE(t.value({2, 2, 2}) < 0.0);  // the centre of leaf 1 (child 0) is inside
        place_vertices(t, {});
        std::ostringstream first;
        const std::size_t bad = wrong_signs(t, first);
        CHECK_MESSAGE(bad == 0, bad << " leaves have OctreeNode::signs that do not match their corners" << first.str());
        CHECK(t.vertices.empty());
    }
    // An exact signed distance (Lf = 1) and the root left a leaf (level 0 of a level-3 tree, half diagonal 1.73):
    // a ball of radius 0.3 around the corner (1, 1, 1), |f(centre)| = 1.43 is below Lf times the half diagonal, so
    // the corners decide: one corner inside, a vertex
    const FieldPtr ball = geolab::sphere(glm::dvec3(1.0), 0.3);
    Octree t;
    t.init_cartesian(*ball, 3, glm::dvec3(-1.0), 2.0);
    place_vertices(t, {});
    INFO("a ball of radius 0.3 around the corner (1, 1, 1) of a root leaf");
    CHECK(t.nodes[0].signs == 0x80);
    CHECK(t.vertices.size() == 1);
    // The shortcut's margin: a plane (exact distance, Lf = 1) at distance hd − 1e-12 from the root's centre, normal
    // along the diagonal, cuts off only the corner (1, 1, 1) at 1e-12 from it: |f(centre)| is within 1e-9 of Lf·hd
    // but below it, so the corners still decide (a margin that rounds the other way loses the corner)
    struct Plane : geolab::ScalarField {
        double d;
        explicit Plane(double dist) : d(dist) {}
        double value(const glm::dvec3& p) const override { return glm::dot(p, glm::dvec3(1.0 / std::sqrt(3.0))) - d; }
        geolab::Box bounds() const override { return {glm::dvec3(-1.0), glm::dvec3(1.0)}; }
        double lipschitz() const override { return 1.0; }
    };
    const Plane plane(std::sqrt(3.0) - 1e-12);
    Octree tp;
    tp.init_cartesian(plane, 3, glm::dvec3(-1.0), 2.0);
    REQUIRE(tp.value({8, 8, 8}) > 0.0);
    place_vertices(tp, {});
    INFO("a plane 1e-12 short of the corner (1, 1, 1) of a root leaf");
    CHECK(tp.nodes[0].signs == 0x7f);
    CHECK(tp.vertices.size() == 1);
}

TEST_CASE("place_vertices: each sign-changing finest edge's crossing is computed once on larger trees; spherical "
          "trees too (poles and the origin)" *
          geolab::points(1) * geolab::builds_on("Task 1, Task 2, Task 10") *
          geolab::hint("Return the number of crossings you computed: one per distinct sign-changing finest edge, an "
                       "edge named by its two lattice ends as Octree::canonical names them (the phi seam, the polar "
                       "axis and the origin merge points), however many leaves share it and however far apart in "
                       "the traversal they are. A crossing computed twice, or two edges sharing one, is a bug. "
                       "Handout §5.1.")) {
    // the test's count: distinct (canonical lower end, canonical upper end) of the finest leaves' sign-changing
    // cell edges, degenerate ones (both ends merged into one point) left out
    auto distinct_edges = [](const Octree& t, std::size_t& coarse_changes) {
        // a coarse leaf computes its own crossings (its edges are not finest edges): its distinct edges count apart
        std::vector<std::array<std::int64_t, 7>> keys, coarse;
        for (std::uint32_t li : tree_shape(t).leaves) {
            const OctreeNode& nd = t.nodes[li];
            for (int e = 0; e < 12; ++e) {
                const glm::ivec3 q0 = t.corner(nd, cell_edge_corners[e][0]), q1 = t.corner(nd, cell_edge_corners[e][1]);
                const glm::ivec3 k0 = t.canonical(q0), k1 = t.canonical(q1);
                if (k0 == k1 || (t.value(q0) <= 0.0) == (t.value(q1) <= 0.0)) continue;
                const bool finest = nd.level == t.max_level;
                (finest ? keys : coarse).push_back({finest ? -1 : std::int64_t(li), k0.x, k0.y, k0.z, k1.x, k1.y, k1.z});
            }
        }
        auto distinct = [](std::vector<std::array<std::int64_t, 7>>& v) {
            std::sort(v.begin(), v.end());
            return std::size_t(std::unique(v.begin(), v.end()) - v.begin());
        };
        coarse_changes = distinct(coarse);
        return distinct(keys);
    };
    const FieldPtr ball = geolab::sphere({0.05, -0.1, 0.07}, 0.7), ring = geolab::torus({0, 0, 0}, 0.6, 0.25),
                   csg = geolab::named_implicit("csg");
    const PolygonSoup lion_mesh = load_model("lion");
    const geolab::MeshField lion(lion_mesh);
    const std::pair<const ScalarField*, const char*> cartesian[] = {
        {ball.get(), "sphere, Cartesian level 7"}, {ring.get(), "torus, Cartesian level 7"},
        {csg.get(), "csg, Cartesian level 7"}, {&lion, "lion (a field whose sign jumps), Cartesian level 5"}};
    for (auto [f, name] : cartesian) {
        Octree t = given_octree(*f, f == &lion ? 5 : 7);
        const std::size_t crossings = place_vertices(t, {});
        // the finest leaves' corners are all in the tree's cache now (their signs were needed): reading them again
        // samples nothing
        const std::size_t samples = t.samples();
        for (std::uint32_t li : tree_shape(t).leaves)
            if (t.nodes[li].level == t.max_level)
                for (int c = 0; c < 8; ++c) t.value(t.corner(t.nodes[li], c));
        const std::size_t resampled = t.samples() - samples;
        std::size_t coarse = 0;
        const std::size_t want = distinct_edges(t, coarse);
        INFO(name << ": place_vertices returned " << crossings << "; distinct sign-changing finest edges " << want);
        REQUIRE(coarse == 0);  // the given tree refines every sign change to the finest level
        CHECK(crossings == want);
        CHECK_MESSAGE(resampled == 0, "reading the finest leaves' corners after place_vertices took " << resampled
                                          << " new samples: the tree's cache must keep what place_vertices sampled");
    }
    // spherical: the surface cuts the theta-edges leaving both poles (origin at the centre), the radial edges
    // leaving the origin (origin just inside the surface), and an inner sphere r_min > 0
    const FieldPtr s = geolab::sphere({0.1, -0.05, 0.2}, 0.7);
    struct Case {
        glm::dvec3 origin;
        double r_min, r_max;
        const char* what;
    } cases[] = {{{0.1, -0.05, 0.2}, 0.0, 1.2, "sphere, origin at its centre, spherical level 5"},
                 {{0.1, -0.05, 0.2 - 0.69}, 0.0, 1.6, "sphere, origin 0.01 inside it, spherical level 5"},
                 {{0.0, 0.0, 0.0}, 0.1, 1.2, "sphere, origin near its centre, r_min 0.1, spherical level 5"}};
    for (const Case& cs : cases) {
        Octree t = build_spherical_octree(*s, 5, cs.origin, cs.r_min, cs.r_max);
        const std::size_t crossings = place_vertices(t, {});
        std::size_t coarse = 0;
        const std::size_t want = distinct_edges(t, coarse);
        INFO(cs.what << ": place_vertices returned " << crossings << "; distinct sign-changing finest edges " << want
                     << " (+ " << coarse << " on coarse leaves)");
        CHECK(crossings == want + coarse);
    }
}

TEST_CASE("place_vertices: a QEF minimiser that leaves its cell gives way to the mass point" *
          geolab::points(2) * geolab::builds_on("Task 1, Task 2") *
          geolab::hint("The QEF minimiser can be far outside the cell (nearly parallel planes, noisy normals): then "
                       "take the mass point (the mean of the crossings, inside the cell) instead. Where the minimiser "
                       "is inside, keep it unchanged. Handout §5.1.")) {
    const WobblyPlane f(0.1234);
    const Octree t = tree_with_vertices(f, 4);
    std::size_t outside = 0, solved_outside = 0, moved = 0, not_mass = 0, n = 0;
    std::ostringstream first;
    const double h = t.size / t.resolution();
    for (std::uint32_t li : tree_shape(t).leaves) {
        const OctreeNode& nd = t.nodes[li];
        if (nd.vertex == invalid_index) continue;
        REQUIRE(nd.vertex < t.vertices.size());
        ++n;
        const Box b = cell_box(t, nd);
        const DualVertex& v = t.vertices[nd.vertex];
        const glm::dvec3 x = qef_of(t, nd.vertex).solve(0.01);
        const double out = box_outside(b, v.position);
        if (box_outside(b, x) > 1e-9 * h) ++solved_outside, not_mass += glm::length(v.position - qef_of(t, nd.vertex).mass_point()) > 1e-9 * h;
        else if (glm::length(v.position - x) > 1e-9 * h) ++moved;
        if (out > 1e-9 * h && outside++ < 3)
            first << "\n  cell [" << str(b.lo) << ", " << str(b.hi) << "] has its vertex at " << str(v.position);
    }
    INFO("plane z = 0.1234 with gradients that swing around (WobblyPlane), level 4: " << n << " vertices, "
         << solved_outside << " QEF minimisers outside their cells");
    REQUIRE(n > 0);
    REQUIRE(solved_outside > 0);
    CHECK_MESSAGE(outside == 0, outside << " vertices lie outside their cells" << first.str());
    CHECK_MESSAGE(moved == 0, moved << " vertices differ from their QEF minimiser although it lies in the cell");
    CHECK_MESSAGE(not_mass == 0, not_mass << " vertices whose QEF minimiser leaves the cell are not its mass point");
}

TEST_CASE("place_vertices: the cells at a box's corners get the exact corners; every vertex is on the box" *
          geolab::points(2) * geolab::builds_on("Task 1, Task 2") *
          geolab::hint("Hermite data (crossing + unit normal) on every sign-changing edge, QEF solved with tau = 0.01: "
                       "a corner cell has rank 3 and its vertex is the exact corner. Handout §5.1.")) {
    const glm::dvec3 c(0.03, -0.02, 0.01), half(0.61, 0.47, 0.33);
    const FieldPtr f = geolab::box(c, half);
    const Octree t = tree_with_vertices(*f, 4);
    const double h = t.size / t.resolution();
    INFO("box centre " << str(c) << ", half extents " << str(half) << ", level 4, h = " << h);
    for (int k = 0; k < 8; ++k) {
        const glm::dvec3 corner = c + half * glm::dvec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
        const std::uint32_t leaf = leaf_at(t, corner);
        REQUIRE(leaf != invalid_index);
        REQUIRE(t.nodes[leaf].vertex != invalid_index);
        REQUIRE(t.nodes[leaf].vertex < t.vertices.size());
        const glm::dvec3 v = t.vertices[t.nodes[leaf].vertex].position;
        INFO("corner " << str(corner) << ": vertex of its cell " << str(v));
        CHECK(glm::length(v - corner) < 1e-6 * h);
    }
    double worst = 0;
    for (const DualVertex& v : t.vertices) worst = std::max(worst, std::abs(f->value(v.position)));
    CHECK_MESSAGE(worst < 1e-6 * h, "max |f(vertex)| = " << worst << " (" << worst / h << " h)");
}

}  // TEST_SUITE

TEST_SUITE("Task 5: simplification") {

TEST_CASE("simplify: a box collapses to its 8 corner vertices" * geolab::points(1) *
          geolab::builds_on("Task 1, Task 2") *
          geolab::hint("Bottom-up: 8 leaf children merge when the sign tests pass and the merged QEF's residual "
                       "sqrt(Q / count) <= tolerance with its minimiser in the parent cell. Flat faces and straight "
                       "edges fit exactly, so only the corners remain. Handout §5.2.")) {
    const FieldPtr f = geolab::box({0.03, -0.02, 0.01}, {0.61, 0.47, 0.33});
    Octree t = tree_with_vertices(*f, 5);
    const std::size_t before = leaves_with_vertex(t);
    const double h = t.size / t.resolution();
    const std::size_t collapses = simplify(t, 1e-5 * h, 0.01);
    const std::size_t after = leaves_with_vertex(t);
    INFO("box, level 5: leaves with a vertex " << before << " before, " << after << " after " << collapses
                                               << " collapses");
    CHECK(collapses > 0);
    CHECK(after == 8);
    CHECK(tree_shape(t).bad_children == 0);
    std::ostringstream first_signs;
    const std::size_t bad_signs = wrong_signs(t, first_signs);
    CHECK_MESSAGE(bad_signs == 0, bad_signs << " leaves (collapsed parents among them) have OctreeNode::signs that "
                                               "do not match their corners" << first_signs.str());
    for (std::uint32_t li : tree_shape(t).leaves) {
        const OctreeNode& nd = t.nodes[li];
        if (nd.vertex == invalid_index) continue;
        REQUIRE(nd.vertex < t.vertices.size());
        const glm::dvec3 v = t.vertices[nd.vertex].position;
        CHECK_MESSAGE(std::abs(f->value(v)) < 1e-6 * h, "vertex " << str(v) << " is off the box");
        CHECK(box_outside(cell_box(t, nd), v) < 1e-9 * h);
    }
}

TEST_CASE("simplify: at the default tolerance a curved surface keeps its finest vertices" * geolab::points(1) *
          geolab::builds_on("Task 1, Task 2") *
          geolab::hint("The tolerance is a length (1e-5 h here): a sphere's merged QEF never fits that well, so no "
                       "cell with a vertex collapses (empty cells may). Handout §5.2.")) {
    const FieldPtr f = geolab::sphere({0.0, 0.0, 0.0}, 0.8);
    Octree t = tree_with_vertices(*f, 5);
    const std::size_t before = leaves_with_vertex(t);
    simplify(t, 1e-5 * t.size / t.resolution(), 0.01);
    const std::size_t after = leaves_with_vertex(t);
    INFO("sphere r = 0.8, level 5: leaves with a vertex " << before << " before, " << after << " after");
    REQUIRE(before > 0);
    CHECK(after == before);
}

TEST_CASE("simplify: the topology tests keep two nearby solids apart at any tolerance" * geolab::points(1) *
          geolab::builds_on("Task 1, Task 2") *
          geolab::hint("Collapse only when the parent's corner signs form one sheet AND every edge midpoint; face "
                       "centre and the cell centre agree with a corner of that edge/face/cell (Ju et al. 2002). "
                       "Handout §5.2.")) {
    // two boxes whose facing sides are 1.3 finest cells apart, the gap centred in a level-4 cell: the parent's
    // corners are inside (left and right), its middle outside
    const double h = 1.76 / 32, gap_mid = -0.88 + 2 * h * 8.5;
    const FieldPtr slabs = geolab::csg_union(geolab::box({(-0.8 + gap_mid - 0.65 * h) / 2, 0, 0},
                                                         {(0.8 + gap_mid - 0.65 * h) / 2, 0.6, 0.6}),
                                             geolab::box({(0.8 + gap_mid + 0.65 * h) / 2, 0, 0},
                                                         {(0.8 - gap_mid - 0.65 * h) / 2, 0.6, 0.6}));
    const FieldPtr spheres =
        geolab::csg_union(geolab::sphere({-0.45, 0.0, 0.0}, 0.4), geolab::sphere({0.45, 0.0, 0.0}, 0.4));
    const std::pair<FieldPtr, const char*> cases[] = {
        {slabs, "two boxes x in [-0.8, 0.019] and [0.091, 0.8] (gap 1.3 h)"},
        {spheres, "two spheres r = 0.4 at x = -0.45 and 0.45 (gap 0.1)"}};
    for (const auto& [f, name] : cases) {
        Octree t;
        const PolygonSoup s = cartesian_pipeline(*f, 5, 1e6, &t);  // tolerance 1e6 h: residuals never stop a collapse
        INFO(name << ", level 5, simplified with a huge tolerance");
        REQUIRE(std::abs(t.size / t.resolution() - (f == slabs ? h : t.size / 32)) < 1e-12);
        LAB09_CHECK_CLOSED_MANIFOLD(s, name);
        CHECK(components(s) == 2);
        CHECK(edge_report(s).euler() == 4);
        const double ht = t.size / t.resolution();
        for (std::uint32_t li : tree_shape(t).leaves) {
            const OctreeNode& nd = t.nodes[li];
            if (nd.vertex == invalid_index) continue;
            REQUIRE(nd.vertex < t.vertices.size());
            CHECK(box_outside(cell_box(t, nd), t.vertices[nd.vertex].position) < 1e-9 * ht);
        }
    }
}

TEST_CASE("simplify: tolerance 0 merges only exact fits; a box with faces on coarse lattice planes gives 8 corners" *
          geolab::points(1) * geolab::builds_on("Task 1, Task 2") *
          geolab::hint("Collapse when sqrt(Q / count) <= tolerance: with tolerance 0 the cells whose merged QEF fits "
                       "exactly (Q = 0: flat faces with exact crossings) still merge, nothing else does. Samples that "
                       "are exactly 0 (faces on lattice planes) are inside, in the 27 sub-lattice signs too. "
                       "Handout §5.2.")) {
    // a box whose faces lie half-way between finest lattice planes, on a dyadic lattice (domain [-2, 2]^3, h = 1/8):
    // every crossing, normal and QEF sum on a face is exact, so a face's merged QEF has Q = 0 exactly
    struct DyadicBox final : ScalarField {
        glm::dvec3 lo{-2.0 + 0.125 * 6.5, -2.0 + 0.125 * 9.5, -2.0 + 0.125 * 10.5};
        glm::dvec3 hi{-2.0 + 0.125 * 25.5, -2.0 + 0.125 * 22.5, -2.0 + 0.125 * 21.5};
        double value(const glm::dvec3& p) const override {
            double v = -1e300;
            for (int a = 0; a < 3; ++a) v = std::max({v, lo[a] - p[a], p[a] - hi[a]});
            return v;
        }
        glm::dvec3 gradient(const glm::dvec3& p) const override {
            double best = -1e300;
            glm::dvec3 g(0.0);
            for (int a = 0; a < 3; ++a)
                for (int sg : {-1, 1}) {
                    const double v = sg < 0 ? lo[a] - p[a] : p[a] - hi[a];
                    if (v > best) best = v, g = glm::dvec3(0.0), g[a] = sg;
                }
            return g;
        }
        Box bounds() const override { return {glm::dvec3(-1.0), glm::dvec3(1.0)}; }
        double lipschitz() const override { return 1.0; }
    } dyadic;
    {
        Octree t = given_octree(dyadic, 5, 0.5);
        REQUIRE(t.size == 4.0);
        REQUIRE(t.min_corner == glm::dvec3(-2.0));
        place_vertices(t, {});
        const std::size_t before = leaves_with_vertex(t);
        const std::size_t collapses = simplify(t, 0.0, 0.01);
        const std::size_t after = leaves_with_vertex(t);
        const double h = 0.125;
        std::size_t inexact = 0;
        std::ostringstream first;
        for (std::uint32_t li : tree_shape(t).leaves) {
            const OctreeNode& nd = t.nodes[li];
            if (nd.vertex == invalid_index || nd.level == t.max_level) continue;
            REQUIRE(nd.vertex < t.vertices.size());
            // Q(x) of the merged QEF, from its sums (x^T AtA x - 2 x^T Atb + btb)
            const DualVertex& v = t.vertices[nd.vertex];
            const Qef& q = qef_of(t, nd.vertex);
            const glm::dvec3 x = v.position;
            const double xax = q.ata[0] * x.x * x.x + q.ata[3] * x.y * x.y + q.ata[5] * x.z * x.z +
                               2 * (q.ata[1] * x.x * x.y + q.ata[2] * x.x * x.z + q.ata[4] * x.y * x.z);
            const double residual = std::sqrt(std::max(0.0, xax - 2 * glm::dot(x, q.atb) + q.btb) / std::max(q.count, 1));
            if (residual > 1e-9 * h && inexact++ < 3)
                first << "\n  merged leaf level " << int(nd.level) << " (" << nd.x << ", " << nd.y << ", " << nd.z
                      << "): sqrt(Q/count) = " << residual / h << " h at its vertex " << str(x);
        }
        const PolygonSoup s = contour(t);
        INFO("box with faces half-way between lattice planes (exact arithmetic), level 5, tolerance 0: leaves with a "
             "vertex " << before << " before, " << after << " after " << collapses << " collapses");
        CHECK_MESSAGE(after < before, "no cell with a vertex merged at tolerance 0, although flat faces fit exactly");
        CHECK_MESSAGE(inexact == 0, inexact << " merged leaves do not fit their QEF exactly" << first.str());
        LAB09_CHECK_CLOSED_MANIFOLD(s, "dyadic box, simplified at tolerance 0");
        const glm::dvec3 e = dyadic.hi - dyadic.lo;
        CHECK(std::abs(enclosed_volume(s) - e.x * e.y * e.z) < 1e-9 * e.x * e.y * e.z);
        CHECK(max_abs_f(dyadic, s) < 1e-9 * h);
    }
    // boxes whose faces lie on the lattice planes of level 3 or 2 (every sample on a face is exactly 0: inside)
    const LatticeBox coarse[] = {LatticeBox(5, 0.05, {8, 8, 8}, {24, 24, 16}),
                                 LatticeBox(5, 0.05, {4, 8, 12}, {28, 20, 24})};
    for (const LatticeBox& f : coarse) {
        Octree t;
        const PolygonSoup s = cartesian_pipeline(f, 5, 1e-5, &t);
        const double h = t.size / t.resolution();
        INFO("box " << str(f.lo_) << " - " << str(f.hi_) << " with faces on coarse lattice planes, level 5, "
                    << "tolerance 1e-5 h: " << s.n_vertices() << " vertices, " << s.n_faces() << " faces");
        CHECK(s.n_vertices() == 8);
        CHECK(s.n_faces() == 12);
        LAB09_CHECK_CLOSED_MANIFOLD(s, "coarse lattice box, simplified");
        for (const glm::dvec3& v : s.positions) {
            double nearest = 1e300;
            for (int c = 0; c < 8; ++c)
                nearest = std::min(nearest, glm::length(v - glm::dvec3(c & 1 ? f.hi_.x : f.lo_.x, c & 2 ? f.hi_.y : f.lo_.y,
                                                                        c & 4 ? f.hi_.z : f.lo_.z)));
            CHECK_MESSAGE(nearest < 1e-6 * h, "vertex " << str(v) << " is " << nearest / h << " h from the nearest corner");
        }
        const glm::dvec3 e = f.hi_ - f.lo_;
        CHECK(std::abs(enclosed_volume(s) - e.x * e.y * e.z) < 1e-6 * e.x * e.y * e.z);
    }
}

TEST_CASE("simplify: tree.qefs must hold one QEF per vertex; if not std::invalid_argument and nothing changes" *
          geolab::points(1) * geolab::builds_on("Task 1, Task 2") *
          geolab::hint("simplify merges the children's QEFs from tree.qefs (tree.qefs[i] is the QEF of "
                       "tree.vertices[i], which place_vertices fills side by side). A tree whose two arrays differ "
                       "in length is a caller's mistake: throw std::invalid_argument before changing anything, "
                       "rather than reading past the end. Handout §5.2.")) {
    const FieldPtr f = geolab::box({0.03, -0.02, 0.01}, {0.61, 0.47, 0.33});  // collapses when the QEFs are there
    for (int defect = 0; defect < 3; ++defect) {
        Octree t = tree_with_vertices(*f, 4);
        REQUIRE(t.qefs.size() == t.vertices.size());
        const char* what[] = {"no QEF at all (tree.qefs empty)", "one QEF missing", "one QEF too many"};
        if (defect == 0) t.qefs.clear();
        else if (defect == 1) t.qefs.pop_back();
        else t.qefs.push_back(Qef{});
        const std::vector<OctreeNode> nodes = t.nodes;
        const std::size_t vertices = t.vertices.size(), qefs = t.qefs.size();
        INFO("box level 4, " << what[defect] << ": " << qefs << " QEFs for " << vertices << " vertices");
        CHECK_THROWS_AS(simplify(t, 1e-6, 0.01), std::invalid_argument);
        bool unchanged = t.vertices.size() == vertices && t.qefs.size() == qefs && t.nodes.size() == nodes.size();
        for (std::size_t i = 0; unchanged && i < nodes.size(); ++i)
            unchanged = t.nodes[i].first_child == nodes[i].first_child && t.nodes[i].vertex == nodes[i].vertex &&
                        t.nodes[i].signs == nodes[i].signs;
        CHECK_MESSAGE(unchanged, "the tree changed although simplify threw");
    }
}

TEST_CASE("simplify: the sign tests decide each of the 256 corner configurations (also with a stray point)" *
          geolab::points(1) *
          geolab::builds_on("Task 1") *
          geolab::hint("Test (0): every child's own corner signs form one sheet (one piece, no ambiguous face). "
                       "Test (1): the inside corners are connected through cube edges, and so are the outside ones "
                       "(both, for every one of the 256 configurations). Test (2): each of the 19 sub-lattice points "
                       "that is not a corner (edge midpoints, face centres, the centre) has the sign of at least one "
                       "corner of its edge, face or cell. Read the 27 signs from the children's OctreeNode::signs. "
                       "Handout §5.2.")) {
    // One parent of level 0 with 8 finest children (level 1). The test writes the children's signs (a pattern of
    // the 27 sub-lattice signs) and gives each child with a sign change a vertex whose QEF is the 3 axis planes
    // through the parent's centre: the merged QEF then fits exactly (Q = 0) with its minimiser at the centre, so
    // only the sign tests decide. Nothing of your place_vertices or Qef::add is used.
    const FieldPtr dummy = geolab::sphere({0.0, 0.0, 0.0}, 1.0);
    const glm::dvec3 lo(0.5, -1.5, 2.0), centre = lo + glm::dvec3(1.0);
    auto ijk = [](int p) { return glm::ivec3(p % 3, (p / 3) % 3, p / 9); };
    // the parent corners of the feature whose centre is sub-lattice point p (the corner itself for a corner)
    auto feature_corners = [&](int p) {
        int corners = 0;
        for (int c = 0; c < 8; ++c) {
            bool on = true;
            for (int a = 0; a < 3; ++a)
                if (ijk(p)[a] != 1 && ijk(p)[a] != 2 * ((c >> a) & 1)) on = false;
            if (on) corners |= 1 << c;
        }
        return corners;
    };
    // the corners of `mask` are connected through cube edges (breadth first; an empty set is connected)
    auto connected = [](int mask) {
        if (mask == 0) return true;
        int seen = 0, todo = 0;
        for (int c = 0; c < 8; ++c)
            if (mask & (1 << c)) {
                seen = todo = 1 << c;
                break;
            }
        while (todo) {
            int c = 0;
            while (!(todo & (1 << c))) ++c;
            todo &= ~(1 << c);
            for (int a = 0; a < 3; ++a) {
                const int d = c ^ (1 << a);
                if ((mask & (1 << d)) && !(seen & (1 << d))) seen |= 1 << d, todo |= 1 << d;
            }
        }
        return seen == mask;
    };
    auto corner_point = [](int c) { return 2 * (c & 1) + 6 * ((c >> 1) & 1) + 18 * (c >> 2); };
    // the QEF of the planes x = p.x, y = p.y, z = p.z, summed by hand: minimiser p, Q(p) = 0
    auto axis_planes = [](const glm::dvec3& p) {
        Qef q;
        q.ata[0] = q.ata[3] = q.ata[5] = 1.0;
        q.atb = p;
        q.btb = glm::dot(p, p);
        q.mass_sum = 3.0 * p;
        q.count = 3;
        return q;
    };
    Lcg rng(2026);
    std::size_t cases = 0, wrong = 0;
    std::ostringstream first;
    for (int m = 0; m < 256; ++m) {
        for (int variant = 0; variant < 4; ++variant) {
            // the 27 signs: corners from m; every other point the sign of one of its feature's corners (chosen at
            // random), except in variant 3 one point whose feature's corners all agree gets the other sign
            std::uint32_t in = 0;
            int stray = -1;
            for (int p = 0; p < 27; ++p) {
                const int fc = feature_corners(p);
                int pick = int(rng.uniform() * 8.0), c = 0;
                for (int k = 0;; k = (k + 1) % 8)
                    if ((fc >> k) & 1 && pick-- <= 0) {
                        c = k;
                        break;
                    }
                if ((m >> c) & 1) in |= 1u << p;
            }
            if (variant == 3) {
                std::vector<int> uniform_features;
                for (int p = 0; p < 27; ++p) {
                    const int fc = feature_corners(p);
                    if (p == corner_point(std::countr_zero(unsigned(fc))) && std::popcount(unsigned(fc)) == 1) continue;
                    if ((m & fc) == 0 || (m & fc) == fc) uniform_features.push_back(p);
                }
                if (uniform_features.empty()) continue;
                stray = uniform_features[std::size_t(rng.uniform() * double(uniform_features.size()))];
                in ^= 1u << stray;
            }
            Octree t;
            t.init_cartesian(*dummy, 1, lo, 2.0);
            const std::uint32_t first_child = t.split(0);
            int vertices = 0;
            bool children_sheet = true;  // test (0): every child's own corners form one sheet
            for (int child = 0; child < 8; ++child) {
                OctreeNode& ch = t.nodes[first_child + child];
                int signs = 0;
                for (int c = 0; c < 8; ++c) {
                    const glm::ivec3 q = glm::ivec3(child & 1, (child >> 1) & 1, child >> 2) +
                                         glm::ivec3(c & 1, (c >> 1) & 1, c >> 2);
                    signs |= int((in >> (q.x + 3 * q.y + 9 * q.z)) & 1u) << c;
                }
                ch.signs = std::uint8_t(signs);
                children_sheet = children_sheet && connected(signs) && connected(~signs & 0xff);
                ch.vertex = invalid_index;
                if (signs == 0 || signs == 0xff) continue;
                ch.vertex = std::uint32_t(t.vertices.size());
                t.vertices.push_back({centre + glm::dvec3(child & 1 ? 0.5 : -0.5, child & 2 ? 0.5 : -0.5,
                                                          child & 4 ? 0.5 : -0.5)});
                t.qefs.push_back(axis_planes(centre));
                ++vertices;
            }
            // what Ju et al.'s tests decide, computed here
            bool agree = true;
            for (int p = 0; p < 27; ++p) {
                const int fc = feature_corners(p), on = int((in >> p) & 1u);
                if (!(on ? (m & fc) : (~m & fc))) agree = false;
            }
            const bool sheet = connected(m) && connected(~m & 0xff);
            const bool collapse = children_sheet && sheet && agree && (vertices == 0 || (m != 0 && m != 0xff));
            const std::size_t collapses = simplify(t, 1e-6, 0.01);  // Q = 0 up to rounding
            ++cases;
            const OctreeNode& root = t.nodes[0];
            bool ok = collapses == (collapse ? 1u : 0u) && root.is_leaf() == collapse;
            if (ok && collapse) {
                ok = root.signs == m && (root.vertex == invalid_index) == (vertices == 0);
                if (ok && vertices > 0) {
                    ok = root.vertex < t.vertices.size() && qef_of(t, root.vertex).count == 3 * vertices &&
                         glm::length(t.vertices[root.vertex].position - centre) < 1e-12;
                }
            }
            if (!ok && wrong++ < 3) {
                first << "\n  corners inside " << std::bitset<8>(unsigned(m)) << " (bit c = corner c), the 27 signs "
                      << std::bitset<27>(in) << " (bit i + 3j + 9k)";
                if (stray >= 0) first << " with point " << stray << " on neither side of its feature's corners";
                first << ": one sheet " << (sheet ? "yes" : "no") << ", every point agrees with a corner of its "
                      << "feature " << (agree ? "yes" : "no") << ", every child's corners one sheet "
                      << (children_sheet ? "yes" : "no") << "; expected " << (collapse ? "a collapse" : "no collapse")
                      << ", got " << collapses << " collapses, root " << (root.is_leaf() ? "a leaf" : "not a leaf");
                if (root.is_leaf())
                    first << " with signs " << std::bitset<8>(root.signs) << ", vertex "
                          << (root.vertex == invalid_index ? std::string("none")
                                                           : root.vertex < t.vertices.size()
                                                                 ? str(t.vertices[root.vertex].position)
                                                                 : std::string("out of range"));
            }
        }
    }
    INFO(cases << " trees of one parent and 8 finest children (signs written by the test; each child with a "
               "sign change has a vertex whose QEF is the 3 axis planes through the parent's centre)");
    CHECK_MESSAGE(wrong == 0, wrong << " trees were simplified wrongly" << first.str());
    // test (3): the same planes through a point outside the parent (by a tenth of its side, below or above it on one
    // axis) or inside it, corner 0 inside and every other sub-lattice point outside
    const glm::dvec3 targets[] = {centre, lo + glm::dvec3(0.3, -0.2, 1.1), lo + glm::dvec3(1.7, 1.2, 2.2),
                                  lo + glm::dvec3(2.2, 1.0, 1.0), lo + glm::dvec3(0.01, 1.99, 0.5)};
    for (const glm::dvec3& target : targets) {
        Octree t;
        t.init_cartesian(*dummy, 1, lo, 2.0);
        const std::uint32_t first_child = t.split(0);
        t.nodes[first_child].signs = 1;  // corner 0 of child 0 (the parent's corner 0) inside
        t.nodes[first_child].vertex = 0;
        t.vertices.push_back({lo + glm::dvec3(0.5)});
        t.qefs.push_back(axis_planes(target));
        const bool in_cell = box_outside(Box{lo, lo + glm::dvec3(2.0)}, target) == 0.0;
        const std::size_t collapses = simplify(t, 1e-6, 0.01);
        INFO("corner 0 inside; the merged QEF's minimiser " << str(target) << " is "
                                                            << (in_cell ? "inside" : "outside") << " the parent cell "
                                                            << str(lo) << " + [0, 2]^3; got " << collapses
                                                            << " collapses");
        CHECK(collapses == (in_cell ? 1u : 0u));
        if (in_cell && t.nodes[0].is_leaf() && t.nodes[0].vertex < t.vertices.size())
            CHECK(glm::length(t.vertices[t.nodes[0].vertex].position - target) < 1e-12);
    }
    // a merged QEF of a single plane (count 1; its minimiser is the mass point, inside): a collapse; a child with a
    // sign change whose vertex has an empty QEF, or no vertex at all: no minimiser, no collapse
    for (int kind = 0; kind < 3; ++kind) {
        Octree t;
        t.init_cartesian(*dummy, 1, lo, 2.0);
        const std::uint32_t first_child = t.split(0);
        t.nodes[first_child].signs = 1;
        if (kind < 2) {
            t.nodes[first_child].vertex = 0;
            Qef q;
            if (kind == 0) {  // the plane x = centre.x through the centre, by hand
                q.ata[0] = 1.0;
                q.atb = {centre.x, 0.0, 0.0};
                q.btb = centre.x * centre.x;
                q.mass_sum = centre;
                q.count = 1;
            }
            t.vertices.push_back({lo + glm::dvec3(0.5)});
            t.qefs.push_back(q);
        }
        const std::size_t collapses = simplify(t, 1e-6, 0.01);
        const char* what[] = {"one plane through the centre (count 1)", "an empty QEF (count 0)", "no vertex"};
        INFO("corner 0 inside; the child with the sign change has " << what[kind] << "; got " << collapses
                                                                    << " collapses");
        CHECK(collapses == (kind == 0 ? 1u : 0u));
    }
}

}  // TEST_SUITE

TEST_SUITE("Task 6: contouring polygons") {

TEST_CASE("contour: sphere and torus give closed oriented 2-manifolds (chi 2 and 0)" * geolab::points(1) *
          geolab::hint("One polygon per sign-changing minimal edge, through the vertices of the 4 leaves around "
                       "it (locate at the edge midpoint +- half a finest cell), each edge once. Handout §5.3.")) {
    const FieldPtr sphere = geolab::sphere({0.02, -0.03, 0.05}, 0.7), torus = geolab::torus({0, 0, 0}, 0.6, 0.25);
    const PolygonSoup a = given_pipeline(*sphere, 5), b = given_pipeline(*torus, 5);
    LAB09_CHECK_CLOSED_MANIFOLD(a, "sphere level 5");
    LAB09_CHECK_CLOSED_MANIFOLD(b, "torus level 5");
    CHECK(edge_report(a).euler() == 2);
    CHECK(edge_report(b).euler() == 0);
    CHECK(components(a) == 1);
    CHECK(components(b) == 1);
}

TEST_CASE("contour: one quad (two triangles) per sign-changing edge; every vertex used" * geolab::points(1) *
          geolab::hint("Emit each sign-changing edge once (it is seen by up to 4 leaves); split each quad into 2 "
                       "triangles; the soup holds only referenced vertices. Handout §5.3.")) {
    const FieldPtr f = geolab::sphere({0.02, -0.03, 0.05}, 0.7);
    Octree t;
    const PolygonSoup s = given_pipeline(*f, 4, &t);
    const std::size_t edges = sign_changing_finest_edges(t), with_vertex = leaves_with_vertex(t);
    INFO("sphere level 4: " << edges << " sign-changing edges, " << with_vertex << " leaves with a vertex; soup has "
                            << s.n_faces() << " faces and " << s.n_vertices() << " vertices");
    CHECK(s.is_triangle_soup());
    CHECK(s.n_faces() == 2 * edges);
    CHECK(s.n_vertices() == with_vertex);
    CHECK(edge_report(s).referenced_vertices == s.n_vertices());
}

TEST_CASE("contour: winding follows the sign (outward normals; the inside-out field flips every face)" *
          geolab::points(1) *
          geolab::hint("Counter-clockwise around the edge's axis when the edge's LOWER end is inside (f <= 0), "
                       "reversed otherwise. Do not orient by geometry: -f has the same surface with inside and "
                       "outside swapped. Handout §5.3.")) {
    const FieldPtr f = geolab::torus({0.0, 0.05, 0.0}, 0.6, 0.25);
    const Negated g(f);
    const PolygonSoup a = given_pipeline(*f, 5), b = given_pipeline(g, 5);
    REQUIRE(a.n_faces() > 0);
    REQUIRE(b.n_faces() > 0);
    const double va = enclosed_volume(a), vb = enclosed_volume(b);
    INFO("torus level 5: volume " << va << " (expected > 0); inside-out torus: " << vb << " (expected " << -va << ")");
    CHECK(va > 0);
    CHECK(std::abs(vb + va) < 1e-9 * va);
    for (int k = 0; k < 2; ++k) {
        const PolygonSoup& s = k ? b : a;
        const ScalarField& field = k ? static_cast<const ScalarField&>(g) : *f;
        std::size_t against = 0;
        for (std::size_t i = 0; i < s.n_faces(); ++i) {
            auto vs = s.face(i);
            REQUIRE(vs.size() >= 3);
            const glm::dvec3 p0 = s.positions[vs[0]], p1 = s.positions[vs[1]], p2 = s.positions[vs[2]];
            const glm::dvec3 n = glm::cross(p1 - p0, p2 - p0);
            if (glm::dot(n, field.gradient((p0 + p1 + p2) / 3.0)) < 0) ++against;
        }
        CHECK_MESSAGE(against == 0, (k ? "inside-out torus: " : "torus: ")
                                        << against << " of " << s.n_faces() << " triangles face against grad f");
    }
}

TEST_CASE("contour: exactly the contract's triangles on uniform and adaptive Cartesian trees (edge by edge)" *
          geolab::points(1) *
          geolab::hint("For every sign-changing minimal edge: the leaves in the quadrants (-,-), (+,-), (+,+), (-,+) "
                       "of the other two axes (b, c) = (a+1, a+2) mod 3, in that order when the edge's lower end is "
                       "inside, reversed otherwise; repeated leaves dropped (a triangle); from a leaf with several "
                       "vertices the one whose edges hold the edge; a quad split along the diagonal whose triangles "
                       "both face outward when only one does, else the SHORTER one. Adaptive trees: an edge is minimal "
                       "when no leaf around it is smaller; emit it once. Handout §5.3 and §1.1.")) {
    struct Case {
        FieldPtr f;
        int level, collapse_from;  // collapse_from > level: no collapse (a uniform band of finest leaves)
        const char* what;
    };
    const LatticeBox lbox(5, 0.05, {6, 9, 11}, {25, 20, 23});
    const FieldPtr lattice_box(&lbox, [](const ScalarField*) {});
    // a sphere whose bounds() claim less than it is: the domain cube cuts it (edges at the domain's faces have
    // quadrants outside the domain: no polygon there, the surface stays open)
    struct Cropped final : ScalarField {
        FieldPtr f = geolab::sphere({0.1, -0.05, 0.08}, 0.8);
        double value(const glm::dvec3& p) const override { return f->value(p); }
        glm::dvec3 gradient(const glm::dvec3& p) const override { return f->gradient(p); }
        Box bounds() const override { return {glm::dvec3(-0.55, -0.6, -0.5), glm::dvec3(0.65, 0.5, 0.6)}; }
        double lipschitz() const override { return 1.0; }
    };
    const FieldPtr cropped = std::make_shared<Cropped>();
    const Case cases[] = {
        {geolab::sphere({0.02, -0.03, 0.05}, 0.7), 4, 9, "sphere r = 0.7, level 4"},
        {geolab::torus({0.01, 0.02, -0.03}, 0.6, 0.25), 5, 9, "torus, level 5"},
        {lattice_box, 5, 9, "box with faces on lattice planes (equal diagonals), level 5"},
        {geolab::named_implicit("csg"), 5, 3, "csg, level 5, cells of levels 3-4 merged where the sign tests allow"},
        {geolab::named_implicit("rounded_box"), 5, 2, "rounded box, level 5, cells of levels 2-4 merged"},
        {geolab::sphere({0.05, 0.02, -0.04}, 0.75), 5, 3, "sphere r = 0.75, level 5, cells of levels 3-4 merged"},
        {cropped, 4, 9, "sphere r = 0.8 cut by the domain cube (an open surface), level 4"},
        {cropped, 5, 3, "sphere r = 0.8 cut by the domain cube, level 5, cells of levels 3-4 merged"},
    };
    for (const Case& cs : cases) {
        Octree t = given_octree(*cs.f, cs.level);
        given_vertices(t);
        const std::size_t merged = cs.collapse_from <= cs.level ? given_collapse(t, cs.collapse_from) : 0;
        const ReferenceContour ref = reference_contour(t);
        INFO(cs.what << ": " << merged << " cells merged (without your simplify); " << ref.edges
                     << " sign-changing minimal edges, " << ref.tie_quads.size() << " quads with equal diagonals");
        REQUIRE(ref.no_vertex.empty());
        REQUIRE(ref.edges > 0);
        if (cs.collapse_from <= cs.level) REQUIRE(merged > 0);
        PolygonSoup s;
        REQUIRE_NOTHROW(s = contour(t));
        const std::string diff = compare_polygons(s, ref);
        CHECK_MESSAGE(diff.empty(), diff);
        const std::size_t used = edge_report(s).referenced_vertices;
        CHECK_MESSAGE(used == s.n_vertices(), s.n_vertices() << " positions in the soup, " << used << " used by faces");
    }
}

TEST_CASE("contour: a box with faces on lattice planes (f = 0 at lattice points) is closed and exact" *
          geolab::points(2) * geolab::builds_on("Task 1, Task 2") *
          geolab::hint("Use the same tie rule (f <= 0 inside) in place_vertices and contour: a sample that is exactly "
                       "0 must be on the same side for both, or cells around an edge lack vertices. Handout §5.3.")) {
    const LatticeBox f(5, 0.05, {6, 9, 11}, {25, 20, 23});
    const PolygonSoup s = cartesian_pipeline(f, 5);
    LAB09_CHECK_CLOSED_MANIFOLD(s, "lattice box level 5");
    const glm::dvec3 e = f.hi_ - f.lo_;
    const double exact = e.x * e.y * e.z, got = enclosed_volume(s);
    INFO("box volume " << exact << ", mesh volume " << got);
    CHECK(std::abs(got - exact) < 1e-6 * exact);
}

}  // TEST_SUITE
