// ADVERSARIAL CASE trivial_answers: every function of lab 08 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
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
    return {};
}

Binvox decode_binvox(const std::string& bytes, const std::string& name) {
    return {};
}

}  // namespace geolab::voxels
