// The OSMesa context: software GL 3.3 core (llvmpipe) into a buffer in memory.
#include <GL/osmesa.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "context.hpp"

namespace geolab::render::detail {
namespace {

GlProc osmesa_get_proc(const char* name) { return reinterpret_cast<GlProc>(OSMesaGetProcAddress(name)); }

// An OSMesa context bound to its own RGBA buffer of width × height.
class OsMesaContext final : public Context {
public:
    OsMesaContext(int width, int height) : width_(width), height_(height), buffer_(4 * std::size_t(width) * height) {
        const int attribs[] = {OSMESA_FORMAT,
                               OSMESA_RGBA,
                               OSMESA_DEPTH_BITS,
                               24,
                               OSMESA_STENCIL_BITS,
                               0,
                               OSMESA_ACCUM_BITS,
                               0,
                               OSMESA_PROFILE,
                               OSMESA_CORE_PROFILE,
                               OSMESA_CONTEXT_MAJOR_VERSION,
                               3,
                               OSMESA_CONTEXT_MINOR_VERSION,
                               3,
                               0};
        ctx_ = OSMesaCreateContextAttribs(attribs, nullptr);
        if (!ctx_)
            throw std::runtime_error(
                "geolab::render: OSMesa could not create a GL 3.3 core context (is libOSMesa from Mesa >= 12 "
                "with llvmpipe installed?)");
    }
    ~OsMesaContext() override {
        OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
        OSMesaDestroyContext(ctx_);
    }
    void make_current() override {
        if (!OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_))
            throw std::runtime_error("geolab::render: OSMesaMakeCurrent failed for a " + std::to_string(width_) + "x" +
                                     std::to_string(height_) + " buffer");
    }
    GetProc get_proc() const override { return osmesa_get_proc; }

private:
    int width_, height_;
    std::vector<std::uint8_t> buffer_;
    OSMesaContext ctx_ = nullptr;
};

}  // namespace

std::unique_ptr<Context> make_osmesa_context(int width, int height) {
    return std::make_unique<OsMesaContext>(width, height);
}

}  // namespace geolab::render::detail
