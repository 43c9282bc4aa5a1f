// ADVERSARIAL CASE always_throws: every function of lab 07 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 6: first hits and ray-cast images (handout §7).
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/csg.hpp"

namespace geolab::csg {

std::optional<Hit> first_hit(const PreparedTree& t, const Ray& ray, double t_min, SpanLists& lists) {
    throw std::invalid_argument(__func__);
}

std::optional<Hit> first_hit(const Tree& t, const Ray& ray, double t_min) {
    throw std::invalid_argument(__func__);
}

render::Image render_image(const Tree& t, const PinholeCamera& camera, int width, int height, const glm::dvec3& light) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::csg
