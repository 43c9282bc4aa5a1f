// ADVERSARIAL CASE forbidden_wrapper: lab 04 forbids lib's polygonizer in Task 4. This file (Task 2's, left a stub)
// hides a call of geolab::polygonize behind a table of function pointers; marching_cubes.cpp calls the helper.
// Honest: what the code earns with no list, less its Task 4 points (the check zeroes Task 4).
#include <algorithm>
// Task 2: the field (handout §3).
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/blobby.hpp"
#include "geolab/polygonize.hpp"

namespace geolab::blobby {

namespace helpers {
// The lattice's values as a field (nearest lattice point), polygonized by lib through a table of pointers.
struct LatticeField : geolab::ScalarField {
    const Lattice& l;
    explicit LatticeField(const Lattice& lattice) : l(lattice) {}
    double value(const glm::dvec3& p) const override {
        const glm::ivec3 i = glm::clamp(glm::ivec3(glm::round((p - l.origin) / l.h)), glm::ivec3(0), l.n - 1);
        return l.values[std::size_t(i.x) + std::size_t(l.n.x) * (std::size_t(i.y) + std::size_t(l.n.y) * std::size_t(i.z))];
    }
    geolab::Box bounds() const override { return {l.origin, l.origin + l.h * glm::dvec3(l.n - 1)}; }
};
using Polygonizer = geolab::PolygonSoup (*)(const geolab::ScalarField&, const geolab::Box&, int, double);
Polygonizer const table[] = {&geolab::polygonize};
McMesh via_lib(const Lattice& L, double iso) {
    McMesh m;
    const LatticeField f(L);
    volatile int k = 0;
    m.soup = table[k](f, f.bounds(), std::max({L.n.x, L.n.y, L.n.z}) - 1, iso);
    m.normals.assign(m.soup.positions.size(), glm::dvec3(0, 0, 1));
    return m;
}
}  // namespace helpers

FieldValue field(const BlobScene& scene, const glm::dvec3& p) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::blobby
