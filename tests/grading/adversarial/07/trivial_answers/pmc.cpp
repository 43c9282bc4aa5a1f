// ADVERSARIAL CASE trivial_answers: every function of lab 07 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 3: point membership classification (handout §4).
#include <cmath>
#include <stdexcept>

#include "geolab/csg.hpp"

namespace geolab::csg {

// Helper functions of your own can go here.

Membership classify(const Tree& t, const glm::dvec3& x, double rel_tol) {
    return {};
}

}  // namespace geolab::csg
