// ADVERSARIAL CASE trivial_answers: every function of lab 07 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 6: first hits and ray-cast images (handout §7).
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/csg.hpp"

namespace geolab::csg {

std::optional<Hit> first_hit(const PreparedTree& t, const Ray& ray, double t_min, SpanLists& lists) {
    return {};
}

std::optional<Hit> first_hit(const Tree& t, const Ray& ray, double t_min) {
    return {};
}

render::Image render_image(const Tree& t, const PinholeCamera& camera, int width, int height, const glm::dvec3& light) {
    return {};
}

}  // namespace geolab::csg
