// ADVERSARIAL CASE hostile_soup: mesh_tree answers a soup whose last face claims 2^28 indices, render_image an image
// of w x h pixels with 4 bytes. Code in the judge that walks the answer
// (PolygonSoup::face() spans indices[offsets[f]..offsets[f+1]); render::Image::pixel() reads rgba at 4·(y·w + x))
// would read memory outside it: the judge refuses such an answer as malformed. Honest: 0.
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
    // the size asked for, with the pixels of a 1 x 1 image: pixel(x, y) would read far past them
    render::Image img;
    img.width = width;
    img.height = height;
    img.rgba = {255, 255, 255, 255};
    return img;
}

}  // namespace geolab::csg
