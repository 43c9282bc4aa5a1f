#include "gl.hpp"

#include <stdexcept>
#include <string>

namespace geolab::render::detail {

void Gl::load(GetProc get_proc) {
#define GEOLAB_GL_LOAD(type, name)                       \
    name = reinterpret_cast<type>(get_proc("gl" #name)); \
    if (!name) throw std::runtime_error("geolab::render: the GL context does not provide gl" #name);
    GEOLAB_GL_FUNCTIONS(GEOLAB_GL_LOAD)
#undef GEOLAB_GL_LOAD
}

namespace {

GLuint compile(const Gl& gl, GLenum type, const char* source) {
    GLuint s = gl.CreateShader(type);
    gl.ShaderSource(s, 1, &source, nullptr);
    gl.CompileShader(s);
    GLint ok = 0;
    gl.GetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        gl.GetShaderInfoLog(s, sizeof log, nullptr, log);
        gl.DeleteShader(s);
        throw std::runtime_error(std::string("geolab::render: shader does not compile: ") + log);
    }
    return s;
}

}  // namespace

GLuint link_program(const Gl& gl, const char* vs, const char* gs, const char* fs) {
    GLuint p = gl.CreateProgram();
    GLuint shaders[3] = {compile(gl, GL_VERTEX_SHADER, vs), gs ? compile(gl, GL_GEOMETRY_SHADER, gs) : 0,
                         compile(gl, GL_FRAGMENT_SHADER, fs)};
    for (GLuint s : shaders)
        if (s) gl.AttachShader(p, s);
    gl.LinkProgram(p);
    for (GLuint s : shaders)
        if (s) gl.DeleteShader(s);  // flagged; freed with the program
    GLint ok = 0;
    gl.GetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        gl.GetProgramInfoLog(p, sizeof log, nullptr, log);
        gl.DeleteProgram(p);
        throw std::runtime_error(std::string("geolab::render: shader program does not link: ") + log);
    }
    return p;
}

}  // namespace geolab::render::detail
