// ADVERSARIAL CASE hostile_soup: tessellate_patches answers a mesh whose triangle names position 7 of 3. Code in the
// judge that walks the answer
// (PolygonSoup::face() spans indices[offsets[f]..offsets[f+1]); render::Image::pixel() reads rgba at 4·(y·w + x))
// would read memory outside it: the judge refuses such an answer as malformed. Honest: 0.
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
    PatchMesh m;
    m.soup.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.soup.indices = {0, 1, 7};  // an index past the positions
    m.soup.offsets = {0, 3};
    m.normals.assign(3, glm::dvec3(0, 0, 1));
    return m;
}

}  // namespace geolab::bezier
