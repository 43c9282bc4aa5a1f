#include "geolab/mesh_field.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace geolab {
namespace {

constexpr std::uint32_t kLeafSize = 8;  // triangles per leaf at most (8 measured faster than 2, 4)
constexpr double kBeta = 2.0;           // far-field accuracy: expand when |c − p| > β r
constexpr int kStackSize = 128;         // > depth of a median-split tree on 2³² triangles
constexpr double kInv4Pi = 0.25 * std::numbers::inv_pi;

glm::dvec3 closest_point_on_segment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    glm::dvec3 ab = b - a;
    double len2 = glm::dot(ab, ab);
    if (len2 == 0.0) return a;
    return a + std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) * ab;
}

// closest point on a zero-area triangle: the best of its three edges
glm::dvec3 closest_point_on_degenerate(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                       const glm::dvec3& c) {
    glm::dvec3 best = closest_point_on_segment(p, a, b);
    for (glm::dvec3 q : {closest_point_on_segment(p, b, c), closest_point_on_segment(p, c, a)})
        if (glm::dot(q - p, q - p) < glm::dot(best - p, best - p)) best = q;
    return best;
}

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

glm::dvec3 closest_point_on_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                     const glm::dvec3& c) {
    // vertex region A
    glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return a;
    // vertex region B
    glm::dvec3 bp = p - b;
    double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return b;
    // edge region AB
    double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 && d1 - d3 > 0.0) return a + (d1 / (d1 - d3)) * ab;
    // vertex region C
    glm::dvec3 cp = p - c;
    double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return c;
    // edge region AC
    double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 && d2 - d6 > 0.0) return a + (d2 / (d2 - d6)) * ac;
    // edge region BC
    double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0 && (d4 - d3) + (d5 - d6) > 0.0)
        return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
    // face region: barycentric (u, v, w) ∝ (va, vb, vc), whose sum is |ab × ac|²
    double sum = va + vb + vc;
    if (!(sum > 0.0)) return closest_point_on_degenerate(p, a, b, c);
    return a + (vb / sum) * ab + (vc / sum) * ac;
}

double triangle_solid_angle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    glm::dvec3 x = a - p, y = b - p, z = c - p;
    double lx = glm::length(x), ly = glm::length(y), lz = glm::length(z);
    double det = glm::dot(x, glm::cross(y, z));
    double denom = lx * ly * lz + glm::dot(x, y) * lz + glm::dot(y, z) * lx + glm::dot(z, x) * ly;
    return 2.0 * std::atan2(det, denom);
}

namespace {

// Does the soup's oriented boundary chain not vanish? Vertices are identified by their exact position (soups read
// from STL repeat them per face); every polygon edge a→b counts +1 on the undirected edge, b→a counts −1. A closed,
// consistently oriented surface cancels every edge (inward-oriented ones too); a hole or a misoriented pair does not,
// and then the winding number is fractional near that edge.
bool has_open_boundary(const PolygonSoup& soup) {
    std::vector<std::uint32_t> by_position(soup.positions.size()), id(soup.positions.size());
    for (std::uint32_t i = 0; i < by_position.size(); ++i) by_position[i] = i;
    auto less = [&](std::uint32_t a, std::uint32_t b) {
        const glm::dvec3 &p = soup.positions[a], &q = soup.positions[b];
        return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z);
    };
    std::sort(by_position.begin(), by_position.end(), less);
    for (std::size_t k = 0; k < by_position.size(); ++k)
        id[by_position[k]] = (k > 0 && !less(by_position[k - 1], by_position[k])) ? id[by_position[k - 1]]
                                                                                 : std::uint32_t(k);
    std::vector<std::pair<std::uint64_t, int>> edges;  // (undirected key, ±1)
    edges.reserve(soup.indices.size());
    for (std::size_t f = 0; f + 1 < soup.offsets.size(); ++f) {
        auto vs = soup.face(f);
        if (vs.size() < 3) continue;
        for (std::size_t i = 0; i < vs.size(); ++i) {
            const std::uint32_t a = id[vs[i]], b = id[vs[(i + 1) % vs.size()]];
            if (a == b) continue;
            edges.push_back({(std::uint64_t(std::min(a, b)) << 32) | std::max(a, b), a < b ? 1 : -1});
        }
    }
    std::sort(edges.begin(), edges.end());
    for (std::size_t i = 0; i < edges.size();) {
        int net = 0;
        std::size_t j = i;
        for (; j < edges.size() && edges[j].first == edges[i].first; ++j) net += edges[j].second;
        if (net != 0) return true;
        i = j;
    }
    return false;
}

}  // namespace

