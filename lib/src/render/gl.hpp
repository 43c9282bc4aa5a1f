#pragma once
// The GL 3.3 core functions the drawing layer uses, as a table filled from a context's get-proc callback.
// The drawing code calls only this table, never gl* symbols: libOSMesa exports the whole GL API, and a
// window's GL (libGL via GLFW) must not be confused with it.
#include <GL/glcorearb.h>  // types and enums only (GL_GLEXT_PROTOTYPES is not defined)

#include "context.hpp"

namespace geolab::render::detail {

// X(type, name): every function the drawing layer calls, without its "gl" prefix.
#define GEOLAB_GL_FUNCTIONS(X)                                   \
    X(PFNGLGETSTRINGPROC, GetString)                             \
    X(PFNGLGETERRORPROC, GetError)                               \
    X(PFNGLVIEWPORTPROC, Viewport)                               \
    X(PFNGLCLEARCOLORPROC, ClearColor)                           \
    X(PFNGLCLEARPROC, Clear)                                     \
    X(PFNGLENABLEPROC, Enable)                                   \
    X(PFNGLDISABLEPROC, Disable)                                 \
    X(PFNGLDEPTHFUNCPROC, DepthFunc)                             \
    X(PFNGLDEPTHMASKPROC, DepthMask)                             \
    X(PFNGLBLENDFUNCPROC, BlendFunc)                             \
    X(PFNGLCULLFACEPROC, CullFace)                               \
    X(PFNGLPOLYGONOFFSETPROC, PolygonOffset)                     \
    X(PFNGLPIXELSTOREIPROC, PixelStorei)                         \
    X(PFNGLREADBUFFERPROC, ReadBuffer)                           \
    X(PFNGLREADPIXELSPROC, ReadPixels)                           \
    X(PFNGLFINISHPROC, Finish)                                   \
    X(PFNGLCREATESHADERPROC, CreateShader)                       \
    X(PFNGLSHADERSOURCEPROC, ShaderSource)                       \
    X(PFNGLCOMPILESHADERPROC, CompileShader)                     \
    X(PFNGLGETSHADERIVPROC, GetShaderiv)                         \
    X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)               \
    X(PFNGLDELETESHADERPROC, DeleteShader)                       \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram)                     \
    X(PFNGLATTACHSHADERPROC, AttachShader)                       \
    X(PFNGLLINKPROGRAMPROC, LinkProgram)                         \
    X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                       \
    X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)             \
    X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                     \
    X(PFNGLUSEPROGRAMPROC, UseProgram)                           \
    X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)           \
    X(PFNGLUNIFORM1FPROC, Uniform1f)                             \
    X(PFNGLUNIFORM2FPROC, Uniform2f)                             \
    X(PFNGLUNIFORM1IPROC, Uniform1i)                             \
    X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)               \
    X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                 \
    X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                 \
    X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)           \
    X(PFNGLGENBUFFERSPROC, GenBuffers)                           \
    X(PFNGLBINDBUFFERPROC, BindBuffer)                           \
    X(PFNGLBUFFERDATAPROC, BufferData)                           \
    X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                     \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray) \
    X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)         \
    X(PFNGLDRAWARRAYSPROC, DrawArrays)                           \
    X(PFNGLLOGICOPPROC, LogicOp)                                 \
    X(PFNGLGETINTEGERVPROC, GetIntegerv)

// The function table of one context. Valid only while that context is current.
struct Gl {
#define GEOLAB_GL_MEMBER(type, name) type name = nullptr;
    GEOLAB_GL_FUNCTIONS(GEOLAB_GL_MEMBER)
#undef GEOLAB_GL_MEMBER

    // Fills every entry through get_proc; throws std::runtime_error naming the first function not found.
    void load(GetProc get_proc);
};

// A program of a vertex, an optional geometry (gs may be null) and a fragment shader, in the current context.
// Throws std::runtime_error with the GLSL log when one does not compile or the program does not link.
GLuint link_program(const Gl& gl, const char* vs, const char* gs, const char* fs);

}  // namespace geolab::render::detail
