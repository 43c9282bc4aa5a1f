// ADVERSARIAL CASE tmp_1_plant: the reference smoothing, which also leaves a copy of itself in /tmp, /var/tmp and
// /dev/shm for a later submission (tmp_2_use) to #include. Each compile and test must get its own empty /tmp.
#include <fstream>
// Task 5: uniform Laplacian smoothing (handout §7).
#include <stdexcept>
#include <string>
#include <vector>

#include "geolab/halfedge.hpp"

namespace geolab::halfedge {

void laplacian_smoothing(Mesh& mesh, double t, int iterations) {
    for (const char* p : {"/tmp/geolab_adv_planted.cpp", "/var/tmp/geolab_adv_planted.cpp", "/dev/shm/geolab_adv_planted.cpp"})
        std::ofstream(p) << R"PLANT(
// Task 5: uniform Laplacian smoothing (handout §7).
#include <stdexcept>
#include <string>
#include <vector>

#include "geolab/halfedge.hpp"

namespace geolab::halfedge {

void laplacian_smoothing(Mesh& mesh, double t, int iterations) {
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

)PLANT";
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
