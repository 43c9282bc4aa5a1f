// Task 3: point membership classification (handout §4).
#include <cmath>
#include <stdexcept>

#include "geolab/csg.hpp"

namespace geolab::csg {

// Helper functions of your own can go here.

Membership classify(const Tree& t, const glm::dvec3& x, double rel_tol) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::csg
