// ADVERSARIAL CASE hostile_values (see surface.cpp): a 16 MB "file", and an IoError with a line past any file.
#include <string>

#include "geolab/voxels.hpp"

namespace geolab::voxels {

std::string encode_binvox(const Binvox&) { return std::string(16u << 20, '\x01'); }

Binvox decode_binvox(const std::string& bytes, const std::string& name) {
    throw geolab::IoError(name, ~std::size_t(0), std::string(1u << 20, 'x'));
}

}  // namespace geolab::voxels
