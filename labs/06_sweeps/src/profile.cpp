// Task 1: profiles (handout §2).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/predicates.hpp"
#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

double signed_area(const Loop& loop) {
    throw geolab::NotImplemented(__func__);
}

namespace {
// Helper functions of your own can go here.
}  // namespace

void validate_profile(const Profile& p) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::sweeps
