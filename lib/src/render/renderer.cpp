#include "renderer.hpp"

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>
#include <stdexcept>
#include <string>

namespace geolab::render::detail {
namespace {

// ---- GLSL 3.30 core ---------------------------------------------------------------------------------------

// Meshes: Blinn-Phong with a headlight-style key light (from the viewer, a little up and to the left) plus
// ambient; two-sided, so the back of an open surface is lit like its front.
const char* kMeshVs = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_color;
uniform mat4 u_view, u_proj;
out vec3 v_pos, v_normal, v_color;
void main() {
    vec4 p = u_view * vec4(a_position, 1.0);
    v_pos = p.xyz;
    v_normal = mat3(u_view) * a_normal;  // the view is a rigid motion
    v_color = a_color;
    gl_Position = u_proj * p;
})";

const char* kMeshFs = R"(#version 330 core
in vec3 v_pos, v_normal, v_color;
uniform float u_opacity;
out vec4 frag;
void main() {
    vec3 n = dot(v_normal, v_normal) > 1e-24 ? normalize(v_normal) : vec3(0.0, 0.0, 1.0);
    if (!gl_FrontFacing) n = -n;
    vec3 v = normalize(-v_pos);
    vec3 l = normalize(vec3(-0.35, 0.45, 1.0));
    float diffuse = max(dot(n, l), 0.0);
    float specular = pow(max(dot(n, normalize(l + v)), 0.0), 48.0);
    vec3 c = v_color * (0.38 + 0.62 * diffuse) + vec3(0.18 * specular);
    frag = vec4(min(c, vec3(1.0)), u_opacity);
})";

// Lines: each segment becomes a screen-space quad `u_width` pixels wide (core GL has no wide lines), clipped at
// the near plane first. Vertices are pulled slightly towards the eye so that edges on a surface stay visible.
const char* kLineVs = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_color;
uniform mat4 u_view, u_proj;
uniform float u_pull;
out vec3 g_color;
void main() {
    vec4 p = u_view * vec4(a_position, 1.0);
    p.xyz *= 1.0 - u_pull;
    g_color = a_color;
    gl_Position = u_proj * p;
})";

const char* kLineGs = R"(#version 330 core
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;
in vec3 g_color[];
out vec3 f_color;
uniform vec2 u_viewport;
uniform float u_width;
void emit(vec4 p, vec2 offset_px, vec3 c) {
    gl_Position = vec4(p.xy + offset_px * 2.0 / u_viewport * p.w, p.zw);
    f_color = c;
    EmitVertex();
}
void main() {
    vec4 p0 = gl_in[0].gl_Position, p1 = gl_in[1].gl_Position;
    vec3 c0 = g_color[0], c1 = g_color[1];
    float d0 = p0.z + p0.w, d1 = p1.z + p1.w;  // signed distance to the near plane, clip space
    if (d0 < 0.0 && d1 < 0.0) return;
    if (d0 < 0.0) { float t = d0 / (d0 - d1); p0 = mix(p0, p1, t); c0 = mix(c0, c1, t); }
    if (d1 < 0.0) { float t = d1 / (d1 - d0); p1 = mix(p1, p0, t); c1 = mix(c1, c0, t); }
    vec2 s0 = p0.xy / p0.w * u_viewport * 0.5, s1 = p1.xy / p1.w * u_viewport * 0.5;
    vec2 dir = s1 - s0;
    float len = length(dir);
    dir = len > 1e-6 ? dir / len : vec2(1.0, 0.0);
    vec2 along = dir * 0.5 * u_width, across = vec2(-dir.y, dir.x) * 0.5 * u_width;  // square caps
    emit(p0, -along + across, c0);
    emit(p0, -along - across, c0);
    emit(p1, along + across, c1);
    emit(p1, along - across, c1);
    EndPrimitive();
})";

const char* kLineFs = R"(#version 330 core
in vec3 f_color;
out vec4 frag;
void main() { frag = vec4(f_color, 1.0); })";

// Points: round discs of `u_size` pixels with a thin darker rim.
const char* kPointVs = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_color;
uniform mat4 u_view, u_proj;
uniform float u_pull, u_size;
out vec3 f_color;
void main() {
    vec4 p = u_view * vec4(a_position, 1.0);
    p.xyz *= 1.0 - u_pull;
    f_color = a_color;
    gl_Position = u_proj * p;
    gl_PointSize = u_size;
})";

