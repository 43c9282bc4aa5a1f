#pragma once
//! \file render/render.hpp
//! The drawing layer of geolab, all of it: Scene (what to draw), Camera (orbit camera), render_image /
//! render_png (headless, OSMesa) and Viewer (interactive window, GLFW), plus picking helpers.
//! The lab demos' shared machinery (command line, window loop, cameras, arrows, figures) is in
//! geolab/render/demo.hpp (not included here: it brings CLI11); docs/demo-framework.md shows a demo written on it.
//!
//!     geolab::render::Scene scene;
//!     scene.add_mesh(soup, {.smooth = false, .wireframe = true});
//!     auto cam = geolab::render::Camera::framing(scene.bounds());
//!     geolab::render::render_png(scene, cam, "figure.png");
#include "geolab/render/camera.hpp"
#include "geolab/render/headless.hpp"
#include "geolab/render/image.hpp"
#include "geolab/render/pick.hpp"
#include "geolab/render/scene.hpp"
#include "geolab/render/viewer.hpp"
