// ADVERSARIAL CASE forge_test_case: registers an extra TEST_CASE worth 1000 points (the test header is on the
// include path) that always passes.
// A modified copy of the lab 09 poles.cpp (Task 11), graded by tests/grading/adversarial_09/run.sh.
#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"
#include "geolab/grading/test.hpp"

TEST_SUITE("Task 11: poles") {
    TEST_CASE("fill_poles: bonus" * geolab::points(1000)) { CHECK(true); }
}

namespace geolab::dc {

PoleFillResult fill_poles(PolygonSoup& soup, std::span<const PoleRing> rings, const ScalarField& f,
                          const glm::dvec3& origin, PoleFill::Method method) {
    throw geolab::NotImplemented(__func__);  // the honest part: nothing done
}

}  // namespace geolab::dc
