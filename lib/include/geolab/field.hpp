#pragma once
//! \file field.hpp
//! Signed scalar fields f: R³ → R, negative inside, with a gradient. Used by the implicit-surface labs
//! (blobby objects, CSG, dual contouring). Analytic fields give exact gradients; others fall back to central
//! differences.
#include <memory>

#include <glm/vec3.hpp>

namespace geolab {

//! An axis-aligned box [lo, hi].
struct Box {
    glm::dvec3 lo{0.0}, hi{0.0};
    glm::dvec3 center() const { return 0.5 * (lo + hi); }
    glm::dvec3 size() const { return hi - lo; }
    double diagonal() const;
};

//! A signed field: value(p) < 0 inside, > 0 outside, 0 on the surface (the tie rule f ≤ 0 means inside).
class ScalarField {
public:
    virtual ~ScalarField() = default;
    //! f(p).
    virtual double value(const glm::dvec3& p) const = 0;
    //! ∇f(p). Default: central differences with step h = 1e-6 · bounds().diagonal().
    virtual glm::dvec3 gradient(const glm::dvec3& p) const;
    //! A box that contains the whole surface {f = 0}.
    virtual Box bounds() const = 0;
    //! A Lipschitz constant L with |f(p) − f(q)| ≤ L |p − q| (1 for exact signed distances), used by
    //! conservative octree refinement. Return 0 if unknown.
    virtual double lipschitz() const { return 0.0; }
    //! True when the sign of f may jump where |f| > 0 (the winding-number sign of a mesh with holes flips on a
    //! surface spanning each hole). Then lipschitz() bounds the change of |f| only, and a test on |f| alone cannot
    //! promise that a cell holds no sign change.
    virtual bool sign_may_jump() const { return false; }
};

using FieldPtr = std::shared_ptr<const ScalarField>;

}  // namespace geolab
