#pragma once
//! \file quadric.hpp
//! A plain quadric: a symmetric 4×4 matrix Q and its value XᵀQX at X = (x, y, z, 1). Lab 07 uses it as a CSG
//! primitive (inside where XᵀQX ≤ 0). Only the type and its evaluation live here: classification, transforms and
//! ray intersection are lab 03's tasks and stay there.
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace geolab {

//! The quadric surface XᵀQX = 0, Q symmetric (Q[col][row], glm's column-major order).
struct Quadric {
    glm::dmat4 Q{0.0};
    //! XᵀQX at X = (p, 1).
    double value(const glm::dvec3& p) const {
        const glm::dvec4 X(p, 1.0);
        const glm::dvec4 QX = Q * X;
        return X.x * QX.x + X.y * QX.y + X.z * QX.z + X.w * QX.w;
    }
};

}  // namespace geolab
