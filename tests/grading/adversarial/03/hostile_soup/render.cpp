// ADVERSARIAL CASE hostile_soup: the tessellations answer a soup whose last face claims 2^28 indices, the renderer
// an image of w x h pixels with 4 bytes. Code in the judge that walks the answer
// (PolygonSoup::face() spans indices[offsets[f]..offsets[f+1]); render::Image::pixel() reads rgba at 4·(y·w + x))
// would read memory outside it: the judge refuses such an answer as malformed. Honest: 0.
// Task 7: images (handout §9).
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {

render::Image render_lambert(const Scene& scene, const PinholeCamera& camera, int width, int height) {
    // the size asked for, with the pixels of a 1 x 1 image: pixel(x, y) would read far past them
    render::Image img;
    img.width = width;
    img.height = height;
    img.rgba = {255, 255, 255, 255};
    return img;
}

}  // namespace geolab::quadrics