MeshField::MeshField(const PolygonSoup& soup) {
    // fan-triangulate, checking the indices and the positions used
    for (std::size_t f = 0; f + 1 < soup.offsets.size(); ++f) {
        auto vs = soup.face(f);
        for (std::uint32_t v : vs) {
            if (v >= soup.positions.size())
                throw std::invalid_argument("MeshField: face " + std::to_string(f) + " uses vertex " +
                                            std::to_string(v) + " but there are only " +
                                            std::to_string(soup.positions.size()));
            if (!finite(soup.positions[v]))
                throw std::invalid_argument("MeshField: vertex " + std::to_string(v) + " is not finite");
        }
        for (std::size_t i = 1; i + 1 < vs.size(); ++i)
            tris_.push_back({soup.positions[vs[0]], soup.positions[vs[i]], soup.positions[vs[i + 1]]});
    }
    if (tris_.empty()) throw std::invalid_argument("MeshField: the soup has no triangle");
    open_ = has_open_boundary(soup);
    if (tris_.size() >= std::numeric_limits<std::uint32_t>::max() / 2)
        throw std::invalid_argument("MeshField: too many triangles");

    // build the tree over a permutation, then store the triangles in tree order
    std::vector<glm::dvec3> centroids(tris_.size());
    std::vector<std::uint32_t> order(tris_.size());
    for (std::uint32_t t = 0; t < tris_.size(); ++t) {
        centroids[t] = (tris_[t].a + tris_[t].b + tris_[t].c) / 3.0;
        order[t] = t;
    }
    std::vector<Leaf> node_ranges;
    nodes_.reserve(tris_.size() / 2 + 1);
    root_ = build_subtree(order, centroids, 0, static_cast<std::uint32_t>(tris_.size()), bbox_, node_ranges);
    std::vector<Triangle> sorted(tris_.size());
    for (std::size_t i = 0; i < order.size(); ++i) sorted[i] = tris_[order[i]];
    tris_ = std::move(sorted);

    // far-field expansions of every subtree
    node_expansions_.reserve(nodes_.size());
    for (const Leaf& range : node_ranges) node_expansions_.push_back(expansion_of(range.first, range.count));
    leaf_expansions_.reserve(leaves_.size());
    for (const Leaf& leaf : leaves_) leaf_expansions_.push_back(expansion_of(leaf.first, leaf.count));
}

namespace {

// round a box outwards to floats, so that the float box still contains the double one
void store_box(const Box& b, float lo[3], float hi[3]) {
    for (int i = 0; i < 3; ++i) {
        lo[i] = static_cast<float>(b.lo[i]);
        if (lo[i] > b.lo[i]) lo[i] = std::nextafter(lo[i], -std::numeric_limits<float>::infinity());
        hi[i] = static_cast<float>(b.hi[i]);
        if (hi[i] < b.hi[i]) hi[i] = std::nextafter(hi[i], std::numeric_limits<float>::infinity());
    }
}

double box_distance2(const glm::dvec3& p, const float lo[3], const float hi[3]) {
    double d2 = 0.0;
    for (int i = 0; i < 3; ++i) {
        double d = std::max({lo[i] - p[i], p[i] - hi[i], 0.0});
        d2 += d * d;
    }
    return d2;
}

}  // namespace

