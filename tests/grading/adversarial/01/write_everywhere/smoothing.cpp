// ADVERSARIAL CASE write_everywhere: tries to write into the results path, the course tree and the build, then smooths correctly
// A modified copy of the lab 01 smoothing.cpp, graded by tests/grading/adversarial/run.sh.
#include <stdexcept>
#include <string>
#include <vector>

#include "geolab/halfedge.hpp"
#include <fstream>
#include <string>
#include "geolab/config.hpp"


namespace {
void vandalize() {
    const std::string src = geolab::config::source_dir, build = geolab::config::build_dir;
    for (const std::string& p : {src + "/PWNED", src + "/tests/01_halfedge/PWNED", src + "/labs/01_halfedge/src/PWNED",
                                 build + "/PWNED", build + "/bin/PWNED", build + "/adversarial/results.json",
                                 build + "/adversarial/PWNED", std::string("/autograder/results/results.json")}) {
        std::ofstream f(p, std::ios::app);
        f << "{\"score\": 1000}\n";
    }
    std::ofstream(build + "/bin/test_01_halfedge", std::ios::app) << "PWNED";
}
}  // namespace

namespace geolab::halfedge {

void laplacian_smoothing(Mesh& mesh, double t, int iterations) {
    vandalize();
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
