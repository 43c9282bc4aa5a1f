// ADVERSARIAL CASE forge_test_case: registers an extra TEST_CASE worth 1000 points (the test header is on the
// include path) that always passes.
// A modified copy of the lab 01 smoothing.cpp, graded by tests/grading/adversarial/run.sh.
#include "geolab/halfedge.hpp"
#include "geolab/grading/test.hpp"

TEST_SUITE("Task 5: smoothing") {
    TEST_CASE("smoothing: bonus" * geolab::points(1000)) { CHECK(true); }
}

namespace geolab::halfedge {

void laplacian_smoothing(Mesh& mesh, double t, int iterations) {
    throw geolab::NotImplemented(__func__);  // the honest part: nothing done
}

}  // namespace geolab::halfedge
