// Task 2: the field (handout §3).
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/blobby.hpp"

namespace geolab::blobby {

FieldValue field(const BlobScene& scene, const glm::dvec3& p) {
    // BEGIN SOLUTION
    if (!std::isfinite(scene.threshold)) throw std::invalid_argument("field: the threshold is not finite");
    FieldValue out{scene.threshold, glm::dvec3(0.0)};
    for (std::size_t i = 0; i < scene.blobs.size(); ++i) {
        const Blob& b = scene.blobs[i];
        const glm::dvec3 d = p - b.center;
        const double r = glm::length(d);
        try {
            out.value -= density(scene.kernel, b, r);
            if (r > 0) out.gradient -= density_derivative(scene.kernel, b, r) / r * d;
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument("field: blob " + std::to_string(i) + ": " + e.what());
        }
    }
    return out;
    // END SOLUTION
}

}  // namespace geolab::blobby
