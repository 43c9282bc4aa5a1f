#include "geolab/errors.hpp"

#include <atomic>

namespace geolab {
namespace {
std::atomic<std::uint64_t> g_not_implemented{0};
}

NotImplemented::NotImplemented(const std::string& function)
    : std::logic_error("not implemented: " + function + " (this is yours to write; see the handout)") {
    ++g_not_implemented;
}

std::uint64_t NotImplemented::count() { return g_not_implemented.load(); }

IoError::IoError(std::string file, std::size_t line, const std::string& reason)
    : std::runtime_error(file + ":" + std::to_string(line) + ": " + reason), file_(std::move(file)), line_(line) {}

}  // namespace geolab
