// Lab 09: manifold dual contouring (handout §1.1): a vertex per piece of a finest cell's surface, polygons that take
// the piece crossing their edge, the diagonal of each quad, and closed 2-manifolds on real models.
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
}  // namespace

TEST_SUITE("Task 4: vertex placement") {

TEST_CASE("place_vertices: a finest leaf gets one vertex per piece of its surface in DualVertex's layout" *
          geolab::points(2) *
          geolab::hint("cell_surface(signs, face_joins(tree, leaf)) gives the pieces of a finest leaf: one vertex per "
                       "piece, consecutive from OctreeNode::vertex, vertex k with the edges of piece k and pieces = the "
                       "count; its QEF holds the crossings of its own piece's edges only. Handout §1.1.")) {
    const DiagonalBalls balls(5, {16, 16, 16}, 0.4, 0.2);
    const LatticeBlock cavities = two_cavities();
    const std::pair<const ScalarField*, const char*> cases[] = {
        {&balls, "two balls r = 0.4, 0.2 h apart across a cell's diagonal, level 5"},
        {&cavities, "lattice block [2, 6]^3 with two outside points on a face diagonal, level 3"}};
    for (const auto& [f, name] : cases) {
        Octree t = given_octree(*f, f == &balls ? 5 : 3);
        place_vertices(t, {});
        INFO(name << ": " << leaves_with_pieces(t, 2) << " leaves with 2 or more pieces, " << leaves_with_joins(t)
                  << " with a joined face");
        REQUIRE(leaves_with_pieces(t, 2) > 0);
        if (f == &cavities) REQUIRE(leaves_with_joins(t) > 0);
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

TEST_CASE("place_vertices: the two pieces of a cell between two balls stay on their own balls" * geolab::points(1) *
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

}  // TEST_SUITE

TEST_SUITE("Task 5: simplification") {

TEST_CASE("simplify: a cell with two pieces never merges: two nearly touching balls stay two closed surfaces" *
          geolab::points(1) *
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
                       "take it, the other folds the mesh; otherwise take the shorter diagonal. Handout §1.1.")) {
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
        {{{-0.3, -0.3}, {0.9, -0.9}, {0.3, 0.3}, {-0.9, 0.9}}, 0, "a convex quad: both face outward, a-c is shorter"}};
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

}  // TEST_SUITE

TEST_SUITE("Task 7: Cartesian one-shot") {

TEST_CASE("dual_contour_cartesian: cow and armadillo at level 5 are closed 2-manifolds without self-intersections" *
          geolab::points(2) * geolab::time_limit(60) *
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

TEST_CASE("dual_contour_spherical: cow and armadillo at level 5 are closed 2-manifolds" * geolab::points(2) *
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