const char* kPointFs = R"(#version 330 core
in vec3 f_color;
uniform float u_size, u_rim;
out vec4 frag;
void main() {
    float r = length(gl_PointCoord * 2.0 - 1.0);
    if (r > 1.0) discard;
    float rim_start = 1.0 - 2.0 * u_rim / u_size;
    frag = vec4(r > rim_start ? 0.45 * f_color : f_color, 1.0);
})";

// Overlay: flat rectangles given in output pixels (top-left origin), with an RGBA colour; blended, no depth.
const char* kOverlayVs = R"(#version 330 core
layout(location = 0) in vec2 a_pixel;
layout(location = 1) in vec4 a_color;
uniform vec2 u_viewport;
uniform float u_scale;
out vec4 f_color;
void main() {
    vec2 p = a_pixel * u_scale / u_viewport;
    gl_Position = vec4(2.0 * p.x - 1.0, 1.0 - 2.0 * p.y, 0.0, 1.0);
    f_color = a_color;
})";

const char* kOverlayFs = R"(#version 330 core
in vec4 f_color;
out vec4 frag;
void main() { frag = f_color; })";

void push(std::vector<float>& out, glm::vec3 v) { out.insert(out.end(), {v.x, v.y, v.z}); }

constexpr float kPull = 1.5e-3f;  // lines and points move this fraction of their depth towards the eye

}  // namespace

Renderer::Renderer(const Gl& gl) : gl_(gl) {
    prog_.mesh = link_program(gl, kMeshVs, nullptr, kMeshFs);
    prog_.lines = link_program(gl, kLineVs, kLineGs, kLineFs);
    prog_.points = link_program(gl, kPointVs, nullptr, kPointFs);
    prog_.overlay = link_program(gl, kOverlayVs, nullptr, kOverlayFs);
}

Renderer::~Renderer() {
    free_batches();
    set_overlay({});
    gl_.DeleteProgram(prog_.mesh);
    gl_.DeleteProgram(prog_.lines);
    gl_.DeleteProgram(prog_.points);
    gl_.DeleteProgram(prog_.overlay);
}

void Renderer::free_batches() {
    for (auto* list : {&opaque_, &overlay_, &transparent_, &flat_}) {
        for (Batch& b : *list) {
            gl_.DeleteBuffers(1, &b.vbo);
            gl_.DeleteVertexArrays(1, &b.vao);
        }
        list->clear();
    }
}

Renderer::Batch Renderer::make_batch(Kind kind, const std::vector<float>& data, int floats_per_vertex) {
    std::vector<int> sizes(floats_per_vertex / 3, 3);  // vec3 attributes: position, [normal,] colour
    return make_batch(kind, data, sizes);
}

Renderer::Batch Renderer::make_batch(Kind kind, const std::vector<float>& data, const std::vector<int>& sizes) {
    Batch b{kind};
    int floats_per_vertex = 0;
    for (int n : sizes) floats_per_vertex += n;
    b.count = static_cast<GLsizei>(data.size() / floats_per_vertex);
    gl_.GenVertexArrays(1, &b.vao);
    gl_.BindVertexArray(b.vao);
    gl_.GenBuffers(1, &b.vbo);
    gl_.BindBuffer(GL_ARRAY_BUFFER, b.vbo);
    gl_.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(), GL_STATIC_DRAW);
    // the attributes, interleaved
    const GLsizei stride = floats_per_vertex * sizeof(float);
    std::size_t offset = 0;
    for (GLuint a = 0; a < sizes.size(); ++a) {
        gl_.EnableVertexAttribArray(a);
        gl_.VertexAttribPointer(a, sizes[a], GL_FLOAT, GL_FALSE, stride,
                                reinterpret_cast<const void*>(offset * sizeof(float)));
        offset += static_cast<std::size_t>(sizes[a]);
    }
    gl_.BindVertexArray(0);
    return b;
}

