// ADVERSARIAL CASE always_throws: every function of lab 07 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 3: point membership classification (handout §4).
#include <cmath>
#include <stdexcept>

#include "geolab/csg.hpp"

namespace geolab::csg {

// Helper functions of your own can go here.

Membership classify(const Tree& t, const glm::dvec3& x, double rel_tol) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::csg
