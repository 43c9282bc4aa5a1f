// Task 6: .binvox (handout §7).
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "geolab/voxels.hpp"

namespace geolab::voxels {

// Helper functions of your own can go here.

std::string encode_binvox(const Binvox& file) {
    throw geolab::NotImplemented(__func__);
}

Binvox decode_binvox(const std::string& bytes, const std::string& name) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::voxels
