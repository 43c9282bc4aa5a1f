// ADVERSARIAL CASE trivial_answers: every function of lab 05 returns a default value of its type (an empty grid, a
// zero, an empty list) or does nothing, and never throws. Honest: 0 (no task is done); a test that passes here
// asserts nothing a non-answer cannot satisfy. Generated from the stub by replacing its throw with `return {};`.
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
    return {};
}

glm::dvec3 patch_du(const BezierPatch& S, double u, double v) {
    return {};
}

glm::dvec3 patch_dv(const BezierPatch& S, double u, double v) {
    return {};
}

glm::dvec3 patch_normal(const BezierPatch& S, double u, double v) {
    return {};
}

PatchMesh tessellate_patches(const std::vector<BezierPatch>& patches, int n, double weld_tol, bool flip) {
    return {};
}

}  // namespace geolab::bezier
