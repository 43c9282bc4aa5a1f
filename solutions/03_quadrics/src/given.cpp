// Given code of lab 03 (read it, do not write it): the types' names and canonical forms, the camera's rays.
#include <cmath>
#include <numbers>

#include "geolab/quadrics.hpp"

namespace geolab::quadrics {

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
