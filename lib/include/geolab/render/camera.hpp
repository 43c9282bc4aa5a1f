#pragma once
//! \file render/camera.hpp
//! An orbit camera: it looks at `target` from `distance` away, turned by `yaw_deg` about the world up axis and
//! raised by `pitch_deg` above the horizon; perspective projection. Also the pick ray through a pixel.
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "geolab/field.hpp"

namespace geolab::render {

//! A ray origin + t · direction, t ≥ 0, with |direction| = 1.
struct Ray {
    glm::vec3 origin{0.0f}, direction{0.0f, 0.0f, -1.0f};
};

//! Orbit camera. With yaw = pitch = 0 it looks from the front: from +z towards −z when up = +y, from −y
//! towards +y when up = +z. Positive yaw moves the eye to the right (counter-clockwise about up seen from above).
struct Camera {
    glm::vec3 target{0.0f};
    float distance = 5.0f;
    float yaw_deg = 30.0f;
    float pitch_deg = 20.0f;
    float fov_deg = 35.0f;           //!< field of view across the shorter image side
    glm::vec3 up{0.0f, 1.0f, 0.0f};  //!< the world up axis, e.g. (0,1,0) or (0,0,1)

    //! A camera that looks at the centre of `box` from (yaw, pitch) and is just far enough for all eight
    //! corners of the box to be in view (8% margin), at any aspect ratio.
    static Camera framing(const Box& box, float yaw_deg = 30.0f, float pitch_deg = 20.0f,
                          glm::vec3 up = {0.0f, 1.0f, 0.0f});

    //! The eye position in world space.
    glm::vec3 eye() const;
    //! World → eye matrix.
    glm::mat4 view() const;
    //! Eye → clip matrix for width / height = aspect. Near and far planes follow the distance
    //! (0.01 · distance and 100 · distance).
    glm::mat4 proj(float aspect) const;
    //! The ray from the eye through the point (x, y) of a width × height image, in pixels, (0, 0) = top-left
    //! corner (window / mouse coordinates; pixel centres are at +0.5).
    Ray ray(double x, double y, int width, int height) const;
    //! Where the world point p appears in a width × height image: (x, y) in pixels as ray() takes them (the
    //! inverse of ray) and z, the depth of p along the viewing direction (> 0 in front of the eye; x and y
    //! are meaningless when z ≤ 0).
    glm::dvec3 pixel(const glm::dvec3& p, int width, int height) const;

    //! What a mouse drag of (dx, dy) pixels does to the camera: orbit turns the eye about the target (0.4° a
    //! pixel; the pitch stays within ±89°); pan moves the target with the cursor in a width × height view.
    void orbit(double dx, double dy);
    void pan(double dx, double dy, int width, int height);
};

}  // namespace geolab::render
