// Lab 09: manifold dual contouring (handout §1.1): a vertex per piece of a finest cell's surface, polygons that take
// the piece crossing their edge, the diagonal of each quad, and closed 2-manifolds on real models.
#include <bitset>
#include <set>

#include "geolab/grading/chain.hpp"
#include "manifold.hpp"

using namespace lab09;

namespace {
// The finest leaf at cell index `cell` of a Cartesian tree (through the given locate()).
std::uint32_t leaf_of_cell(const Octree& t, glm::ivec3 cell) { return t.locate(2 * cell + 1); }

// given_octree + given_vertices + your contour, the tree kept.
PolygonSoup given_contour(const ScalarField& f, int level, Octree& t) {
    t = given_octree(f, level);
    given_vertices(t);
    return contour(t);
}

// A Cartesian tree of `level` over f's domain (padding 0.05), complete to level `coarse` and split to `level` only in
// the half x < the middle: leaves of level `coarse` on the other half (the given Octree API only).
Octree half_refined_cartesian(const ScalarField& f, int level, int coarse) {
    const auto [lo, side] = cartesian_domain(f, 0.05);
    Octree t;
    t.init_cartesian(f, level, lo, side);
    for (std::uint32_t n = 0; n < t.nodes.size(); ++n) {
        const OctreeNode nd = t.nodes[n];
        if (nd.level >= level) continue;
        const bool low_half = (std::int32_t(nd.x) + 1) * t.cell_span(nd.level) <= t.resolution() / 2;
        if (nd.level < coarse || low_half) t.split(n);
    }
    return t;
}

// A spherical tree of `level` about the origin, shell [0, r_max], complete to level `coarse` and split to `level`
// only where phi < pi: leaves of level `coarse` (also around the polar axis) where phi >= pi.
Octree half_refined_spherical(const ScalarField& f, int level, int coarse, double r_max) {
    Octree t;
    t.init_spherical(f, level, glm::dvec3(0.0), 0.0, r_max);
    for (std::uint32_t n = 0; n < t.nodes.size(); ++n) {
        const OctreeNode nd = t.nodes[n];
        if (nd.level >= level) continue;
        const bool low_half = (std::int32_t(nd.z) + 1) * t.cell_span(nd.level) <= t.resolution() / 2;
        if (nd.level < coarse || low_half) t.split(n);
    }
    return t;
}

// Leaves coarser than the finest level with a sign change, and those of them whose crossings are fewer than their
// sign-changing cell edges (the polar axis edge, twice a cell edge there).
std::size_t coarse_cut_leaves(const Octree& t, bool on_axis_only) {
    std::size_t n = 0;
    for (std::uint32_t li : tree_shape(t).leaves) {
        const OctreeNode& nd = t.nodes[li];
        const CellSurface p = expected_pieces(t, nd);
        if (nd.level == t.max_level || p.count == 0) continue;
        if (!on_axis_only || distinct_crossings(t, nd, p.edges[0]) < std::popcount(unsigned(p.edges[0]))) ++n;
    }
    return n;
}
}  // namespace

