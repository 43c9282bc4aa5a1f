// Task 6: first hits and ray-cast images (handout §7).
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/csg.hpp"

namespace geolab::csg {

std::optional<Hit> first_hit(const PreparedTree& t, const Ray& ray, double t_min, SpanLists& lists) {
    // BEGIN SOLUTION
    ray_spans(t, ray, lists);
    for (const Span& s : lists[t.root]) {
        double at;
        glm::dvec3 n;
        if (s.t0 >= t_min) {
            at = s.t0;
            n = s.n0;
        } else if (s.t1 >= t_min) {
            at = s.t1;
            n = s.n1;
        } else {
            continue;
        }
        if (!std::isfinite(at)) return std::nullopt;
        return Hit{at, ray.origin + at * ray.direction, n};
    }
    return std::nullopt;
    // END SOLUTION
}

std::optional<Hit> first_hit(const Tree& t, const Ray& ray, double t_min) {
    // BEGIN SOLUTION
    SpanLists lists;
    return first_hit(prepare(t), ray, t_min, lists);
    // END SOLUTION
}

render::Image render_image(const Tree& t, const PinholeCamera& camera, int width, int height, const glm::dvec3& light) {
    // BEGIN SOLUTION
    if (width < 1 || height < 1) throw std::invalid_argument("render_image: width and height must be >= 1");
    const PreparedTree p = prepare(t);  // checked and inverted once, not once per pixel
    SpanLists lists;                     // reused by every pixel: no allocation per ray
    const glm::dvec3 l = glm::normalize(light);
    render::Image img;
    img.width = width;
    img.height = height;
    img.rgba.assign(std::size_t(4) * width * height, 255);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const auto h = first_hit(p, camera.ray(x, y, width, height), 0.0, lists);
            if (!h) continue;
            const double v = 0.1 + 0.8 * std::abs(glm::dot(h->normal, l));
            const auto g = static_cast<std::uint8_t>(std::lround(255 * v));
            std::uint8_t* px = &img.rgba[4 * (std::size_t(y) * width + x)];
            px[0] = px[1] = px[2] = g;
        }
    return img;
    // END SOLUTION
}

}  // namespace geolab::csg
