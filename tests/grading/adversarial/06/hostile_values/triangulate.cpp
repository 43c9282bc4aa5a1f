// ADVERSARIAL CASE hostile_values: triangles naming points 10^9 and 2^32 − 1 of a profile of a few points; frames
// (frames.cpp) all NaN, as many as the path has samples, and a NaN mismatch. Tests that index or compare them fail;
// nothing is read outside an answer. Honest: 0.
#include <array>
#include <cstdint>
#include <vector>

#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

std::vector<std::array<std::uint32_t, 3>> triangulate(const Profile& p) {
    return {{0u, 1000000000u, 0xffffffffu}, {0u, 1u, 2u}};
}

}  // namespace geolab::sweeps
