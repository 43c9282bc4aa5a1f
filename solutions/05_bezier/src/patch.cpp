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
// The column j (P_0j .. P_nj) and row i (P_i0 .. P_im).
Poly3 column(const BezierPatch& S, int j) {
    Poly3 c(S.degree_u + 1);
    for (int i = 0; i <= S.degree_u; ++i) c[i] = S.points[i * (S.degree_v + 1) + j];
    return c;
}
// The curve in v of the columns' values (d = 0) or u-derivatives (d = 1) at u.
Poly3 v_curve(const BezierPatch& S, double u, int d) {
    Poly3 q(S.degree_v + 1);
    for (int j = 0; j <= S.degree_v; ++j) q[j] = d == 0 ? de_casteljau(column(S, j), u) : derivative(column(S, j), u);
    return q;
}
// The mixed derivative S_uv.
glm::dvec3 patch_duv(const BezierPatch& S, double u, double v) { return derivative(v_curve(S, u, 1), v); }

// Bernstein values and derivatives of degree n at t (for the tessellator's many evaluations).
void basis(int n, double t, double* B, double* dB) {
    // B_k^n by the triangle, dB_k = n (B_(k−1)^(n−1) − B_k^(n−1))
    double b[32] = {1.0};
    for (int r = 1; r < n; ++r) {
        for (int k = r; k >= 1; --k) b[k] = (1 - t) * b[k] + t * b[k - 1];
        b[0] *= (1 - t);
    }
    for (int k = 0; k <= n; ++k) dB[k] = n * ((k > 0 ? b[k - 1] : 0.0) - (k < n ? b[k] : 0.0));
    double c[32];
    std::memcpy(c, b, sizeof(double) * n);
    c[n] = 0.0;
    for (int k = n; k >= 1; --k) c[k] = (1 - t) * c[k] + t * c[k - 1];
    c[0] *= (1 - t);
    std::memcpy(B, c, sizeof(double) * (n + 1));
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
    double uu = u, vv = v;
    for (int attempt = 0; attempt < 12; ++attempt) {
        const glm::dvec3 su = patch_du(S, uu, vv), sv = patch_dv(S, uu, vv);
        const glm::dvec3 n = glm::cross(su, sv);
        const double scale = glm::length(su) + glm::length(sv);
        if (glm::length(n) > 1e-12 * scale * scale) return glm::normalize(n);
        // First-order term of S_u × S_v moving into the patch (σ = the direction towards the centre).
        const glm::dvec3 suv = patch_duv(S, uu, vv);
        const double su_sign = uu <= 0.5 ? 1.0 : -1.0, sv_sign = vv <= 0.5 ? 1.0 : -1.0;
        const glm::dvec3 m = su_sign * glm::cross(su, suv) + sv_sign * glm::cross(suv, sv);
        const double s2 = scale + glm::length(suv);
        if (glm::length(m) > 1e-12 * s2 * s2) return glm::normalize(m);
        // Move towards the centre and try again.
        const double step = 1e-6 * std::pow(10.0, attempt / 2);
        uu += (uu <= 0.5 ? step : -step);
        vv += (vv <= 0.5 ? step : -step);
    }
    return glm::dvec3(0.0, 0.0, 1.0);  // a patch collapsed to a point or a line: any unit vector
    // END SOLUTION
}

