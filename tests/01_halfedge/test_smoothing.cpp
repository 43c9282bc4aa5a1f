// Lab 01, Task 5: uniform Laplacian smoothing (handout §7). Meshes from stored connectivity (stored.hpp), never
// from your build_mesh.
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab01;

namespace {
double max_distance(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
    double d = 0;
    for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, glm::length(a[i] - b[i]));
    return d;
}
}  // namespace

// Smoothing averages each vertex's one-ring, which your Task 3 walks (one_ring_vertices): these tests build on it
// (geolab/grading/chain.hpp).
TEST_SUITE("Task 5: smoothing") {
    TEST_CASE("smoothing: one step on an octahedron with a raised top matches the hand computation" *
              geolab::points(3) * geolab::builds_on("Task 3") *
              geolab::hint("Compute every L(v) from the OLD positions (keep a copy), then move: v + t (mean of the "
                           "neighbours - v). Moving vertices one by one in place gives different numbers.")) {
        // Vertices +-x (0, 1), +-y (2, 3), +-z (4, 5), all of valence 4; the top is raised to (0,0,2). With t = 1/2:
        //   top:    mean of the equator = 0                    -> (0,0,2) + (0 - (0,0,2))/2      = (0,0,1)
        //   +x:     mean of +-y, top, bottom = (0,0,0.25)      -> (1,0,0) + ((0,0,.25)-(1,0,0))/2 = (0.5,0,0.125)
        //   bottom: mean of the equator = 0                    -> (0,0,-0.5)
        PolygonSoup soup = octahedron();
        soup.positions[4] = {0, 0, 2};
        INFO(mesh_to_string(soup));
        Mesh m = stored_mesh("octahedron", soup);
        laplacian_smoothing(m, 0.5);
        const std::vector<glm::dvec3> expect = {{0.5, 0, 0.125},  {-0.5, 0, 0.125}, {0, 0.5, 0.125},
                                                {0, -0.5, 0.125}, {0, 0, 1},        {0, 0, -0.5}};
        for (Vertex v : m.vertices()) {
            CAPTURE(v);
            INFO("expected " << str(expect[v.idx]) << ", got " << str(m.position(v)));
            CHECK(glm::length(m.position(v) - expect[v.idx]) < 1e-12);
        }
    }

    TEST_CASE("smoothing: t = 0 changes nothing and bad arguments throw std::invalid_argument" * geolab::points(2) *
              geolab::builds_on("Task 3") *
              geolab::hint("Check t in [0, 1] (NaN is not) and iterations >= 0 before anything else.")) {
        const PolygonSoup soup = fx::icosphere(1);
        Mesh m = stored_mesh("icosphere(1)", soup);
        laplacian_smoothing(m, 0.0, 3);
        CHECK(m.positions() == soup.positions);
        laplacian_smoothing(m, 0.7, 0);
        CHECK(m.positions() == soup.positions);
        for (double t : {-0.1, 1.5, std::nan("")}) {
            CAPTURE(t);
            CHECK_THROWS_AS(laplacian_smoothing(m, t), std::invalid_argument);
        }
        CHECK_THROWS_AS(laplacian_smoothing(m, 0.5, -1), std::invalid_argument);
        CHECK(m.positions() == soup.positions);
    }

    TEST_CASE(
        "smoothing: a jittered flat grid stays flat and its boundary does not move" * geolab::points(2) *
        geolab::builds_on("Task 3") *
        geolab::hint("Skip boundary vertices (mesh.is_boundary(v)); each interior vertex moves toward the mean of "
                     "its neighbours.")) {
        PolygonSoup soup = fx::grid(6, 6);
        const auto on_boundary = boundary_vertices(soup);
        for (std::size_t v = 0; v < soup.n_vertices(); ++v)
            if (!on_boundary[v]) soup.positions[v] += 0.04 * glm::dvec3(std::sin(3.0 * v), std::cos(5.0 * v), 0.0);
        Mesh m = stored_mesh("grid(6 x 6)", soup);
        laplacian_smoothing(m, 0.5, 3);
        auto ref = soup.positions;
        for (int i = 0; i < 3; ++i) ref = reference_smoothing_step(soup, ref, 0.5);
        for (Vertex v : m.vertices()) {
            CAPTURE(v);
            INFO(std::string(on_boundary[v.idx] ? "boundary vertex" : "interior vertex")
                 << ": expected " << str(ref[v.idx]) << ", got " << str(m.position(v)));
            CHECK(m.position(v).z == 0.0);
            if (on_boundary[v.idx]) CHECK(m.position(v) == soup.positions[v.idx]);
            CHECK(glm::length(m.position(v) - ref[v.idx]) < 1e-12);
        }
    }

    TEST_CASE("smoothing: a sphere keeps its centroid and shrinks" * geolab::points(2) * geolab::builds_on("Task 3") *
              geolab::hint("Uniform Laplacian smoothing moves every vertex toward the mean of its neighbours: a closed "
                           "convex surface shrinks; a symmetric one keeps its centre.")) {
        const PolygonSoup soup = fx::icosphere(2);
        Mesh m = stored_mesh("icosphere(2)", soup);
        laplacian_smoothing(m, 0.5, 2);
        const auto ref = reference_smoothing_step(soup, reference_smoothing_step(soup, soup.positions, 0.5), 0.5);
        {  // the picture in the report: your smoothed sphere next to the expected one
            PolygonSoup yours = soup, expected = soup;
            yours.positions = m.positions();
            expected.positions = ref;
            geolab::attach_mesh_figure("sphere-2-steps", yours, expected);
        }
        glm::dvec3 centroid(0.0);
        double mean_radius = 0;
        for (Vertex v : m.vertices()) centroid += m.position(v), mean_radius += glm::length(m.position(v));
        centroid /= double(m.n_vertices());
        mean_radius /= double(m.n_vertices());
        INFO("centroid " << str(centroid) << ", mean radius " << mean_radius << " (was 1)");
        CHECK(glm::length(centroid) < 1e-12);
        CHECK(mean_radius < 0.999);
        CHECK(mean_radius > 0.9);
        CHECK(max_distance(m.positions(), ref) < 1e-12);
    }

    TEST_CASE("smoothing: t = 1 is allowed and moves every interior vertex onto the centroid of its neighbours" *
              geolab::points(2) * geolab::builds_on("Task 3") *
              geolab::hint("t may be anything in [0, 1], both ends included: with t = 1, v + 1 (mean - v) = the mean of "
                           "the neighbours (old positions).")) {
        // The octahedron with its top raised to (0,0,2), t = 1: top and bottom go to the mean of the equator, 0;
        // +x goes to the mean of +-y, top and bottom, (0, 0, 0.25); the same for the other equator vertices.
        PolygonSoup soup = octahedron();
        soup.positions[4] = {0, 0, 2};
        INFO(mesh_to_string(soup));
        Mesh m = stored_mesh("octahedron", soup);
        REQUIRE_NOTHROW(laplacian_smoothing(m, 1.0));
        for (Vertex v : m.vertices()) {
            const glm::dvec3 expect = v.idx < 4 ? glm::dvec3(0, 0, 0.25) : glm::dvec3(0.0);
            CAPTURE(v);
            INFO("octahedron, t = 1: expected " << str(expect) << ", got " << str(m.position(v)));
            CHECK(glm::length(m.position(v) - expect) < 1e-12);
        }
        // The open pyramid, 2 iterations with t = 1: its only interior vertex, the apex, goes onto the centre of the
        // rim (0, 0, 0) and stays there; the rim does not move. Compared with brute-force steps on the soup.
        const Fixture box = fixture("open pyramid");
        Mesh mb = stored_mesh(box);
        REQUIRE_NOTHROW(laplacian_smoothing(mb, 1.0, 2));
        const auto ref =
            reference_smoothing_step(box.soup, reference_smoothing_step(box.soup, box.soup.positions, 1.0), 1.0);
        for (Vertex v : mb.vertices()) {
            CAPTURE(v);
            INFO("open pyramid, t = 1, 2 iterations: expected " << str(ref[v.idx]) << ", got " << str(mb.position(v)));
            CHECK(glm::length(mb.position(v) - ref[v.idx]) < 1e-12);
        }
    }

}  // TEST_SUITE
