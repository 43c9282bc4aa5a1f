// ADVERSARIAL CASE fork_leave_child: forks children that sleep forever, smooths correctly
// A modified copy of the lab 01 smoothing.cpp, graded by tests/grading/adversarial/run.sh.
#include <stdexcept>
#include <string>
#include <vector>

#include "geolab/halfedge.hpp"
#include <unistd.h>

namespace geolab::halfedge {

void laplacian_smoothing(Mesh& mesh, double t, int iterations) {
    if (::fork() == 0) {
        for (;;) ::pause();
    }
    if (!(t >= 0.0 && t <= 1.0))
        throw std::invalid_argument("laplacian_smoothing: t = " + std::to_string(t) + " is not in [0, 1]");
    if (iterations < 0)
        throw std::invalid_argument("laplacian_smoothing: iterations = " + std::to_string(iterations) + " < 0");
    std::vector<glm::dvec3> old;
    std::vector<Vertex> ring;
    for (int it = 0; it < iterations; ++it) {
        old = mesh.positions();  // Jacobi: every L(v) reads the positions before this iteration
        for (Vertex v : mesh.vertices()) {
            if (mesh.is_boundary(v)) continue;  // boundary and isolated vertices stay put
            one_ring_vertices(mesh, v, ring);
            glm::dvec3 mean(0.0);
            for (Vertex w : ring) mean += old[w.idx];
            mean /= static_cast<double>(ring.size());
            mesh.position(v) = old[v.idx] + t * (mean - old[v.idx]);  // v + t·L(v), L(v) = mean − v
        }
    }
}

}  // namespace geolab::halfedge
