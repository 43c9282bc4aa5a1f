// Lab 09, Task 3: the Cartesian octree with conservative refinement (handout §4).
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab09;

namespace {
CartesianParams params(int level) {
    CartesianParams p;
    p.max_level = level;
    return p;
}

// Every surface sample must lie in a leaf of level L (checked through the given Octree::locate).
void check_surface_cells_are_finest(const Octree& t, const ScalarField& f, const std::string& label) {
    const double h = t.size / t.resolution();
    Box box = f.bounds();
    box.lo -= h, box.hi += h;
    const auto samples = surface_samples(f, box, 0.3 * h);
    INFO(label << ": " << samples.size() << " surface samples, grid step 0.3 h, h = " << h);
    REQUIRE(samples.size() > 100);
    std::size_t bad = 0;
    std::ostringstream first;
    for (const auto& p : samples) {
        const std::uint32_t leaf = leaf_at(t, p);
        REQUIRE(leaf != invalid_index);
        if (t.nodes[leaf].level != t.max_level && bad++ < 3)
            first << "\n  surface point " << str(p) << " is in a leaf of level " << int(t.nodes[leaf].level)
                  << " (cell " << t.nodes[leaf].x << ", " << t.nodes[leaf].y << ", " << t.nodes[leaf].z << ")";
    }
    CHECK_MESSAGE(bad == 0, bad << " surface samples lie in leaves coarser than max_level " << t.max_level
                                << first.str());
}
}  // namespace

