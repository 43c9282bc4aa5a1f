// Headless back end: render_image draws into an OSMesa context (osmesa_context.cpp) and reads it back.
#include "geolab/render/headless.hpp"

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "context.hpp"
#include "renderer.hpp"

namespace geolab::render {
namespace detail {
namespace {

// Averages 2×2 blocks of `big` (2w × 2h) into a w × h image.
Image downsample2(const Image& big) {
    Image img{big.width / 2, big.height / 2, {}};
    img.rgba.resize(4 * std::size_t(img.width) * img.height);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            for (int c = 0; c < 4; ++c) {
                auto at = [&](int dx, int dy) {
                    return int(big.rgba[4 * (std::size_t(2 * y + dy) * big.width + (2 * x + dx)) + c]);
                };
                int sum = at(0, 0) + at(1, 0) + at(0, 1) + at(1, 1);
                img.rgba[4 * (std::size_t(y) * img.width + x) + c] = std::uint8_t((sum + 2) / 4);
            }
    return img;
}

}  // namespace
}  // namespace detail

Image render_image(const Scene& scene, const Camera& camera, int width, int height, bool antialias) {
    if (width < 1 || height < 1 || width > 8192 || height > 8192)
        throw std::invalid_argument("geolab::render::render_image: image size " + std::to_string(width) + "x" +
                                    std::to_string(height) + " is not in [1, 8192]");
    const int scale = antialias ? 2 : 1;
    const int w = scale * width, h = scale * height;
    std::unique_ptr<detail::Context> context = detail::make_osmesa_context(w, h);
    context->make_current();
    detail::Gl gl;
    gl.load(context->get_proc());
    Image big;
    {
        detail::Renderer renderer(gl);
        renderer.upload(scene);
        renderer.draw(camera, w, h, float(scale));
        gl.Finish();
        big = renderer.read_pixels(w, h);
    }
    return antialias ? detail::downsample2(big) : big;
}

Image render_image(const Scene& scene, int width, int height, bool antialias) {
    return render_image(scene, Camera::framing(scene.bounds()), width, height, antialias);
}

void render_png(const Scene& scene, const Camera& camera, const std::filesystem::path& file, int width, int height,
                bool antialias) {
    render_image(scene, camera, width, height, antialias).write_png(file);
}

}  // namespace geolab::render
