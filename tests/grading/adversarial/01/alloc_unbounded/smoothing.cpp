// ADVERSARIAL CASE alloc_unbounded: allocates and touches memory without bound
// A modified copy of the lab 01 smoothing.cpp, graded by tests/grading/adversarial/run.sh.
#include <stdexcept>
#include <string>
#include <vector>

#include "geolab/halfedge.hpp"
#include <cstring>
#include <vector>

namespace geolab::halfedge {

void laplacian_smoothing(Mesh& mesh, double t, int iterations) {
    std::vector<char*> hog;
    for (;;) {
        char* p = new char[64 << 20];
        std::memset(p, 1, 64 << 20);
        hog.push_back(p);
    }
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::halfedge
