// Lab 09, hidden: manifold dual contouring on real models and spherical trees (handout §1.1).
#include "geolab/grading/chain.hpp"
#include "../manifold.hpp"

using namespace lab09;

namespace {
// A complete spherical tree of `level` about `origin` (the given Octree API only).
Octree complete_spherical(const ScalarField& f, int level, const glm::dvec3& origin, double r_max) {
    Octree t;
    t.init_spherical(f, level, origin, 0.0, r_max);
    for (std::uint32_t n = 0; n < t.nodes.size(); ++n)
        if (t.nodes[n].level < level) t.split(n);
    return t;
}
// The bunny's field and a shell around it: origin at the centre of its bounds, r_max 1.05 x the farthest corner.
struct Bunny {
    PolygonSoup input = load_model("bunny00");
    geolab::MeshField f{input};
    glm::dvec3 origin = f.bounds().center();
    double r_max = 1.05 * glm::length(f.bounds().hi - f.bounds().lo) / 2.0;
};
}  // namespace

TEST_SUITE("Task 4: vertex placement") {

TEST_CASE("place_vertices hidden (spherical): one vertex per piece on the bunny's spherical tree" *
          geolab::points(1) * geolab::builds_on("Task 1, Task 2") *
          geolab::hidden() * geolab::time_limit(60) *
          geolab::hint("Spherical finest leaves get one vertex per piece of cell_surface(signs, face_joins) too, in "
                       "DualVertex's layout; the polar axis edge's two copies in a cell are one piece.")) {
    const Bunny b;
    Octree t = complete_spherical(b.f, 4, b.origin, b.r_max);
    place_vertices(t, {});
    INFO("bunny00, complete spherical tree of level 4: " << leaves_with_pieces(t, 2) << " leaves with 2 or more pieces");
    REQUIRE(leaves_with_pieces(t, 2) > 0);
    std::ostringstream first;
    const std::size_t wrong = wrong_layouts(t, first, false);
    CHECK_MESSAGE(wrong == 0, wrong << " leaves do not have one vertex per piece as DualVertex's layout says" << first.str());
}

}  // TEST_SUITE

TEST_SUITE("Task 5: simplification") {

TEST_CASE("simplify hidden: csg; torus and two nearly touching balls stay 2-manifolds at 0.05 to 0.5 h" *
          geolab::points(1) * geolab::builds_on("Task 1, Task 2") * geolab::hidden() *
          geolab::hint("No merge across a child with two pieces or an ambiguous face; Ju et al.'s sign tests for the "
                       "rest. Non-manifold vertices count too, not only edges.")) {
    const DiagonalBalls balls(5, {16, 16, 16}, 0.4, 0.2);
    const FieldPtr csg = geolab::named_implicit("csg"), torus = geolab::named_implicit("torus");
    const std::pair<const ScalarField*, const char*> cases[] = {
        {csg.get(), "csg"}, {torus.get(), "torus"}, {&balls, "two balls 0.2 h apart"}};
    for (const auto& [f, name] : cases)
        for (double tol : {0.05, 0.5}) {
            const PolygonSoup s = cartesian_pipeline(*f, 5, tol);
            LAB09_CHECK_2_MANIFOLD(s, std::string(name) + " level 5 simplified at " + std::to_string(tol) + " h", false);
        }
}

}  // TEST_SUITE

TEST_SUITE("Task 6: contouring polygons") {

TEST_CASE("contour hidden: the bunny's spherical tree (cells with two pieces and pole rings) is a 2-manifold" *
          geolab::points(1) * geolab::hidden() * geolab::time_limit(60) *
          geolab::hint("Each polygon takes, in every leaf around its edge, the piece that crosses the edge, across the "
                       "phi seam too; each pole ring the piece that crosses the axis edge. Open rings are the only "
                       "boundary.")) {
    const Bunny b;
    Octree t = complete_spherical(b.f, 4, b.origin, b.r_max);
    given_vertices(t);  // not your place_vertices: Task 6 alone
    REQUIRE(leaves_with_pieces(t, 2) > 0);
    std::vector<PoleRing> rings;
    PolygonSoup s;
    REQUIRE_NOTHROW(s = contour(t, &rings));
    const geolab::SurfaceCheck sc = surface_check(s, false);
    INFO("bunny00, complete spherical tree of level 4, pole rings left open: " << rings.size() << " rings; "
                                                                                << sc.summary());
    CHECK(rings.size() == 2);
    CHECK(sc.non_manifold_edges == 0);
    CHECK(sc.non_manifold_vertices == 0);
    CHECK(sc.misoriented_edges == 0);
    CHECK(boundary_loops(s) == rings.size());
    std::size_t ring_edges = 0;
    for (const PoleRing& r : rings) ring_edges += r.ring.size();
    CHECK(sc.boundary_edges == ring_edges);
}

}  // TEST_SUITE

TEST_SUITE("Task 7: Cartesian one-shot") {

TEST_CASE("bunny hidden: Cartesian level 6 is a closed 2-manifold without self-intersections" *
          geolab::points(1) * geolab::whole_chain() *
          geolab::hidden() * geolab::time_limit(60) *
          geolab::hint("One vertex per piece, polygons through the piece crossing each edge, QEF minimisers outside "
                       "their cells replaced by mass points, the non-folding diagonal.")) {
    const PolygonSoup input = load_model("bunny00");
    const geolab::MeshField f(input);
    CartesianParams p;
    p.max_level = 6;
    const PolygonSoup s = dual_contour_cartesian(f, p);
    LAB09_CHECK_2_MANIFOLD(s, "bunny00 Cartesian level 6", true);
}

}  // TEST_SUITE

TEST_SUITE("Task 10: spherical octree") {

TEST_CASE("bunny hidden: spherical level 6 is a closed 2-manifold without self-intersections" *
          geolab::points(1) * geolab::whole_chain() *
          geolab::hidden() * geolab::time_limit(60) *
          geolab::hint("The same manifold rules on the spherical tree, with both pole rings filled.")) {
    const PolygonSoup input = load_model("bunny00");
    const geolab::MeshField f(input);
    SphericalParams p;
    p.max_level = 6;  // the origin: the centre of the field's bounds (the default)
    const PolygonSoup s = dual_contour_spherical(f, p);
    LAB09_CHECK_2_MANIFOLD(s, "bunny00 spherical level 6", true);
}

}  // TEST_SUITE
