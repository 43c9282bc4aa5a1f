// Lab 09 — Task 3: the Cartesian octree build (the octree structure itself is given, in octree_given.cpp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <string>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"

namespace geolab::dc {

// ---- Task 3: the Cartesian octree -----------------------------------------------------------------------------------

Octree build_octree(const ScalarField& f, const CartesianParams& params) {
    // BEGIN SOLUTION
    if (params.max_level < 1 || params.max_level > 10)
        throw std::invalid_argument("build_octree: max_level must be in [1, 10], got " +
                                    std::to_string(params.max_level));
    auto [lo, side] = cartesian_domain(f, params.padding);
    Octree tree;
    tree.init_cartesian(f, params.max_level, lo, side);
    // Lipschitz constant: the field's, or a sampled estimate (2 × max |∇f| on a 9³ lattice)
    double lf = f.lipschitz();
    if (!(lf > 0.0)) {
        double g = 0.0;
        for (int i = 0; i <= 8; ++i)
            for (int j = 0; j <= 8; ++j)
                for (int k = 0; k <= 8; ++k)
                    g = std::max(g, glm::length(f.gradient(lo + side / 8.0 * glm::dvec3(i, j, k))));
        lf = 2.0 * g;
    }
    const double half_diag0 = 0.5 * std::sqrt(3.0) * side;  // root cell
    // breadth-first: children are appended behind the nodes being processed
    for (std::uint32_t n = 0; n < tree.nodes.size(); ++n) {
        const OctreeNode nd = tree.nodes[n];
        if (nd.level >= tree.max_level) continue;
        // Speed: at the first node of each level (its nodes are n..end), reserve room for all their children at once
        // rather than letting the array double (each doubling copies it into fresh memory)
        if (n > 0 && tree.nodes[n - 1].level != nd.level) {
            tree.nodes.reserve(tree.nodes.size() + 8 * (tree.nodes.size() - n));
            prefer_huge_pages(tree.nodes);  // and 2 MiB pages once the array is large (lib memory.hpp)
        }
        const std::int32_t s = tree.cell_span(nd.level);
        glm::ivec3 center(std::int32_t(nd.x) * s + s / 2, std::int32_t(nd.y) * s + s / 2,
                          std::int32_t(nd.z) * s + s / 2);
        const double half_diag = half_diag0 / double(std::int32_t(1) << nd.level);  // exact: a power of 2
        // Speed: the centre of a cell that stays a leaf is never used again; cache only the centres of split cells
        // (they become corners of the children)
        const double v = tree.sample(center);
        if (std::abs(v) <= lf * half_diag) {
            tree.store(center, v);
            tree.split(n);
        }
    }
    tree.refine_around_sign_changes();  // a guarantee where the test alone is none (estimated Lf, sign jumps)
    return tree;
    // END SOLUTION
}

}  // namespace geolab::dc
