// SliceRasterizer: an OSMesa context, one shader program that keeps the fragments of a depth slab, XOR logic op.
#include "geolab/render/slicer.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "context.hpp"
#include "gl.hpp"

namespace geolab::render {
namespace {

// Corners arrive in window coordinates (pixels x, y and the depth), computed in double on the CPU.
const char* kSliceVs = R"(#version 330 core
layout(location = 0) in vec3 a_window;
uniform vec2 u_size;
out vec3 v_window;
void main() {
    v_window = a_window;
    gl_Position = vec4(2.0 * a_window.xy / u_size - 1.0, 0.0, 1.0);
})";

// Each triangle hands its first corner and its normal (b − a) × (c − a), in window coordinates, to its fragments.
const char* kSliceGs = R"(#version 330 core
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vec3 v_window[];
flat out vec3 g_a, g_n;
void main() {
    vec3 a = v_window[0];
    vec3 n = cross(v_window[1] - a, v_window[2] - a);
    for (int i = 0; i < 3; ++i) {
        g_a = a;
        g_n = n;
        gl_Position = gl_in[i].gl_Position;
        EmitVertex();
    }
    EndPrimitive();
})";

// A fragment passes when the triangle crosses its pixel's column at a depth d with lo < d <= hi, i.e. when the
// point (pixel centre, hi) lies above the triangle's plane (towards +depth) and (pixel centre, lo) does not. A
// point exactly on the plane is decided for the point moved by a perturbation whose components shrink in the
// order x, y with the depth at place u_rank (simulation of simplicity; the rasterizer's fill rule is the same
// perturbation in x, y). The XOR logic op flips the pixel.
const char* kSliceFs = R"(#version 330 core
flat in vec3 g_a, g_n;
uniform float u_lo, u_hi;
uniform int u_rank;
out vec4 frag;
float first_nonzero(float a, float b, float c) { return a != 0.0 ? a : (b != 0.0 ? b : c); }
bool above(float depth) {
    vec3 p = vec3(gl_FragCoord.xy, depth) - g_a;
    float s = g_n.x * p.x + g_n.y * p.y + g_n.z * p.z;
    if (s == 0.0)
        s = u_rank == 0 ? first_nonzero(g_n.z, g_n.x, g_n.y)
          : u_rank == 1 ? first_nonzero(g_n.x, g_n.z, g_n.y) : first_nonzero(g_n.x, g_n.y, g_n.z);
    return (s > 0.0) == (g_n.z > 0.0);
}
void main() {
    if (g_n.z == 0.0 || !above(u_hi) || above(u_lo)) discard;
    frag = vec4(1.0);
})";

}  // namespace

struct SliceRasterizer::Impl {
    int width = 0, height = 0;
    std::unique_ptr<detail::Context> context;
    detail::Gl gl;
    GLuint program = 0, vao = 0, vbo = 0;
    GLint u_size = -1, u_lo = -1, u_hi = -1, u_rank = -1;
    int depth_rank = 2;
    GLint subpixel_bits = 0;  // GL_SUBPIXEL_BITS: the rasterizer snaps window x, y to multiples of 2^-bits
    std::size_t triangles = 0;

    void current() { context->make_current(); }
};

SliceRasterizer::SliceRasterizer(int width, int height) : impl_(std::make_unique<Impl>()) {
    if (width < 1 || height < 1 || width > 8192 || height > 8192)
        throw std::invalid_argument("geolab::render::SliceRasterizer: image size " + std::to_string(width) + "x" +
                                    std::to_string(height) + " is not in [1, 8192]");
    Impl& m = *impl_;
    m.width = width;
    m.height = height;
    m.context = detail::make_osmesa_context(width, height);
    m.current();
    m.gl.load(m.context->get_proc());
    const detail::Gl& gl = m.gl;
    m.program = detail::link_program(gl, kSliceVs, kSliceGs, kSliceFs);
    m.u_size = gl.GetUniformLocation(m.program, "u_size");
    m.u_rank = gl.GetUniformLocation(m.program, "u_rank");
    m.u_lo = gl.GetUniformLocation(m.program, "u_lo");
    m.u_hi = gl.GetUniformLocation(m.program, "u_hi");
    gl.GenVertexArrays(1, &m.vao);
    gl.GenBuffers(1, &m.vbo);
    gl.BindVertexArray(m.vao);
    gl.BindBuffer(GL_ARRAY_BUFFER, m.vbo);
    gl.EnableVertexAttribArray(0);
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
    gl.UseProgram(m.program);
    gl.Viewport(0, 0, width, height);
    gl.Disable(GL_DEPTH_TEST);
    gl.Disable(GL_CULL_FACE);
    gl.Disable(GL_BLEND);
    gl.Enable(GL_DEPTH_CLAMP);  // no near/far clipping: the slab test alone selects by depth
    gl.Enable(GL_COLOR_LOGIC_OP);
    gl.LogicOp(GL_XOR);
    gl.Uniform2f(m.u_size, float(width), float(height));
    gl.GetIntegerv(GL_SUBPIXEL_BITS, &m.subpixel_bits);
    gl.Uniform1i(m.u_rank, m.depth_rank);
    clear();
}

