// Task 7: images (handout §9).
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {

render::Image render_lambert(const Scene& scene, const PinholeCamera& camera, int width, int height) {
    // BEGIN SOLUTION
    if (width < 1 || height < 1) throw std::invalid_argument("render_lambert: width and height must be >= 1");
    const glm::dvec3 l = glm::normalize(scene.light);
    render::Image img;
    img.width = width;
    img.height = height;
    img.rgba.assign(std::size_t(4) * width * height, 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const Ray ray = camera.ray(x, y, width, height);
            std::optional<Hit> hit;
            if (scene.is_superquadric) {
                hit = intersect_superquadric(scene.sq, ray, 0.0, std::numeric_limits<double>::infinity());
            } else {
                const auto hits = intersect_in_box(scene.Q, ray, scene.box);
                if (!hits.empty()) hit = hits.front();
            }
            const double v = hit ? 0.1 + 0.9 * std::abs(glm::dot(hit->normal, l)) : 0.0;
            const auto byte = static_cast<std::uint8_t>(std::lround(255 * v));
            std::uint8_t* p = img.rgba.data() + 4 * (std::size_t(y) * width + x);
            p[0] = p[1] = p[2] = byte;
            p[3] = 255;
        }
    return img;
    // END SOLUTION
}

}  // namespace geolab::quadrics
