// Lab 09 — the octree data structure (given: the tasks use it, it is not a task).
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"

namespace geolab::dc {

namespace {
void check_level(int level, const char* who) {
    if (level < 1 || level > 10)
        throw std::invalid_argument(std::string(who) + ": max_level must be in [1, 10], got " + std::to_string(level));
}
}  // namespace

void Octree::init_cartesian(const ScalarField& f, int level, const glm::dvec3& lo, double side) {
    check_level(level, "Octree::init_cartesian");
    if (!(side > 0.0) || !std::isfinite(side))
        throw std::invalid_argument("Octree::init_cartesian: the domain size must be positive and finite");
    coordinates = Coordinates::cartesian;
    max_level = level;
    min_corner = lo;
    size = side;
    field = &f;
    nodes.assign(1, OctreeNode{});
    vertices.clear();
    qefs.clear();
    release_samples();
    samples_ = 0;
}

void Octree::release_samples() {
    cache_ = BlockGrid<double>(std::numeric_limits<double>::quiet_NaN(), resolution() + 1);
    even_cache_ = BlockGrid<double>(std::numeric_limits<double>::quiet_NaN(), resolution() / 2 + 1);
}

void Octree::init_spherical(const ScalarField& f, int level, const glm::dvec3& o, double rmin, double rmax) {
    check_level(level, "Octree::init_spherical");
    if (!(rmin >= 0.0)) throw std::invalid_argument("Octree::init_spherical: r_min must be >= 0");
    if (!(rmin < rmax) || !std::isfinite(rmax))
        throw std::invalid_argument("Octree::init_spherical: need r_min < r_max (got r_min = " + std::to_string(rmin) +
                                    ", r_max = " + std::to_string(rmax) + ")");
    coordinates = Coordinates::spherical;
    max_level = level;
    origin = o;
    r_min = rmin;
    r_max = rmax;
    field = &f;
    nodes.assign(1, OctreeNode{});
    vertices.clear();
    qefs.clear();
    release_samples();
    samples_ = 0;
    const int n = resolution();
    sin_t_.resize(n + 1);
    cos_t_.resize(n + 1);
    sin_p_.resize(n + 1);
    cos_p_.resize(n + 1);
    for (int i = 0; i <= n; ++i) {
        double t = pi * i / n, p = 2.0 * pi * i / n;
        sin_t_[i] = std::sin(t);
        cos_t_[i] = std::cos(t);
        sin_p_[i] = std::sin(p);
        cos_p_[i] = std::cos(p);
    }
    // exact values on the axes and the seam: every pole point is exactly on the axis, φ = 2π is φ = 0
    sin_t_[0] = sin_t_[n] = 0.0;
    cos_t_[0] = 1.0;
    cos_t_[n] = -1.0;
    sin_p_[0] = sin_p_[n] = 0.0;
    cos_p_[0] = cos_p_[n] = 1.0;
}

Spherical Octree::lattice_spherical(glm::ivec3 q) const {
    const double n = resolution();
    if (coordinates == Coordinates::cartesian) {
        glm::dvec3 p = lattice_point(q);
        return {p.x, p.y, p.z};
    }
    return {r_min + (r_max - r_min) * (q.x / n), pi * (q.y / n), 2.0 * pi * (q.z / n)};
}

glm::dvec3 Octree::spherical_lattice_point(glm::ivec3 q) const {
    const double n = resolution();
    const std::int32_t ni = resolution();
    double r = r_min + (r_max - r_min) * (q.x / n);
    std::int32_t t = std::clamp(q.y, 0, ni);
    std::int32_t p = ((q.z % ni) + ni) % ni;
    double st = sin_t_[t];
    return origin + glm::dvec3(r * st * cos_p_[p], r * st * sin_p_[p], r * cos_t_[t]);
}

glm::dvec3 Octree::spherical_point(const Spherical& s) const { return origin + to_cartesian(s); }

void Octree::sub_lattice_values(glm::ivec3 base, double (&out)[27]) const {
    if (coordinates == Coordinates::spherical) {  // the seam and the poles map points to canonical ones
        for (int k = 0; k < 3; ++k)
            for (int j = 0; j < 3; ++j)
                for (int i = 0; i < 3; ++i) out[i + 3 * j + 9 * k] = value(base + glm::ivec3(i, j, k));
        return;
    }
    // Speed: the 8 points with all offsets even are the parent's corners, in even_cache_ (see cache_slot); along each
    // axis the other offsets fall into one block of cache_ or two (split where the block boundary falls). Look each
    // block up once, then read the slots through per-axis tables.
    constexpr int b = BlockGrid<double>::B;
    int block_step[3][3], local[3][3];  // offset o along axis a: in the lower (0) or upper (1) block, local coordinate
    for (int a = 0; a < 3; ++a)
        for (int o = 0; o < 3; ++o) {
            const int l = (base[a] & (b - 1)) + o;
            block_step[a][o] = l >= b;
            local[a][o] = l & (b - 1);
        }
    double* blocks[2][2][2] = {};
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i) {
                const glm::ivec3 q = base + glm::ivec3(i, j, k);
                double* v;
                if (((q.x | q.y | q.z) & 1) == 0) {
                    v = &cache_slot(q);
                } else {
                    double*& slots = blocks[block_step[2][k]][block_step[1][j]][block_step[0][i]];
                    if (!slots) slots = cache_.block_of(q);
                    v = &slots[local[0][i] + b * (local[1][j] + b * local[2][k])];
                }
                if (*v != *v) *v = sample(q);
                out[i + 3 * j + 9 * k] = *v;
            }
}