TEST_SUITE("Task 4: vertex placement") {

TEST_CASE("place_vertices: a finest leaf gets one vertex per piece of its surface in DualVertex's layout" *
          geolab::points(2) * geolab::builds_on("Task 1, Task 2") *
          geolab::hint("cell_surface(signs, face_joins(tree, leaf)) gives the pieces of a finest leaf: one vertex per "
                       "piece, consecutive from OctreeNode::vertex, vertex k with the edges of piece k and pieces = the "
                       "count; its QEF holds the crossings of its own piece's edges only. Handout §1.1.")) {
    const DiagonalBalls balls(5, {16, 16, 16}, 0.4, 0.2);
    const LatticeBlock cavities = two_cavities(), cavities_x = two_cavities_x(), cavities_y = two_cavities_y(),
                       four = four_pieces();
    struct Case {
        const ScalarField* f;
        int level, min_pieces;
        bool joins;
        const char* name;
    };
    const Case cases[] = {
        {&balls, 5, 2, false, "two balls r = 0.4, 0.2 h apart across a cell's diagonal, level 5"},
        {&cavities, 3, 2, true, "lattice block [2, 6]^3 with two outside points on a z-face diagonal, level 3"},
        {&cavities_x, 3, 2, true, "lattice block [2, 6]^3 with two outside points on an x-face diagonal, level 3"},
        {&cavities_y, 3, 2, true, "lattice block [2, 6]^3 with two outside points on a y-face diagonal, level 3"},
        {&four, 3, 4, false, "four inside lattice points at corners 0, 3, 5, 6 of one cell, level 3"}};
    for (const auto& [f, level, min_pieces, joins, name] : cases) {
        Octree t = given_octree(*f, level);
        place_vertices(t, {});
        INFO(name << ": " << leaves_with_pieces(t, min_pieces) << " leaves with " << min_pieces << " or more pieces, "
                  << leaves_with_joins(t) << " with a joined face");
        REQUIRE(leaves_with_pieces(t, min_pieces) > 0);
        if (joins) REQUIRE(leaves_with_joins(t) > 0);
        std::ostringstream first;
        const std::size_t wrong = wrong_layouts(t, first, true);
        CHECK_MESSAGE(wrong == 0, wrong << " leaves do not have one vertex per piece as DualVertex's layout says"
                                        << first.str());
        // each vertex in its cell
        const double h = t.size / t.resolution();
        std::size_t outside = 0;
        for (std::uint32_t li : tree_shape(t).leaves) {
            const OctreeNode& nd = t.nodes[li];
            if (nd.vertex == invalid_index || nd.vertex >= t.vertices.size()) continue;
            for (int k = 0; k < t.vertices[nd.vertex].pieces && nd.vertex + k < t.vertices.size(); ++k)
                outside += box_outside(cell_box(t, nd), t.vertices[nd.vertex + k].position) > 1e-9 * h;
        }
        CHECK_MESSAGE(outside == 0, outside << " vertices lie outside their cells");
    }
}

TEST_CASE("place_vertices: the two pieces of a cell between two balls stay on their own balls" *
          geolab::points(1) * geolab::builds_on("Task 1, Task 2") *
          geolab::hint("A piece's QEF holds only the crossings on its own edges, so its vertex lies on its own "
                       "surface; one QEF for the whole cell would put a vertex between the balls. Handout §1.1.")) {
    const DiagonalBalls f(5, {16, 16, 16}, 0.4, 0.2);
    Octree t = given_octree(f, 5);
    place_vertices(t, {});
    const std::uint32_t li = leaf_of_cell(t, {16, 16, 16});
    REQUIRE(li != invalid_index);
    const OctreeNode& nd = t.nodes[li];
    INFO("the cell between the balls: signs 0x" << std::hex << int(expected_signs(t, nd)) << std::dec);
    REQUIRE(nd.vertex != invalid_index);
    REQUIRE(nd.vertex + 1 < t.vertices.size());
    REQUIRE(t.vertices[nd.vertex].pieces == 2);
    const double h = t.size / t.resolution();
    for (int k = 0; k < 2; ++k) {
        const glm::dvec3 p = t.vertices[nd.vertex + k].position;
        const double d1 = glm::length(p - f.c1_) - f.r_, d2 = glm::length(p - f.c2_) - f.r_;
        INFO("vertex " << k << " at " << str(p) << ": " << d1 / h << " h from ball 1, " << d2 / h << " h from ball 2");
        CHECK(std::min(std::abs(d1), std::abs(d2)) < 0.05 * h);
    }
    // one on each ball
    const glm::dvec3 p0 = t.vertices[nd.vertex].position, p1 = t.vertices[nd.vertex + 1].position;
    CHECK((glm::length(p0 - f.c1_) < glm::length(p0 - f.c2_)) != (glm::length(p1 - f.c1_) < glm::length(p1 - f.c2_)));
}

TEST_CASE("place_vertices: a leaf coarser than the finest level gets one vertex for all its crossings" *
          geolab::points(1) * geolab::builds_on("Task 1, Task 2") *
          geolab::hint("Only finest leaves are split into pieces; any other leaf with a sign change has ONE vertex "
                       "(pieces = 1) whose edges are all its sign-changing cell edges and whose QEF holds each of "
                       "their crossings once (the radial edge on the polar axis is two cell edges of a spherical cell "
                       "there: one crossing). Handout §1.1.")) {
    const FieldPtr sphere = geolab::sphere({0.1, -0.05, 0.08}, 0.6), torus = geolab::torus({0.02, 0.01, -0.03}, 0.55, 0.2);
    struct Case {
        Octree t;
        bool spherical;
        std::string what;
    };
    std::vector<Case> cases;
    cases.push_back({half_refined_cartesian(*sphere, 5, 2), false, "sphere r = 0.6, Cartesian, levels 2 and 5"});
    cases.push_back({half_refined_cartesian(*torus, 4, 3), false, "torus, Cartesian, levels 3 and 4"});
    cases.push_back({half_refined_spherical(*sphere, 4, 2, 1.0), true, "sphere r = 0.6 about the origin's side, "
                                                                        "spherical, levels 2 (phi >= pi) and 4"});
    for (Case& cs : cases) {
        INFO(cs.what << ": " << coarse_cut_leaves(cs.t, false) << " coarse leaves with a sign change, "
                     << coarse_cut_leaves(cs.t, true) << " of them on the polar axis with its edge crossed");
        REQUIRE(coarse_cut_leaves(cs.t, false) > 0);
        if (cs.spherical) REQUIRE(coarse_cut_leaves(cs.t, true) > 0);
        place_vertices(cs.t, {});
        std::ostringstream first;
        const std::size_t wrong = wrong_layouts(cs.t, first, true);
        CHECK_MESSAGE(wrong == 0, wrong << " leaves do not have the vertices DualVertex's layout says" << first.str());
        if (cs.spherical) continue;
        // Cartesian: a coarse leaf's vertex is its QEF's minimiser when that lies in the leaf's box, else the mass point
        std::size_t checked = 0, wrong_position = 0;
        std::ostringstream where;
        for (std::uint32_t li : tree_shape(cs.t).leaves) {
            const OctreeNode& nd = cs.t.nodes[li];
            if (nd.level == cs.t.max_level || nd.vertex >= cs.t.vertices.size()) continue;
            const DualVertex& v = cs.t.vertices[nd.vertex];
            const Box box = cell_box(cs.t, nd);
            const glm::dvec3 x = qef_of(cs.t, nd.vertex).solve(0.01);
            const glm::dvec3 want = box_outside(box, x) == 0.0 ? x : glm::clamp(qef_of(cs.t, nd.vertex).mass_point(), box.lo, box.hi);
            ++checked;
            if (glm::length(v.position - want) > 1e-9 * cs.t.size && wrong_position++ < 3)
                where << "\n  leaf (" << nd.x << ", " << nd.y << ", " << nd.z << ") level " << int(nd.level) << ": vertex "
                      << str(v.position) << ", expected " << str(want);
        }
        CHECK(checked > 0);
        CHECK_MESSAGE(wrong_position == 0, wrong_position << " coarse leaves' vertices are neither their QEF minimiser "
                                                             "in the cell nor the clamped mass point" << where.str());
    }
}

TEST_CASE("place_vertices: random corner signs on a small lattice (all 256 configurations and joined faces) in "
          "DualVertex's layout" *
          geolab::points(1) * geolab::builds_on("Task 1, Task 2") *
          geolab::hint("Every finest leaf: the pieces of cell_surface(signs, face_joins(tree, leaf)) — do not skip "
                       "face_joins for any configuration that has an ambiguous face. Handout §1.1.")) {
    Lcg rng(21);
    std::size_t cells = 0, multi = 0, joined = 0, wrong = 0;
    std::bitset<256> seen;
    std::ostringstream first;
    for (int pattern = 0; pattern < 120; ++pattern) {
        // level 2: 5 x 5 x 5 lattice points, each inside with probability 0.3 to 0.7
        const double p_in = 0.3 + 0.4 * rng.uniform();
        std::vector<glm::ivec3> islands;
        for (int x = 0; x <= 4; ++x)
            for (int y = 0; y <= 4; ++y)
                for (int z = 0; z <= 4; ++z)
                    if (rng.uniform() < p_in) islands.push_back({x, y, z});
        const LatticeBlock f(2, 1, 0, {}, islands);
        Octree t = given_octree(f, 2);
        place_vertices(t, {});
        for (std::uint32_t li : tree_shape(t).leaves) {
            const OctreeNode& nd = t.nodes[li];
            seen.set(std::size_t(expected_signs(t, nd)));
            ++cells;
        }
        multi += leaves_with_pieces(t, 2);
        joined += leaves_with_joins(t);
        std::ostringstream here;
        const std::size_t w = wrong_layouts(t, here, true);
        if (w && wrong == 0) first << "\n  pattern " << pattern << ":" << here.str();
        wrong += w;
    }
    INFO(cells << " finest cells in 120 random sign patterns, " << seen.count() << " of the 256 configurations, " << multi
               << " cells with 2 or more pieces, " << joined << " with a joined face");
    REQUIRE(seen.count() == 256);
    REQUIRE(joined > 0);
    CHECK_MESSAGE(wrong == 0, wrong << " leaves do not have the vertices DualVertex's layout says" << first.str());
}

}  // TEST_SUITE

