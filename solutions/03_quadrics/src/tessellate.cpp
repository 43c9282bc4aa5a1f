// Task 6: tessellation (handout §8).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {
namespace {
// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.

// The (η, ω) grid's connectivity: vertex 0 the south pole, 1 the north pole, ring i (1..n_eta−1) vertex j at
// 2 + (i − 1)·n_omega + j; counter-clockwise seen from outside when ω turns counter-clockwise about +z.
void grid_faces(PolygonSoup& soup, int n_eta, int n_omega) {
    auto v = [&](int i, int j) { return std::uint32_t(2 + (i - 1) * n_omega + (j % n_omega)); };
    for (int j = 0; j < n_omega; ++j) soup.add_face({0u, v(1, j + 1), v(1, j)});
    for (int i = 1; i + 1 < n_eta; ++i)
        for (int j = 0; j < n_omega; ++j) {
            soup.add_face({v(i, j), v(i, j + 1), v(i + 1, j + 1)});
            soup.add_face({v(i, j), v(i + 1, j + 1), v(i + 1, j)});
        }
    for (int j = 0; j < n_omega; ++j) soup.add_face({v(n_eta - 1, j), v(n_eta - 1, j + 1), 1u});
}

void check_grid(int n_eta, int n_omega, const char* who) {
    if (n_eta < 2 || n_omega < 3)
        throw std::invalid_argument(std::string(who) + ": n_eta must be >= 2 and n_omega >= 3");
}
// END SOLUTION
}  // namespace

PolygonSoup tessellate_superquadric(const Superquadric& s, int n_eta, int n_omega) {
    // BEGIN SOLUTION
    check_grid(n_eta, n_omega, "tessellate_superquadric");
    (void)inside_outside(s, glm::dvec3(0.0));  // validates the radii and exponents
    PolygonSoup soup;
    soup.positions.push_back({0, 0, -s.radii.z});
    soup.positions.push_back({0, 0, s.radii.z});
    const double pi = std::numbers::pi;
    for (int i = 1; i < n_eta; ++i)
        for (int j = 0; j < n_omega; ++j)
            soup.positions.push_back(superquadric_point(s, -pi / 2 + pi * i / n_eta, -pi + 2 * pi * j / n_omega));
    grid_faces(soup, n_eta, n_omega);
    return soup;
    // END SOLUTION
}

PolygonSoup tessellate_ellipsoid(const glm::dmat4& Q, int n_eta, int n_omega) {
    // BEGIN SOLUTION
    check_grid(n_eta, n_omega, "tessellate_ellipsoid");
    const glm::dmat3 A(Q);  // the upper-left 3×3 (Q is symmetric)
    const glm::dvec3 b{Q[3][0], Q[3][1], Q[3][2]};
    const SymmetricEigen e = symmetric_eigen(Q, 3);
    const glm::dvec3 ev{e.values[0], e.values[1], e.values[2]};
    // the eigenvectors as columns: a rotation (det +1), so the frame is right-handed and the mesh stays outward
    const glm::dmat3 V{glm::dvec3(e.vectors[0]), glm::dvec3(e.vectors[1]), glm::dvec3(e.vectors[2])};
    const double big = std::max({std::abs(ev.x), std::abs(ev.y), std::abs(ev.z)});
    for (int i = 0; i < 3; ++i)
        if (!(std::abs(ev[i]) > 1e-9 * big))
            throw std::invalid_argument("tessellate_ellipsoid: Q is not an ellipsoid (A is singular)");
    // centre c = −A⁻¹ b; there (x − c)ᵀ A (x − c) = −k with k the value of XᵀQX at c
    const glm::dvec3 c = -(glm::inverse(A) * b);
    const double k = glm::dot(c, A * c) + 2 * glm::dot(b, c) + Q[3][3];
    glm::dvec3 radius;
    for (int i = 0; i < 3; ++i) {
        const double r2 = -k / ev[i];
        if (!(r2 > 0)) throw std::invalid_argument("tessellate_ellipsoid: Q is not a real ellipsoid");
        radius[i] = std::sqrt(r2);
    }
    PolygonSoup soup;
    const double pi = std::numbers::pi;
    auto place = [&](double eta, double omega) {
        const glm::dvec3 u{std::cos(eta) * std::cos(omega), std::cos(eta) * std::sin(omega), std::sin(eta)};
        return c + V * (radius * u);
    };
    soup.positions.push_back(c - radius.z * V[2]);
    soup.positions.push_back(c + radius.z * V[2]);
    for (int i = 1; i < n_eta; ++i)
        for (int j = 0; j < n_omega; ++j) soup.positions.push_back(place(-pi / 2 + pi * i / n_eta, -pi + 2 * pi * j / n_omega));
    grid_faces(soup, n_eta, n_omega);
    return soup;
    // END SOLUTION
}

}  // namespace geolab::quadrics
