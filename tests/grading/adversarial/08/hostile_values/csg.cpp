// ADVERSARIAL CASE hostile_values (see surface.cpp): NaN densities of the right size, grids with no words.
#include <limits>

#include "geolab/voxels.hpp"

namespace geolab::voxels {
namespace {
ValueGrid nan_like(const ValueGrid& f) {
    ValueGrid g = f;
    for (double& v : g.values) v = std::numeric_limits<double>::quiet_NaN();
    return g;
}
BitGrid wordless(const BitGrid& a) {
    BitGrid g;
    g.dims = a.dims;
    return g;
}
}  // namespace

ValueGrid csg_union(const ValueGrid& f1, const ValueGrid&) { return nan_like(f1); }
ValueGrid csg_intersection(const ValueGrid& f1, const ValueGrid&) { return nan_like(f1); }
ValueGrid csg_add(const ValueGrid& f1, const ValueGrid&, double, double) { return nan_like(f1); }
ValueGrid csg_subtract(const ValueGrid& f1, const ValueGrid&) { return nan_like(f1); }
BitGrid bits_union(const BitGrid& a, const BitGrid&) { return wordless(a); }
BitGrid bits_intersection(const BitGrid& a, const BitGrid&) { return wordless(a); }
BitGrid bits_difference(const BitGrid& a, const BitGrid&) { return wordless(a); }
BitGrid bits_complement(const BitGrid& a) { return wordless(a); }

}  // namespace geolab::voxels