void Renderer::upload(const Scene& scene) {
    free_batches();
    background_ = scene.background;
    auto add_lines = [&](std::vector<Batch>& list, const std::vector<glm::vec3>& pos,
                         const std::vector<glm::vec3>& color, glm::vec3 one_color, float width) {
        if (pos.size() < 2) return;
        std::vector<float> data;
        data.reserve(pos.size() * 6);
        for (std::size_t i = 0; i < pos.size(); ++i) {
            push(data, pos[i]);
            push(data, color.empty() ? one_color : color[i]);
        }
        Batch b = make_batch(Kind::Lines, data, 6);
        b.size = width;
        list.push_back(b);
    };
    for (const Scene::Mesh& m : scene.meshes()) {
        if (m.position.empty()) continue;
        std::vector<float> data;
        data.reserve(m.position.size() * 9);
        for (std::size_t i = 0; i < m.position.size(); ++i) {
            push(data, m.position[i]);
            push(data, m.normal[i]);
            push(data, m.color[i]);
        }
        const bool opaque = m.style.opacity >= 1.0f;
        Batch b = make_batch(Kind::Mesh, data, 9);
        b.opacity = m.style.opacity;
        (opaque ? opaque_ : transparent_).push_back(b);
        add_lines(opaque ? overlay_ : transparent_, m.wire, {}, m.style.wire_color, m.style.wire_width);
    }
    for (const Scene::Lines& l : scene.lines()) add_lines(overlay_, l.position, l.color, {}, l.width);
    for (const Scene::Points& p : scene.points()) {
        if (p.position.empty()) continue;
        std::vector<float> data;
        for (std::size_t i = 0; i < p.position.size(); ++i) {
            push(data, p.position[i]);
            push(data, p.color[i]);
        }
        Batch b = make_batch(Kind::Points, data, 6);
        b.size = p.size;
        overlay_.push_back(b);
    }
    if (!scene.overlay().empty()) flat_.push_back(rect_batch(scene.overlay()));
}

Renderer::Batch Renderer::rect_batch(const std::vector<Scene::Rect>& rects) {
    // two triangles a rectangle: (x, y) and (r, g, b, a) per vertex
    std::vector<float> data;
    data.reserve(rects.size() * 36);
    for (const Scene::Rect& r : rects) {
        const glm::vec2 c[6] = {r.lo, {r.hi.x, r.lo.y}, r.hi, r.lo, r.hi, {r.lo.x, r.hi.y}};
        for (const glm::vec2& p : c) data.insert(data.end(), {p.x, p.y, r.color.r, r.color.g, r.color.b, r.color.a});
    }
    return make_batch(Kind::Overlay, data, {2, 4});
}

void Renderer::set_overlay(const std::vector<Scene::Rect>& rects) {
    for (Batch& b : widgets_) {
        gl_.DeleteBuffers(1, &b.vbo);
        gl_.DeleteVertexArrays(1, &b.vao);
    }
    widgets_.clear();
    if (!rects.empty()) widgets_.push_back(rect_batch(rects));
}

GLint Renderer::uniform(GLuint program, const char* name) const { return gl_.GetUniformLocation(program, name); }

void Renderer::draw_batch(const Batch& b, const glm::mat4& view, const glm::mat4& proj, glm::vec2 viewport,
                          float pixel_scale) {
    if (b.kind == Kind::Overlay) {
        gl_.UseProgram(prog_.overlay);
        gl_.Uniform2f(uniform(prog_.overlay, "u_viewport"), viewport.x, viewport.y);
        gl_.Uniform1f(uniform(prog_.overlay, "u_scale"), pixel_scale);
        gl_.BindVertexArray(b.vao);
        gl_.DrawArrays(GL_TRIANGLES, 0, b.count);
        return;
    }
    GLuint p = b.kind == Kind::Mesh ? prog_.mesh : b.kind == Kind::Lines ? prog_.lines : prog_.points;
    gl_.UseProgram(p);
    gl_.UniformMatrix4fv(uniform(p, "u_view"), 1, GL_FALSE, glm::value_ptr(view));
    gl_.UniformMatrix4fv(uniform(p, "u_proj"), 1, GL_FALSE, glm::value_ptr(proj));
    gl_.BindVertexArray(b.vao);
    switch (b.kind) {
        case Kind::Mesh:
            gl_.Uniform1f(uniform(p, "u_opacity"), b.opacity);
            gl_.DrawArrays(GL_TRIANGLES, 0, b.count);
            break;
        case Kind::Lines:
            gl_.Uniform1f(uniform(p, "u_pull"), kPull);
            gl_.Uniform2f(uniform(p, "u_viewport"), viewport.x, viewport.y);
            gl_.Uniform1f(uniform(p, "u_width"), b.size * pixel_scale);
            gl_.DrawArrays(GL_LINES, 0, b.count);
            break;
        case Kind::Overlay:
            break;  // drawn above
        case Kind::Points:
            gl_.Uniform1f(uniform(p, "u_pull"), kPull);
            gl_.Uniform1f(uniform(p, "u_size"), b.size * pixel_scale);
            gl_.Uniform1f(uniform(p, "u_rim"), 1.0f * pixel_scale);
            gl_.DrawArrays(GL_POINTS, 0, b.count);
            break;
    }
}

