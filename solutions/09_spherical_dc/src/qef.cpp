// Lab 09 — task 1: the quadratic error function of dual contouring.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"

namespace geolab::dc {

void Qef::add(const glm::dvec3& p, const glm::dvec3& n) {
    // BEGIN SOLUTION
    double d = glm::dot(n, p);
    ata[0] += n.x * n.x;
    ata[1] += n.x * n.y;
    ata[2] += n.x * n.z;
    ata[3] += n.y * n.y;
    ata[4] += n.y * n.z;
    ata[5] += n.z * n.z;
    atb += n * d;
    btb += d * d;
    mass_sum += p;
    count += 1;
    // END SOLUTION
}

double Qef::error(const glm::dvec3& x) const {
    // BEGIN SOLUTION
    // xᵀ AᵀA x − 2 xᵀ Aᵀb + bᵀb
    glm::dvec3 ax(ata[0] * x.x + ata[1] * x.y + ata[2] * x.z, ata[1] * x.x + ata[3] * x.y + ata[4] * x.z,
                  ata[2] * x.x + ata[4] * x.y + ata[5] * x.z);
    return glm::dot(x, ax) - 2.0 * glm::dot(x, atb) + btb;
    // END SOLUTION
}

glm::dvec3 Qef::solve(double tau, glm::dvec3* mass_point_out, int* rank_out) const {
    // BEGIN SOLUTION
    const glm::dvec3 m = mass_point();
    if (mass_point_out) *mass_point_out = m;
    if (count == 0) {
        if (rank_out) *rank_out = 0;
        return m;
    }
    // right-hand side about the mass point: r = Aᵀb − AᵀA m
    const glm::dvec3 r = atb - glm::dvec3(ata[0] * m.x + ata[1] * m.y + ata[2] * m.z,
                                          ata[1] * m.x + ata[3] * m.y + ata[4] * m.z,
                                          ata[2] * m.x + ata[4] * m.y + ata[5] * m.z);
    // Speed: the common case needs no decomposition. A small cell on a smooth surface sees nearly parallel
    // normals: λ2 + λ3 = σ is tiny. With T = trace = λ1 + σ and S = sum of the principal 2×2 minors ≥ λ1 σ,
    // S < (T − σ*) σ*, σ* = τ T / (1 + τ), proves σ < σ* < τ λ1 (both small eigenvalues truncated, rank 1); we
    // ask for half of that bound, to stay clear of the threshold. Then λ1 is the largest root of
    // det(λI − AᵀA) = λ³ − Tλ² + Sλ − D, reached by Newton from above (monotone: the cubic is convex and
    // increasing above its largest root), and e1 is the largest cross product of two rows of AᵀA − λ1 I.
    const double trace = ata[0] + ata[3] + ata[5];
    const double minors = ata[0] * ata[3] - ata[1] * ata[1] + ata[0] * ata[5] - ata[2] * ata[2] +
                          ata[3] * ata[5] - ata[4] * ata[4];
    const double sigma = tau * trace / (1.0 + tau);
    if (tau > 0.0 && tau < 1.0 && trace > 0.0 && minors < 0.5 * (trace - sigma) * sigma) {
        const double det = ata[0] * (ata[3] * ata[5] - ata[4] * ata[4]) - ata[1] * (ata[1] * ata[5] - ata[4] * ata[2]) +
                           ata[2] * (ata[1] * ata[4] - ata[3] * ata[2]);
        // Start at T − S/T: still ≥ λ1 (S/T ≤ σ because λ2 λ3 ≤ σ²) and within σ²/T of it. Newton converges
        // quadratically: after a step δ the error is about 2δ²/λ1, so a step below 1e-8 λ1 leaves < 1e-15 λ1.
        double l1 = trace - minors / trace;
        for (int it = 0; it < 16; ++it) {
            const double p = ((l1 - trace) * l1 + minors) * l1 - det, dp = (3.0 * l1 - 2.0 * trace) * l1 + minors;
            const double step = dp > 0.0 ? p / dp : 0.0;
            l1 -= step;
            if (!(step > 1e-8 * l1)) break;
        }
        const glm::dvec3 r0(ata[0] - l1, ata[1], ata[2]), r1(ata[1], ata[3] - l1, ata[4]), r2(ata[2], ata[4], ata[5] - l1);
        glm::dvec3 e = glm::cross(r0, r1);
        for (const glm::dvec3& c : {glm::cross(r0, r2), glm::cross(r1, r2)})
            if (glm::dot(c, c) > glm::dot(e, e)) e = c;
        const double len2 = glm::dot(e, e);
        if (len2 > 0.0 && l1 > 0.0) {
            if (rank_out) *rank_out = 1;
            return m + e * (glm::dot(e, r) / (l1 * len2));  // e unnormalised: e (e·r) / (λ1 |e|²)
        }
    }
    // symmetric eigen-decomposition AᵀA = V diag(λ) Vᵀ by cyclic Jacobi rotations (Golub & Van Loan §8.5)
    double a[3][3] = {{ata[0], ata[1], ata[2]}, {ata[1], ata[3], ata[4]}, {ata[2], ata[4], ata[5]}};
    double v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    // the rotation in the (p, q) plane that zeroes a[p][q]; r is the third index. Speed: it updates only the
    // entries that change, in the symmetric form of Numerical Recipes §11.1, and takes its cosine and sine from
    // two square roots and one division (this runs for every dual vertex: its latency chain is the cost).
    auto rotate = [&](int p, int q, int r) {
        const double apq = a[p][q];
        if (apq == 0.0) return;
        const double d = a[q][q] - a[p][p];
        const double w = std::abs(d) + std::sqrt(d * d + 4.0 * apq * apq);  // 2|apq| / |tan φ|
        const double sgn_apq = d >= 0.0 ? 2.0 * apq : -2.0 * apq;
        const double t = sgn_apq / w;  // tan φ, |φ| ≤ π/4
        const double inv = 1.0 / std::sqrt(w * w + sgn_apq * sgn_apq);
        const double c = w * inv, s = sgn_apq * inv;
        a[p][p] -= t * apq;
        a[q][q] += t * apq;
        a[p][q] = a[q][p] = 0.0;
        const double arp = a[r][p], arq = a[r][q];
        a[r][p] = a[p][r] = c * arp - s * arq;
        a[r][q] = a[q][r] = s * arp + c * arq;
        for (int k = 0; k < 3; ++k) {  // V ← V J
            const double vkp = v[k][p], vkq = v[k][q];
            v[k][p] = c * vkp - s * vkq;
            v[k][q] = s * vkp + c * vkq;
        }
    };
    for (int sweep = 0; sweep < 12; ++sweep) {
        double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if (off <= 1e-22 * diag) break;  // off-diagonal below 1e-11 of the diagonal
        rotate(0, 1, 2);
        rotate(0, 2, 1);
        rotate(1, 2, 0);
    }
    double lmax = std::max({std::abs(a[0][0]), std::abs(a[1][1]), std::abs(a[2][2])});
    glm::dvec3 x = m;
    int rank = 0;
    for (int i = 0; i < 3; ++i) {
        double l = a[i][i];
        if (!(lmax > 0.0) || l < tau * lmax) continue;  // truncated: keep the mass point's coordinate
        glm::dvec3 e(v[0][i], v[1][i], v[2][i]);
        x += e * (glm::dot(e, r) / l);
        ++rank;
    }
    if (rank_out) *rank_out = rank;
    return x;
    // END SOLUTION
}

}  // namespace geolab::dc
