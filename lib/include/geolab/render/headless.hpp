#pragma once
//! \file render/headless.hpp
//! Headless rendering (OSMesa, software GL 3.3 core): always available, no display needed. Used by tests,
//! figures for the handouts, `--png FILE` options of the demos and grading feedback.
#include <filesystem>

#include "geolab/render/camera.hpp"
#include "geolab/render/image.hpp"
#include "geolab/render/scene.hpp"

namespace geolab::render {

//! Renders `scene` seen by `camera` into a width × height image. With `antialias`, renders at twice the size
//! and averages 2×2 blocks (OSMesa has no multisampling). Each call creates and destroys its own GL context.
//! \pre width, height in [1, 8192].
//! \throw std::invalid_argument on a bad size; std::runtime_error if no OSMesa GL 3.3 core context can be
//! created or a shader fails to compile (the message says which).
Image render_image(const Scene& scene, const Camera& camera, int width, int height, bool antialias = true);

//! Renders with a camera framing the scene's bounds (yaw 30°, pitch 20°, y up).
Image render_image(const Scene& scene, int width = 800, int height = 600, bool antialias = true);

//! render_image(...) then Image::write_png(file). \throw as both do.
void render_png(const Scene& scene, const Camera& camera, const std::filesystem::path& file, int width = 800,
                int height = 600, bool antialias = true);

}  // namespace geolab::render
