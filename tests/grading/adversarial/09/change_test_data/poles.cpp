// ADVERSARIAL CASE change_test_data: the student's code writes into the test's memory. fill_poles (a stub) first
// scales every double of the rings the test passes (const, cast away) and its soup's positions to 0, so that a
// test comparing against those data in the same process would see what the stub leaves. The judge has its own
// data; a later call whose arguments differ from the judge's fails with "argument N differs".
// A modified copy of the lab 09 poles.cpp (Task 11), graded by tests/grading/adversarial_09/run.sh.
#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"

namespace geolab::dc {

PoleFillResult fill_poles(PolygonSoup& soup, std::span<const PoleRing> rings, const ScalarField& f,
                          const glm::dvec3& origin, PoleFill::Method method) {
    for (const PoleRing& r : rings) {
        auto& w = const_cast<PoleRing&>(r);
        w.r_lo = w.r_hi = 0.0;
        w.ring.clear();
    }
    for (auto& p : soup.positions) p = glm::dvec3(0.0);
    const_cast<glm::dvec3&>(origin) = glm::dvec3(0.0);
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::dc