TEST_SUITE("Task 3: Cartesian octree") {

TEST_CASE("build_octree: every finest cell the sphere passes through is a leaf at max_level" * geolab::points(2) *
          geolab::hint("Refine while |f(centre)| <= Lf * (half diagonal of the cell): a Lipschitz field cannot reach "
                       "0 inside a cell whose centre is farther than that. Corner signs alone miss surfaces that "
                       "enter and leave a cell between its corners. Handout §4.2.")) {
    const FieldPtr f = geolab::sphere({0.1, -0.2, 0.05}, 0.7);
    for (int level : {4, 6}) {
        const Octree t = build_octree(*f, params(level));
        const auto [lo, side] = cartesian_domain(*f, 0.05);
        INFO("sphere centre (0.1, -0.2, 0.05) radius 0.7, level " << level);
        REQUIRE(t.nodes.size() > 1);
        CHECK(t.max_level == level);
        CHECK(t.coordinates == Coordinates::cartesian);
        CHECK(glm::length(t.min_corner - lo) < 1e-12);
        CHECK(std::abs(t.size - side) < 1e-12);
        check_surface_cells_are_finest(t, *f, "sphere level " + std::to_string(level));
    }
}

TEST_CASE("build_octree: refines exactly the cells allowed by the conservative test; leaves tile the cube" *
          geolab::points(2) *
          geolab::hint("Internal nodes: |f(c)| <= Lf * half diagonal; leaves above max_level: |f(c)| > Lf * half "
                       "diagonal (do not refine everything: the tree must stay sparse). lipschitz() == 0: Lf = 2 x "
                       "the largest |grad f| at the 9^3 points lo + side/8 (i, j, k). Use Octree::split so "
                       "children follow the c = cx + 2cy + 4cz order. Handout §4.2.")) {
    const FieldPtr torus = geolab::torus({0.05, 0.0, -0.1}, 0.6, 0.25);
    // and fields without a Lipschitz constant: Lf = 2 max |grad f| on the 9^3 lattice of the domain cube. |grad f| =
    // 2 |p - c| is largest at the lattice corner farthest from c: any corner when the domain is centred on c; the
    // corner (0, 8, 0) or (8, 0, 8) of the lattice with the larger bounds; and below 1 everywhere for a tiny ball
    const glm::dvec3 c1(0.3, -0.1, 0.2), c2(-0.2, 0.15, 0.1);
    const QuadraticBall quadratics[] = {
        QuadraticBall({0.1, -0.2, 0.05}, 0.6),
        QuadraticBall(c1, 0.5, Box{c1 - glm::dvec3(1.1, 0.5, 0.9), c1 + glm::dvec3(0.5, 1.1, 0.5)}),
        QuadraticBall(c2, 0.5, Box{c2 - glm::dvec3(0.5, 1.1, 0.5), c2 + glm::dvec3(1.1, 0.5, 0.9)}),
        QuadraticBall({0.02, 0.01, -0.03}, 0.05)};
    // every reachable node against the rule |f(c)| <= lf * half diagonal, from its centre sample
    auto check_rule = [](const Octree& t, const ScalarField& f, double lf, const std::string& what, bool sparse) {
        const int L = t.max_level;
        const TreeShape shape = tree_shape(t);
        INFO(what << ", level " << L << ": " << shape.leaves.size() << " leaves; expected Lf = " << lf);
        REQUIRE(shape.leaves.size() > 8);
        CHECK(shape.bad_children == 0);
        CHECK(shape.deeper_than_max == 0);
        double volume = 0;
        const double h = t.size / t.resolution();
        std::size_t too_coarse = 0, too_fine = 0;
        std::vector<std::uint32_t> stack{0};
        while (!stack.empty()) {
            const std::uint32_t n = stack.back();
            stack.pop_back();
            const OctreeNode& nd = t.nodes[n];
            const std::int32_t s = t.cell_span(nd.level);
            const glm::dvec3 c = t.min_corner + h * (glm::dvec3(nd.x, nd.y, nd.z) * double(s) + 0.5 * s);
            const double half_diag = 0.5 * std::sqrt(3.0) * h * s;
            const double v = std::abs(f.value(c)), bound = lf * half_diag;
            if (nd.is_leaf()) {
                volume += std::pow(h * s, 3);
                if (nd.level < L && v <= bound * (1 - 1e-9)) ++too_coarse;
            } else {
                if (v > bound * (1 + 1e-9)) ++too_fine;
                for (int c8 = 0; c8 < 8; ++c8) stack.push_back(nd.first_child + c8);
            }
        }
        CHECK_MESSAGE(too_coarse == 0, too_coarse << " leaves above max_level pass the test |f(c)| <= Lf * half "
                                                     "diagonal (they may contain the surface and must be split)");
        CHECK_MESSAGE(too_fine == 0, too_fine << " nodes were split although |f(c)| > Lf * half diagonal (over-refined)");
        CHECK(std::abs(volume - std::pow(t.size, 3)) < 1e-9 * std::pow(t.size, 3));
        if (sparse) CHECK(shape.leaves.size() < std::size_t(1) << (3 * L - 2));
    };
    for (int k = 0; k < 5; ++k) {
        const ScalarField& f = k == 0 ? *torus : static_cast<const ScalarField&>(quadratics[k - 1]);
        const Octree t = build_octree(f, params(5));
        const double lf = k == 0 ? f.lipschitz() : quadratics[k - 1].estimate(t.min_corner, t.size);
        std::ostringstream what;
        if (k == 0) what << "torus R = 0.6, r = 0.25";
        else
            what << "f = |p - c|^2 - r^2, c = " << str(quadratics[k - 1].c_) << ", r = " << quadratics[k - 1].r_
                 << ", bounds " << str(f.bounds().lo) << " - " << str(f.bounds().hi) << ", no Lipschitz constant";
        check_rule(t, f, lf, what.str(), k == 0);
    }
    // exactly the 9^3 points lo + side/8 (i, j, k), i, j, k = 0..8: a gradient 1000 times too long at one of them
    // (a corner of the lattice) must be seen, and at points beside the lattice (index 9 or -1 on one axis, a half
    // index, far outside) must not
    const glm::dvec3 c(0.1, -0.05, 0.02);
    const double r = 0.6;
    const auto [lo, side] = cartesian_domain(SpikyGradient(c, r, glm::dvec3(1e9)), 0.05);
    auto at = [&, lo = lo, side = side](double i, double j, double k) { return lo + side / 8.0 * glm::dvec3(i, j, k); };
    std::vector<glm::dvec3> lattice;
    for (int i = 0; i <= 8; ++i)
        for (int j = 0; j <= 8; ++j)
            for (int k = 0; k <= 8; ++k) lattice.push_back(at(i, j, k));
    struct Spike {
        glm::dvec3 p;
        double scale;
        const char* what;
    };
    const Spike spikes[] = {{at(0, 0, 0), 1.0, "lattice index (0, 0, 0)"},
                            {at(8, 8, 8), 1.0, "lattice index (8, 8, 8)"},
                            {at(9, 4, 4), 1.0, "index (9, 4, 4), beside the lattice"},
                            {at(4, 9, 4), 1.0, "index (4, 9, 4), beside the lattice"},
                            {at(4, 4, 9), 1.0, "index (4, 4, 9), beside the lattice"},
                            {at(0.5, 0.5, 0.5), 1.0, "index (0.5, 0.5, 0.5), between lattice points"},
                            {at(-1, -1, -1), 1.0, "index (-1, -1, -1), beside the lattice"},
                            {at(64, 64, 64), 1.0, "index (64, 64, 64), far outside"},
                            {glm::dvec3(1e9), 0.1, "nowhere, |grad f| = 0.1 everywhere"}};
    for (const Spike& sp : spikes) {
        const SpikyGradient f(c, r, sp.p, sp.scale);
        const Octree t = build_octree(f, params(4));
        check_rule(t, f, f.estimate(lattice),
                   std::string("sphere distance without a Lipschitz constant, |grad f| 1000 times too long at ") + sp.what,
                   false);
    }
}

TEST_CASE("build_octree: a thin torus (tube thinner than the coarse cells) is refined all along" * geolab::points(2) *
          geolab::hint("A tube of radius 0.015 never contains a lattice corner of the coarse levels: only the "
                       "conservative distance test sees it. Handout §4.2.")) {
    const FieldPtr f = geolab::torus({0.0, 0.0, 0.0}, 0.6, 0.015);
    for (int level : {5, 6}) {
        const Octree t = build_octree(*f, params(level));
        REQUIRE(t.nodes.size() > 1);
        check_surface_cells_are_finest(t, *f, "thin torus R = 0.6, r = 0.015, level " + std::to_string(level));
    }
}

TEST_CASE("build_octree: a mesh with a hole (its sign jumps across the hole): every leaf at a sign change is finest" *
          geolab::points(2) * geolab::builds_on("Task 1, Task 2, Task 4, Task 5, Task 6") *
          geolab::hint("The distance test is a guarantee only where f is continuous. MeshField's sign flips on a cap "
                       "across a hole, far from the mesh, where |f| is large: finish the tree with the given "
                       "tree.refine_around_sign_changes(). Handout §2, 'Where the test is no guarantee'.")) {
    const PolygonSoup open_sphere = sphere_with_hole();
    REQUIRE(boundary_loops(open_sphere) == 1);
    const geolab::MeshField f(open_sphere);
    REQUIRE(f.sign_may_jump());
    for (int level : {5, 6}) {
        Octree t = build_octree(f, params(level));
        REQUIRE(t.nodes.size() > 1);
        INFO("icosphere r = 0.8 with a hole of radius 0.6 around +Z, level " << level);
        check_closure(t);
        // what goes wrong otherwise: contour finds a leaf without a vertex around a sign-changing edge
        place_vertices(t, {});
        PolygonSoup s;
        CHECK_NOTHROW(s = contour(t));
        const EdgeReport er = edge_report(s);
        INFO("contour: " << describe(er));
        CHECK(er.faces > 0);
        CHECK_MESSAGE(er.boundary == 0, "the cap across the hole must close the mesh: " << er.boundary
                                                                                     << " boundary edges");
    }
}

TEST_CASE("build_octree: max_level outside 1..10 throws std::invalid_argument; 1 and 10 are accepted" *
          geolab::points(1) *
          geolab::hint("Check the level first (Octree::init_cartesian does it too): 1 <= max_level <= 10, both ends "
                       "included. Handout §4.1.")) {
    const FieldPtr f = geolab::sphere({0, 0, 0}, 0.5);
    const Octree ok = build_octree(*f, params(3));
    REQUIRE(ok.nodes.size() > 1);
    const Octree one = build_octree(*f, params(1));
    CHECK(one.max_level == 1);
    CHECK(tree_shape(one).leaves.size() == 8);
    // level 10 around a sphere of radius 0.004 (about 2 finest cells) inside the bounds [-1, 1]^3
    const TinySphere tiny({0.3, -0.2, 0.1}, 0.004);
    Octree ten;
    CHECK_NOTHROW(ten = build_octree(tiny, params(10)));
    INFO("tiny sphere, level 10: " << ten.nodes.size() << " nodes, max_level " << ten.max_level);
    CHECK(ten.max_level == 10);
    REQUIRE(ten.nodes.size() > 1);
    const std::uint32_t leaf = leaf_at(ten, {0.3, -0.2, 0.104});
    REQUIRE(leaf != invalid_index);
    CHECK(int(ten.nodes[leaf].level) == 10);
    CHECK(tree_shape(ten).deeper_than_max == 0);
    CHECK_THROWS_AS(build_octree(*f, params(0)), std::invalid_argument);
    CHECK_THROWS_AS(build_octree(*f, params(11)), std::invalid_argument);
    CHECK_THROWS_AS(build_octree(*f, params(-2)), std::invalid_argument);
}

}  // TEST_SUITE
