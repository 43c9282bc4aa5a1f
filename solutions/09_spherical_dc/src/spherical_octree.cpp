// Lab 09 — task 6: the spherical-coordinate octree; the spherical one-shot function.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"

namespace geolab::dc {

Octree build_spherical_octree(const ScalarField& f, int max_level, const glm::dvec3& origin, double r_min,
                              double r_max) {
    // BEGIN SOLUTION
    Octree tree;
    tree.init_spherical(f, max_level, origin, r_min, r_max);
    // Lipschitz constant: the field's, or 2 × max |∇f| sampled on a 9³ lattice of the shell's bounding cube
    double lf = f.lipschitz();
    if (!(lf > 0.0)) {
        double g = 0.0;
        for (int i = 0; i <= 8; ++i)
            for (int j = 0; j <= 8; ++j)
                for (int k = 0; k <= 8; ++k)
                    g = std::max(g, glm::length(f.gradient(origin + r_max * (glm::dvec3(i, j, k) / 4.0 - 1.0))));
        lf = 2.0 * g;
    }
    // unit direction of a lattice point (θ index, φ index)
    auto dir = [&](std::int32_t t, std::int32_t p) {
        glm::ivec3 q(tree.resolution(), t, p);  // at r_max: direction = (point − origin) / r_max
        return (tree.lattice_point(q) - origin) / r_max;
    };
    for (std::uint32_t n = 0; n < tree.nodes.size(); ++n) {
        const OctreeNode nd = tree.nodes[n];
        if (nd.level >= tree.max_level) continue;
        if (nd.level == 0) {  // the root spans all of φ: always split
            tree.split(n);
            continue;
        }
        // Speed: at the first node of each level (its nodes are n..end), reserve room for all their children at once
        // rather than letting the array double (each doubling copies it into fresh memory)
        if (n > 0 && tree.nodes[n - 1].level != nd.level) {
            tree.nodes.reserve(tree.nodes.size() + 8 * (tree.nodes.size() - n));
            prefer_huge_pages(tree.nodes);  // and 2 MiB pages once the array is large (lib memory.hpp)
        }
        const std::int32_t s = tree.cell_span(nd.level);
        const glm::ivec3 lo(std::int32_t(nd.x) * s, std::int32_t(nd.y) * s, std::int32_t(nd.z) * s);
        const glm::ivec3 mid = lo + s / 2;
        // ball around c = the parameter midpoint containing the curved cell
        glm::dvec3 uc = dir(mid.y, mid.z);
        double cos_max = 1.0;
        for (int c = 0; c < 4; ++c)
            cos_max = std::min(cos_max, glm::dot(uc, dir(lo.y + (c & 1) * s, lo.z + (c >> 1) * s)));
        double r_lo = tree.lattice_spherical(lo).r, r_hi = tree.lattice_spherical(lo + s).r;
        double rc = 0.5 * (r_lo + r_hi), radius = 0.0;
        for (double r : {r_lo, r_hi}) radius = std::max(radius, std::sqrt(std::max(0.0, r * r + rc * rc - 2.0 * r * rc * cos_max)));
        const double v = tree.sample(mid);  // cached only when the cell splits (as in build_octree)
        if (std::abs(v) <= lf * radius * (1.0 + 1e-12)) {
            tree.store(mid, v);
            tree.split(n);
        }
    }
    tree.refine_around_sign_changes();  // a guarantee where the test alone is none (estimated Lf, sign jumps)
    return tree;
    // END SOLUTION
}

PolygonSoup dual_contour_spherical(const ScalarField& f, const SphericalParams& params, DcStats* stats) {
    // BEGIN SOLUTION
    auto t0 = std::chrono::steady_clock::now();
    if (params.max_level < 1 || params.max_level > 10)
        throw std::invalid_argument("dual_contour_spherical: max_level must be in [1, 10], got " +
                                    std::to_string(params.max_level));
    Box b = f.bounds();
    glm::dvec3 ext = b.hi - b.lo;
    double m = std::max({ext.x, ext.y, ext.z});
    if (!(ext.x >= 0.0 && ext.y >= 0.0 && ext.z >= 0.0) || !(m > 0.0) || !std::isfinite(m))
        throw std::invalid_argument("dual_contour_spherical: the field's bounds() are empty or not finite");
    // origin: given or the bounds' centre, then moved off the surface (eq. 6)
    glm::dvec3 x0 = params.origin.value_or(b.center());
    OriginParams op = params.origin_params;
    if (!(op.unit > 0.0)) op.unit = m / double(1 << params.max_level);
    std::vector<glm::dvec3> path =
        params.correct_origin ? correct_origin(f, x0, op) : std::vector<glm::dvec3>{x0};
    const glm::dvec3 origin = path.back();
    // shell: r_max encloses the bounds box
    double r_max = params.r_max;
    if (!(r_max > 0.0)) {
        for (int c = 0; c < 8; ++c) {
            glm::dvec3 q((c & 1) ? b.hi.x : b.lo.x, (c & 2) ? b.hi.y : b.lo.y, (c & 4) ? b.hi.z : b.lo.z);
            r_max = std::max(r_max, glm::length(q - origin));
        }
        r_max *= 1.05;
    }
    Octree tree = build_spherical_octree(f, params.max_level, origin, params.r_min, r_max);
    std::size_t crossings = place_vertices(tree, {params.tau, params.crossing_tolerance});
    // memory: spherical trees are not simplified, and the polygons read neither QEFs nor samples
    tree.qefs = {};
    tree.release_samples();
    std::vector<PoleRing> rings;
    PolygonSoup soup = contour(tree, &rings);
    PoleFillResult fill = fill_poles(soup, rings, f, origin, params.pole_fill);
    if (stats) {
        *stats = DcStats{};
        stats->cells = tree.reachable_nodes();
        stats->leaves = tree.leaves().size();
        stats->samples = tree.samples();
        stats->crossings = crossings;
        stats->vertices = soup.n_vertices();
        stats->faces = soup.n_faces();
        stats->pole_rings = rings.size();
        stats->ghost_vertices = fill.ghost_vertices.size();
        stats->origin = origin;
        stats->origin_path = std::move(path);
        stats->r_min = params.r_min;
        stats->r_max = r_max;
        stats->pole_fill = std::move(fill);
        stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    return soup;
    // END SOLUTION
}

}  // namespace geolab::dc
