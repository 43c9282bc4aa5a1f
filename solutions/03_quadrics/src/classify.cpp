// Task 3: classification (handout §5).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {
namespace {
// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here (symmetric_eigen is given).

// The numbers of positive and negative eigenvalues (zero: |λ| ≤ 1e-9 · max |λ|).
struct Inertia {
    int pos = 0, neg = 0;
    int rank() const { return pos + neg; }
};
Inertia inertia(int n, const glm::dmat4& Q) {
    const SymmetricEigen e = symmetric_eigen(Q, n);  // throws on a non-finite entry
    const double* ev = e.values;
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