void Renderer::draw(const Camera& camera, int width, int height, float pixel_scale) {
    const glm::mat4 view = camera.view(), proj = camera.proj(float(width) / float(height));
    const glm::vec2 viewport(width, height);
    gl_.Viewport(0, 0, width, height);
    gl_.ClearColor(background_.r, background_.g, background_.b, 1.0f);
    gl_.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl_.Enable(GL_DEPTH_TEST);
    gl_.DepthFunc(GL_LEQUAL);
    gl_.DepthMask(GL_TRUE);
    gl_.Disable(GL_BLEND);
    gl_.Disable(GL_CULL_FACE);
    gl_.Enable(GL_PROGRAM_POINT_SIZE);

    // opaque faces, pushed back a little so that edges drawn on them win the depth test
    gl_.Enable(GL_POLYGON_OFFSET_FILL);
    gl_.PolygonOffset(1.0f, 1.0f);
    for (const Batch& b : opaque_) draw_batch(b, view, proj, viewport, pixel_scale);
    gl_.Disable(GL_POLYGON_OFFSET_FILL);

    // wireframes, lines, points
    for (const Batch& b : overlay_) draw_batch(b, view, proj, viewport, pixel_scale);

    // transparent meshes: blended without depth writes, back faces then front faces (exact for convex shapes)
    if (!transparent_.empty()) {
        gl_.Enable(GL_BLEND);
        gl_.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        gl_.DepthMask(GL_FALSE);
        gl_.Enable(GL_CULL_FACE);
        for (GLenum cull : {GL_FRONT, GL_BACK}) {
            gl_.CullFace(cull);
            for (const Batch& b : transparent_) {
                if (b.kind == Kind::Mesh) draw_batch(b, view, proj, viewport, pixel_scale);
            }
        }
        gl_.Disable(GL_CULL_FACE);
        gl_.DepthMask(GL_TRUE);
        for (const Batch& b : transparent_) {
            if (b.kind != Kind::Mesh) draw_batch(b, view, proj, viewport, pixel_scale);
        }
        gl_.Disable(GL_BLEND);
    }

    // the overlay: over everything, blended, in the order given
    if (!flat_.empty() || !widgets_.empty()) {
        gl_.Disable(GL_DEPTH_TEST);
        gl_.Enable(GL_BLEND);
        gl_.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        for (const Batch& b : flat_) draw_batch(b, view, proj, viewport, pixel_scale);
        for (const Batch& b : widgets_) draw_batch(b, view, proj, viewport, pixel_scale);
        gl_.Disable(GL_BLEND);
        gl_.Enable(GL_DEPTH_TEST);
    }
    gl_.BindVertexArray(0);
    gl_.UseProgram(0);
}

Image Renderer::read_pixels(int width, int height) const {
    Image img{width, height, std::vector<std::uint8_t>(4 * std::size_t(width) * height)};
    std::vector<std::uint8_t> bottom_up(img.rgba.size());
    gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl_.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
    const std::size_t row = 4 * std::size_t(width);
    for (int y = 0; y < height; ++y)
        std::copy_n(bottom_up.data() + (height - 1 - y) * row, row, img.rgba.data() + y * row);
    for (std::size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 255;  // the framebuffer is opaque
    return img;
}

}  // namespace geolab::render::detail
