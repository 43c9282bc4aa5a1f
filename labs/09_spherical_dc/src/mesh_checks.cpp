// Lab 09 — mesh checks (given: used by the tests and the geolab program, not a task).
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "geolab/dual_contouring.hpp"

namespace geolab::dc {

MeshCheck check_mesh(const PolygonSoup& soup) {
    MeshCheck mc;
    // directed edges (lo, hi, forward?) sorted by undirected key
    struct Half {
        std::uint64_t key;
        bool forward;
    };
    std::vector<Half> edges;
    edges.reserve(soup.indices.size());
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        auto vs = soup.face(f);
        bool degenerate = false;
        for (std::size_t i = 0; i < vs.size(); ++i) {
            std::uint32_t a = vs[i], b = vs[(i + 1) % vs.size()];
            for (std::size_t j = 0; j < i; ++j) degenerate |= vs[j] == vs[i];
            if (a == b) continue;
            std::uint32_t lo = std::min(a, b), hi = std::max(a, b);
            edges.push_back({(std::uint64_t(lo) << 32) | hi, a < b});
        }
        mc.degenerate_faces += degenerate;
    }
    std::sort(edges.begin(), edges.end(), [](const Half& x, const Half& y) { return x.key < y.key; });
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        int fwd = 0;
        while (j < edges.size() && edges[j].key == edges[i].key) fwd += edges[j++].forward;
        std::size_t n = j - i;
        if (n == 1) ++mc.boundary_edges;
        else if (n > 2) ++mc.non_manifold_edges;
        else if (fwd != 1) ++mc.misoriented_edges;
        i = j;
    }
    return mc;
}

std::size_t boundary_edge_count(const PolygonSoup& soup) { return check_mesh(soup).boundary_edges; }
std::size_t non_manifold_edge_count(const PolygonSoup& soup) { return check_mesh(soup).non_manifold_edges; }
bool is_closed_manifold(const PolygonSoup& soup) { return check_mesh(soup).closed_manifold(); }

double signed_volume(const PolygonSoup& soup) {
    double v = 0.0;
    // about the first vertex: smaller terms, same result for closed meshes
    const glm::dvec3 o = soup.positions.empty() ? glm::dvec3(0.0) : soup.positions[0];
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        auto vs = soup.face(f);
        for (std::size_t i = 1; i + 1 < vs.size(); ++i)
            v += glm::dot(soup.positions[vs[0]] - o,
                          glm::cross(soup.positions[vs[i]] - o, soup.positions[vs[i + 1]] - o));
    }
    return v / 6.0;
}

double max_abs_value(const ScalarField& f, const PolygonSoup& soup) {
    double m = 0.0;
    for (const auto& p : soup.positions) m = std::max(m, std::abs(f.value(p)));
    return m;
}

}  // namespace geolab::dc
