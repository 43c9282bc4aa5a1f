// Task 5: tensor-product patches — points, partial derivatives, normals, tessellation (handout §6).
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <stdexcept>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "geolab/bezier.hpp"

namespace geolab::bezier {

namespace {
// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.
void check(const BezierPatch& S, const char* who) {
    if (S.degree_u < 1 || S.degree_v < 1)
        throw std::invalid_argument(std::string(who) + ": degrees must be >= 1");
    if (S.points.size() != std::size_t(S.degree_u + 1) * std::size_t(S.degree_v + 1))
        throw std::invalid_argument(std::string(who) + ": " + std::to_string(S.points.size()) +
                                    " control points for degrees " + std::to_string(S.degree_u) + " x " +
                                    std::to_string(S.degree_v));
}

// The curve in v whose control points are the columns' values (d = 0), u-derivatives (d = 1) or second
// u-derivatives (d = 2) at u; column j is P_0j .. P_nj.
Poly3 v_curve(const BezierPatch& S, double u, int d) {
    Poly3 q(S.degree_v + 1);
    for (int j = 0; j <= S.degree_v; ++j) {
        Poly3 column(S.degree_u + 1);
        for (int i = 0; i <= S.degree_u; ++i) column[i] = S.points[i * (S.degree_v + 1) + j];
        q[j] = d == 0 ? de_casteljau(column, u) : d == 1 ? derivative(column, u) : second_derivative(column, u);
    }
    return q;
}

// The unit normal at (u, v) from S_u and S_v there, by the contract's rule where S_u × S_v = 0: the direction of
// d/dδ S_u × S_v moving to (u + σ_u δ, v + σ_v δ) (σ = +1 on the lower half of a parameter, towards the centre),
// then the normal at the point moved by 1e-6 that way, then (0, 0, 1).
glm::dvec3 unit_normal(const BezierPatch& S, double u, double v, const glm::dvec3& su, const glm::dvec3& sv) {
    const glm::dvec3 n = glm::cross(su, sv);
    const double scale = glm::length(su) + glm::length(sv);
    if (glm::length(n) > 1e-12 * scale * scale) return glm::normalize(n);
    const double su_sign = u <= 0.5 ? 1.0 : -1.0, sv_sign = v <= 0.5 ? 1.0 : -1.0;
    const glm::dvec3 suu = de_casteljau(v_curve(S, u, 2), v), suv = derivative(v_curve(S, u, 1), v),
                     svv = second_derivative(v_curve(S, u, 0), v);
    // d/dδ (S_u × S_v) = (σ_u S_uu + σ_v S_uv) × S_v + S_u × (σ_u S_uv + σ_v S_vv)
    const glm::dvec3 m = glm::cross(su_sign * suu + sv_sign * suv, sv) + glm::cross(su, su_sign * suv + sv_sign * svv);
    if (glm::length(m) > 0) return glm::normalize(m);
    const double uu = u + su_sign * 1e-6, vv = v + sv_sign * 1e-6;
    const glm::dvec3 moved = glm::cross(de_casteljau(v_curve(S, uu, 1), vv), derivative(v_curve(S, uu, 0), vv));
    if (glm::length(moved) > 0) return glm::normalize(moved);
    return glm::dvec3(0.0, 0.0, 1.0);  // a patch collapsed to a point
}

// Bernstein values B[i][k] = B_k^d(i/n) and derivatives dB[i][k] = d (B_(k−1)^(d−1) − B_k^(d−1))(i/n), k = 0..d,
// i = 0..n, for the tessellator's grid (bernstein is 0 for k − 1 < 0 and k > d − 1).
struct BasisTable {
    std::vector<std::vector<double>> B, dB;
};
BasisTable basis_table(int d, int n) {
    BasisTable T;
    for (int i = 0; i <= n; ++i) {
        const double t = double(i) / n;
        std::vector<double> B, dB;
        for (int k = 0; k <= d; ++k) {
            B.push_back(bernstein(d, k, t));
            dB.push_back(d * (bernstein(d - 1, k - 1, t) - bernstein(d - 1, k, t)));
        }
        T.B.push_back(B);
        T.dB.push_back(dB);
    }
    return T;
}
// END SOLUTION
}  // namespace

glm::dvec3 patch_point(const BezierPatch& S, double u, double v) {
    // BEGIN SOLUTION
    check(S, "patch_point");
    return de_casteljau(v_curve(S, u, 0), v);
    // END SOLUTION
}

glm::dvec3 patch_du(const BezierPatch& S, double u, double v) {
    // BEGIN SOLUTION
    check(S, "patch_du");
    return de_casteljau(v_curve(S, u, 1), v);
    // END SOLUTION
}

glm::dvec3 patch_dv(const BezierPatch& S, double u, double v) {
    // BEGIN SOLUTION
    check(S, "patch_dv");
    return derivative(v_curve(S, u, 0), v);
    // END SOLUTION
}

glm::dvec3 patch_normal(const BezierPatch& S, double u, double v) {
    // BEGIN SOLUTION
    check(S, "patch_normal");
    return unit_normal(S, u, v, de_casteljau(v_curve(S, u, 1), v), derivative(v_curve(S, u, 0), v));
    // END SOLUTION
}

PatchMesh tessellate_patches(const std::vector<BezierPatch>& patches, int n, double weld_tol, bool flip) {
    // BEGIN SOLUTION
    if (n < 1) throw std::invalid_argument("tessellate_patches: n must be >= 1");
    if (!(weld_tol >= 0)) throw std::invalid_argument("tessellate_patches: weld_tol must be >= 0");
    for (const auto& S : patches) check(S, "tessellate_patches");
    PatchMesh mesh;
    auto& soup = mesh.soup;
    const std::size_t samples = patches.size() * (n + 1) * (n + 1);  // reserve() sizes: capacity only
    soup.positions.reserve(samples);
    mesh.normals.reserve(samples);
    soup.indices.reserve(6 * samples);
    soup.offsets.reserve(2 * samples);
    auto add_vertex = [&](const glm::dvec3& p, const glm::dvec3& nrm) {
        soup.positions.push_back(p);
        mesh.normals.push_back(flip ? -nrm : nrm);
        return std::uint32_t(soup.positions.size() - 1);
    };
    // Border vertices by key x + y + z: a border sample becomes the earliest border vertex within weld_tol, or a new
    // one. Within weld_tol the keys differ by at most √3 weld_tol < 2 weld_tol (the margin absorbs the keys'
    // rounding); the teapot's seams lie in the planes x = 0 and y = 0, which one coordinate alone would not spread.
    std::multimap<double, std::uint32_t> border;
    const std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
    auto weld = [&](const glm::dvec3& p, const glm::dvec3& nrm) {
        const double key = p.x + p.y + p.z;
        std::uint32_t found = none;
        for (auto it = border.lower_bound(key - 2 * weld_tol); it != border.end() && it->first <= key + 2 * weld_tol;
             ++it)
            if (glm::length(soup.positions[it->second] - p) <= weld_tol) found = std::min(found, it->second);
        if (found != none) return found;
        const std::uint32_t v = add_vertex(p, nrm);
        border.emplace(key, v);
        return v;
    };
    // A triangle turning like S_u × S_v (reversed when flip); none when two of its vertices are one.
    auto add_triangle = [&](std::uint32_t x, std::uint32_t y, std::uint32_t z) {
        if (x == y || y == z || x == z) return;
        if (flip) soup.add_face({x, z, y});
        else soup.add_face({x, y, z});
    };
    std::map<int, BasisTable> tables;  // by degree: the teapot's 32 patches share one
    auto table = [&](int d) -> const BasisTable& {
        auto it = tables.find(d);
        if (it == tables.end()) it = tables.emplace(d, basis_table(d, n)).first;
        return it->second;
    };
    std::vector<std::uint32_t> id;  // the vertex of sample (i, j) at i (n + 1) + j
    Poly3 q, qu;
    for (const auto& S : patches) {
        const int du = S.degree_u, dv = S.degree_v;
        const BasisTable &Tu = table(du), &Tv = table(dv);
        id.clear();
        for (int i = 0; i <= n; ++i) {
            // The v-curves of the columns' values and u-derivatives at u = i/n.
            q.clear();
            qu.clear();
            for (int j = 0; j <= dv; ++j) {
                glm::dvec3 x(0.0), xu(0.0);
                for (int a = 0; a <= du; ++a) {
                    x += Tu.B[i][a] * S.points[a * (dv + 1) + j];
                    xu += Tu.dB[i][a] * S.points[a * (dv + 1) + j];
                }
                q.push_back(x);
                qu.push_back(xu);
            }
            for (int j = 0; j <= n; ++j) {
                glm::dvec3 p(0.0), su(0.0), sv(0.0);
                for (int b = 0; b <= dv; ++b) {
                    p += Tv.B[j][b] * q[b];
                    su += Tv.B[j][b] * qu[b];
                    sv += Tv.dB[j][b] * q[b];
                }
                const glm::dvec3 nrm = unit_normal(S, double(i) / n, double(j) / n, su, sv);
                const bool on_border = i == 0 || j == 0 || i == n || j == n;
                id.push_back(on_border ? weld(p, nrm) : add_vertex(p, nrm));
            }
        }
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const std::uint32_t a = id[i * (n + 1) + j], b = id[(i + 1) * (n + 1) + j],
                                    c = id[(i + 1) * (n + 1) + j + 1], d = id[i * (n + 1) + j + 1];
                add_triangle(a, b, c);
                add_triangle(a, c, d);
            }
    }
    return mesh;
    // END SOLUTION
}

}  // namespace geolab::bezier
