// ADVERSARIAL CASE forbidden_wrapper: lab 03 forbids lib's Quadric::value (XᵀQX, Task 1's evaluate). This file
// (Task 3's, left a stub) hides the call in a template helper of its own, instantiated here for geolab::Quadric:
// an inline function leaves no call in any object, only the source shows it. matrix_form.cpp calls the helper.
// Honest: what the code earns with no list, less its Task 1 points (the check zeroes Task 1).
#include <stdexcept>

#include "geolab/quadric.hpp"
#include "geolab/quadrics.hpp"

namespace geolab::quadrics {

namespace helpers {
template <class Q>
double value_of(const Q& q, const glm::dvec3& x) {
    return q.value(x);
}
double xtqx(const glm::dmat4& Q, const glm::dvec3& x) { return value_of(geolab::Quadric{Q}, x); }
}  // namespace helpers

QuadricType classify(const glm::dmat4& Q) { throw geolab::NotImplemented(__func__); }

}  // namespace geolab::quadrics