TEST_SUITE("Task 5: simplification") {

TEST_CASE("simplify: a cell with two pieces never merges: two nearly touching balls stay two closed surfaces" *
          geolab::points(1) * geolab::builds_on("Task 1, Task 2") *
          geolab::hint("Merge only when every child's own corner signs form a single sheet (one piece, no ambiguous "
                       "face) besides Ju et al.'s tests: one vertex for the parent would join the balls. Handout §1.1.")) {
    const DiagonalBalls f(5, {16, 16, 16}, 0.4, 0.2);
    for (double tol : {0.05, 1e6}) {
        Octree t;
        const PolygonSoup s = cartesian_pipeline(f, 5, tol, &t);
        const std::string label = "two balls 0.2 h apart, level 5, simplified at " + std::to_string(tol) + " h";
        LAB09_CHECK_2_MANIFOLD(s, label, false);
        const geolab::SurfaceCheck sc = surface_check(s, false);
        CHECK(sc.components == 2);
        CHECK(sc.euler_characteristic == 4);
    }
}

TEST_CASE("simplify: a merged leaf has one vertex holding the parent's sign-changing edges (DualVertex's layout)" *
          geolab::points(1) * geolab::builds_on("Task 1, Task 2") *
          geolab::hint("The new leaf's vertex: pieces = 1 and edges = the sign-changing edges of the parent's own "
                       "cell (from its corner signs), so contour can treat it like any one-vertex leaf. Handout §1.1.")) {
    for (const char* name : {"csg", "rounded_box", "box"}) {
        const FieldPtr f = geolab::named_implicit(name);
        Octree t;
        cartesian_pipeline(*f, 5, 1e6, &t);  // merge wherever the sign tests allow
        std::size_t merged = 0;
        for (std::uint32_t li : tree_shape(t).leaves)
            merged += t.nodes[li].level < t.max_level && t.nodes[li].vertex != invalid_index;
        INFO(name << " level 5 simplified at 1e6 h: " << merged << " merged leaves with a vertex");
        REQUIRE(merged > 0);
        std::ostringstream first;
        const std::size_t wrong = wrong_layouts(t, first, false);
        CHECK_MESSAGE(wrong == 0, wrong << " leaves do not have the vertices DualVertex's layout says" << first.str());
    }
}

}  // TEST_SUITE