std::uint32_t MeshField::build_subtree(std::vector<std::uint32_t>& order, const std::vector<glm::dvec3>& centroids,
                                       std::uint32_t begin, std::uint32_t end, Box& box,
                                       std::vector<Leaf>& node_ranges) {
    // bounds of the triangles and of their centroids
    constexpr double inf = std::numeric_limits<double>::infinity();
    box = {glm::dvec3(inf), glm::dvec3(-inf)};
    glm::dvec3 clo(inf), chi(-inf);
    for (std::uint32_t i = begin; i < end; ++i) {
        const Triangle& t = tris_[order[i]];
        box.lo = glm::min(glm::min(box.lo, t.a), glm::min(t.b, t.c));
        box.hi = glm::max(glm::max(box.hi, t.a), glm::max(t.b, t.c));
        clo = glm::min(clo, centroids[order[i]]);
        chi = glm::max(chi, centroids[order[i]]);
    }
    if (end - begin <= kLeafSize) {
        leaves_.push_back({begin, end - begin});
        return static_cast<std::uint32_t>(leaves_.size() - 1) | kLeafBit;
    }

    // median split along the longest axis of the centroid box
    glm::dvec3 ext = chi - clo;
    int axis = (ext.x >= ext.y && ext.x >= ext.z) ? 0 : (ext.y >= ext.z ? 1 : 2);
    std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                     [&](std::uint32_t s, std::uint32_t t) { return centroids[s][axis] < centroids[t][axis]; });
    auto index = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    node_ranges.push_back({begin, end - begin});
    Box left, right;
    std::uint32_t l = build_subtree(order, centroids, begin, mid, left, node_ranges);
    std::uint32_t r = build_subtree(order, centroids, mid, end, right, node_ranges);
    Node& node = nodes_[index];
    node.child[0] = l;
    node.child[1] = r;
    store_box(left, node.lo[0], node.hi[0]);
    store_box(right, node.lo[1], node.hi[1]);
    return index;
}

MeshField::Expansion MeshField::expansion_of(std::uint32_t first, std::uint32_t count) const {
    Expansion e;
    // N = Σ N_t and the area-weighted centroid c
    double area = 0.0;
    glm::dvec3 weighted(0.0), lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (std::uint32_t i = first; i < first + count; ++i) {
        const Triangle& t = tris_[i];
        glm::dvec3 Nt = 0.5 * glm::cross(t.b - t.a, t.c - t.a);
        double At = glm::length(Nt);
        e.N += Nt;
        area += At;
        weighted += At * (t.a + t.b + t.c) / 3.0;
        lo = glm::min(lo, t.a);
        hi = glm::max(hi, t.a);
    }
    e.c = area > 0.0 ? weighted / area : 0.5 * (lo + hi);
    // T = Σ (centroid_t − c) ⊗ N_t and r = max |vertex − c|
    for (std::uint32_t i = first; i < first + count; ++i) {
        const Triangle& t = tris_[i];
        glm::dvec3 Nt = 0.5 * glm::cross(t.b - t.a, t.c - t.a);
        glm::dvec3 d = (t.a + t.b + t.c) / 3.0 - e.c;
        for (int r = 0; r < 3; ++r)
            for (int s = 0; s < 3; ++s) e.T[r][s] += d[r] * Nt[s];
        for (const glm::dvec3& v : {t.a, t.b, t.c}) e.r = std::max(e.r, glm::length(v - e.c));
    }
    return e;
}

const MeshField::Expansion& MeshField::expansion(std::uint32_t ref) const {
    return (ref & kLeafBit) ? leaf_expansions_[ref & ~kLeafBit] : node_expansions_[ref];
}

void MeshField::test_leaf(const glm::dvec3& p, const Leaf& leaf, Hit& best) const {
    for (std::uint32_t i = leaf.first; i < leaf.first + leaf.count; ++i) {
        glm::dvec3 q = closest_point_on_triangle(p, tris_[i].a, tris_[i].b, tris_[i].c);
        double d2 = glm::dot(q - p, q - p);
        if (d2 < best.d2) best = {d2, q, i};
    }
}

