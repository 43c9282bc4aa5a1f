// Task 2: triangulation by ear clipping with hole bridging (handout §3).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/predicates.hpp"
#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

namespace {
// Helper functions of your own can go here.
}  // namespace

std::vector<std::array<std::uint32_t, 3>> triangulate(const Profile& p) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::sweeps
