// Task 1: the matrix form (handout §3).
#include <cmath>
#include <stdexcept>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {

glm::dmat4 to_matrix(const Coefficients& k) {
    // BEGIN SOLUTION
    glm::dmat4 Q(0.0);  // Q[col][row]; symmetric, so the order does not matter
    Q[0][0] = k.a;
    Q[1][1] = k.b;
    Q[2][2] = k.c;
    Q[3][3] = k.d;
    Q[1][2] = Q[2][1] = k.f;  // 2f yz
    Q[0][2] = Q[2][0] = k.g;  // 2g zx
    Q[0][1] = Q[1][0] = k.h;  // 2h xy
    Q[0][3] = Q[3][0] = k.p;  // 2p x
    Q[1][3] = Q[3][1] = k.q;  // 2q y
    Q[2][3] = Q[3][2] = k.r;  // 2r z
    return Q;
    // END SOLUTION
}

Coefficients to_coefficients(const glm::dmat4& Q) {
    // BEGIN SOLUTION
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (!std::isfinite(Q[i][j]))
                throw std::invalid_argument("to_coefficients: entry Q[" + std::to_string(i) + "][" +
                                            std::to_string(j) + "] is not finite");
    auto sym = [&](int i, int j) { return 0.5 * (Q[i][j] + Q[j][i]); };
    Coefficients k;
    k.a = Q[0][0];
    k.b = Q[1][1];
    k.c = Q[2][2];
    k.d = Q[3][3];
    k.f = sym(1, 2);
    k.g = sym(0, 2);
    k.h = sym(0, 1);
    k.p = sym(0, 3);
    k.q = sym(1, 3);
    k.r = sym(2, 3);
    return k;
    // END SOLUTION
}

double evaluate(const glm::dmat4& Q, const glm::dvec3& x) {
    // BEGIN SOLUTION
    const glm::dvec4 X(x, 1.0);
    return glm::dot(X, Q * X);
    // END SOLUTION
}

glm::dvec3 gradient(const glm::dmat4& Q, const glm::dvec3& x) {
    // BEGIN SOLUTION
    const glm::dvec4 X(x, 1.0);
    return 2.0 * glm::dvec3(Q * X);
    // END SOLUTION
}

}  // namespace geolab::quadrics
