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
        for (Vertex v : mesh.vertices()) {
            glm::dvec3 p = mesh.position(v);
            if (!fixed[v.idx] && degree[v.idx] > 0) p += t * (sum[v.idx] / double(degree[v.idx]) - p);
            mesh.set(next_pos, v, p);
        }
        for (Vertex v : mesh.vertices())
            if (!fixed[v.idx]) mesh.position(v) = mesh.get(next_pos, v);
    }
    mesh.remove_property(next_pos);

    double min_volume = std::numeric_limits<double>::infinity();
    for (Cell c : mesh.cells()) {
        if (mesh.is_deleted(c)) continue;
        const auto hfs = mesh.halffaces(c);
        std::vector<Vertex> corners;
        cell_vertices(mesh, c, corners);
        if (hfs.size() != 4 || corners.size() != 4) continue;
        halfface_vertices(mesh, hfs[0], loop);
        Vertex d;
        for (Vertex x : corners)
            if (x != loop[0] && x != loop[1] && x != loop[2]) d = x;
        const glm::dvec3 a = mesh.position(loop[0]);
        // the loop is counter-clockwise seen from outside: d is behind it, so the determinant is negative
        const double det = glm::dot(glm::cross(mesh.position(loop[1]) - a, mesh.position(loop[2]) - a),
                                    mesh.position(d) - a);
        min_volume = std::min(min_volume, -det / 6.0);
    }
    return min_volume;
    // END SOLUTION
}

}  // namespace geolab::halfface
