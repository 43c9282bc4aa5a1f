// ADVERSARIAL CASE forbidden_wrapper: lab 08 forbids lib's check_surface in Task 4 (it counts boundary edges). This
// file (Task 1's, left a stub) hides the call in a helper of its own; solid.cpp reaches it only through a table of
// function pointers. Honest: what the code earns with no list, less its Task 4 points (the check zeroes Task 4).
#include <map>
#include <stdexcept>
#include <tuple>

#include "geolab/surface_checks.hpp"
#include "geolab/voxels.hpp"

namespace geolab::voxels {

namespace helpers {
std::uint64_t edges_of(const PolygonSoup& mesh) {  // an external helper: another file may call it
    // weld equal positions first (check_surface keeps them apart), then let lib count the edges of one face
    std::map<std::tuple<double, double, double>, std::uint32_t> id;
    PolygonSoup welded;
    welded.offsets = mesh.offsets;
    for (const auto& p : mesh.positions) {
        const auto [it, fresh] = id.emplace(std::tuple{p.x, p.y, p.z}, std::uint32_t(welded.positions.size()));
        if (fresh) welded.positions.push_back(p);
    }
    for (const auto v : mesh.indices) {
        const auto& p = mesh.positions[v];
        welded.indices.push_back(id.at(std::tuple{p.x, p.y, p.z}));
    }
    CheckOptions o;
    o.self_intersections = false;
    return geolab::check_surface(welded, o).boundary_edges;
}
}  // namespace helpers

std::uint64_t voxel_index(const Dims& dims, std::int64_t i, std::int64_t j, std::int64_t k) {
    throw geolab::NotImplemented(__func__);
}

std::uint64_t count_set(const BitGrid& grid) { throw geolab::NotImplemented(__func__); }

}  // namespace geolab::voxels
