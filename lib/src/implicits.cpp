#include "geolab/implicits.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <limits>
#include <stdexcept>
#include <utility>

namespace geolab {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// sign with sign(0) = +1, so that gradients at medial planes pick one side instead of vanishing
double sign_of(double x) { return x < 0.0 ? -1.0 : 1.0; }

// a unit vector perpendicular to the unit vector a
glm::dvec3 any_perpendicular(const glm::dvec3& a) {
    glm::dvec3 e = std::abs(a.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    return glm::normalize(glm::cross(a, e));
}

void require(bool ok, const char* message) {
    if (!ok) throw std::invalid_argument(message);
}

class Sphere final : public ScalarField {
public:
    Sphere(glm::dvec3 c, double r) : c_(c), r_(r) {}
    double value(const glm::dvec3& p) const override { return glm::length(p - c_) - r_; }
    glm::dvec3 gradient(const glm::dvec3& p) const override {
        glm::dvec3 v = p - c_;
        double n = glm::length(v);
        return n > 0.0 ? v / n : glm::dvec3(0, 0, 1);
    }
    Box bounds() const override { return {c_ - r_, c_ + r_}; }
    double lipschitz() const override { return 1.0; }

private:
    glm::dvec3 c_;
    double r_;
};

class Torus final : public ScalarField {
public:
    Torus(glm::dvec3 c, double R, double r) : c_(c), R_(R), r_(r) {}
    double value(const glm::dvec3& p) const override {
        glm::dvec3 v = p - c_;
        return std::hypot(std::hypot(v.x, v.y) - R_, v.z) - r_;
    }
    glm::dvec3 gradient(const glm::dvec3& p) const override {
        // q = (ρ − R, z) in the meridian plane; ∇f = (q.x e_ρ + q.y e_z) / |q|
        glm::dvec3 v = p - c_;
        double rho = std::hypot(v.x, v.y);
        glm::dvec3 e_rho = rho > 0.0 ? glm::dvec3(v.x / rho, v.y / rho, 0.0) : glm::dvec3(1, 0, 0);
        double qx = rho - R_, qz = v.z, q = std::hypot(qx, qz);
        if (q == 0.0) return e_rho;
        return (qx * e_rho + glm::dvec3(0, 0, qz)) / q;
    }
    Box bounds() const override {
        glm::dvec3 h(R_ + r_, R_ + r_, r_);
        return {c_ - h, c_ + h};
    }
    double lipschitz() const override { return 1.0; }

private:
    glm::dvec3 c_;
    double R_, r_;
};

class RoundedBox final : public ScalarField {
public:
    RoundedBox(glm::dvec3 c, glm::dvec3 half, double rounding)
        : c_(c), half_(half), inner_(half - rounding), r_(rounding) {}
    double value(const glm::dvec3& p) const override {
        // q = |v| − b: outside part |max(q, 0)|, inside part max(q.x, q.y, q.z) (≤ 0)
        glm::dvec3 q = glm::abs(p - c_) - inner_;
        double inside = std::min(std::max({q.x, q.y, q.z}), 0.0);
        return glm::length(glm::max(q, 0.0)) + inside - r_;
    }
    glm::dvec3 gradient(const glm::dvec3& p) const override {
        glm::dvec3 v = p - c_;
        glm::dvec3 s(sign_of(v.x), sign_of(v.y), sign_of(v.z));
        glm::dvec3 q = glm::abs(v) - inner_;
        glm::dvec3 m = glm::max(q, 0.0);
        double n = glm::length(m);
        if (n > 0.0) return s * m / n;  // outside the inner box: towards the nearest point
        int i = (q.x >= q.y && q.x >= q.z) ? 0 : (q.y >= q.z ? 1 : 2);  // inside: the nearest face
        glm::dvec3 g(0.0);
        g[i] = s[i];
        return g;
    }
    Box bounds() const override { return {c_ - half_, c_ + half_}; }
    double lipschitz() const override { return 1.0; }

private:
    glm::dvec3 c_, half_, inner_;
    double r_;
};

class Cylinder final : public ScalarField {
public:
    Cylinder(glm::dvec3 c, glm::dvec3 axis, double r, double h) : c_(c), a_(glm::normalize(axis)), r_(r), h_(h) {}
    double value(const glm::dvec3& p) const override {
        auto [dr, dz, e_r, s] = local(p);
        (void)e_r;
        (void)s;
        return std::min(std::max(dr, dz), 0.0) + std::hypot(std::max(dr, 0.0), std::max(dz, 0.0));
    }
    glm::dvec3 gradient(const glm::dvec3& p) const override {
        auto [dr, dz, e_r, s] = local(p);
        glm::dvec3 e_z = s * a_;
        double mr = std::max(dr, 0.0), mz = std::max(dz, 0.0), n = std::hypot(mr, mz);
        if (n > 0.0) return (mr * e_r + mz * e_z) / n;
        return dr >= dz ? e_r : e_z;
    }
    Box bounds() const override {
        glm::dvec3 ext;
        for (int i = 0; i < 3; ++i) ext[i] = h_ * std::abs(a_[i]) + r_ * std::sqrt(std::max(0.0, 1.0 - a_[i] * a_[i]));
        return {c_ - ext, c_ + ext};
    }
    double lipschitz() const override { return 1.0; }

private:
    struct Local {
        double dr, dz;   // radial and axial excess over the cylinder
        glm::dvec3 e_r;  // radial unit direction
        double s;        // side of the mid-plane (±1)
    };
    Local local(const glm::dvec3& p) const {
        glm::dvec3 v = p - c_;
        double z = glm::dot(v, a_);
        glm::dvec3 radial = v - z * a_;
        double rho = glm::length(radial);
        glm::dvec3 e_r = rho > 0.0 ? radial / rho : any_perpendicular(a_);
        return {rho - r_, std::abs(z) - h_, e_r, sign_of(z)};
    }
    glm::dvec3 c_, a_;
    double r_, h_;
};

class Halfspace final : public ScalarField {
public:
    Halfspace(glm::dvec3 point, glm::dvec3 normal) : p0_(point), n_(glm::normalize(normal)) {}
    double value(const glm::dvec3& p) const override { return glm::dot(p - p0_, n_); }
    glm::dvec3 gradient(const glm::dvec3&) const override { return n_; }
    Box bounds() const override { return {glm::dvec3(-kInf), glm::dvec3(kInf)}; }
    double lipschitz() const override { return 1.0; }

private:
    glm::dvec3 p0_, n_;
};

Box box_union(const Box& a, const Box& b) { return {glm::min(a.lo, b.lo), glm::max(a.hi, b.hi)}; }

Box box_intersection(const Box& a, const Box& b) {
    Box r{glm::max(a.lo, b.lo), glm::min(a.hi, b.hi)};
    for (int i = 0; i < 3; ++i)
        if (r.lo[i] > r.hi[i]) r.lo[i] = r.hi[i] = 0.5 * (r.lo[i] + r.hi[i]);
    return r;
}

//! Which of min / max / max(a, −b) a Binary node computes.
enum class Op { unite, intersect, subtract };

class Binary final : public ScalarField {
public:
    Binary(Op op, FieldPtr a, FieldPtr b) : op_(op), a_(std::move(a)), b_(std::move(b)) {}
    double value(const glm::dvec3& p) const override {
        double a = a_->value(p), b = b_->value(p);
        switch (op_) {
            case Op::unite:
                return std::min(a, b);
            case Op::intersect:
                return std::max(a, b);
            case Op::subtract:
                return std::max(a, -b);
        }
        return a;
    }
    glm::dvec3 gradient(const glm::dvec3& p) const override {
        // the gradient of the child that attains the min / max (ties go to a)
        double a = a_->value(p), b = b_->value(p);
        switch (op_) {
            case Op::unite:
                return a <= b ? a_->gradient(p) : b_->gradient(p);
            case Op::intersect:
                return a >= b ? a_->gradient(p) : b_->gradient(p);
            case Op::subtract:
                return a >= -b ? a_->gradient(p) : -b_->gradient(p);
        }
        return a_->gradient(p);
    }
    Box bounds() const override {
        switch (op_) {
            case Op::unite:
                return box_union(a_->bounds(), b_->bounds());
            case Op::intersect:
                return box_intersection(a_->bounds(), b_->bounds());
            case Op::subtract:
                return a_->bounds();
        }
        return a_->bounds();
    }
    double lipschitz() const override { return combined_lipschitz(a_->lipschitz(), b_->lipschitz()); }
    bool sign_may_jump() const override { return a_->sign_may_jump() || b_->sign_may_jump(); }

    static double combined_lipschitz(double la, double lb) { return (la == 0.0 || lb == 0.0) ? 0.0 : std::max(la, lb); }

private:
    Op op_;
    FieldPtr a_, b_;
};

class SmoothUnion final : public ScalarField {
public:
    SmoothUnion(FieldPtr a, FieldPtr b, double k) : a_(std::move(a)), b_(std::move(b)), k_(k) {}
    double value(const glm::dvec3& p) const override {
        double a = a_->value(p), b = b_->value(p), h = blend(a, b);
        return b * (1.0 - h) + a * h - k_ * h * (1.0 - h);
    }
    glm::dvec3 gradient(const glm::dvec3& p) const override {
        double h = blend(a_->value(p), b_->value(p));
        if (h >= 1.0) return a_->gradient(p);
        if (h <= 0.0) return b_->gradient(p);
        return h * a_->gradient(p) + (1.0 - h) * b_->gradient(p);
    }
    Box bounds() const override {
        Box u = box_union(a_->bounds(), b_->bounds());
        return {u.lo - 0.25 * k_, u.hi + 0.25 * k_};  // smin ≥ min − k/4
    }
    double lipschitz() const override { return Binary::combined_lipschitz(a_->lipschitz(), b_->lipschitz()); }
    bool sign_may_jump() const override { return a_->sign_may_jump() || b_->sign_may_jump(); }

private:
    double blend(double a, double b) const { return std::clamp(0.5 + 0.5 * (b - a) / k_, 0.0, 1.0); }
    FieldPtr a_, b_;
    double k_;
};

class Translated final : public ScalarField {
public:
    Translated(FieldPtr f, glm::dvec3 t) : f_(std::move(f)), t_(t) {}
    double value(const glm::dvec3& p) const override { return f_->value(p - t_); }
    glm::dvec3 gradient(const glm::dvec3& p) const override { return f_->gradient(p - t_); }
    Box bounds() const override {
        Box b = f_->bounds();
        return {b.lo + t_, b.hi + t_};
    }
    double lipschitz() const override { return f_->lipschitz(); }
    bool sign_may_jump() const override { return f_->sign_may_jump(); }

private:
    FieldPtr f_;
    glm::dvec3 t_;
};

class Scaled final : public ScalarField {
public:
    Scaled(FieldPtr f, double s) : f_(std::move(f)), s_(s) {}
    double value(const glm::dvec3& p) const override { return s_ * f_->value(p / s_); }
    glm::dvec3 gradient(const glm::dvec3& p) const override { return f_->gradient(p / s_); }
    Box bounds() const override {
        Box b = f_->bounds();
        return {b.lo * s_, b.hi * s_};
    }
    double lipschitz() const override { return f_->lipschitz(); }
    bool sign_may_jump() const override { return f_->sign_may_jump(); }

private:
    FieldPtr f_;
    double s_;
};

void require_children(const FieldPtr& a, const FieldPtr& b, const char* function) {
    if (!a || !b) throw std::invalid_argument(std::string(function) + ": a child field is null");
}

// the registry: name → factory, in the order implicit_names() reports
const std::vector<std::pair<std::string, std::function<FieldPtr()>>>& registry() {
    static const std::vector<std::pair<std::string, std::function<FieldPtr()>>> table = {
        {"sphere",
         [] {
             return sphere({0, 0, 0}, 0.8);
         }},
        {"torus",
         [] {
             return torus({0, 0, 0}, 0.6, 0.25);
         }},
        {"box",
         [] {
             return box({0, 0, 0}, {0.7, 0.5, 0.35});
         }},
        {"cube",
         [] {
             return box({0, 0, 0}, glm::dvec3(0.6));
         }},
        {"rounded_box",
         [] {
             return box({0, 0, 0}, glm::dvec3(0.6), 0.15);
         }},
        {"cylinder",
         [] {
             return cylinder({0, 0, 0}, {0, 0, 1}, 0.5, 0.7);
         }},
        {"box_minus_sphere",
         [] {
             return csg_difference(box({0, 0, 0}, glm::dvec3(0.6)), sphere({0, 0, 0}, 0.75));
         }},
        {"csg",
         [] {
             FieldPtr body = csg_intersection(box({0, 0, 0}, glm::dvec3(0.6)), sphere({0, 0, 0}, 0.78));
             FieldPtr holes = csg_union(
                 csg_union(cylinder({0, 0, 0}, {1, 0, 0}, 0.35, 1.0), cylinder({0, 0, 0}, {0, 1, 0}, 0.35, 1.0)),
                 cylinder({0, 0, 0}, {0, 0, 1}, 0.35, 1.0));
             return csg_difference(body, holes);
         }},
        {"rounded_union",
         [] {
             return smooth_union(box({-0.2, 0, 0}, {0.45, 0.45, 0.3}), sphere({0.35, 0.1, 0.1}, 0.45), 0.2);
         }},
        {"blob",
         [] {
             return smooth_union(sphere({-0.35, 0, 0}, 0.45), sphere({0.35, 0, 0}, 0.45), 0.3);
         }},
    };
    return table;
}

}  // namespace

FieldPtr sphere(glm::dvec3 center, double radius) {
    require(radius > 0.0, "sphere: radius must be > 0");
    return std::make_shared<Sphere>(center, radius);
}

FieldPtr torus(glm::dvec3 center, double R, double r) {
    require(r > 0.0 && r < R, "torus: radii must satisfy 0 < r < R");
    return std::make_shared<Torus>(center, R, r);
}

FieldPtr box(glm::dvec3 center, glm::dvec3 half_extents, double rounding) {
    double smallest = std::min({half_extents.x, half_extents.y, half_extents.z});
    require(smallest > 0.0, "box: every half extent must be > 0");
    require(rounding >= 0.0 && rounding <= smallest, "box: rounding must lie in [0, smallest half extent]");
    return std::make_shared<RoundedBox>(center, half_extents, rounding);
}

FieldPtr cylinder(glm::dvec3 center, glm::dvec3 axis, double radius, double half_height) {
    require(radius > 0.0 && half_height > 0.0, "cylinder: radius and half_height must be > 0");
    require(glm::length(axis) > 0.0, "cylinder: axis must be non-zero");
    return std::make_shared<Cylinder>(center, axis, radius, half_height);
}

FieldPtr halfspace(glm::dvec3 point, glm::dvec3 normal) {
    require(glm::length(normal) > 0.0, "halfspace: normal must be non-zero");
    return std::make_shared<Halfspace>(point, normal);
}

FieldPtr csg_union(FieldPtr a, FieldPtr b) {
    require_children(a, b, "csg_union");
    return std::make_shared<Binary>(Op::unite, std::move(a), std::move(b));
}

FieldPtr csg_intersection(FieldPtr a, FieldPtr b) {
    require_children(a, b, "csg_intersection");
    return std::make_shared<Binary>(Op::intersect, std::move(a), std::move(b));
}

FieldPtr csg_difference(FieldPtr a, FieldPtr b) {
    require_children(a, b, "csg_difference");
    return std::make_shared<Binary>(Op::subtract, std::move(a), std::move(b));
}

FieldPtr smooth_union(FieldPtr a, FieldPtr b, double k) {
    require_children(a, b, "smooth_union");
    require(k > 0.0, "smooth_union: k must be > 0");
    return std::make_shared<SmoothUnion>(std::move(a), std::move(b), k);
}

FieldPtr translated(FieldPtr f, glm::dvec3 offset) {
    require(f != nullptr, "translated: field is null");
    return std::make_shared<Translated>(std::move(f), offset);
}

FieldPtr scaled(FieldPtr f, double s) {
    require(f != nullptr, "scaled: field is null");
    require(s > 0.0, "scaled: s must be > 0");
    return std::make_shared<Scaled>(std::move(f), s);
}

std::vector<std::string> implicit_names() {
    std::vector<std::string> names;
    for (const auto& [name, make] : registry()) names.push_back(name);
    return names;
}

FieldPtr named_implicit(const std::string& name) {
    for (const auto& [known, make] : registry())
        if (known == name) return make();
    std::string list;
    for (const auto& known : implicit_names()) list += (list.empty() ? "" : ", ") + known;
    throw std::invalid_argument("named_implicit: unknown implicit '" + name + "' (known: " + list + ")");
}

}  // namespace geolab
