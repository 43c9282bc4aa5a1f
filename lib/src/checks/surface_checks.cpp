// check_surface(): the defect counts of a polygon mesh, with exact predicates for the geometric ones.
#include "geolab/surface_checks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "geolab/predicates.hpp"

namespace geolab {

namespace {

using glm::dvec2;
using glm::dvec3;

//! Union–find over 0..n−1 with path halving.
struct DisjointSets {
    std::vector<std::uint32_t> parent;
    explicit DisjointSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
    std::uint32_t find(std::uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
    void unite(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

//! The coordinate plane (0: drop x, 1: drop y, 2: drop z) on which triangle abc projects to a proper triangle;
//! −1 when abc is degenerate (collinear). Projecting points of abc's plane onto it is an affine bijection, so
//! every incidence question about coplanar points is answered the same in 2D.
int projection_axis(const dvec3& a, const dvec3& b, const dvec3& c) {
    if (orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y}) != 0) return 2;
    if (orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z}) != 0) return 0;
    if (orient2d({a.z, a.x}, {b.z, b.x}, {c.z, c.x}) != 0) return 1;
    return -1;
}

dvec2 project(const dvec3& p, int axis) {
    switch (axis) {
        case 0: return {p.y, p.z};
        case 1: return {p.z, p.x};
        default: return {p.x, p.y};
    }
}

//! Closed segments pq and rs (2D) have a point in common.
bool segments_meet_2d(const dvec2& p, const dvec2& q, const dvec2& r, const dvec2& s) {
    const int o1 = orient2d(p, q, r), o2 = orient2d(p, q, s), o3 = orient2d(r, s, p), o4 = orient2d(r, s, q);
    if (o1 * o2 < 0 && o3 * o4 < 0) return true;
    // touching or collinear: an endpoint on the other segment (coordinate-wise between, exact comparisons)
    auto on = [](const dvec2& a, const dvec2& b, const dvec2& x) {
        return std::min(a.x, b.x) <= x.x && x.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= x.y &&
               x.y <= std::max(a.y, b.y);
    };
    return (o1 == 0 && on(p, q, r)) || (o2 == 0 && on(p, q, s)) || (o3 == 0 && on(r, s, p)) ||
           (o4 == 0 && on(r, s, q));
}

//! Point x lies in the closed proper triangle abc (2D).
bool point_in_triangle_2d(const dvec2& x, const dvec2& a, const dvec2& b, const dvec2& c) {
    const int s1 = orient2d(a, b, x), s2 = orient2d(b, c, x), s3 = orient2d(c, a, x);
    return !((s1 > 0 || s2 > 0 || s3 > 0) && (s1 < 0 || s2 < 0 || s3 < 0));
}

//! The closed segment pq meets the closed proper triangle abc (3D).
bool segment_meets_triangle(const dvec3& p, const dvec3& q, const dvec3& a, const dvec3& b, const dvec3& c) {
    const int op = orient3d(a, b, c, p), oq = orient3d(a, b, c, q);
    if (op * oq > 0) return false;
    if (op == 0 && oq == 0) {  // coplanar: decide in the plane
        const int k = projection_axis(a, b, c);
        const dvec2 P = project(p, k), Q = project(q, k), A = project(a, k), B = project(b, k), C = project(c, k);
        return point_in_triangle_2d(P, A, B, C) || point_in_triangle_2d(Q, A, B, C) || segments_meet_2d(P, Q, A, B) ||
               segments_meet_2d(P, Q, B, C) || segments_meet_2d(P, Q, C, A);
    }
    // pq crosses or touches the plane; the line through it passes through the triangle iff the three
    // tetrahedra (p, q, edge) do not have strictly opposite orientations
    const int s1 = orient3d(p, q, a, b), s2 = orient3d(p, q, b, c), s3 = orient3d(p, q, c, a);
    return !((s1 > 0 || s2 > 0 || s3 > 0) && (s1 < 0 || s2 < 0 || s3 < 0));
}

//! A quick proof that triangles t and u do not meet: the plane of one has the other strictly on one side with a
//! margin larger than the rounding of the dot products (the normal is computed in doubles, but any direction
//! that separates the projections proves disjointness, so only the projections' rounding matters). False means
//! "not proven", never "they meet". Spares the exact tests most pairs whose boxes overlap, such as a cap's long
//! slivers against the thin wall triangles along its rim.
bool separated_by_a_plane(const std::array<dvec3, 3>& t, const std::array<dvec3, 3>& u) {
    double scale = 0.0;
    for (const auto& p : t) scale = std::max({scale, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    for (const auto& p : u) scale = std::max({scale, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    auto apart = [&](const std::array<dvec3, 3>& a, const std::array<dvec3, 3>& b) {
        const dvec3 n = glm::cross(a[1] - a[0], a[2] - a[0]);
        const double n1 = std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
        if (!(n1 > 0.0) || !std::isfinite(n1 * scale)) return false;
        // |computed n·p − n·p| ≤ 3ε·Σ|n_i||p_i| ≤ 3ε·n1·scale; 1e-13 is a wide margin over 3ε ≈ 6.7e-16
        const double margin = 1e-13 * n1 * scale;
        const double a0 = glm::dot(n, a[0]), a1 = glm::dot(n, a[1]), a2 = glm::dot(n, a[2]);
        const double lo = std::min({a0, a1, a2}), hi = std::max({a0, a1, a2});
        const double b0 = glm::dot(n, b[0]), b1 = glm::dot(n, b[1]), b2 = glm::dot(n, b[2]);
        return std::min({b0, b1, b2}) > hi + margin || std::max({b0, b1, b2}) < lo - margin;
    };
    return apart(t, u) || apart(u, t);
}

//! Closed proper triangles meet.
bool triangles_meet(const std::array<dvec3, 3>& t, const std::array<dvec3, 3>& u) {
    for (int i = 0; i < 3; ++i)
        if (segment_meets_triangle(t[i], t[(i + 1) % 3], u[0], u[1], u[2])) return true;
    for (int i = 0; i < 3; ++i)
        if (segment_meets_triangle(u[i], u[(i + 1) % 3], t[0], t[1], t[2])) return true;
    return false;
}

//! x lies in the closed cone at apex v spanned by the directions p − v and q − v (2D, angle below π).
bool in_cone_2d(const dvec2& v, const dvec2& p, const dvec2& q, const dvec2& x) {
    const int s = orient2d(v, p, q);
    return orient2d(v, p, x) * s >= 0 && orient2d(v, x, q) * s >= 0;
}

struct Triangle {
    std::uint32_t face;
    std::array<std::uint32_t, 3> v;
};

enum class Meet { none, disjoint, vertex, edge };

//! How triangles t and u (both proper) meet beyond what their shared vertex indices allow.
Meet improper_meeting(const Triangle& t, const Triangle& u, const std::vector<dvec3>& pos) {
    std::array<int, 3> in_u{-1, -1, -1};  // in_u[i]: position in u of t's i-th vertex, −1 if none
    int shared = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (t.v[i] == u.v[j]) in_u[i] = j, ++shared;
    const std::array<dvec3, 3> T{pos[t.v[0]], pos[t.v[1]], pos[t.v[2]]};
    const std::array<dvec3, 3> U{pos[u.v[0]], pos[u.v[1]], pos[u.v[2]]};
    if (shared == 0) return !separated_by_a_plane(T, U) && triangles_meet(T, U) ? Meet::disjoint : Meet::none;
    if (shared == 3) return Meet::edge;  // the same triangle twice
    if (shared == 1) {
        int i = 0;
        while (in_u[i] < 0) ++i;
        const int j = in_u[i];
        const dvec3 &v = T[i], &p = T[(i + 1) % 3], &q = T[(i + 2) % 3];
        const dvec3 &r = U[(j + 1) % 3], &s = U[(j + 2) % 3];
        {
            // The projections onto a plane where t is proper: if the two corners at v do not overlap there, the
            // triangles cannot meet beyond v in space either (the projection of their intersection lies in the
            // intersection of their projections). Decides flat neighbourhoods without exact 3D arithmetic.
            const int k = projection_axis(v, p, q);
            const dvec2 V = project(v, k), P = project(p, k), Q = project(q, k), R = project(r, k), S = project(s, k);
            if (orient2d(V, R, S) != 0 && !(in_cone_2d(V, P, Q, R) || in_cone_2d(V, P, Q, S) ||
                                            in_cone_2d(V, R, S, P) || in_cone_2d(V, R, S, Q)))
                return Meet::none;
        }
        const int orient_r = orient3d(v, p, q, r), orient_s = orient3d(v, p, q, s);
        // u touches t's plane only at v: the triangles meet nowhere else (the common case, decided quickly)
        if (orient_r * orient_s > 0) return Meet::none;
        // coplanar: u is then proper in t's projection too, so the corner test above ran and found an overlap
        if (orient_r == 0 && orient_s == 0) return Meet::vertex;
        // not coplanar: the two triangles meet in a segment from v; it leaves v only if it reaches an edge
        // opposite v in one of them
        const dvec3& w = U[j];
        if (orient3d(w, r, s, p) * orient3d(w, r, s, q) > 0) return Meet::none;  // the same, the other way round
        const bool meet = segment_meets_triangle(p, q, U[0], U[1], U[2]) || segment_meets_triangle(r, s, T[0], T[1], T[2]);
        return meet ? Meet::vertex : Meet::none;
    }
    // an edge in common: they overlap only when coplanar with the third vertices on the same side
    int i = 0;
    while (in_u[i] >= 0) ++i;  // t's vertex not in u
    int j = 0;
    while (j < 3 && (u.v[j] == t.v[0] || u.v[j] == t.v[1] || u.v[j] == t.v[2])) ++j;
    const dvec3 &a = T[i], &e0 = T[(i + 1) % 3], &e1 = T[(i + 2) % 3], &b = U[j];
    // Projected onto a plane where t is proper: a and b on opposite sides of the edge (or b on its line) means no
    // overlap, whether or not the two are coplanar; only same-side pairs need the exact coplanarity test.
    const int k = projection_axis(e0, e1, a);
    const dvec2 E0 = project(e0, k), E1 = project(e1, k);
    if (orient2d(E0, E1, project(a, k)) * orient2d(E0, E1, project(b, k)) <= 0) return Meet::none;
    return orient3d(e0, e1, a, b) == 0 ? Meet::edge : Meet::none;
}

//! Candidate pairs by a uniform grid over the triangles' bounding boxes; each overlapping pair is tested once
//! (in the first grid cell the two boxes share).
void count_intersections(const PolygonSoup& soup, const std::vector<Triangle>& tris, SurfaceCheck& out) {
    const std::size_t n = tris.size();
    if (n < 2) return;
    std::vector<dvec3> lo(n), hi(n);
    dvec3 glo(INFINITY), ghi(-INFINITY);
    double mean_extent = 0.0;
    for (std::size_t t = 0; t < n; ++t) {
        lo[t] = hi[t] = soup.positions[tris[t].v[0]];
        for (int k = 1; k < 3; ++k) {
            lo[t] = glm::min(lo[t], soup.positions[tris[t].v[k]]);
            hi[t] = glm::max(hi[t], soup.positions[tris[t].v[k]]);
        }
        glo = glm::min(glo, lo[t]);
        ghi = glm::max(ghi, hi[t]);
        const dvec3 e = hi[t] - lo[t];
        mean_extent += std::max({e.x, e.y, e.z});
    }
    mean_extent /= double(n);
    const dvec3 span = ghi - glo;
    // cells about the size of a triangle, at most ~2 per triangle in total
    double h = std::max(mean_extent, 1e-300);
    auto cells_along = [&](double len, double step) { return std::max<std::size_t>(1, std::size_t(std::ceil(len / step))); };
    while (double(cells_along(span.x, h)) * double(cells_along(span.y, h)) * double(cells_along(span.z, h)) >
           2.0 * double(n) + 8.0)
        h *= 1.26;
    const std::size_t nx = cells_along(span.x, h), ny = cells_along(span.y, h), nz = cells_along(span.z, h);
    auto cell_of = [&](const dvec3& p, std::array<std::size_t, 3>& c) {
        const dvec3 r = (p - glo) / h;
        c = {std::min(nx - 1, std::size_t(std::max(0.0, r.x))), std::min(ny - 1, std::size_t(std::max(0.0, r.y))),
             std::min(nz - 1, std::size_t(std::max(0.0, r.z)))};
    };
    std::vector<std::array<std::size_t, 3>> c0(n), c1(n);
    std::vector<std::size_t> start(nx * ny * nz + 1, 0);
    for (std::size_t t = 0; t < n; ++t) {
        cell_of(lo[t], c0[t]);
        cell_of(hi[t], c1[t]);
        for (std::size_t z = c0[t][2]; z <= c1[t][2]; ++z)
            for (std::size_t y = c0[t][1]; y <= c1[t][1]; ++y)
                for (std::size_t x = c0[t][0]; x <= c1[t][0]; ++x) ++start[(z * ny + y) * nx + x + 1];
    }
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<std::uint32_t> items(start.back());
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t t = 0; t < n; ++t)
        for (std::size_t z = c0[t][2]; z <= c1[t][2]; ++z)
            for (std::size_t y = c0[t][1]; y <= c1[t][1]; ++y)
                for (std::size_t x = c0[t][0]; x <= c1[t][0]; ++x) items[fill[(z * ny + y) * nx + x]++] = std::uint32_t(t);

    std::vector<std::tuple<std::uint32_t, std::uint32_t, Meet>> pairs;  // (face, face, how), faces ordered
    for (std::size_t cell = 0; cell + 1 < start.size(); ++cell) {
        const std::size_t x = cell % nx, y = (cell / nx) % ny, z = cell / (nx * ny);
        for (std::size_t i = start[cell]; i < start[cell + 1]; ++i)
            for (std::size_t j = i + 1; j < start[cell + 1]; ++j) {
                const std::uint32_t a = items[i], b = items[j];
                if (tris[a].face == tris[b].face) continue;
                if (lo[a].x > hi[b].x || lo[b].x > hi[a].x || lo[a].y > hi[b].y || lo[b].y > hi[a].y ||
                    lo[a].z > hi[b].z || lo[b].z > hi[a].z)
                    continue;
                // test the pair only in the first cell both boxes cover
                if (x != std::max(c0[a][0], c0[b][0]) || y != std::max(c0[a][1], c0[b][1]) ||
                    z != std::max(c0[a][2], c0[b][2]))
                    continue;
                const Meet m = improper_meeting(tris[a], tris[b], soup.positions);
                if (m != Meet::none)
                    pairs.emplace_back(std::min(tris[a].face, tris[b].face), std::max(tris[a].face, tris[b].face), m);
            }
    }
    // a pair of polygons counts once, by the first way (in the enum's order) two of their triangles meet
    std::sort(pairs.begin(), pairs.end());
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        if (i > 0 && std::get<0>(pairs[i]) == std::get<0>(pairs[i - 1]) && std::get<1>(pairs[i]) == std::get<1>(pairs[i - 1]))
            continue;
        switch (std::get<2>(pairs[i])) {
            case Meet::disjoint: ++out.intersecting_disjoint; break;
            case Meet::vertex: ++out.intersecting_vertex_sharing; break;
            case Meet::edge: ++out.intersecting_edge_sharing; break;
            case Meet::none: break;
        }
    }
}

}  // namespace

bool SurfaceCheck::closed_manifold() const {
    return faces > 0 && self_intersection_checked && boundary_edges == 0 && non_manifold_edges == 0 &&
           misoriented_edges == 0 && non_manifold_vertices == 0 && repeated_index_faces == 0 && zero_area_faces == 0 &&
           coincident_vertices == 0 && self_intersecting_pairs() == 0;
}

std::string SurfaceCheck::summary() const {
    std::ostringstream s;
    s << "V " << vertices << " E " << edges << " F " << faces << " χ " << euler_characteristic << ", " << components
      << (components == 1 ? " component" : " components") << "; boundary edges " << boundary_edges
      << ", non-manifold edges " << non_manifold_edges << " / vertices " << non_manifold_vertices
      << ", misoriented edges " << misoriented_edges << ", repeated-index faces " << repeated_index_faces
      << ", zero-area faces " << zero_area_faces << ", coincident vertices " << coincident_vertices;
    if (self_intersection_checked)
        s << ", self-intersecting pairs " << self_intersecting_pairs() << " (" << intersecting_disjoint << " disjoint, "
          << intersecting_vertex_sharing << " vertex-sharing, " << intersecting_edge_sharing << " edge-sharing)";
    else
        s << ", self-intersections not checked";
    return s.str();
}

SurfaceCheck check_surface(const PolygonSoup& soup, const CheckOptions& options) {
    SurfaceCheck out;
    const std::size_t nv = soup.positions.size(), nf = soup.n_faces();
    out.faces = nf;
    for (std::size_t f = 0; f < nf; ++f) {
        const auto vs = soup.face(f);
        if (vs.size() < 3) throw std::invalid_argument("check_surface: face " + std::to_string(f) + " has " +
                                                       std::to_string(vs.size()) + " vertices (at least 3 needed)");
        for (std::uint32_t v : vs)
            if (v >= nv)
                throw std::invalid_argument("check_surface: face " + std::to_string(f) + " uses vertex " +
                                            std::to_string(v) + " of " + std::to_string(nv));
    }

    // used and coincident vertices
    std::vector<char> used(nv, 0);
    for (std::uint32_t v : soup.indices) used[v] = 1;
    std::vector<std::uint32_t> order;
    for (std::uint32_t v = 0; v < nv; ++v)
        if (used[v]) order.push_back(v);
    out.vertices = order.size();
    auto key = [&](std::uint32_t v) { return std::tie(soup.positions[v].x, soup.positions[v].y, soup.positions[v].z); };
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
    for (std::size_t i = 1; i < order.size(); ++i) out.coincident_vertices += key(order[i]) == key(order[i - 1]);

    // edges: sorted directed half-edges by undirected key
    struct Half {
        std::uint64_t key;
        bool forward;
    };
    std::vector<Half> halves;
    halves.reserve(soup.indices.size());
    // corner fans: (vertex, neighbour, corner) — corners around a vertex sharing an edge are in one fan
    struct Spoke {
        std::uint64_t key;
        std::uint32_t corner;
    };
    std::vector<Spoke> spokes;
    spokes.reserve(2 * soup.indices.size());
    DisjointSets components(nv);
    for (std::size_t f = 0; f < nf; ++f) {
        const auto vs = soup.face(f);
        const std::size_t k = vs.size(), c0 = soup.offsets[f];
        bool repeated = false;
        for (std::size_t i = 0; i < k; ++i) {
            const std::uint32_t a = vs[i], b = vs[(i + 1) % k], prev = vs[(i + k - 1) % k];
            for (std::size_t j = 0; j < i; ++j) repeated |= vs[j] == a;
            components.unite(a, vs[0]);
            if (a != b) halves.push_back({(std::uint64_t(std::min(a, b)) << 32) | std::max(a, b), a < b});
            if (a != b) spokes.push_back({(std::uint64_t(a) << 32) | b, std::uint32_t(c0 + i)});
            if (a != prev) spokes.push_back({(std::uint64_t(a) << 32) | prev, std::uint32_t(c0 + i)});
        }
        out.repeated_index_faces += repeated;
        bool all_degenerate = true;
        for (std::size_t i = 1; i + 1 < k && all_degenerate; ++i)
            all_degenerate = collinear(soup.positions[vs[0]], soup.positions[vs[i]], soup.positions[vs[i + 1]]);
        out.zero_area_faces += all_degenerate;
    }
    std::sort(halves.begin(), halves.end(), [](const Half& x, const Half& y) { return x.key < y.key; });
    for (std::size_t i = 0; i < halves.size();) {
        std::size_t j = i;
        int fwd = 0;
        while (j < halves.size() && halves[j].key == halves[i].key) fwd += halves[j++].forward;
        const std::size_t m = j - i;
        ++out.edges;
        if (m == 1) ++out.boundary_edges;
        else if (m > 2) ++out.non_manifold_edges;
        else if (fwd != 1) ++out.misoriented_edges;
        i = j;
    }
    out.euler_characteristic = long(out.vertices) - long(out.edges) + long(out.faces);
    for (std::uint32_t v = 0; v < nv; ++v)
        if (used[v] && components.find(v) == v) ++out.components;

    // fans around each vertex: corners joined through the edges they share
    std::sort(spokes.begin(), spokes.end(), [](const Spoke& x, const Spoke& y) { return x.key < y.key; });
    DisjointSets fans(soup.indices.size());
    for (std::size_t i = 1; i < spokes.size(); ++i)
        if (spokes[i].key == spokes[i - 1].key) fans.unite(spokes[i].corner, spokes[i - 1].corner);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> vertex_fan;  // (vertex, fan root)
    vertex_fan.reserve(soup.indices.size());
    for (std::size_t c = 0; c < soup.indices.size(); ++c) vertex_fan.emplace_back(soup.indices[c], fans.find(std::uint32_t(c)));
    std::sort(vertex_fan.begin(), vertex_fan.end());
    vertex_fan.erase(std::unique(vertex_fan.begin(), vertex_fan.end()), vertex_fan.end());
    for (std::size_t i = 1; i < vertex_fan.size(); ++i)
        if (vertex_fan[i].first == vertex_fan[i - 1].first &&
            (i < 2 || vertex_fan[i - 2].first != vertex_fan[i].first))
            ++out.non_manifold_vertices;

    if (options.self_intersections) {
        std::vector<Triangle> tris;
        tris.reserve(soup.indices.size());
        for (std::size_t f = 0; f < nf; ++f) {
            const auto vs = soup.face(f);
            for (std::size_t i = 1; i + 1 < vs.size(); ++i) {
                const Triangle t{std::uint32_t(f), {vs[0], vs[i], vs[i + 1]}};
                if (t.v[0] == t.v[1] || t.v[1] == t.v[2] || t.v[0] == t.v[2]) continue;
                if (collinear(soup.positions[t.v[0]], soup.positions[t.v[1]], soup.positions[t.v[2]])) continue;
                tris.push_back(t);
            }
        }
        count_intersections(soup, tris, out);
        out.self_intersection_checked = true;
    }
    return out;
}

}  // namespace geolab
