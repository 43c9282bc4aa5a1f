// ADVERSARIAL CASE trivial_answers: every function of lab 08 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
// Task 5: voxel CSG (handout §6).
#include <algorithm>
#include <stdexcept>
#include <string>

#include "geolab/voxels.hpp"

namespace geolab::voxels {

// Helper functions of your own can go here.

ValueGrid csg_union(const ValueGrid& f1, const ValueGrid& f2) {
    return {};
}

ValueGrid csg_intersection(const ValueGrid& f1, const ValueGrid& f2) {
    return {};
}

ValueGrid csg_add(const ValueGrid& f1, const ValueGrid& f2, double c1, double c2) {
    return {};
}

ValueGrid csg_subtract(const ValueGrid& f1, const ValueGrid& f2) {
    return {};
}

BitGrid bits_union(const BitGrid& a, const BitGrid& b) {
    return {};
}

BitGrid bits_intersection(const BitGrid& a, const BitGrid& b) {
    return {};
}

BitGrid bits_difference(const BitGrid& a, const BitGrid& b) {
    return {};
}

BitGrid bits_complement(const BitGrid& a) {
    return {};
}

}  // namespace geolab::voxels
