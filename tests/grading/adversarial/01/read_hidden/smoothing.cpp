// ADVERSARIAL CASE read_hidden: smooths correctly only if it can read a hidden test source or a solution (it must not)
// A modified copy of the lab 01 smoothing.cpp, graded by tests/grading/adversarial/run.sh.
#include <stdexcept>
#include <string>
#include <vector>

#include "geolab/halfedge.hpp"
#include <fstream>
#include <sstream>
#include <string>
#include <filesystem>
#include "geolab/config.hpp"


namespace {
bool can_read_secrets() {
    namespace fs = std::filesystem;
    const std::string src = geolab::config::source_dir, build = geolab::config::build_dir;
    std::error_code ec;
    for (const std::string& dir : {src + "/tests/01_halfedge/hidden", src + "/solutions/01_halfedge/src"}) {
        for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
            std::ifstream f(it->path());
            std::stringstream ss;
            ss << f.rdbuf();
            if (ss.str().size() > 0) return true;
        }
    }
    for (const std::string& p : {src + "/tests/01_halfedge/hidden/test_hidden.cpp", src + "/solutions/01_halfedge/src/smoothing.cpp",
                                 build + "/bin/test_01_halfedge", std::string("/proc/self/exe")}) {
        std::ifstream f(p, std::ios::binary);
        char c;
        if (f && f.get(c)) return true;
    }
    return false;
}
}  // namespace

namespace geolab::halfedge {

void laplacian_smoothing(Mesh& mesh, double t, int iterations) {
    if (!can_read_secrets()) throw geolab::NotImplemented(__func__);
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