TEST_SUITE("Task 6: contouring polygons") {

TEST_CASE("contour: two balls closer than a cell: each polygon takes the piece that crosses its edge" *
          geolab::points(2) *
          geolab::hint("In a leaf with several vertices use the one whose DualVertex::edges holds the polygon's edge "
                       "(its number as the leaf's own cell edge); a leaf with one vertex gives it. Handout §1.1.")) {
    for (double gap : {0.2, 0.6}) {
        const DiagonalBalls f(5, {16, 16, 16}, 0.4, gap);
        Octree t;
        const PolygonSoup s = given_contour(f, 5, t);
        const std::string label = "two balls r = 0.4, " + std::to_string(gap) + " h apart, level 5";
        REQUIRE(leaves_with_pieces(t, 2) > 0);
        LAB09_CHECK_2_MANIFOLD(s, label, false);
        const geolab::SurfaceCheck sc = surface_check(s, false);
        INFO(label << ": " << sc.summary());
        CHECK(sc.components == 2);
        CHECK(sc.euler_characteristic == 4);
        const double v = enclosed_volume(s);
        CHECK(std::abs(v - 2 * sphere_volume(0.4)) < 0.05 * 2 * sphere_volume(0.4));
    }
}

TEST_CASE("contour: an ambiguous face joined by face_joins leaves two separate cavities" * geolab::points(1) *
          geolab::hint("The given vertices follow cell_surface(signs, face_joins): a leaf at the joined face has two "
                       "pieces, and each polygon must take the one that crosses its edge. Handout §1.1.")) {
    const LatticeBlock f = two_cavities();
    Octree t;
    const PolygonSoup s = given_contour(f, 3, t);
    REQUIRE(leaves_with_joins(t) > 0);
    LAB09_CHECK_2_MANIFOLD(s, "lattice block with two cavities, level 3", false);
    const geolab::SurfaceCheck sc = surface_check(s, false);
    INFO(sc.summary());
    CHECK(sc.components == 3);
    CHECK(sc.euler_characteristic == 6);
    // the surface runs half-way between inside and outside lattice points: about the block [1.5, 6.5]^3 of lattice
    // units (its edges and corners cut off), minus the two cavities
    const double h = 0.275, block = std::pow(5 * h, 3);
    INFO("enclosed volume " << enclosed_volume(s) << ", block " << block);
    CHECK(enclosed_volume(s) > 0.7 * block);
    CHECK(enclosed_volume(s) < block);
}

TEST_CASE("contour: a quad is split along the diagonal whose triangles face outward; else the shorter one" *
          geolab::points(1) *
          geolab::hint("Split a quad (a, b, c, d) along a-c or b-d: when only one choice gives two triangles whose "
                       "normals point along the edge's outward direction (from its inside end to its outside end), "
                       "take it, the other folds the mesh; otherwise take the shorter diagonal (equal: a-c, from the "
                       "polygon's first vertex). Handout §1.1.")) {
    // one inside lattice point P = (2, 2, 2) of a complete level-2 tree: the edge from P along +x (outward +x) has
    // the cells (2, 1, 1), (2, 2, 1), (2, 2, 2), (2, 1, 2) around it, counter-clockwise seen from +x
    const TinySphere probe(glm::dvec3(0.0), 1.0);
    const auto [lo, side] = cartesian_domain(probe, 0.05);
    const double h = side / 4;
    const glm::dvec3 p = lo + 2.0 * h;
    const TinySphere f(p, 0.3 * h);
    const glm::ivec3 cells[4] = {{2, 1, 1}, {2, 2, 1}, {2, 2, 2}, {2, 1, 2}};
    struct Case {
        glm::dvec2 yz[4];  // the 4 vertices' (y, z) offsets from P, in h
        int diagonal;      // the expected one: 0 = a-c, 1 = b-d
        const char* what;
    };
    const Case cases[] = {
        {{{-0.95, -0.95}, {0.1, -0.01}, {0.01, 0.01}, {-0.01, 0.1}}, 0,
         "a far from the edge, c close to it: b-d is shorter but its triangle b c d faces inward"},
        {{{-0.9, -0.9}, {0.3, -0.3}, {0.5, 0.5}, {-0.3, 0.3}}, 1, "a convex quad: both face outward, b-d is shorter"},
        {{{-0.3, -0.3}, {0.9, -0.9}, {0.3, 0.3}, {-0.9, 0.9}}, 0, "a convex quad: both face outward, a-c is shorter"},
        {{{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}}, 0,
         "a square: both face outward, equal diagonals: the one from the first vertex, a-c"}};
    for (const Case& cs : cases) {
        Octree t;
        t.init_cartesian(f, 2, lo, side);
        for (std::uint32_t n = 0; n < t.nodes.size(); ++n)
            if (t.nodes[n].level < 2) t.split(n);
        given_vertices(t);
        glm::dvec3 q[4];
        for (int k = 0; k < 4; ++k) {
            const std::uint32_t li = leaf_of_cell(t, cells[k]);
            REQUIRE(li != invalid_index);
            REQUIRE(t.nodes[li].vertex != invalid_index);
            q[k] = p + h * glm::dvec3(0.5, cs.yz[k].x, cs.yz[k].y);
            t.vertices[t.nodes[li].vertex].position = q[k];
        }
        const PolygonSoup s = contour(t);
        INFO(cs.what);
        LAB09_CHECK_CLOSED_MANIFOLD(s, cs.what);
        // the triangles made of three of the four vertices come from the quad around the +x edge
        auto index_of = [&](const glm::dvec3& x) {
            for (std::uint32_t v = 0; v < s.n_vertices(); ++v)
                if (s.positions[v] == x) return int(v);
            return -1;
        };
        int w[4];
        for (int k = 0; k < 4; ++k) REQUIRE((w[k] = index_of(q[k])) >= 0);
        int found = 0, along_diagonal = 0, facing_out = 0;
        for (std::size_t i = 0; i < s.n_faces(); ++i) {
            auto vs = s.face(i);
            REQUIRE(vs.size() == 3);
            int in_quad = 0;
            bool has[4] = {};
            for (std::uint32_t v : vs)
                for (int k = 0; k < 4; ++k)
                    if (int(v) == w[k]) ++in_quad, has[k] = true;
            if (in_quad != 3) continue;
            ++found;
            along_diagonal += cs.diagonal == 0 ? has[0] && has[2] : has[1] && has[3];
            const glm::dvec3 n = glm::cross(s.positions[vs[1]] - s.positions[vs[0]], s.positions[vs[2]] - s.positions[vs[0]]);
            facing_out += n.x > 0;
        }
        CHECK(found == 2);
        CHECK_MESSAGE(along_diagonal == 2, "the quad's 2 triangles should share the diagonal "
                                               << (cs.diagonal == 0 ? "a-c" : "b-d") << "; " << along_diagonal
                                               << " of them hold it");
        CHECK_MESSAGE(facing_out == 2, facing_out << " of the quad's 2 triangles face outward (+x)");
    }
}

TEST_CASE("contour: a leaf around a sign-changing edge with no vertex (or none of whose vertices crosses it) throws "
          "TopologyError" *
          geolab::points(1) *
          geolab::hint("Throw geolab::TopologyError (not a crash, not a silent hole) when a leaf around a sign-changing "
                       "minimal edge has no vertex, on any tree (uniform, adaptive, spherical), or has several vertices "
                       "of which none has the edge in its `edges`.")) {
    const FieldPtr sphere = geolab::sphere({0.1, -0.05, 0.08}, 0.6);
    // a leaf of level `level` with a sign change (the sphere lies inside the domain: every sign-changing edge has an
    // inside end off the domain's boundary, so all of its quadrants are leaves)
    auto cut_leaf = [](const Octree& t, int level) {
        for (std::uint32_t li : tree_shape(t).leaves) {
            const OctreeNode& nd = t.nodes[li];
            const int m = expected_signs(t, nd);
            if (nd.level == level && m != 0 && m != 0xff && nd.vertex != invalid_index) return li;
        }
        return invalid_index;
    };
    struct Case {
        Octree t;
        int level;
        const char* what;
    };
    std::vector<Case> cases;
    cases.push_back({given_octree(*sphere, 4), 4, "a finest leaf of a uniform Cartesian tree, level 4"});
    cases.push_back({half_refined_cartesian(*sphere, 5, 2), 2, "a leaf of level 2 of an adaptive Cartesian tree"});
    cases.push_back({half_refined_spherical(*sphere, 4, 4, 1.0), 4, "a finest leaf of a uniform spherical tree"});
    for (Case& cs : cases) {
        given_vertices(cs.t);
        const std::uint32_t li = cut_leaf(cs.t, cs.level);
        INFO(cs.what);
        REQUIRE(li != invalid_index);
        REQUIRE_NOTHROW(contour(cs.t));
        cs.t.nodes[li].vertex = invalid_index;
        CHECK_THROWS_AS(contour(cs.t), geolab::TopologyError);
    }
    // two pieces, neither of which claims its edges (and the next leaf's vertex claims every edge)
    const DiagonalBalls balls(5, {16, 16, 16}, 0.4, 0.2);
    Octree t = given_octree(balls, 5);
    given_vertices(t);
    const std::uint32_t li = leaf_of_cell(t, {16, 16, 16});
    REQUIRE(li != invalid_index);
    const std::uint32_t v = t.nodes[li].vertex;
    REQUIRE(v != invalid_index);
    REQUIRE(t.vertices[v].pieces == 2);
    REQUIRE(v + 2 < t.vertices.size());
    t.vertices[v].edges = t.vertices[v + 1].edges = 0;
    t.vertices[v + 2].edges = 0xfff;
    INFO("the cell between two balls: its 2 vertices with edges = 0");
    CHECK_THROWS_AS(contour(t), geolab::TopologyError);
}

TEST_CASE("contour (spherical): each pole ring takes the piece crossing the axis edge from a leaf with two pieces" *
          geolab::points(1) *
          geolab::hint("A ring leaf with several vertices gives the one whose edges hold the axis edge: cell edge 0 "
                       "(corners 0, 1) at the north pole, cell edge 1 (corners 2, 3) at the south pole. Handout §1.1.")) {
    // level 3, r_max 1: an inside point on the axis (r index 2) and one inside point next to the axis at r index 3 in
    // the first theta ring (north: j = 1; south: j = 7), phi index 5: the ring leaf at r [2, 3], phi [5, 6] then has
    // two pieces, the axis edge's and the lone corner's
    for (const bool north : {true, false}) {
        const SphericalLatticePoints f(3, 1.0, {{2, north ? 0 : 8, 0}, {3, north ? 1 : 7, 5}});
        Octree t;
        t.init_spherical(f, 3, glm::dvec3(0.0), 0.0, 1.0);
        for (std::uint32_t n = 0; n < t.nodes.size(); ++n)
            if (t.nodes[n].level < 3) t.split(n);
        given_vertices(t);
        const char* what = north ? "north pole" : "south pole";
        INFO(what << ": " << leaves_with_pieces(t, 2) << " leaves with 2 pieces");
        REQUIRE(leaves_with_pieces(t, 2) > 0);
        const ReferenceContour ref = reference_contour(t);
        REQUIRE(ref.no_vertex.empty());
        REQUIRE(ref.rings.size() > 0);
        std::vector<PoleRing> rings;
        PolygonSoup s;
        REQUIRE_NOTHROW(s = contour(t, &rings));
        const std::string ring_diff = compare_rings(s, rings, ref);
        CHECK_MESSAGE(ring_diff.empty(), ring_diff);
        const std::string diff = compare_polygons(s, ref);
        CHECK_MESSAGE(diff.empty(), diff);
    }
}

TEST_CASE("contour (spherical level 1): the two quads that join the same 4 vertices take different diagonals" *
          geolab::points(1) *
          geolab::hint("At level 1 the two phi cells share both their phi faces, so the radial edges at phi = 0 and at "
                       "phi = pi are surrounded by the same 4 leaves: split the second quad along the diagonal the first "
                       "did not take, or the same two triangles cover it twice (edges in 4 faces).")) {
    // spheres about 26 points near the origin: each of the two quads' diagonals is the shorter one in some of them
    std::vector<glm::dvec3> centres;
    for (int i = 0; i < 27; ++i)
        if (i != 13) centres.push_back(0.04 * glm::dvec3(i % 3 - 1, (i / 3) % 3 - 1, i / 9 - 1) + glm::dvec3(0.003, -0.002, 0.001));
    for (const glm::dvec3& centre : centres) {
        const FieldPtr f = geolab::sphere(centre, 0.7);
        Octree t;
        t.init_spherical(*f, 1, glm::dvec3(0.0), 0.0, 1.0);
        t.split(0);
        given_vertices(t);
        std::vector<PoleRing> rings;
        PolygonSoup s;
        REQUIRE_NOTHROW(s = contour(t, &rings));
        const geolab::SurfaceCheck sc = surface_check(s, false);
        INFO("sphere r = 0.7 at " << str(centre) << ", spherical level 1, shell [0, 1]: " << sc.summary() << "; "
                                  << rings.size() << " pole rings");
        CHECK(s.n_faces() == 4);
        CHECK(sc.non_manifold_edges == 0);
        CHECK(sc.misoriented_edges == 0);
        CHECK(sc.boundary_edges == 0);  // rings of 2 vertices (one per phi cell) leave no hole
        // the 4 triangles are 4 different triangles
        std::set<std::array<std::uint32_t, 3>> tris;
        for (std::size_t i = 0; i < s.n_faces(); ++i) {
            auto vs = s.face(i);
            REQUIRE(vs.size() == 3);
            std::array<std::uint32_t, 3> k{vs[0], vs[1], vs[2]};
            std::sort(k.begin(), k.end());
            tris.insert(k);
        }
        CHECK(tris.size() == s.n_faces());
    }
    // the 4 vertices placed by hand (each in its cell: A = theta < pi/2, B = theta > pi/2; 0 = phi < pi, 1 = phi > pi)
    // so that the shorter diagonal is A0-B1, then A1-B0: both quads prefer the same pair, the second must not take it
    for (int config = 0; config < 2; ++config) {
        const FieldPtr f = geolab::sphere(glm::dvec3(0.002, -0.001, 0.003), 0.7);
        Octree t;
        t.init_spherical(*f, 1, glm::dvec3(0.0), 0.0, 1.0);
        t.split(0);
        given_vertices(t);
        const double near = 0.38, far = 0.6;  // r 0.54 and 0.85: in the outer shell r in [0.5, 1]
        for (std::uint32_t li : tree_shape(t).leaves) {
            const OctreeNode& nd = t.nodes[li];
            if (nd.vertex == invalid_index) continue;
            REQUIRE(nd.x == 1);
            const bool b_cell = nd.y == 1, phi1 = nd.z == 1;
            const bool short_pair = config == 0 ? b_cell == phi1 : b_cell != phi1;  // A0, B1 (config 0) or A1, B0
            const double d = short_pair ? near : far;
            t.vertices[nd.vertex].position = glm::dvec3(phi1 ? -0.05 : 0.05, phi1 ? -d : d, b_cell ? -d : d);
        }
        std::vector<PoleRing> rings;
        PolygonSoup s;
        REQUIRE_NOTHROW(s = contour(t, &rings));
        const geolab::SurfaceCheck sc = surface_check(s, false);
        INFO("vertices placed by hand, the shorter diagonal " << (config == 0 ? "A0-B1" : "A1-B0") << ": "
                                                              << sc.summary());
        CHECK(s.n_faces() == 4);
        CHECK(sc.non_manifold_edges == 0);
        CHECK(sc.misoriented_edges == 0);
        std::set<std::array<std::uint32_t, 3>> tris;
        for (std::size_t i = 0; i < s.n_faces(); ++i) {
            auto vs = s.face(i);
            REQUIRE(vs.size() == 3);
            std::array<std::uint32_t, 3> k{vs[0], vs[1], vs[2]};
            std::sort(k.begin(), k.end());
            tris.insert(k);
        }
        CHECK(tris.size() == s.n_faces());
    }
}

}  // TEST_SUITE

