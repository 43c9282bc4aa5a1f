// ADVERSARIAL CASE sleep_forever: sleeps forever
// A modified copy of the lab 01 smoothing.cpp, graded by tests/grading/adversarial/run.sh.
#include <stdexcept>
#include <string>
#include <vector>

#include "geolab/halfedge.hpp"
#include <unistd.h>

namespace geolab::halfedge {

void laplacian_smoothing(Mesh& mesh, double t, int iterations) {
    for (;;) ::sleep(1000);
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::halfedge
