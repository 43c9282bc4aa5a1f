// ADVERSARIAL CASE always_throws: every function of lab 05 rejects every input (std::invalid_argument, the error
// most contracts name). Honest: 0 (no task is done); a test that passes here checks only that bad input is
// rejected, never that good input is accepted. Generated from the stub by replacing its throw.
// Task 5: tensor-product patches — points, partial derivatives, normals, tessellation (handout §6).
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "geolab/bezier.hpp"

namespace geolab::bezier {

namespace {
// Helper functions of your own can go here.
}  // namespace

glm::dvec3 patch_point(const BezierPatch& S, double u, double v) {
    throw std::invalid_argument(__func__);
}

glm::dvec3 patch_du(const BezierPatch& S, double u, double v) {
    throw std::invalid_argument(__func__);
}

glm::dvec3 patch_dv(const BezierPatch& S, double u, double v) {
    throw std::invalid_argument(__func__);
}

glm::dvec3 patch_normal(const BezierPatch& S, double u, double v) {
    throw std::invalid_argument(__func__);
}

PatchMesh tessellate_patches(const std::vector<BezierPatch>& patches, int n, double weld_tol, bool flip) {
    throw std::invalid_argument(__func__);
}

}  // namespace geolab::bezier
