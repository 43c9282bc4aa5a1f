// Task 6: region decomposition into the paper's cell complex (handout §8).
#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

#include "geolab/halfface.hpp"

namespace geolab::halfface {

namespace {
// Helper functions of your own can go here.
}  // namespace

RegionComplex region_complex(const Mesh& mesh, const std::vector<std::int32_t>& labels) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::halfface
