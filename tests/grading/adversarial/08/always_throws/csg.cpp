// ADVERSARIAL CASE always_throws: every function of lab 08 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 5: voxel CSG (handout §6).
#include <algorithm>
#include <stdexcept>
#include <string>

#include "geolab/voxels.hpp"

namespace geolab::voxels {

// Helper functions of your own can go here.

ValueGrid csg_union(const ValueGrid& f1, const ValueGrid& f2) {
    throw std::invalid_argument(__func__);
}

ValueGrid csg_intersection(const ValueGrid& f1, const ValueGrid& f2) {
    throw std::invalid_argument(__func__);
}

ValueGrid csg_add(const ValueGrid& f1, const ValueGrid& f2, double c1, double c2) {
    throw std::invalid_argument(__func__);
}

ValueGrid csg_subtract(const ValueGrid& f1, const ValueGrid& f2) {
    throw std::invalid_argument(__func__);
}

BitGrid bits_union(const BitGrid& a, const BitGrid& b) {
    throw std::invalid_argument(__func__);
}

BitGrid bits_intersection(const BitGrid& a, const BitGrid& b) {
    throw std::invalid_argument(__func__);
}

BitGrid bits_difference(const BitGrid& a, const BitGrid& b) {
    throw std::invalid_argument(__func__);
}

BitGrid bits_complement(const BitGrid& a) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::voxels
