// Task 3: classification (handout §5).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {
namespace {
// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here (e.g. the eigenvalues of a symmetric matrix).

// The eigenvalues of the symmetric n×n matrix m (n ≤ 4) by cyclic Jacobi rotations.
void symmetric_eigenvalues(int n, double m[4][4], double out[4]) {
    for (int sweep = 0; sweep < 100; ++sweep) {
        double off = 0, diag = 0;
        for (int i = 0; i < n; ++i) {
            diag += m[i][i] * m[i][i];
            for (int j = i + 1; j < n; ++j) off += m[i][j] * m[i][j];
        }
        if (off <= 1e-34 * diag || off == 0) break;
        for (int p = 0; p < n; ++p)
            for (int q = p + 1; q < n; ++q) {
                if (m[p][q] == 0) continue;
                const double theta = (m[q][q] - m[p][p]) / (2 * m[p][q]);
                const double t = (theta >= 0 ? 1 : -1) / (std::abs(theta) + std::sqrt(theta * theta + 1));
                const double c = 1 / std::sqrt(t * t + 1), s = t * c;
                for (int k = 0; k < n; ++k) {  // columns p, q
                    const double kp = m[k][p], kq = m[k][q];
                    m[k][p] = c * kp - s * kq;
                    m[k][q] = s * kp + c * kq;
                }
                for (int k = 0; k < n; ++k) {  // rows p, q
                    const double pk = m[p][k], qk = m[q][k];
                    m[p][k] = c * pk - s * qk;
                    m[q][k] = s * pk + c * qk;
                }
            }
    }
    for (int i = 0; i < n; ++i) out[i] = m[i][i];
}

// The numbers of positive and negative eigenvalues (zero: |λ| ≤ 1e-9 · max |λ|).
struct Inertia {
    int pos = 0, neg = 0;
    int rank() const { return pos + neg; }
};
Inertia inertia(int n, const glm::dmat4& Q) {
    double m[4][4], ev[4];
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) m[i][j] = 0.5 * (Q[i][j] + Q[j][i]);
    symmetric_eigenvalues(n, m, ev);
    double big = 0;
    for (int i = 0; i < n; ++i) big = std::max(big, std::abs(ev[i]));
    Inertia r;
    for (int i = 0; i < n; ++i) {
        if (std::abs(ev[i]) <= 1e-9 * big) continue;
        (ev[i] > 0 ? r.pos : r.neg)++;
    }
    return r;
}
// END SOLUTION
}  // namespace

QuadricType classify(const glm::dmat4& Q) {
    // BEGIN SOLUTION
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (!std::isfinite(Q[i][j])) throw std::invalid_argument("classify: an entry of Q is not finite");
    const Inertia a = inertia(3, Q), q = inertia(4, Q);
    const int r3 = a.rank(), r4 = q.rank();
    const bool a_definite = a.pos == 0 || a.neg == 0;  // the non-zero eigenvalues of A agree in sign
    const bool q_one_sign = q.pos == 0 || q.neg == 0;   // ... and those of Q
    using T = QuadricType;
    if (r3 == 0) throw std::invalid_argument("classify: the quadratic part is zero (a plane or nothing, not a quadric)");
    if (r3 == 3) {
        if (r4 == 4) {
            if (a_definite) return q_one_sign ? T::imaginary_ellipsoid : T::real_ellipsoid;
            return std::min(q.pos, q.neg) == 2 ? T::hyperboloid_one_sheet : T::hyperboloid_two_sheets;
        }
        return a_definite ? T::imaginary_cone : T::real_cone;
    }
    if (r3 == 2) {
        if (r4 == 4) return a_definite ? T::elliptic_paraboloid : T::hyperbolic_paraboloid;
        if (r4 == 3) {
            if (!a_definite) return T::hyperbolic_cylinder;
            return q_one_sign ? T::imaginary_elliptic_cylinder : T::real_elliptic_cylinder;
        }
        return a_definite ? T::imaginary_intersecting_planes : T::real_intersecting_planes;
    }
    // r3 == 1
    if (r4 >= 3) return T::parabolic_cylinder;
    if (r4 == 2) return q_one_sign ? T::imaginary_parallel_planes : T::real_parallel_planes;
    return T::coincident_planes;
    // END SOLUTION
}

}  // namespace geolab::quadrics
