// ADVERSARIAL CASE inline_syscall: the reference smoothing, but it writes through an inline `syscall` instruction
// while the forbidden list names every libc I/O call. Rejected: a raw system call instruction.
#include <stdexcept>
#include <string>
#include <vector>

#include "geolab/halfedge.hpp"

namespace {
long raw_out(long fd, const void* buf, long n) {
    long ret;
    asm volatile("syscall" : "=a"(ret) : "a"(1L), "D"(fd), "S"(buf), "d"(n) : "rcx", "r11", "memory");
    return ret;
}
}  // namespace


namespace geolab::halfedge {

void laplacian_smoothing(Mesh& mesh, double t, int iterations) {
    if (!(t >= 0.0 && t <= 1.0))
        throw std::invalid_argument("laplacian_smoothing: t = " + std::to_string(t) + " is not in [0, 1]");
    if (iterations < 0)
        throw std::invalid_argument("laplacian_smoothing: iterations = " + std::to_string(iterations) + " < 0");
    raw_out(2, "smoothing\n", 10);
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
