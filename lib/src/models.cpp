#include "geolab/models.hpp"

#include <cstdlib>

#include "geolab/config.hpp"

namespace geolab {

std::filesystem::path models_dir() {
    if (const char* env = std::getenv("GEOLAB_MODELS"); env && *env) return env;
    return config::models_dir;
}

std::optional<std::filesystem::path> model_path(const std::string& name) {
    std::filesystem::path p = models_dir() / name;
    if (!p.has_extension()) p += ".off";
    std::error_code ec;
    if (std::filesystem::is_regular_file(p, ec)) return p;
    return std::nullopt;
}

}  // namespace geolab
