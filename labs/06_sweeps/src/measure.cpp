// Task 7: volume, area and Pappus's theorems (handout §8).
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

double mesh_volume(const PolygonSoup& mesh) {
    throw geolab::NotImplemented(__func__);
}

double mesh_area(const PolygonSoup& mesh) {
    throw geolab::NotImplemented(__func__);
}

Pappus pappus(const Profile& p, double angle) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::sweeps