SliceRasterizer::~SliceRasterizer() {
    Impl& m = *impl_;
    m.current();
    m.gl.DeleteBuffers(1, &m.vbo);
    m.gl.DeleteVertexArrays(1, &m.vao);
    m.gl.DeleteProgram(m.program);
}

int SliceRasterizer::width() const { return impl_->width; }
int SliceRasterizer::height() const { return impl_->height; }
std::size_t SliceRasterizer::triangle_count() const { return impl_->triangles; }

void SliceRasterizer::set_triangles(std::span<const glm::dvec3> corners, const glm::dmat4& camera) {
    const char* where = "geolab::render::SliceRasterizer::set_triangles: ";
    if (corners.size() % 3 != 0)
        throw std::invalid_argument(where + std::to_string(corners.size()) + " corners is not a multiple of 3");
    if (corners.size() > std::size_t(std::numeric_limits<GLint>::max()))
        throw std::invalid_argument(where + std::string("more than 2^31 - 1 corners"));
    if (camera[0][3] != 0 || camera[1][3] != 0 || camera[2][3] != 0 || camera[3][3] != 1)
        throw std::invalid_argument(where + std::string("the camera must be affine (last row 0 0 0 1)"));
    Impl& m = *impl_;
    // window coordinates, in double; x and y snapped to the rasterizer's lattice here, so that the coverage and
    // the fragment shader's plane test see the same triangle; then rounded once to float
    const glm::dvec2 half_size(0.5 * m.width, 0.5 * m.height);
    const double lattice = std::ldexp(1.0, m.subpixel_bits);
    auto snap = [&](double x) { return std::abs(x) < 1e15 ? std::nearbyint(x * lattice) / lattice : x; };
    std::vector<float> data(3 * corners.size());
    constexpr double fmax = std::numeric_limits<float>::max();
    for (std::size_t c = 0; c < corners.size(); ++c) {
        const glm::dvec4 clip = camera * glm::dvec4(corners[c], 1.0);
        const glm::dvec3 w(snap((clip.x + 1.0) * half_size.x), snap((clip.y + 1.0) * half_size.y), clip.z);
        for (int d = 0; d < 3; ++d) {
            if (!(std::abs(w[d]) <= fmax))
                throw std::invalid_argument(where + std::string("corner ") + std::to_string(c) +
                                            " has a window coordinate that is not a finite float (" + std::to_string(w[d]) + ")");
            data[3 * c + d] = float(w[d]);
        }
    }
    m.current();
    m.gl.BindBuffer(GL_ARRAY_BUFFER, m.vbo);
    m.gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(float)), data.data(), GL_STATIC_DRAW);
    m.triangles = corners.size() / 3;
}

void SliceRasterizer::set_depth_rank(int rank) {
    if (rank < 0 || rank > 2)
        throw std::invalid_argument("geolab::render::SliceRasterizer::set_depth_rank: rank " + std::to_string(rank) +
                                    " is not 0, 1 or 2");
    Impl& m = *impl_;
    m.current();
    m.depth_rank = rank;
    m.gl.Uniform1i(m.u_rank, rank);
}

int SliceRasterizer::depth_rank() const { return impl_->depth_rank; }

void SliceRasterizer::clear() {
    Impl& m = *impl_;
    m.current();
    m.gl.Disable(GL_COLOR_LOGIC_OP);  // glClear is not affected by the logic op, but keep the state obvious
    m.gl.ClearColor(0, 0, 0, 0);
    m.gl.Clear(GL_COLOR_BUFFER_BIT);
    m.gl.Enable(GL_COLOR_LOGIC_OP);
}

void SliceRasterizer::draw_xor(std::size_t first, std::size_t count, float lo, float hi) {
    Impl& m = *impl_;
    if (first > m.triangles || count > m.triangles - first)
        throw std::out_of_range("geolab::render::SliceRasterizer::draw_xor: triangles [" + std::to_string(first) + ", " +
                                std::to_string(first + count) + ") but only " + std::to_string(m.triangles) + " are set");
    if (std::isnan(lo) || std::isnan(hi))
        throw std::invalid_argument("geolab::render::SliceRasterizer::draw_xor: a slab bound is NaN");
    if (count == 0) return;
    m.current();
    m.gl.Uniform1f(m.u_lo, lo);
    m.gl.Uniform1f(m.u_hi, hi);
    m.gl.DrawArrays(GL_TRIANGLES, GLint(3 * first), GLsizei(3 * count));
}

std::vector<std::uint8_t> SliceRasterizer::read() {
    Impl& m = *impl_;
    m.current();
    std::vector<std::uint8_t> image(std::size_t(m.width) * std::size_t(m.height));
    m.gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    m.gl.ReadPixels(0, 0, m.width, m.height, GL_RED, GL_UNSIGNED_BYTE, image.data());
    for (std::uint8_t& p : image) p = p != 0;
    return image;
}

int SliceRasterizer::subpixel_bits() const { return int(impl_->subpixel_bits); }

}  // namespace geolab::render
