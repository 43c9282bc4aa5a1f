// Task 5: voxel CSG (handout §6).
#include <algorithm>
#include <stdexcept>
#include <string>

#include "geolab/voxels.hpp"

namespace geolab::voxels {

// Helper functions of your own can go here.

ValueGrid csg_union(const ValueGrid& f1, const ValueGrid& f2) {
    throw geolab::NotImplemented(__func__);
}

ValueGrid csg_intersection(const ValueGrid& f1, const ValueGrid& f2) {
    throw geolab::NotImplemented(__func__);
}

ValueGrid csg_add(const ValueGrid& f1, const ValueGrid& f2, double c1, double c2) {
    throw geolab::NotImplemented(__func__);
}

ValueGrid csg_subtract(const ValueGrid& f1, const ValueGrid& f2) {
    throw geolab::NotImplemented(__func__);
}

BitGrid bits_union(const BitGrid& a, const BitGrid& b) {
    throw geolab::NotImplemented(__func__);
}

BitGrid bits_intersection(const BitGrid& a, const BitGrid& b) {
    throw geolab::NotImplemented(__func__);
}

BitGrid bits_difference(const BitGrid& a, const BitGrid& b) {
    throw geolab::NotImplemented(__func__);
}

BitGrid bits_complement(const BitGrid& a) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::voxels