MeshField::Hit MeshField::closest_hit(const glm::dvec3& p) const {
    Hit best{std::numeric_limits<double>::infinity(), glm::dvec3(0.0), 0};
    if (root_ & kLeafBit) {
        test_leaf(p, leaves_[root_ & ~kLeafBit], best);
        return best;
    }
    struct Entry {
        std::uint32_t node;
        double d2;  // squared distance from p to the node's box
    };
    Entry stack[kStackSize];
    int top = 0;
    stack[top++] = {root_, 0.0};
    while (top > 0) {
        Entry e = stack[--top];
        if (e.d2 >= best.d2) continue;
        const Node& node = nodes_[e.node];
        double d[2] = {box_distance2(p, node.lo[0], node.hi[0]), box_distance2(p, node.lo[1], node.hi[1])};
        // the nearer child first: leaves at once, inner nodes pushed last so they pop first
        int first = d[1] < d[0] ? 1 : 0;
        for (int k : {first, 1 - first}) {
            if (d[k] >= best.d2) continue;
            std::uint32_t ref = node.child[k];
            if (ref & kLeafBit) test_leaf(p, leaves_[ref & ~kLeafBit], best);
        }
        for (int k : {1 - first, first}) {
            std::uint32_t ref = node.child[k];
            if (!(ref & kLeafBit) && d[k] < best.d2) stack[top++] = {ref, d[k]};
        }
    }
    return best;
}

double MeshField::unsigned_distance(const glm::dvec3& p, glm::dvec3* closest) const {
    Hit h = closest_hit(p);
    if (closest) *closest = h.point;
    return std::sqrt(h.d2);
}

double MeshField::winding_number(const glm::dvec3& p) const {
    double w = 0.0;
    std::uint32_t stack[kStackSize];
    int top = 0;
    stack[top++] = root_;
    while (top > 0) {
        std::uint32_t ref = stack[--top];
        const Expansion& e = expansion(ref);
        glm::dvec3 r = e.c - p;
        double d2 = glm::dot(r, r);
        if (d2 > kBeta * kBeta * e.r * e.r) {
            // far field: N·r/|r|³ + (tr T/|r|³ − 3 rᵀTr/|r|⁵), all over 4π
            double d = std::sqrt(d2), inv3 = 1.0 / (d2 * d), inv5 = inv3 / d2;
            double trace = e.T[0][0] + e.T[1][1] + e.T[2][2], rTr = 0.0;
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) rTr += r[i] * e.T[i][j] * r[j];
            w += kInv4Pi * (glm::dot(e.N, r) * inv3 + trace * inv3 - 3.0 * rTr * inv5);
        } else if (ref & kLeafBit) {
            const Leaf& leaf = leaves_[ref & ~kLeafBit];
            for (std::uint32_t i = leaf.first; i < leaf.first + leaf.count; ++i)
                w += kInv4Pi * triangle_solid_angle(p, tris_[i].a, tris_[i].b, tris_[i].c);
        } else {
            stack[top++] = nodes_[ref].child[1];
            stack[top++] = nodes_[ref].child[0];
        }
    }
    return w;
}

double MeshField::winding_number_exact(const glm::dvec3& p) const {
    double w = 0.0;
    for (const Triangle& t : tris_) w += triangle_solid_angle(p, t.a, t.b, t.c);
    return w * kInv4Pi;
}

bool MeshField::inside(const glm::dvec3& p) const { return std::abs(winding_number(p)) >= 0.5; }

double MeshField::value(const glm::dvec3& p) const {
    double d = std::sqrt(closest_hit(p).d2);
    return inside(p) ? -d : d;
}

glm::dvec3 MeshField::gradient(const glm::dvec3& p) const {
    Hit h = closest_hit(p);
    double d = std::sqrt(h.d2);
    if (d > 1e-12 * bbox_.diagonal()) {
        double sign = inside(p) ? -1.0 : 1.0;
        return sign * (p - h.point) / d;
    }
    // on the surface: the closest triangle's unit normal
    const Triangle& t = tris_[h.tri];
    glm::dvec3 n = glm::cross(t.b - t.a, t.c - t.a);
    double len = glm::length(n);
    return len > 0.0 ? n / len : glm::dvec3(0, 0, 1);
}

Box MeshField::bounds() const {
    glm::dvec3 c = bbox_.center(), h = 0.525 * bbox_.size();
    return {c - h, c + h};
}

}  // namespace geolab
