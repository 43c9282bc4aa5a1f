// Task 6: first hits and ray-cast images (handout §7).
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/csg.hpp"

namespace geolab::csg {

std::optional<Hit> first_hit(const PreparedTree& t, const Ray& ray, double t_min, SpanLists& lists) {
    throw geolab::NotImplemented(__func__);
}

std::optional<Hit> first_hit(const Tree& t, const Ray& ray, double t_min) {
    throw geolab::NotImplemented(__func__);
}

render::Image render_image(const Tree& t, const PinholeCamera& camera, int width, int height, const glm::dvec3& light) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::csg
