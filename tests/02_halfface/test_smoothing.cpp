// Lab 02, Task 4: volume Laplacian smoothing (handout §6). Meshes from stored data (stored.hpp).
#include <bit>
#include <limits>

#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab02;

namespace {
// Vertices on a boundary half-face.
std::vector<bool> boundary_vertices(const Mesh& m) {
    std::vector<bool> b(m.n_vertices(), false);
    for (HalfFace hf : m.halffaces())
        if (!m.is_deleted(hf) && !m.cell(hf).is_valid())
            for (auto v : loop_vertices(m, hf)) b[v] = true;
    return b;
}
// One Jacobi step of the handout's formula, computed here from the edges.
std::vector<glm::dvec3> one_step(const Mesh& m, double t) {
    std::vector<glm::dvec3> sum(m.n_vertices(), glm::dvec3(0)), out = m.positions();
    std::vector<int> d(m.n_vertices(), 0);
    for (Edge e : m.edges()) {
        if (m.is_deleted(e)) continue;
        const auto ev = m.edge_vertices(e);
        sum[ev[0].idx] += m.position(ev[1]), sum[ev[1].idx] += m.position(ev[0]);
        ++d[ev[0].idx], ++d[ev[1].idx];
    }
    const auto bnd = boundary_vertices(m);
    for (Vertex v : m.vertices())
        if (!bnd[v.idx] && d[v.idx] > 0 && !m.is_deleted(v)) {
            const glm::dvec3 L = m.position(v) - sum[v.idx] / double(d[v.idx]);
            out[v.idx] = m.position(v) - t * L;
        }
    return out;
}
// The minimum signed tet volume, from each tet's corners in the cell list order of its stored half-faces.
double min_tet_volume(const Mesh& m) {
    double best = std::numeric_limits<double>::infinity();
    for (Cell c : m.cells()) {
        if (m.is_deleted(c) || m.halffaces(c).size() != 4) continue;
        const auto f = loop_vertices(m, m.halffaces(c)[0]);
        if (f.size() != 3) continue;
        std::uint32_t d = 0;
        for (auto v : loop_vertices(m, m.halffaces(c)[1]))
            if (v != f[0] && v != f[1] && v != f[2]) d = v;
        const glm::dvec3 a = m.position(Vertex{f[0]});
        // the loop is counter-clockwise seen from outside: reverse it for a positive volume
        best = std::min(best, glm::dot(glm::cross(m.position(Vertex{f[2]}) - a, m.position(Vertex{f[1]}) - a),
                                       m.position(Vertex{d}) - a) / 6.0);
    }
    return best;
}
}  // namespace

