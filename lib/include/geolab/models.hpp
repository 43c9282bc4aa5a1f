#pragma once
//! \file models.hpp
//! The classic meshes from Debian's libcgal-demo (fetched by tools/fetch_models.sh into data/models).
#include <filesystem>
#include <optional>
#include <string>

namespace geolab {

//! The folder holding the fetched models: $GEOLAB_MODELS if set, else the one configured at build time.
std::filesystem::path models_dir();

//! The path of model `name` (e.g. "bunny00", "cow"; ".off" optional) if it has been fetched, else nullopt.
//! Tests that need a model skip with a message naming tools/fetch_models.sh when this is empty.
std::optional<std::filesystem::path> model_path(const std::string& name);

}  // namespace geolab
