// Lab 02, Task 2: queries and circulators (handout §4). Meshes from stored data (stored.hpp), never from your
// build_mesh.
#include "helpers.hpp"

using namespace lab02;

namespace {
// The angle of p about the axis a -> b, measured in a fixed frame of that axis.
double angle_about(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& p) {
    const glm::dvec3 z = glm::normalize(b - a);
    glm::dvec3 x = glm::cross(z, std::abs(z.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0));
    x = glm::normalize(x);
    const glm::dvec3 y = glm::cross(z, x);
    const glm::dvec3 d = p - a;
    return std::atan2(glm::dot(d, y), glm::dot(d, x));
}
glm::dvec3 centroid(const Mesh& m, Cell c) {
    glm::dvec3 s(0);
    int n = 0;
    for (HalfFace hf : m.halffaces(c))
        for (auto v : loop_vertices(m, hf)) s += m.position(Vertex{v}), ++n;
    return s / double(n);
}
}  // namespace

TEST_SUITE("Task 2: queries") {
    TEST_CASE("queries: halfface_vertices lists a half-face's loop from the start of halfedge(hf)" * geolab::points(2) *
              geolab::hint("Start with from_vertex(halfedge(hf)) and follow next once around; clear `out` first.")) {
        std::vector<Vertex> out{Vertex{99}};
        for (const Fixture& f : stored_fixtures()) {
            INFO(describe(f));
            const Mesh m = stored_mesh(f);
            for (HalfFace hf : m.halffaces()) {
                halfface_vertices(m, hf, out);
                std::vector<std::uint32_t> got;
                for (Vertex v : out) got.push_back(v.idx);
                const auto expected = loop_vertices(m, hf);
                REQUIRE_MESSAGE(got == expected, hf << ": expected " << list(expected) << ", got " << list(got));
            }
        }
    }

    TEST_CASE("queries: face_cells and boundary_halffaces" * geolab::points(2) *
              geolab::hint("face_cells(f) = (cell(2f), cell(2f+1)); a boundary half-face has no cell and a cell on the "
                           "other side; list them in increasing order.")) {
        std::vector<HalfFace> out{HalfFace{5}};
        for (const Fixture& f : stored_fixtures()) {
            INFO(describe(f));
            const Mesh m = stored_mesh(f);
            const Reference r = reference(f.cells);
            for (Face fc : m.faces()) {
                const auto [a, b] = face_cells(m, fc);
                CHECK_MESSAGE(a == m.cell(Mesh::halfface(fc, 0)), fc << ": first cell expected "
                                                                   << m.cell(Mesh::halfface(fc, 0)) << ", got " << a);
                CHECK_MESSAGE(b == m.cell(Mesh::halfface(fc, 1)), fc << ": second cell expected "
                                                                   << m.cell(Mesh::halfface(fc, 1)) << ", got " << b);
            }
            boundary_halffaces(m, out);
            std::vector<HalfFace> expected;
            for (HalfFace hf : m.halffaces())
                if (!m.cell(hf).is_valid()) expected.push_back(hf);
            CHECK_MESSAGE(out == expected, "boundary half-faces: expected " << list(expected) << ", got " << list(out));
            CHECK_MESSAGE(out.size() == r.boundary_faces, "expected " << r.boundary_faces << " boundary faces");
        }
        // after deleting cells (through the kernel): some first sides 2f lose their cell
        Mesh m = stored_mesh("tet grid 3");
        for (std::uint32_t c : {0u, 1u, 2u, 40u, 77u, 78u, 161u}) kernel_delete_cell(m, Cell{c});
        boundary_halffaces(m, out);
        std::vector<HalfFace> expected;
        for (HalfFace hf : m.halffaces())
            if (!m.is_deleted(hf) && !m.cell(hf).is_valid()) expected.push_back(hf);
        CHECK_MESSAGE(out == expected, "tet grid 3 without cells 0, 1, 2, 40, 77, 78, 161: boundary half-faces expected "
                                           << list(expected) << ", got " << list(out));
    }

    TEST_CASE("queries: cell_vertices lists each corner once in order of first appearance" * geolab::points(3) *
              geolab::hint("Walk halffaces(c) in order and each loop from its halfedge; skip vertices already listed.")) {
        std::vector<Vertex> out;
        for (const Fixture& f : stored_fixtures()) {
            INFO(describe(f));
            const Mesh m = stored_mesh(f);
            for (Cell c : m.cells()) {
                std::vector<std::uint32_t> expected;
                for (HalfFace hf : m.halffaces(c))
                    for (auto v : loop_vertices(m, hf))
                        if (std::find(expected.begin(), expected.end(), v) == expected.end()) expected.push_back(v);
                cell_vertices(m, c, out);
                std::vector<std::uint32_t> got;
                for (Vertex v : out) got.push_back(v.idx);
                REQUIRE_MESSAGE(got == expected, c << ": expected " << list(expected) << ", got " << list(got));
            }
        }
    }

    TEST_CASE("queries: edge_cells visits the cells around every edge once / in radial order / in every configuration" *
              geolab::points(3) *
              geolab::hint("Take a half-edge of e directed b -> a in a cell; the next cell is the cell of "
                           "mate(twin(h)). On a boundary edge walk back first (twin(mate(h))) to the fan's start.")) {
        std::vector<Cell> out;
        for (const Fixture& f : stored_fixtures()) {
            INFO(describe(f));
            const Mesh m = stored_mesh(f);
            for (Edge e : m.edges()) {
                edge_cells(m, e, out);
                for_each_config(m, [&](const auto& x, const char* config) {
                    const auto expected = radial_cells(x, e);
                    REQUIRE_MESSAGE(out == expected, e << " (" << m.edge_vertices(e)[0] << "->" << m.edge_vertices(e)[1]
                                                       << ", configuration " << config << "): expected " << list(expected)
                                                       << ", got " << list(out));
                });
            }
        }
        // every cell deleted (through the kernel, as delete_cell's contract says): no edge has a cell, and the
        // edges have no half-edge left
        Mesh m = stored_mesh("two tets");
        for (Cell c : m.cells()) kernel_delete_cell(m, c);
        for (Edge e : m.edges()) {
            out.assign(1, Cell{7});
            edge_cells(m, e, out);
            CHECK_MESSAGE(out.empty(), "two tets with both cells deleted: " << e << " has no cell, got " << list(out));
        }
    }

    TEST_CASE("queries: edge_cells turns counter-clockwise about a -> b and starts a fan at the boundary" *
              geolab::points(3) *
              geolab::hint("Right-hand rule: thumb from edge_vertices(e)[0] to [1]; the cells' centroids must turn the "
                           "way the fingers curl. Walking b -> a half-edges with h = mate(twin(h)) does that.")) {
        std::vector<Cell> out;
        for (const char* key : {"tet grid 3", "hex grid 2", "cube of 6 pyramids", "Kuhn cube (6 tets)"}) {
            INFO("input: " << key);
            const Mesh m = stored_mesh(key);
            for (Edge e : m.edges()) {
                edge_cells(m, e, out);
                const auto [a, b] = m.edge_vertices(e);
                // (an empty list turns nowhere: it must hold the edge's cells)
                REQUIRE_MESSAGE(out.size() == radial_cells(m, e).size(),
                                e << ": " << out.size() << " cells listed, " << radial_cells(m, e).size() << " around it");
                const glm::dvec3 pa = m.position(a), pb = m.position(b);
                std::vector<double> ang;
                for (Cell c : out) ang.push_back(angle_about(pa, pb, centroid(m, c)));
                const bool interior = radial_cells(m, e).size() == out.size() && !out.empty() &&
                                      [&] {
                                          for (HalfEdge h : m.halfedges())
                                              if (m.edge(h) == e && !m.cell(m.halfface(h)).is_valid()) return false;
                                          return true;
                                      }();
                double turned = 0;
                for (std::size_t i = 0; i + 1 < ang.size() + (interior ? 1 : 0); ++i) {
                    double d = ang[(i + 1) % ang.size()] - ang[i];
                    while (d <= -M_PI) d += 2 * M_PI;
                    while (d > M_PI) d -= 2 * M_PI;
                    REQUIRE_MESSAGE(d > 0, e << ": from " << out[i] << " to " << out[(i + 1) % out.size()]
                                             << " the cells turn clockwise about " << a << "->" << b << " (cells "
                                             << list(out) << ")");
                    turned += d;
                }
                if (interior && out.size() > 1)
                    CHECK_MESSAGE(std::abs(turned - 2 * M_PI) < 1e-6, e << ": an interior edge's cells make one full turn");
                if (!interior && !out.empty()) {
                    // the first cell's b -> a half-edge has a boundary half-face as its mate
                    bool starts_at_boundary = false;
                    for (HalfFace hf : m.halffaces(out.front()))
                        for (auto v : loop_vertices(m, hf)) (void)v;
                    for (HalfEdge h : m.halfedges())
                        if (m.edge(h) == e && m.from_vertex(h) == b && m.cell(m.halfface(h)) == out.front() &&
                            !m.cell(m.halfface(m.mate(h))).is_valid())
                            starts_at_boundary = true;
                    CHECK_MESSAGE(starts_at_boundary, e << ": a boundary edge's list starts at the boundary, got " << list(out));
                }
            }
        }
    }

    TEST_CASE("queries: vertex_cells lists the cells at a vertex once / in increasing order" * geolab::points(3) *
              geolab::hint("The cells of vertex_halffaces(v) that are valid, sorted, without repeats.")) {
        std::vector<Cell> out;
        for (const Fixture& f : stored_fixtures()) {
            INFO(describe(f));
            const Mesh m = stored_mesh(f);
            for (Vertex v : m.vertices()) {
                std::set<std::uint32_t> expected;
                for (std::size_t c = 0; c < f.cells.n_cells(); ++c)
                    for (std::size_t i = 0; i < f.cells.n_faces(c); ++i)
                        for (auto x : f.cells.face(c, i))
                            if (x == v.idx) expected.insert(std::uint32_t(c));
                vertex_cells(m, v, out);
                std::vector<std::uint32_t> got;
                for (Cell c : out) got.push_back(c.idx);
                REQUIRE_MESSAGE(got == std::vector<std::uint32_t>(expected.begin(), expected.end()),
                                v << ": expected " << list(std::vector<std::uint32_t>(expected.begin(), expected.end()))
                                  << ", got " << list(got));
            }
        }
    }
}
