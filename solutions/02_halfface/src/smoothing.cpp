// Task 4: volume Laplacian smoothing (handout §6).
#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/halfface.hpp"

namespace geolab::halfface {

double volume_smoothing(Mesh& mesh, double t, int iterations) {
    // BEGIN SOLUTION
    if (!(t >= 0.0 && t <= 1.0)) throw std::invalid_argument("volume_smoothing: t must be in [0, 1]");
    if (iterations < 0) throw std::invalid_argument("volume_smoothing: iterations must be >= 0");
    // Interior vertices: used by a cell, on no boundary half-face.
    std::vector<std::uint8_t> fixed(mesh.n_vertices(), 0);
    std::vector<Vertex> loop;
    for (Vertex v : mesh.vertices()) fixed[v.idx] = mesh.is_deleted(v) || !mesh.halfedge(v).is_valid();
    for (HalfFace hf : mesh.halffaces())
        if (!mesh.is_deleted(hf) && mesh.is_boundary(hf)) {
            halfface_vertices(mesh, hf, loop);
            for (Vertex v : loop) fixed[v.idx] = 1;
        }
    auto next_pos = mesh.add_property<Kind::vertex, glm::dvec3>("volume_smoothing:new");
    std::vector<glm::dvec3> sum(mesh.n_vertices());
    std::vector<int> degree(mesh.n_vertices());
    for (int it = 0; it < iterations; ++it) {
        std::fill(sum.begin(), sum.end(), glm::dvec3(0.0));
        std::fill(degree.begin(), degree.end(), 0);
        for (Edge e : mesh.edges()) {
            if (mesh.is_deleted(e)) continue;
            const auto [a, b] = mesh.edge_vertices(e);
            sum[a.idx] += mesh.position(b), sum[b.idx] += mesh.position(a);
            ++degree[a.idx], ++degree[b.idx];
        }
        for (Vertex v : mesh.vertices()) {  // an interior vertex has edges: degree > 0
            glm::dvec3 p = mesh.position(v);
            if (!fixed[v.idx]) p += t * (sum[v.idx] / double(degree[v.idx]) - p);
            mesh.set(next_pos, v, p);
        }
        for (Vertex v : mesh.vertices())
            if (!fixed[v.idx]) mesh.position(v) = mesh.get(next_pos, v);
    }
    mesh.remove_property(next_pos);

    // The minimum signed volume over the tetrahedra (cells with 4 faces). With h = a -> b the first half-edge of
    // the first half-face (a, b, c), twin(h) runs b -> a in the face (b, a, d): next(twin(h)) ends at the apex d.
    // The loop (a, b, c) is counter-clockwise seen from outside, so d is behind it and the determinant is negative.
    double min_volume = std::numeric_limits<double>::infinity();
    for (Cell c : mesh.cells()) {
        if (mesh.is_deleted(c) || mesh.halffaces(c).size() != 4) continue;
        const HalfEdge h = mesh.halfedge(mesh.halffaces(c)[0]);
        const glm::dvec3 a = mesh.position(mesh.from_vertex(h)), b = mesh.position(mesh.to_vertex(h));
        const glm::dvec3 cc = mesh.position(mesh.to_vertex(mesh.next(h)));
        const glm::dvec3 d = mesh.position(mesh.to_vertex(mesh.next(mesh.twin(h))));
        min_volume = std::min(min_volume, -glm::dot(glm::cross(b - a, cc - a), d - a) / 6.0);
    }
    return min_volume;
    // END SOLUTION
}

}  // namespace geolab::halfface
