#include "geolab/render/camera.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

namespace geolab::render {
namespace {

// An orthonormal frame (right, up, front) for the world up axis; yaw = pitch = 0 looks along −front.
void frame(glm::vec3 up_axis, glm::vec3& right, glm::vec3& up, glm::vec3& front) {
    up = glm::length(up_axis) > 0.0f ? glm::normalize(up_axis) : glm::vec3(0, 1, 0);
    glm::vec3 ref = std::abs(up.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(0, -1, 0);
    front = glm::normalize(ref - glm::dot(ref, up) * up);
    right = glm::cross(up, front);
}

// Vertical field of view (radians) such that the shorter image side spans fov_deg.
float vertical_fov(float fov_deg, float aspect) {
    float half = glm::radians(fov_deg) * 0.5f;
    if (aspect < 1.0f) half = std::atan(std::tan(half) / aspect);
    return 2.0f * half;
}

}  // namespace

Camera Camera::framing(const Box& box, float yaw_deg, float pitch_deg, glm::vec3 up) {
    Camera c;
    c.target = glm::vec3(box.center());
    c.yaw_deg = yaw_deg;
    c.pitch_deg = pitch_deg;
    c.up = up;
    // every corner (x, y, z in the camera frame, z towards the eye) is in view when
    // distance ≥ z + max(|x|, |y|) / tan(fov / 2); 8% margin
    glm::vec3 right, u, front;
    frame(up, right, u, front);
    const glm::vec3 eye_dir = glm::normalize(c.eye() - c.target);
    const glm::vec3 cam_right = glm::normalize(glm::cross(u, eye_dir)), cam_up = glm::cross(eye_dir, cam_right);
    const float tan_half = std::tan(glm::radians(c.fov_deg) * 0.5f);
    float d = 0.0f;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 corner(i & 1 ? box.hi.x : box.lo.x, i & 2 ? box.hi.y : box.lo.y, i & 4 ? box.hi.z : box.lo.z);
        const glm::vec3 p = glm::vec3(corner) - c.target;
        const float x = glm::dot(p, cam_right), y = glm::dot(p, cam_up), z = glm::dot(p, eye_dir);
        d = std::max(d, z + std::max(std::abs(x), std::abs(y)) / tan_half);
    }
    c.distance = d > 0.0f ? 1.08f * d : 1.0f;  // a single point: any distance
    return c;
}

glm::vec3 Camera::eye() const {
    glm::vec3 right, u, front;
    frame(up, right, u, front);
    const float yaw = glm::radians(yaw_deg), pitch = glm::radians(pitch_deg);
    glm::vec3 dir = std::cos(pitch) * (std::sin(yaw) * right + std::cos(yaw) * front) + std::sin(pitch) * u;
    return target + distance * dir;
}

glm::mat4 Camera::view() const {
    glm::vec3 right, u, front;
    frame(up, right, u, front);
    return glm::lookAt(eye(), target, u);
}

glm::mat4 Camera::proj(float aspect) const {
    return glm::perspective(vertical_fov(fov_deg, aspect), aspect, 0.01f * distance, 100.0f * distance);
}

Ray Camera::ray(double x, double y, int width, int height) const {
    const float aspect = float(width) / float(height);
    // the pixel in normalized device coordinates, then through the inverse of proj · view
    const float nx = float(2.0 * x / width - 1.0), ny = float(1.0 - 2.0 * y / height);
    const glm::mat4 inv = glm::inverse(proj(aspect) * view());
    glm::vec4 near = inv * glm::vec4(nx, ny, -1.0f, 1.0f), far = inv * glm::vec4(nx, ny, 1.0f, 1.0f);
    glm::vec3 a = glm::vec3(near) / near.w, b = glm::vec3(far) / far.w;
    return Ray{eye(), glm::normalize(b - a)};
}

glm::dvec3 Camera::pixel(const glm::dvec3& p, int width, int height) const {
    const float aspect = float(width) / float(height);
    const glm::dvec4 c = glm::dmat4(proj(aspect)) * glm::dmat4(view()) * glm::dvec4(p, 1.0);
    const glm::dvec3 eye_space = glm::dvec3(glm::dmat4(view()) * glm::dvec4(p, 1.0));
    const double w = c.w != 0.0 ? c.w : 1e-300;
    return {(c.x / w + 1.0) * 0.5 * width, (1.0 - c.y / w) * 0.5 * height, -eye_space.z};
}

void Camera::orbit(double dx, double dy) {
    yaw_deg -= 0.4f * float(dx);
    pitch_deg = std::clamp(pitch_deg + 0.4f * float(dy), -89.0f, 89.0f);
}

void Camera::pan(double dx, double dy, int width, int height) {
    // one pixel is this many world units at the target's depth
    const float unit =
        2.0f * distance * std::tan(0.5f * glm::radians(fov_deg)) / float(std::max(1, std::min(width, height)));
    const glm::mat4 v = view();
    const glm::vec3 right(v[0][0], v[1][0], v[2][0]), u(v[0][1], v[1][1], v[2][1]);
    target += unit * (-float(dx) * right + float(dy) * u);
}

}  // namespace geolab::render
