// Task 2: transforms (handout §4).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {

glm::dmat4 transform_quadric(const glm::dmat4& Q, const glm::dmat4& M) {
    // BEGIN SOLUTION
    if (M[0][3] != 0.0 || M[1][3] != 0.0 || M[2][3] != 0.0 || M[3][3] != 1.0)
        throw std::invalid_argument("transform_quadric: M is not affine (its last row is not 0 0 0 1)");
    const glm::dmat3 L(M);
    double norm = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) norm = std::max(norm, std::abs(L[i][j]));
    const double det = glm::determinant(L);
    if (!(std::abs(det) > 1e-12 * norm * norm * norm))
        throw std::invalid_argument("transform_quadric: the linear part of M is singular (det " + std::to_string(det) +
                                    ")");
    // M⁻¹ of an affine map: (L⁻¹, −L⁻¹ t)
    const glm::dmat3 Li = glm::inverse(L);
    glm::dmat4 Mi(Li);
    Mi[3] = glm::dvec4(-(Li * glm::dvec3(M[3])), 1.0);
    glm::dmat4 R = glm::transpose(Mi) * Q * Mi;
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) R[i][j] = R[j][i] = 0.5 * (R[i][j] + R[j][i]);
    return R;
    // END SOLUTION
}

}  // namespace geolab::quadrics