PatchMesh tessellate_patches(const std::vector<BezierPatch>& patches, int n, double weld_tol, bool flip) {
    // BEGIN SOLUTION
    if (n < 1) throw std::invalid_argument("tessellate_patches: n must be >= 1");
    if (!(weld_tol >= 0)) throw std::invalid_argument("tessellate_patches: weld_tol must be >= 0");
    for (const auto& S : patches) {
        check(S, "tessellate_patches");
        if (S.degree_u > 30 || S.degree_v > 30) throw std::invalid_argument("tessellate_patches: degree > 30");
    }
    PatchMesh mesh;
    auto& soup = mesh.soup;
    const std::size_t per = std::size_t(n + 1) * std::size_t(n + 1);
    soup.positions.reserve(patches.size() * per);
    mesh.normals.reserve(patches.size() * per);
    soup.indices.reserve(patches.size() * 6 * std::size_t(n) * std::size_t(n));
    soup.offsets.reserve(patches.size() * 2 * std::size_t(n) * std::size_t(n) + 1);
    // Border vertices go through a hash grid of cell weld_tol (exact positions when weld_tol = 0).
    struct Key {
        std::int64_t x, y, z;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        std::size_t operator()(const Key& k) const {
            return std::size_t(k.x * 73856093) ^ std::size_t(k.y * 19349663) ^ std::size_t(k.z * 83492791);
        }
    };
    std::unordered_map<Key, std::vector<std::uint32_t>, KeyHash> grid;
    const double cell = weld_tol > 0 ? 2 * weld_tol : 0;
    auto key_of = [&](const glm::dvec3& p) {
        if (cell == 0) {
            Key k;
            std::memcpy(&k.x, &p.x, 8);
            std::memcpy(&k.y, &p.y, 8);
            std::memcpy(&k.z, &p.z, 8);
            return k;
        }
        return Key{std::int64_t(std::floor(p.x / cell)), std::int64_t(std::floor(p.y / cell)),
                   std::int64_t(std::floor(p.z / cell))};
    };
    auto add_vertex = [&](const glm::dvec3& p, const glm::dvec3& nrm) {
        soup.positions.push_back(p);
        mesh.normals.push_back(flip ? -nrm : nrm);
        return std::uint32_t(soup.positions.size() - 1);
    };
    auto weld = [&](const glm::dvec3& p, const glm::dvec3& nrm) {
        const Key k = key_of(p);
        if (cell == 0) {
            auto& list = grid[k];
            if (!list.empty()) return list.front();
            list.push_back(add_vertex(p, nrm));
            return list.front();
        }
        for (std::int64_t dx = -1; dx <= 1; ++dx)
            for (std::int64_t dy = -1; dy <= 1; ++dy)
                for (std::int64_t dz = -1; dz <= 1; ++dz) {
                    auto it = grid.find(Key{k.x + dx, k.y + dy, k.z + dz});
                    if (it == grid.end()) continue;
                    for (std::uint32_t v : it->second)
                        if (glm::length(soup.positions[v] - p) <= weld_tol) return v;
                }
        const std::uint32_t v = add_vertex(p, nrm);
        grid[k].push_back(v);
        return v;
    };
    std::vector<double> Bu((n + 1) * 31), dBu((n + 1) * 31), Bv((n + 1) * 31), dBv((n + 1) * 31);
    std::vector<std::uint32_t> id((n + 1) * (n + 1));
    for (const auto& S : patches) {
        const int du = S.degree_u, dv = S.degree_v;
        for (int i = 0; i <= n; ++i) {
            basis(du, double(i) / n, &Bu[i * 31], &dBu[i * 31]);
            basis(dv, double(i) / n, &Bv[i * 31], &dBv[i * 31]);
        }
        for (int i = 0; i <= n; ++i) {
            // The v-curves of the columns' values and u-derivatives at u = i/n.
            glm::dvec3 q[31], qu[31];
            for (int j = 0; j <= dv; ++j) {
                q[j] = qu[j] = glm::dvec3(0.0);
                for (int a = 0; a <= du; ++a) {
                    q[j] += Bu[i * 31 + a] * S.points[a * (dv + 1) + j];
                    qu[j] += dBu[i * 31 + a] * S.points[a * (dv + 1) + j];
                }
            }
            for (int j = 0; j <= n; ++j) {
                glm::dvec3 p(0.0), su(0.0), sv(0.0);
                for (int b = 0; b <= dv; ++b) {
                    p += Bv[j * 31 + b] * q[b];
                    su += Bv[j * 31 + b] * qu[b];
                    sv += dBv[j * 31 + b] * q[b];
                }
                const glm::dvec3 c = glm::cross(su, sv);
                const double scale = glm::length(su) + glm::length(sv);
                const glm::dvec3 nrm = glm::length(c) > 1e-12 * scale * scale
                                           ? glm::normalize(c)
                                           : patch_normal(S, double(i) / n, double(j) / n);
                const bool border = i == 0 || j == 0 || i == n || j == n;
                id[i * (n + 1) + j] = border ? weld(p, nrm) : add_vertex(p, nrm);
            }
        }
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const std::uint32_t a = id[i * (n + 1) + j], b = id[(i + 1) * (n + 1) + j],
                                    c = id[(i + 1) * (n + 1) + j + 1], d = id[i * (n + 1) + j + 1];
                auto tri = [&](std::uint32_t x, std::uint32_t y, std::uint32_t z) {
                    if (x == y || y == z || x == z) return;
                    if (flip) soup.add_face({x, z, y});
                    else soup.add_face({x, y, z});
                };
                tri(a, b, c);
                tri(a, c, d);
            }
    }
    return mesh;
    // END SOLUTION
}

}  // namespace geolab::bezier
