// Given code of lab 03 (read it, do not write it): the types' names and canonical forms, the eigen-decomposition of a
// symmetric matrix, the camera's rays.
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {

SymmetricEigen symmetric_eigen(const glm::dmat4& S, int n) {
    if (n != 3 && n != 4) throw std::invalid_argument("symmetric_eigen: n must be 3 or 4");
    double m[4][4] = {}, v[4][4] = {};  // m: the matrix being diagonalized; v: the product of the rotations
    for (int i = 0; i < n; ++i) {
        v[i][i] = 1;
        for (int j = 0; j < n; ++j) {
            m[i][j] = 0.5 * S[i][j] + 0.5 * S[j][i];
            if (!std::isfinite(m[i][j])) throw std::invalid_argument("symmetric_eigen: an entry is not finite");
        }
    }
    // cyclic Jacobi: each rotation in the (p, q) plane zeroes m[p][q]; the off-diagonal mass falls quadratically
    for (int sweep = 0; sweep < 60; ++sweep) {
        double off = 0, diag = 0;
        for (int i = 0; i < n; ++i) {
            diag += m[i][i] * m[i][i];
            for (int j = i + 1; j < n; ++j) off += m[i][j] * m[i][j];
        }
        if (off == 0 || off <= 1e-34 * diag) break;
        for (int p = 0; p < n; ++p)
            for (int q = p + 1; q < n; ++q) {
                if (m[p][q] == 0) continue;
                const double theta = (m[q][q] - m[p][p]) / (2 * m[p][q]);
                const double t = (theta >= 0 ? 1 : -1) / (std::abs(theta) + std::sqrt(theta * theta + 1));
                const double c = 1 / std::sqrt(t * t + 1), s = t * c;
                for (int k = 0; k < n; ++k) {  // columns p, q of m and of v
                    const double kp = m[k][p], kq = m[k][q];
                    m[k][p] = c * kp - s * kq;
                    m[k][q] = s * kp + c * kq;
                    const double vp = v[k][p], vq = v[k][q];
                    v[k][p] = c * vp - s * vq;
                    v[k][q] = s * vp + c * vq;
                }
                for (int k = 0; k < n; ++k) {  // rows p, q of m
                    const double pk = m[p][k], qk = m[q][k];
                    m[p][k] = c * pk - s * qk;
                    m[q][k] = s * pk + c * qk;
                }
            }
    }
    SymmetricEigen e;
    for (int i = 0; i < n; ++i) {
        e.values[i] = m[i][i];
        for (int k = 0; k < n; ++k) e.vectors[i][k] = v[k][i];
    }
    return e;
}

std::string type_name(QuadricType t) {
    switch (t) {
        case QuadricType::real_ellipsoid: return "real ellipsoid";
        case QuadricType::imaginary_ellipsoid: return "imaginary ellipsoid";
        case QuadricType::hyperboloid_one_sheet: return "hyperboloid of one sheet";
        case QuadricType::hyperboloid_two_sheets: return "hyperboloid of two sheets";
        case QuadricType::real_cone: return "real cone";
        case QuadricType::imaginary_cone: return "imaginary cone";
        case QuadricType::elliptic_paraboloid: return "elliptic paraboloid";
        case QuadricType::hyperbolic_paraboloid: return "hyperbolic paraboloid";
        case QuadricType::real_elliptic_cylinder: return "real elliptic cylinder";
        case QuadricType::imaginary_elliptic_cylinder: return "imaginary elliptic cylinder";
        case QuadricType::hyperbolic_cylinder: return "hyperbolic cylinder";
        case QuadricType::parabolic_cylinder: return "parabolic cylinder";
        case QuadricType::real_intersecting_planes: return "real intersecting planes";
        case QuadricType::imaginary_intersecting_planes: return "imaginary intersecting planes";
        case QuadricType::real_parallel_planes: return "real parallel planes";
        case QuadricType::imaginary_parallel_planes: return "imaginary parallel planes";
        case QuadricType::coincident_planes: return "coincident planes";
    }
    return "unknown type " + std::to_string(static_cast<int>(t));
}

std::string canonical_form(QuadricType t) {
    switch (t) {
        case QuadricType::real_ellipsoid: return "x²/a² + y²/b² + z²/c² = 1";
        case QuadricType::imaginary_ellipsoid: return "x²/a² + y²/b² + z²/c² = −1";
        case QuadricType::hyperboloid_one_sheet: return "x²/a² + y²/b² − z²/c² = 1";
        case QuadricType::hyperboloid_two_sheets: return "x²/a² + y²/b² − z²/c² = −1";
        case QuadricType::real_cone: return "x²/a² + y²/b² − z²/c² = 0";
        case QuadricType::imaginary_cone: return "x²/a² + y²/b² + z²/c² = 0";
        case QuadricType::elliptic_paraboloid: return "x²/a² + y²/b² − z = 0";
        case QuadricType::hyperbolic_paraboloid: return "x²/a² − y²/b² − z = 0";
        case QuadricType::real_elliptic_cylinder: return "x²/a² + y²/b² = 1";
        case QuadricType::imaginary_elliptic_cylinder: return "x²/a² + y²/b² = −1";
        case QuadricType::hyperbolic_cylinder: return "x²/a² − y²/b² = 1";
        case QuadricType::parabolic_cylinder: return "x² − 2rz = 0";
        case QuadricType::real_intersecting_planes: return "x²/a² − y²/b² = 0";
        case QuadricType::imaginary_intersecting_planes: return "x²/a² + y²/b² = 0";
        case QuadricType::real_parallel_planes: return "x² = a²";
        case QuadricType::imaginary_parallel_planes: return "x² = −a²";
        case QuadricType::coincident_planes: return "x² = 0";
    }
    return "?";
}

Ray PinholeCamera::ray(int x, int y, int width, int height) const {
    const glm::dvec3 forward = glm::normalize(target - eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, up));
    const glm::dvec3 upv = glm::cross(right, forward);
    const double h = std::tan(fov_deg * std::numbers::pi / 360.0);
    const double aspect = double(width) / double(height);
    const double px = (2.0 * (x + 0.5) / width - 1.0) * h * aspect;
    const double py = (1.0 - 2.0 * (y + 0.5) / height) * h;
    return Ray{eye, glm::normalize(forward + px * right + py * upv)};
}

}  // namespace geolab::quadrics
