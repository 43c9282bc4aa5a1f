// ADVERSARIAL CASE always_throws: every function of lab 08 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
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
    throw std::invalid_argument(__func__);
}

Binvox decode_binvox(const std::string& bytes, const std::string& name) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::voxels
