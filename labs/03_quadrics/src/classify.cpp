// Task 3: classification (handout §5).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {
namespace {
// Helper functions of your own can go here (symmetric_eigen is given).
}  // namespace

QuadricType classify(const glm::dmat4& Q) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::quadrics
