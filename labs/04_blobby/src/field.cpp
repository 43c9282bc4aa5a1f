// Task 2: the field (handout §3).
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/blobby.hpp"

namespace geolab::blobby {

FieldValue field(const BlobScene& scene, const glm::dvec3& p) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::blobby
