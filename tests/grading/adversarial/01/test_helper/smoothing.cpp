// ADVERSARIAL CASE test_helper: smoothing by the tests' own reference computation (lab01::reference_smoothing_step,
// an inline function of tests/01_halfedge/helpers.hpp that the test objects define). Rejected: a use of a symbol that
// only the test code defines.
#include <stdexcept>
#include <string>
#include <vector>

#include "geolab/halfedge.hpp"

namespace lab01 {
std::vector<glm::dvec3> reference_smoothing_step(const geolab::PolygonSoup& s, const std::vector<glm::dvec3>& p, double t);
}

namespace geolab::halfedge {

void laplacian_smoothing(Mesh& mesh, double t, int iterations) {
    if (!(t >= 0.0 && t <= 1.0))
        throw std::invalid_argument("laplacian_smoothing: t = " + std::to_string(t) + " is not in [0, 1]");
    if (iterations < 0)
        throw std::invalid_argument("laplacian_smoothing: iterations = " + std::to_string(iterations) + " < 0");
    PolygonSoup soup;
    soup.positions = mesh.positions();
    std::vector<Halfedge> hs;
    std::vector<std::uint32_t> f;
    for (Face face : mesh.faces()) {
        face_halfedges(mesh, face, hs);
        f.clear();
        for (Halfedge h : hs) f.push_back(mesh.from_vertex(h).idx);
        soup.add_face(std::span<const std::uint32_t>(f.data(), f.size()));
    }
    for (int it = 0; it < iterations; ++it) {
        const auto next = lab01::reference_smoothing_step(soup, soup.positions, t);
        soup.positions = next;
    }
    for (Vertex v : mesh.vertices()) mesh.position(v) = soup.positions[v.idx];
}

}  // namespace geolab::halfedge