std::uint32_t Octree::locate(glm::ivec3 p2) const {
    const std::int32_t n2 = 2 * resolution();
    if (coordinates == Coordinates::spherical) p2.z = ((p2.z % n2) + n2) % n2;
    for (int a = 0; a < 3; ++a)
        if (p2[a] < 0 || p2[a] > n2) return invalid_index;
    std::uint32_t cur = 0;
    while (!nodes[cur].is_leaf()) {
        const OctreeNode& nd = nodes[cur];
        // the children split at the cell's midpoint, in doubled coordinates 2 (2 c + 1) span/2 = (2c + 1) span
        const std::int32_t s = cell_span(nd.level);
        int c = 0;
        if (p2.x >= (2 * std::int32_t(nd.x) + 1) * s) c |= 1;
        if (p2.y >= (2 * std::int32_t(nd.y) + 1) * s) c |= 2;
        if (p2.z >= (2 * std::int32_t(nd.z) + 1) * s) c |= 4;
        cur = nd.first_child + c;
    }
    return cur;
}

std::vector<std::uint32_t> Octree::leaves() const {
    std::vector<std::uint32_t> out;
    if (nodes.empty()) return out;
    out.reserve(nodes.size() - nodes.size() / 8);  // 7 of every 8 nodes are leaves once the tree is split
    depth_first([&](std::uint32_t n) {
        if (nodes[n].is_leaf()) out.push_back(n);
        return true;
    });
    return out;
}

std::size_t Octree::reachable_nodes() const {
    if (nodes.empty()) return 0;
    std::size_t count = 0;
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty()) {
        std::uint32_t n = stack.back();
        stack.pop_back();
        ++count;
        if (!nodes[n].is_leaf())
            for (int c = 0; c < 8; ++c) stack.push_back(nodes[n].first_child + c);
    }
    return count;
}

std::uint32_t Octree::split(std::uint32_t n) {
    const std::uint32_t first = std::uint32_t(nodes.size());
    const OctreeNode parent = nodes[n];
    nodes.resize(first + 8);  // Speed: one size check for the 8 children, not 8
    OctreeNode* children = nodes.data() + first;
    for (int c = 0; c < 8; ++c) {
        children[c].x = std::uint16_t(2 * parent.x + (c & 1));
        children[c].y = std::uint16_t(2 * parent.y + ((c >> 1) & 1));
        children[c].z = std::uint16_t(2 * parent.z + ((c >> 2) & 1));
        children[c].level = std::uint8_t(parent.level + 1);
    }
    nodes[n].first_child = first;
    return first;
}

std::size_t Octree::refine_around_sign_changes() {
    if (nodes.empty() || !field || (field->lipschitz() > 0.0 && !field->sign_may_jump())) return 0;
    const std::int32_t n_res = resolution();
    const bool spherical = coordinates == Coordinates::spherical;
    std::size_t splits = 0;
    std::vector<std::uint32_t> work = leaves();  // leaves still to check; split() adds their children
    // split the leaf holding the (doubled) point p2 until a finest leaf holds it
    auto refine_at = [&](glm::ivec3 p2) {
        for (std::uint32_t l = locate(p2); l != invalid_index && nodes[l].level < max_level; l = locate(p2)) {
            const std::uint32_t first = split(l);
            ++splits;
            for (int c = 0; c < 8; ++c) work.push_back(first + c);
        }
    };
    while (!work.empty()) {
        const OctreeNode nd = nodes[work.back()];  // a copy: split() may move the nodes
        const std::uint32_t n = work.back();
        work.pop_back();
        if (!nd.is_leaf()) continue;
        glm::ivec3 q[8];
        double v[8];
        int n_in = 0;
        for (int c = 0; c < 8; ++c) q[c] = corner(nd, c), v[c] = value(q[c]), n_in += inside(v[c]);
        if (n_in == 0 || n_in == 8) continue;
        if (nd.level < max_level) {  // (a)
            const std::uint32_t first = split(n);
            ++splits;
            for (int c = 0; c < 8; ++c) work.push_back(first + c);
            continue;
        }
        for (int a = 0; a < 3; ++a)  // (b): the edges c → c + e_a that change sign
            for (int c = 0; c < 8; ++c) {
                if ((c & (1 << a)) || inside(v[c]) == inside(v[c | (1 << a)])) continue;
                if (spherical && a == 0 && (q[c].y == 0 || q[c].y == n_res)) {  // on the polar axis: the ring
                    for (std::int32_t k = 0; k < n_res; ++k)
                        refine_at({2 * q[c].x + 1, q[c].y == 0 ? 1 : 2 * n_res - 1, 2 * k + 1});
                    continue;
                }
                const int b = (a + 1) % 3, d = (a + 2) % 3;
                glm::ivec3 m2 = 2 * q[c];
                m2[a] += 1;
                for (int k = 0; k < 4; ++k) {
                    glm::ivec3 p2 = m2;
                    p2[b] += (k & 1) ? 1 : -1;
                    p2[d] += (k & 2) ? 1 : -1;
                    refine_at(p2);
                }
            }
    }
    return splits;
}

std::pair<glm::dvec3, double> cartesian_domain(const ScalarField& f, double padding) {
    Box b = f.bounds();
    glm::dvec3 ext = b.hi - b.lo;
    double m = std::max({ext.x, ext.y, ext.z});
    if (!(ext.x >= 0.0 && ext.y >= 0.0 && ext.z >= 0.0) || !(m > 0.0) || !std::isfinite(m) ||
        !std::isfinite(b.lo.x + b.lo.y + b.lo.z))
        throw std::invalid_argument("cartesian_domain: the field's bounds() are empty or not finite");
    if (!(padding >= 0.0)) throw std::invalid_argument("cartesian_domain: padding must be >= 0");
    double side = m * (1.0 + 2.0 * padding);
    return {b.center() - glm::dvec3(0.5 * side), side};
}

}  // namespace geolab::dc