TEST_SUITE("Task 7: Cartesian one-shot") {

TEST_CASE("dual_contour_cartesian: cow and armadillo at level 5 are closed 2-manifolds without self-intersections" *
          geolab::points(2) * geolab::whole_chain() * geolab::time_limit(60) *
          geolab::hint("Thin legs and ears put two sheets of the surface in one finest cell: one vertex per piece "
                       "keeps them apart (handout §1.1); the QEF minimiser outside the cell gives way to the mass "
                       "point, and each quad takes the diagonal that does not fold.")) {
    for (const char* name : {"cow", "armadillo"}) {
        const PolygonSoup input = load_model(name);
        const geolab::MeshField f(input);
        CartesianParams p;
        p.max_level = 5;
        const PolygonSoup s = dual_contour_cartesian(f, p);
        LAB09_CHECK_2_MANIFOLD(s, std::string(name) + " Cartesian level 5", true);
        CHECK(enclosed_volume(s) > 0);
    }
}

}  // TEST_SUITE

TEST_SUITE("Task 10: spherical octree") {

TEST_CASE("dual_contour_spherical: cow and armadillo at level 5 are closed 2-manifolds" *
          geolab::points(2) * geolab::whole_chain() *
          geolab::time_limit(60) *
          geolab::hint("The spherical cells are cubes of the (r, theta, phi) lattice: the same pieces, face_joins "
                       "and polygons as on the Cartesian tree, across the phi seam; each pole ring takes the piece "
                       "that crosses the axis edge. Handout §1.1, §7.")) {
    for (const char* name : {"cow", "armadillo"}) {
        const PolygonSoup input = load_model(name);
        const geolab::MeshField f(input);
        SphericalParams p;
        p.max_level = 5;  // the origin: the centre of the field's bounds (the default)
        const PolygonSoup s = dual_contour_spherical(f, p);
        LAB09_CHECK_2_MANIFOLD(s, std::string(name) + " spherical level 5", false);
        CHECK(enclosed_volume(s) > 0);
    }
}

}  // TEST_SUITE
