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

}  // namespace geolab::render::detail