TEST_SUITE("Task 4: smoothing") {
    TEST_CASE("smoothing: boundary vertices keep their positions bit for bit" * geolab::points(2) *
              geolab::builds_on("Task 2") *
              geolab::hint("A vertex on any boundary half-face (no cell) never moves; do not even write p + 0.")) {
        for (const char* key : {"tet grid 3", "hex grid 2", "cube of 6 pyramids"}) {
            INFO("input: " << key);
            Mesh m = stored_mesh(key);
            const Mesh before = m;
            const auto bnd = boundary_vertices(m);
            (void)volume_smoothing(m, 0.5, 7);
            for (Vertex v : m.vertices())
                if (bnd[v.idx])
                    REQUIRE_MESSAGE((std::bit_cast<std::array<std::uint64_t, 3>>(m.position(v)) ==
                                     std::bit_cast<std::array<std::uint64_t, 3>>(before.position(v))),
                                    v << " is on the boundary but moved");
        }
        // (smoothing nothing keeps the boundary too): the interior vertex of hex grid 2, pushed off its rest place,
        // comes back: 7 steps of t = 0.5 leave 1/128 of the push
        Mesh m = stored_mesh("hex grid 2");
        const auto bnd = boundary_vertices(m);
        for (Vertex v : m.vertices()) {
            if (bnd[v.idx]) continue;
            const glm::dvec3 rest = m.position(v);
            m.position(v) += glm::dvec3(0.1, -0.05, 0.08);
            (void)volume_smoothing(m, 0.5, 7);
            CHECK_MESSAGE(glm::length(m.position(v) - rest) < 0.01,
                          "hex grid 2: the interior vertex pushed by 0.14 is still " << glm::length(m.position(v) - rest)
                                                                                     << " from its rest after 7 steps");
            break;
        }
    }

    TEST_CASE("smoothing: one iteration is the Jacobi step v - t L(v) over edge neighbours" * geolab::points(2) *
              geolab::builds_on("Task 2") *
              geolab::hint("L(v) = v - average of the edge neighbours, all from the old positions; apply them after "
                           "computing all of them.")) {
        for (double t : {0.25, 0.5, 1.0}) {
            for (const char* key : {"tet grid 3", "cube of 6 pyramids", "hex grid 2"}) {
                INFO("input: " << key << ", t = " << t);
                Mesh m = stored_mesh(key);
                const auto expected = one_step(m, t);
                (void)volume_smoothing(m, t, 1);
                for (Vertex v : m.vertices())
                    REQUIRE_MESSAGE(glm::length(m.position(v) - expected[v.idx]) <= 1e-12,
                                    v << ": expected (" << expected[v.idx].x << ", " << expected[v.idx].y << ", "
                                      << expected[v.idx].z << "), got (" << m.position(v).x << ", " << m.position(v).y
                                      << ", " << m.position(v).z << ")");
            }
        }
    }

    TEST_CASE("smoothing: iterations converge (interior L(v) -> 0) and the reported minimum volume is right" *
              geolab::points(2) * geolab::builds_on("Task 2") *
              geolab::hint("Return the minimum over tetrahedra of the signed volume after smoothing (positive when not "
                           "inverted).")) {
        Mesh m = stored_mesh("tet grid 3");
        const double vol = volume_smoothing(m, 0.5, 200);
        const auto next = one_step(m, 1.0);
        double worst = 0;
        for (Vertex v : m.vertices()) worst = std::max(worst, glm::length(next[v.idx] - m.position(v)));
        CHECK_MESSAGE(worst < 1e-8, "after 200 iterations of t = 0.5 the interior should be at rest; largest |L(v)| = " << worst);
        const double expected = min_tet_volume(m);
        CHECK_MESSAGE(std::abs(vol - expected) <= 1e-12 * std::max(1.0, std::abs(expected)),
                      "minimum signed tet volume: expected " << expected << ", got " << vol);
        CHECK_MESSAGE(vol > 0, "the smoothed grid must have no inverted tet; minimum volume " << vol);
    }

    TEST_CASE("smoothing: t outside 0..1 or negative iterations throw; t = 0 moves nothing" * geolab::points(1) *
              geolab::builds_on("Task 2") *
              geolab::hint("std::invalid_argument for t < 0, t > 1, NaN or iterations < 0.")) {
        Mesh m = stored_mesh("tet grid 2");
        const Mesh before = m;
        CHECK_THROWS_AS(volume_smoothing(m, -0.1, 1), std::invalid_argument);
        CHECK_THROWS_AS(volume_smoothing(m, 1.5, 1), std::invalid_argument);
        CHECK_THROWS_AS(volume_smoothing(m, std::nan(""), 1), std::invalid_argument);
        CHECK_THROWS_AS(volume_smoothing(m, 0.5, -1), std::invalid_argument);
        const double v = volume_smoothing(m, 0.0, 3);
        CHECK(m.positions() == before.positions());
        CHECK_MESSAGE(std::abs(v - min_tet_volume(before)) <= 1e-15, "t = 0: minimum volume of the unchanged grid expected");
        const double v0 = volume_smoothing(m, 0.5, 0);
        CHECK_MESSAGE(m.positions() == before.positions(), "0 iterations must move nothing");
        CHECK_MESSAGE(std::abs(v0 - min_tet_volume(before)) <= 1e-15, "0 iterations: minimum volume of the unchanged "
                                                                      "grid expected, got " << v0);
    }

    TEST_CASE("smoothing: deleted cells and vertices / meshes without tetrahedra" * geolab::points(2) *
              geolab::builds_on("Task 2") *
              geolab::hint("Only alive tetrahedra count for the minimum volume (+infinity when there is none); a vertex "
                           "marked deleted is not interior and keeps its position.")) {
        // the tet of smallest volume deleted (through the kernel): it no longer counts
        Mesh m = stored_mesh("tet grid 3");
        Cell smallest{0};
        double smallest_volume = std::numeric_limits<double>::infinity();
        for (Cell c : m.cells()) {
            Mesh one = m;
            for (Cell d : one.cells())
                if (d != c) one.set_deleted(d, true);
            if (const double v = min_tet_volume(one); v < smallest_volume) smallest_volume = v, smallest = c;
        }
        kernel_delete_cell(m, smallest);
        // and an interior vertex marked deleted (its cells kept): not interior any more
        const Vertex marked{std::uint32_t(fx::grid_index(3, 2, 2, 2))};
        m.set_deleted(marked, true);
        const Mesh before = m;
        const double v = volume_smoothing(m, 0.0, 1);
        INFO("input: tet grid 3 without its smallest tet (" << smallest << ", volume " << smallest_volume << ")");
        CHECK_MESSAGE(std::abs(v - min_tet_volume(before)) <= 1e-15,
                      "minimum volume of the alive tets expected " << min_tet_volume(before) << ", got " << v);
        const auto expected = one_step(before, 0.5);
        (void)volume_smoothing(m, 0.5, 1);
        CHECK_MESSAGE(m.position(marked) == before.position(marked), marked << " is marked deleted but moved");
        for (Vertex x : m.vertices())
            REQUIRE_MESSAGE(glm::length(m.position(x) - expected[x.idx]) <= 1e-12, x << ": not the Jacobi step");
        // no tetrahedra at all
        for (const char* key : {"hex grid 2", "cube of 6 pyramids", "prisms and pyramids"}) {
            Mesh n = stored_mesh(key);
            const double none = volume_smoothing(n, 0.5, 1);
            CHECK_MESSAGE(none == std::numeric_limits<double>::infinity(),
                          key << ": no tetrahedron, so +infinity expected; got " << none);
        }
    }
}
