// Task 5: voxel CSG (handout §6).
#include <algorithm>
#include <stdexcept>
#include <string>

#include "geolab/voxels.hpp"

namespace geolab::voxels {

// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.
namespace {

void check_pair(const ValueGrid& f1, const ValueGrid& f2, const char* what) {
    if (!(f1.dims == f2.dims)) throw std::invalid_argument(std::string(what) + ": the grids' dims differ");
    for (const ValueGrid* f : {&f1, &f2})
        if (f->dims.nx < 0 || f->dims.ny < 0 || f->dims.nz < 0 || f->values.size() != std::uint64_t(f->dims.count()))
            throw std::invalid_argument(std::string(what) + ": values.size() " + std::to_string(f->values.size()) +
                                        " is not nx*ny*nz");
}

template <class Op>
ValueGrid combine(const ValueGrid& f1, const ValueGrid& f2, const char* what, Op op) {
    check_pair(f1, f2, what);
    ValueGrid out;
    out.dims = f1.dims;
    out.values.resize(f1.values.size());
    for (std::size_t n = 0; n < out.values.size(); ++n) out.values[n] = op(f1.values[n], f2.values[n]);
    return out;
}

void check_bits(const BitGrid& a, const char* what) {
    const BitGrid empty(a.dims);  // checks the dims
    if (a.words.size() != empty.words.size())
        throw std::invalid_argument(std::string(what) + ": " + std::to_string(a.words.size()) + " words for " +
                                    std::to_string(a.dims.count()) + " voxels");
}

template <class Op>
BitGrid combine_bits(const BitGrid& a, const BitGrid& b, const char* what, Op op) {
    if (!(a.dims == b.dims)) throw std::invalid_argument(std::string(what) + ": the grids' dims differ");
    check_bits(a, what);
    check_bits(b, what);
    BitGrid out = a;
    for (std::size_t w = 0; w < out.words.size(); ++w) out.words[w] = op(a.words[w], b.words[w]);
    return out;
}

}  // namespace
// END SOLUTION

ValueGrid csg_union(const ValueGrid& f1, const ValueGrid& f2) {
    // BEGIN SOLUTION
    return combine(f1, f2, "csg_union", [](double x, double y) { return std::max(x, y); });
    // END SOLUTION
}

ValueGrid csg_intersection(const ValueGrid& f1, const ValueGrid& f2) {
    // BEGIN SOLUTION
    return combine(f1, f2, "csg_intersection", [](double x, double y) { return std::min(x, y); });
    // END SOLUTION
}

ValueGrid csg_add(const ValueGrid& f1, const ValueGrid& f2, double c1, double c2) {
    // BEGIN SOLUTION
    return combine(f1, f2, "csg_add", [c1, c2](double x, double y) { return c1 * x + c2 * y; });
    // END SOLUTION
}

ValueGrid csg_subtract(const ValueGrid& f1, const ValueGrid& f2) {
    // BEGIN SOLUTION
    return combine(f1, f2, "csg_subtract", [](double x, double y) { return std::max(x - y, 0.0); });
    // END SOLUTION
}

BitGrid bits_union(const BitGrid& a, const BitGrid& b) {
    // BEGIN SOLUTION
    return combine_bits(a, b, "bits_union", [](std::uint64_t x, std::uint64_t y) { return x | y; });
    // END SOLUTION
}

BitGrid bits_intersection(const BitGrid& a, const BitGrid& b) {
    // BEGIN SOLUTION
    return combine_bits(a, b, "bits_intersection", [](std::uint64_t x, std::uint64_t y) { return x & y; });
    // END SOLUTION
}

BitGrid bits_difference(const BitGrid& a, const BitGrid& b) {
    // BEGIN SOLUTION
    return combine_bits(a, b, "bits_difference", [](std::uint64_t x, std::uint64_t y) { return x & ~y; });
    // END SOLUTION
}

BitGrid bits_complement(const BitGrid& a) {
    // BEGIN SOLUTION
    check_bits(a, "bits_complement");
    BitGrid out = a;
    for (std::uint64_t& w : out.words) w = ~w;
    const std::uint64_t tail = std::uint64_t(a.dims.count()) % 64;  // bits used in the last word (0: all 64)
    if (tail != 0) out.words.back() &= (std::uint64_t(1) << tail) - 1;
    return out;
    // END SOLUTION
}

}  // namespace geolab::voxels
