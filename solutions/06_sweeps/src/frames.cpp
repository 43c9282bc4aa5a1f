// Task 5: Frenet frames and rotation-minimizing frames (handout §6).
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/sweeps.hpp"

namespace geolab::sweeps {

namespace {
// BEGIN SOLUTION
// STUB: // Helper functions of your own can go here.
void check_path(const Path& path, const char* fn) {
    if (path.points.size() < 2)
        throw std::invalid_argument(std::string(fn) + ": the path has " + std::to_string(path.points.size()) +
                                    " points (at least 2)");
    if (path.points.size() != path.tangents.size())
        throw std::invalid_argument(std::string(fn) + ": " + std::to_string(path.points.size()) + " points but " +
                                    std::to_string(path.tangents.size()) + " tangents");
}
// END SOLUTION
}  // namespace

std::vector<Frame> frenet_frames(const Path& path) {
    // BEGIN SOLUTION
    check_path(path, "frenet_frames");
    const std::size_t n = path.points.size();
    const auto& T = path.tangents;
    std::vector<Frame> out(n);
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t prev = path.closed ? (i + n - 1) % n : (i == 0 ? 0 : i - 1);
        const std::size_t next = path.closed ? (i + 1) % n : (i + 1 == n ? i : i + 1);
        const glm::dvec3 k = T[next] - T[prev];
        const glm::dvec3 kp = k - glm::dot(k, T[i]) * T[i];
        out[i].T = T[i];
        if (glm::length(kp) <= 1e-9) {
            out[i].N = out[i].B = glm::dvec3(0.0);
        } else {
            out[i].N = glm::normalize(kp);
            out[i].B = glm::cross(T[i], out[i].N);
        }
    }
    return out;
    // END SOLUTION
}

RmfResult rotation_minimizing_frames(const Path& path, const glm::dvec3& initial_normal) {
    // BEGIN SOLUTION
    check_path(path, "rotation_minimizing_frames");
    const std::size_t n = path.points.size();
    const auto& X = path.points;
    const auto& T = path.tangents;
    const glm::dvec3 r0 = initial_normal - glm::dot(initial_normal, T[0]) * T[0];
    if (!(glm::length(r0) > 1e-9 * glm::length(initial_normal)))
        throw std::invalid_argument("rotation_minimizing_frames: the initial normal is parallel to the first tangent");
    // One double-reflection step from (x, t, r) to (x1, t1).
    auto step = [&](std::size_t i, const glm::dvec3& x, const glm::dvec3& t, const glm::dvec3& r, const glm::dvec3& x1,
                    const glm::dvec3& t1) {
        const glm::dvec3 v1 = x1 - x;
        const double c1 = glm::dot(v1, v1);
        if (c1 == 0)
            throw std::invalid_argument("rotation_minimizing_frames: points " + std::to_string(i) + " and " +
                                        std::to_string((i + 1) % n) + " are equal");
        const glm::dvec3 rL = r - (2 / c1) * glm::dot(v1, r) * v1;
        const glm::dvec3 tL = t - (2 / c1) * glm::dot(v1, t) * v1;
        const glm::dvec3 v2 = t1 - tL;
        const double c2 = glm::dot(v2, v2);
        return c2 > 0 ? rL - (2 / c2) * glm::dot(v2, rL) * v2 : rL;  // v₂ = 0: no second reflection
    };
    RmfResult res;
    res.frames.resize(n);
    glm::dvec3 r = glm::normalize(r0);
    for (std::size_t i = 0; i < n; ++i) {
        if (i > 0) {
            r = step(i - 1, X[i - 1], T[i - 1], r, X[i], T[i]);
            r = glm::normalize(r - glm::dot(r, T[i]) * T[i]);  // keep it exactly in the normal plane
        }
        res.frames[i] = {T[i], r, glm::cross(T[i], r)};
    }
    if (path.closed) {
        // Carried once around (the step back to sample 0), the normal comes back turned by the mismatch about T₀.
        const glm::dvec3 back = step(n - 1, X[n - 1], T[n - 1], r, X[0], T[0]);
        res.mismatch = std::atan2(glm::dot(back, res.frames[0].B), glm::dot(back, res.frames[0].N));
        double L = glm::length(X[0] - X[n - 1]);  // the loop's length
        for (std::size_t i = 1; i < n; ++i) L += glm::length(X[i] - X[i - 1]);
        double s = 0;  // the length from sample 0 to sample i
        for (std::size_t i = 1; i < n; ++i) {
            s += glm::length(X[i] - X[i - 1]);
            Frame& f = res.frames[i];
            const double t = -res.mismatch * s / L;  // N turned by t about T (N ⟂ T, B = T × N)
            f.N = std::cos(t) * f.N + std::sin(t) * f.B;
            f.B = glm::cross(f.T, f.N);
        }
    }
    return res;
    // END SOLUTION
}

}  // namespace geolab::sweeps
