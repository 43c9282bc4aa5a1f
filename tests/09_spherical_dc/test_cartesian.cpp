// Lab 09, Task 7: the Cartesian one-shot function dual_contour_cartesian (handout §5.4).
#include "geolab/fixtures.hpp"
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab09;

namespace {
PolygonSoup cartesian(const ScalarField& f, int level, DcStats* stats = nullptr) {
    CartesianParams p;
    p.max_level = level;
    return dual_contour_cartesian(f, p, stats);
}
double finest_h(const ScalarField& f, int level) { return cartesian_domain(f, 0.05).second / double(1 << level); }

// A field given by its signs at the lattice points of level `level`: -1 where inside(i, j, k), +1 elsewhere, and
// trilinear in between (Lipschitz 2 sqrt(3) / h, so the conservative test splits every cell).
class LatticeSigns final : public ScalarField {
public:
    LatticeSigns(int level, bool (*inside_at)(int, int, int)) : inside_at_(inside_at) {
        const auto [lo, side] = cartesian_domain(*this, 0.05);
        lo_ = lo;
        h_ = side / double(1 << level);
    }
    double value(const glm::dvec3& p) const override {
        glm::dvec3 g;
        return eval(p, g);
    }
    glm::dvec3 gradient(const glm::dvec3& p) const override {
        glm::dvec3 g;
        eval(p, g);
        return g;
    }
    geolab::Box bounds() const override { return {glm::dvec3(-1.0), glm::dvec3(1.0)}; }
    double lipschitz() const override { return 2.0 * std::sqrt(3.0) / h_; }

private:
    double eval(const glm::dvec3& p, glm::dvec3& grad) const {
        const glm::dvec3 u = (p - lo_) / h_, i0 = glm::floor(u), t = u - i0;
        double v = 0.0;
        grad = glm::dvec3(0.0);
        for (int c = 0; c < 8; ++c) {
            const int dx = c & 1, dy = (c >> 1) & 1, dz = c >> 2;
            const double s = inside_at_(int(i0.x) + dx, int(i0.y) + dy, int(i0.z) + dz) ? -1.0 : 1.0;
            const double wx = dx ? t.x : 1.0 - t.x, wy = dy ? t.y : 1.0 - t.y, wz = dz ? t.z : 1.0 - t.z;
            v += s * wx * wy * wz;
            grad += s / h_ * glm::dvec3((dx ? 1.0 : -1.0) * wy * wz, wx * (dy ? 1.0 : -1.0) * wz, wx * wy * (dz ? 1.0 : -1.0));
        }
        return v;
    }
    bool (*inside_at_)(int, int, int);
    glm::dvec3 lo_{0.0};
    double h_ = 1.0;
};
// every face of every cell ambiguous (a 3D checkerboard of signs)
bool checkerboard(int i, int j, int k) { return ((i + j + k) & 1) == 0; }
// x-faces at even x ambiguous (inside where y and z have the same parity) and joined inside the cell (at odd x
// inside unless y is even and z odd), so face_joins looks into the cell beyond every such face, at x - 1
bool joined_faces(int i, int j, int k) { return (i & 1) == 0 ? (j & 1) == (k & 1) : !((j & 1) == 0 && (k & 1) == 1); }
}  // namespace

