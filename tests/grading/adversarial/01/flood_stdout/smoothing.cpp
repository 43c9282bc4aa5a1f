// ADVERSARIAL CASE flood_stdout: floods stdout
// A modified copy of the lab 01 smoothing.cpp, graded by tests/grading/adversarial/run.sh.
#include <stdexcept>
#include <string>
#include <vector>

#include "geolab/halfedge.hpp"
#include <cstdio>

namespace geolab::halfedge {

void laplacian_smoothing(Mesh& mesh, double t, int iterations) {
    for (;;) std::fputs("[doctest] Status: SUCCESS! ........................................\n", stdout);
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::halfedge
