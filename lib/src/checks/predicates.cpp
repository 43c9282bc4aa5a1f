// Exact predicates: a double-precision filter, then GMP integers when the filter cannot decide.
#include "geolab/predicates.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>

#include <gmpxx.h>

namespace geolab {

namespace {

// Relative bound on the rounding error of the double evaluations below, in units of the permanent (the same
// expression with every term replaced by its absolute value). The true bounds are a few machine epsilons
// (Shewchuk: 7ε for orient3d, 3ε for orient2d, ε = 2^-53 ≈ 1.1e-16, differences included); 1e-14 leaves a
// wide margin, so a near-degenerate case costs an exact evaluation rather than a wrong sign.
constexpr double kFilter = 1e-14;

// Exact evaluation in integers: every double is m · 2^e with an integer m of at most 53 bits, so all the inputs of
// one determinant are integers once scaled by 2^-E, E the smallest such e among them; the determinant's sign is
// unchanged by the common positive scale. (Integers, not rationals: no gcd is ever taken.)
template <std::size_t N>
std::array<mpz_class, N> scaled_integers(const std::array<double, N>& x) {
    int lowest = INT_MAX;
    std::array<int, N> exps{};
    std::array<double, N> mants{};
    for (std::size_t i = 0; i < N; ++i) {
        if (x[i] == 0.0) continue;
        mants[i] = std::ldexp(std::frexp(x[i], &exps[i]), 53);  // an integer-valued double, |m| < 2^53
        exps[i] -= 53;
        lowest = std::min(lowest, exps[i]);
    }
    std::array<mpz_class, N> z;
    for (std::size_t i = 0; i < N; ++i) {
        if (x[i] == 0.0) continue;
        z[i] = mants[i];
        mpz_mul_2exp(z[i].get_mpz_t(), z[i].get_mpz_t(), mp_bitcnt_t(exps[i] - lowest));
    }
    return z;
}

int orient3d_exact(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
    const auto z = scaled_integers<12>({a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z});
    const mpz_class adx = z[0] - z[9], ady = z[1] - z[10], adz = z[2] - z[11];
    const mpz_class bdx = z[3] - z[9], bdy = z[4] - z[10], bdz = z[5] - z[11];
    const mpz_class cdx = z[6] - z[9], cdy = z[7] - z[10], cdz = z[8] - z[11];
    const mpz_class det = adx * (bdy * cdz - bdz * cdy) - ady * (bdx * cdz - bdz * cdx) + adz * (bdx * cdy - bdy * cdx);
    return sgn(det);
}

int orient2d_exact(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    const auto z = scaled_integers<6>({a.x, a.y, b.x, b.y, c.x, c.y});
    const mpz_class det = (z[0] - z[4]) * (z[3] - z[5]) - (z[1] - z[5]) * (z[2] - z[4]);
    return sgn(det);
}

}  // namespace

int orient3d(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
    const glm::dvec3 ad = a - d, bd = b - d, cd = c - d;
    const double m1 = bd.y * cd.z - bd.z * cd.y, m2 = bd.x * cd.z - bd.z * cd.x, m3 = bd.x * cd.y - bd.y * cd.x;
    const double det = ad.x * m1 - ad.y * m2 + ad.z * m3;
    const double perm = std::abs(ad.x) * (std::abs(bd.y * cd.z) + std::abs(bd.z * cd.y)) +
                        std::abs(ad.y) * (std::abs(bd.x * cd.z) + std::abs(bd.z * cd.x)) +
                        std::abs(ad.z) * (std::abs(bd.x * cd.y) + std::abs(bd.y * cd.x));
    const double bound = kFilter * perm;
    if (det > bound) return 1;
    if (det < -bound) return -1;
    // every product of the expansion has a factor that is exactly 0 (a difference of equal coordinates is exactly 0,
    // and only then): the determinant is 0 without the integers (four points in one axis-aligned plane, say)
    auto zero = [](double u, double v, double w) { return u == 0.0 || v == 0.0 || w == 0.0; };
    if (zero(ad.x, bd.y, cd.z) && zero(ad.x, bd.z, cd.y) && zero(ad.y, bd.x, cd.z) && zero(ad.y, bd.z, cd.x) &&
        zero(ad.z, bd.x, cd.y) && zero(ad.z, bd.y, cd.x))
        return 0;
    // also reached when det or the bound overflowed (inf or NaN compare false): the exact sign decides
    return orient3d_exact(a, b, c, d);
}

int orient2d(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    const double acx = a.x - c.x, acy = a.y - c.y, bcx = b.x - c.x, bcy = b.y - c.y;
    const double det = acx * bcy - acy * bcx;
    const double bound = kFilter * (std::abs(acx * bcy) + std::abs(acy * bcx));
    if (det > bound) return 1;
    if (det < -bound) return -1;
    if ((acx == 0.0 || bcy == 0.0) && (acy == 0.0 || bcx == 0.0)) return 0;  // both products exactly 0
    return orient2d_exact(a, b, c);
}

bool collinear(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    return orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y}) == 0 && orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z}) == 0 &&
           orient2d({a.z, a.x}, {b.z, b.x}, {c.z, c.x}) == 0;
}

}  // namespace geolab
