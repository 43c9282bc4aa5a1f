// Task 7: meshes of CSG trees and their volumes (handout §8).
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/csg.hpp"
#include "geolab/polygonize.hpp"

namespace geolab::csg {

// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.
namespace {
// The tree's signed distance as a field, on the tree prepared once (not once per sample).
class TreeField final : public ScalarField {
public:
    TreeField(const Tree& t, Box b) : t_(prepare(t)), b_(b) {}
    double value(const glm::dvec3& p) const override { return sdf(t_, p); }
    Box bounds() const override { return b_; }
    double lipschitz() const override { return 1.0; }

private:
    PreparedTree t_;
    Box b_;
};
}  // namespace
// END SOLUTION

PolygonSoup mesh_tree(const Tree& t, int resolution) {
    // BEGIN SOLUTION
    if (resolution < 2) throw std::invalid_argument("mesh_tree: resolution must be >= 2");
    Box b = bounds(t);
    const double diagonal = glm::length(b.hi - b.lo);  // not finite when a side is infinite
    if (!std::isfinite(diagonal))
        throw std::invalid_argument("mesh_tree: the tree is unbounded (intersect half-spaces and quadrics with a "
                                    "bounded solid)");
    const double pad = 0.05 * diagonal;
    b.lo -= glm::dvec3(pad);
    b.hi += glm::dvec3(pad);
    return polygonize(TreeField(t, b), b, resolution);
    // END SOLUTION
}

double volume(const PolygonSoup& mesh) {
    // BEGIN SOLUTION
    check_soup(mesh);
    double v = 0;
    for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
        const auto ids = mesh.face(f);
        const glm::dvec3 p0 = mesh.positions[ids[0]];
        for (std::size_t i = 1; i + 1 < ids.size(); ++i)
            v += glm::dot(p0, glm::cross(mesh.positions[ids[i]], mesh.positions[ids[i + 1]]));
    }
    return v / 6;
    // END SOLUTION
}

}  // namespace geolab::csg
