// Task 5: tensor-product patches — points, partial derivatives, normals, tessellation (handout §6).
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <stdexcept>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "geolab/bezier.hpp"

namespace geolab::bezier {

namespace {
// Helper functions of your own can go here.
}  // namespace

glm::dvec3 patch_point(const BezierPatch& S, double u, double v) {
    throw geolab::NotImplemented(__func__);
}

glm::dvec3 patch_du(const BezierPatch& S, double u, double v) {
    throw geolab::NotImplemented(__func__);
}

glm::dvec3 patch_dv(const BezierPatch& S, double u, double v) {
    throw geolab::NotImplemented(__func__);
}

glm::dvec3 patch_normal(const BezierPatch& S, double u, double v) {
    throw geolab::NotImplemented(__func__);
}

PatchMesh tessellate_patches(const std::vector<BezierPatch>& patches, int n, double weld_tol, bool flip) {
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::bezier
