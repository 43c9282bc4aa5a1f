#pragma once
// The drawing code shared by both back ends: GLSL programs and the GPU copy of one Scene, drawn into the
// current context's framebuffer. Every GL object belongs to the context current at construction; construct,
// use and destroy a Renderer only while that context is current.
#include <vector>

#include "geolab/render/camera.hpp"
#include "geolab/render/image.hpp"
#include "geolab/render/scene.hpp"
#include "gl.hpp"

namespace geolab::render::detail {

class Renderer {
public:
    // Compiles the programs. Throws std::runtime_error with the GLSL log if one fails.
    explicit Renderer(const Gl& gl);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Replaces the GPU copy of the scene.
    void upload(const Scene& scene);
    // Replaces the rectangles drawn over the scene's own overlay (the window's widgets).
    void set_overlay(const std::vector<Scene::Rect>& rects);
    // Clears to the scene background and draws it into a width × height framebuffer. `pixel_scale` converts the
    // scene's pixel sizes (line widths, point sizes) to framebuffer pixels (2 when supersampling).
    void draw(const Camera& camera, int width, int height, float pixel_scale);
    // The framebuffer's pixels, top row first.
    Image read_pixels(int width, int height) const;

private:
    enum class Kind { Mesh, Lines, Points, Overlay };
    struct Batch {
        Kind kind;
        GLuint vao = 0, vbo = 0;
        GLsizei count = 0;  // vertices
        float opacity = 1.0f, size = 1.0f;
    };
    struct Programs {
        GLuint mesh = 0, lines = 0, points = 0, overlay = 0;
    };

    // A vertex array of interleaved float attributes; `sizes`: the floats of each attribute (location 0, 1, ...).
    Batch make_batch(Kind kind, const std::vector<float>& interleaved, const std::vector<int>& sizes);
    // The same with vec3 attributes only (floats_per_vertex / 3 of them).
    Batch make_batch(Kind kind, const std::vector<float>& interleaved, int floats_per_vertex);
    void free_batches();
    void draw_batch(const Batch& b, const glm::mat4& view, const glm::mat4& proj, glm::vec2 viewport,
                    float pixel_scale);
    GLint uniform(GLuint program, const char* name) const;

    const Gl& gl_;
    Programs prog_;
    // drawn in this order (flat_: the scene's overlay rectangles, widgets_: set_overlay's)
    std::vector<Batch> opaque_, overlay_, transparent_, flat_, widgets_;
    Batch rect_batch(const std::vector<Scene::Rect>& rects);
    glm::vec3 background_{1.0f};
};

}  // namespace geolab::render::detail