TEST_SUITE("Task 7: Cartesian one-shot") {

TEST_CASE("dual_contour_cartesian: sphere; off-centre sphere; torus and blob are closed 2-manifolds" *
          geolab::points(2) * geolab::whole_chain() *
          geolab::hint("build_octree -> place_vertices -> simplify (when simplify_tolerance > 0) -> contour. A hole "
                       "or a crack means neighbours disagree on an edge: shared lattice samples, each minimal edge "
                       "once, the same tie rule everywhere. Handout §5.4.")) {
    const std::pair<FieldPtr, const char*> shapes[] = {
        {geolab::sphere({0, 0, 0}, 0.8), "sphere r = 0.8"},
        {geolab::sphere({0.37, -0.21, 0.13}, 0.55), "off-centre sphere r = 0.55 at (0.37, -0.21, 0.13)"},
        {geolab::torus({0, 0, 0}, 0.6, 0.25), "torus R = 0.6, r = 0.25"},
        {geolab::named_implicit("blob"), "blob (smooth union of two spheres)"},
    };
    for (const auto& [f, name] : shapes) {
        DcStats st;
        const PolygonSoup s = cartesian(*f, 5, &st);
        LAB09_CHECK_CLOSED_MANIFOLD(s, std::string(name) + ", level 5");
        CHECK(st.vertices == s.n_vertices());
        CHECK(st.faces == s.n_faces());
        CHECK(components(s) == 1);
        if (f == shapes[0].first) {  // the picture in the report: your sphere next to the exact one
            PolygonSoup exact = geolab::fixtures::icosphere(4);
            for (auto& p : exact.positions) p *= 0.8;
            geolab::attach_mesh_figure("sphere-level5", s, exact);
        }
    }
}

TEST_CASE("dual_contour_cartesian: a box and a cube give exactly 8 vertices and 12 triangles" * geolab::points(2) *
          geolab::whole_chain() *
          geolab::hint("Rank-1 faces, rank-2 edges and rank-3 corners fit their QEFs exactly, so the default "
                       "simplification merges everything down to the 8 corner cells. Handout §5.2.")) {
    for (const char* name : {"box", "cube"})
        for (int level : {4, 6}) {
            const FieldPtr f = geolab::named_implicit(name);
            const PolygonSoup s = cartesian(*f, level);
            INFO(name << " level " << level << ": " << s.n_vertices() << " vertices, " << s.n_faces() << " faces");
            CHECK(s.n_vertices() == 8);
            CHECK(s.n_faces() == 12);
            LAB09_CHECK_CLOSED_MANIFOLD(s, name);
            const double h = finest_h(*f, level);
            CHECK(max_abs_f(*f, s) < 1e-6 * h);
        }
}

TEST_CASE("dual_contour_cartesian: vertices lie on the surface; max |f(v)| <= 0.01 h at levels 7-8" *
          geolab::points(1) * geolab::whole_chain() *
          geolab::hint("The reference measures max|f|/h = 0.0059 (sphere, level 7) and 0.0076 (torus, level 8). A "
                       "larger error: crossings not converged (tolerance relative to the edge), normals not unit, "
                       "QEF not solved about the mass point, or vertices clamped wrongly. Handout §5.1.")) {
    const FieldPtr sphere = geolab::sphere({0.1, 0.0, -0.05}, 0.8), torus = geolab::torus({0, 0, 0}, 0.6, 0.25);
    const std::pair<const ScalarField*, int> cases[] = {{sphere.get(), 7}, {torus.get(), 8}};
    for (auto [f, level] : cases) {
        const PolygonSoup s = cartesian(*f, level);
        REQUIRE(s.n_vertices() > 0);
        const double h = finest_h(*f, level), m = max_abs_f(*f, s);
        INFO((f == sphere.get() ? "sphere" : "torus") << " level " << level << ": max |f(v)| = " << m << " = "
                                                      << m / h << " h (limit 0.01 h)");
        CHECK(m <= 0.01 * h);
    }
}

TEST_CASE("dual_contour_cartesian: enclosed volume within 0.5% of the analytic volume; outward" * geolab::points(2) *
          geolab::whole_chain() *
          geolab::hint("Reference volume errors: sphere level 5 0.11%, torus level 6 0.10%. A negative volume "
                       "means the faces wind inward. Handout §5.3.")) {
    struct Case {
        FieldPtr f;
        double volume;
        int level;
        const char* name;
    };
    const Case cases[] = {
        {geolab::sphere({0.2, 0.1, 0.0}, 0.7), sphere_volume(0.7), 5, "sphere r = 0.7"},
        {geolab::torus({0, 0, 0.1}, 0.6, 0.25), torus_volume(0.6, 0.25), 6, "torus R = 0.6, r = 0.25"},
    };
    for (const Case& c : cases) {
        const PolygonSoup s = cartesian(*c.f, c.level);
        const double v = enclosed_volume(s);
        INFO(c.name << " level " << c.level << ": volume " << v << ", analytic " << c.volume << ", relative error "
                    << (v - c.volume) / c.volume);
        CHECK(v > 0);
        CHECK(std::abs(v - c.volume) <= 0.005 * c.volume);
        CHECK(std::abs(signed_volume(s) - v) < 1e-9 * c.volume);
    }
}

TEST_CASE("dual_contour_cartesian: bad parameters throw std::invalid_argument" * geolab::points(1) *
          geolab::whole_chain() *
          geolab::hint("max_level must be in [1, 10]; a field with empty bounds is rejected by cartesian_domain. "
                       "Handout §5.4.")) {
    const FieldPtr f = geolab::sphere({0, 0, 0}, 0.5);
    const PolygonSoup ok = cartesian(*f, 3);
    REQUIRE(ok.n_faces() > 0);
    CHECK_THROWS_AS(cartesian(*f, 0), std::invalid_argument);
    CHECK_THROWS_AS(cartesian(*f, 11), std::invalid_argument);
    // level 10 is accepted: a sphere of radius 0.004 (about 2 finest cells) inside the bounds [-1, 1]^3
    const TinySphere tiny({0.3, -0.2, 0.1}, 0.004);
    PolygonSoup ten;
    CHECK_NOTHROW(ten = cartesian(tiny, 10));
    LAB09_CHECK_CLOSED_MANIFOLD(ten, "tiny sphere r = 0.004 at (0.3, -0.2, 0.1), level 10");
    INFO("max |f(v)| = " << max_abs_f(tiny, ten) / finest_h(tiny, 10) << " h (reference 0.2 h: the sphere is 2 cells wide)");
    CHECK(max_abs_f(tiny, ten) < 0.3 * finest_h(tiny, 10));
}

TEST_CASE("dual_contour_cartesian: DcStats describes the tree that was contoured; the soup is the chain's exactly "
          "(simplification on and off)" *
          geolab::points(1) * geolab::whole_chain() *
          geolab::hint("cells = nodes reachable from the root after simplification, leaves = reachable leaves, "
                       "crossings = what place_vertices returned, collapses = what simplify returned (0 when "
                       "simplify_tolerance is 0: simplification off), samples = the tree's samples(). The soup is "
                       "contour(simplify(place_vertices(build_octree))) to the bit, in the same order, however the "
                       "one-shot saves memory. Handout §5.4.")) {
    const std::pair<FieldPtr, const char*> shapes[] = {{geolab::sphere({0.1, -0.05, 0.0}, 0.7), "sphere r = 0.7"},
                                                       {geolab::named_implicit("box"), "box"},
                                                       {geolab::torus({0, 0, 0}, 0.6, 0.25), "torus"},
                                                       {geolab::named_implicit("csg"), "csg"}};
    for (const auto& [f, name_c] : shapes)
        for (double tol : {0.0, 1e-5, 0.2}) {
            const std::string name(name_c);
            CartesianParams p;
            p.max_level = 5;
            p.simplify_tolerance = tol;
            DcStats st;
            const PolygonSoup s = dual_contour_cartesian(*f, p, &st);
            // the same chain step by step
            Octree t = build_octree(*f, p);
            const std::size_t crossings = place_vertices(t, {p.tau, p.crossing_tolerance});
            const std::size_t collapses = tol > 0 ? simplify(t, tol * t.size / t.resolution(), p.tau) : 0;
            const PolygonSoup s2 = contour(t);
            std::size_t nodes = 0;
            std::vector<std::uint32_t> stack{0};
            while (!stack.empty()) {
                const std::uint32_t i = stack.back();
                stack.pop_back();
                ++nodes;
                if (!t.nodes[i].is_leaf())
                    for (int k = 0; k < 8; ++k) stack.push_back(t.nodes[i].first_child + k);
            }
            const std::size_t leaves = tree_shape(t).leaves.size();
            INFO(name << ", level 5, simplify_tolerance " << tol << " h: DcStats cells " << st.cells << ", leaves "
                      << st.leaves << ", samples " << st.samples << ", crossings " << st.crossings << ", collapses "
                      << st.collapses << "; the tree: " << nodes << " reachable nodes, " << leaves << " leaves, "
                      << t.samples() << " samples, " << crossings << " crossings, " << collapses << " collapses");
            CHECK(st.cells == nodes);
            CHECK(st.leaves == leaves);
            CHECK(st.samples == t.samples());
            CHECK(st.crossings == crossings);
            CHECK(st.collapses == collapses);
            if (tol == 0) CHECK(st.collapses == 0);
            else CHECK(st.collapses > 0);
            CHECK(st.vertices == s.n_vertices());
            CHECK(st.faces == s.n_faces());
            CHECK(s.n_faces() == s2.n_faces());
            CHECK(s.n_vertices() == s2.n_vertices());
            CHECK_MESSAGE(same_soup(s, s2), name << ": the one-shot's soup differs from the chain's: " << soup_difference(s, s2));
            CHECK(st.seconds >= 0.0);
        }
}

TEST_CASE("dual_contour_cartesian: fields whose faces are ambiguous everywhere give the chain's samples and soup" *
          geolab::points(1) * geolab::whole_chain() *
          geolab::hint("face_joins reads the samples one cell beyond an ambiguous face whose inside corners the cell "
                       "itself connects: a one-shot that forgets samples too early, or draws a face differently from "
                       "the chain, shows up here. Handout §5.4.")) {
    const std::pair<bool (*)(int, int, int), const char*> patterns[] = {
        {checkerboard, "checkerboard (every face ambiguous)"},
        {joined_faces, "x-faces ambiguous and joined in their cell (face_joins looks one cell back)"}};
    for (const auto& [pattern, name] : patterns)
        for (int level : {4, 5}) {
            const LatticeSigns f(level, pattern);
            CartesianParams p;
            p.max_level = level;
            DcStats st;
            const PolygonSoup s = dual_contour_cartesian(f, p, &st);
            Octree t = build_octree(f, p);
            const std::size_t crossings = place_vertices(t, {p.tau, p.crossing_tolerance});
            simplify(t, p.simplify_tolerance * t.size / t.resolution(), p.tau);
            const PolygonSoup chain = contour(t);
            INFO(name << ", level " << level << ": the one-shot took " << st.samples << " samples and "
                      << st.crossings << " crossings; the chain " << t.samples() << " and " << crossings);
            REQUIRE(s.n_faces() > 0);
            CHECK(st.samples == t.samples());
            CHECK(st.crossings == crossings);
            CHECK_MESSAGE(same_soup(s, chain), "the soups differ: " << soup_difference(s, chain));
        }
}

TEST_CASE("dual_contour_cartesian: at level 7 the same samples and crossings and collapses and soup as the chain" *
          geolab::points(1) * geolab::whole_chain() *
          geolab::hint("The one-shot is build_octree -> place_vertices -> simplify -> contour: however it saves time "
                       "or memory, it samples the same lattice points once each, computes the same crossings once "
                       "each, and returns the same soup. Handout §5.4.")) {
    const std::pair<FieldPtr, const char*> shapes[] = {{geolab::sphere({0.05, -0.1, 0.07}, 0.7), "sphere r = 0.7"},
                                                       {geolab::torus({0, 0, 0}, 0.6, 0.25), "torus"},
                                                       {geolab::named_implicit("csg"), "csg"}};
    for (const auto& [f, name] : shapes) {
        CartesianParams p;
        p.max_level = 7;
        DcStats st;
        const PolygonSoup s = dual_contour_cartesian(*f, p, &st);
        Octree t = build_octree(*f, p);
        const std::size_t crossings = place_vertices(t, {p.tau, p.crossing_tolerance});
        const std::size_t collapses = simplify(t, p.simplify_tolerance * t.size / t.resolution(), p.tau);
        const PolygonSoup chain = contour(t);
        INFO(name << ", level 7: the one-shot took " << st.samples << " samples, " << st.crossings << " crossings, "
                  << st.collapses << " collapses; the chain " << t.samples() << ", " << crossings << ", " << collapses);
        CHECK(st.samples == t.samples());
        CHECK(st.crossings == crossings);
        CHECK(st.collapses == collapses);
        CHECK_MESSAGE(same_soup(s, chain), "the soups differ: " << soup_difference(s, chain));
    }
}

}  // TEST_SUITE
