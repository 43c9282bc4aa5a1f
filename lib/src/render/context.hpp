#pragma once
// A GL 3.3 core context, whatever provides it (OSMesa, a GLFW window; later EGL surfaceless). The drawing code
// (Renderer) needs only this interface. No GL header here: osmesa.h pulls in <GL/gl.h>, which must not meet
// <GL/glcorearb.h> in one translation unit, so each back end's system header stays in its own .cpp.
#include <memory>

namespace geolab::render::detail {

// A GL entry point, untyped, and a callback that finds one by name (OSMesaGetProcAddress, glfwGetProcAddress).
using GlProc = void (*)();
using GetProc = GlProc (*)(const char* name);

class Context {
public:
    virtual ~Context() = default;
    // Makes the context current on the calling thread. Throws std::runtime_error if that fails.
    virtual void make_current() = 0;
    // The context's get-proc callback, to fill a Gl table (valid while the context is current).
    virtual GetProc get_proc() const = 0;
};

// An OSMesa GL 3.3 core context drawing into its own width × height RGBA buffer (osmesa_context.cpp).
// Throws std::runtime_error if OSMesa cannot create it.
std::unique_ptr<Context> make_osmesa_context(int width, int height);

}  // namespace geolab::render::detail
