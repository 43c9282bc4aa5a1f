#pragma once
//! \file render/pick.hpp
//! Picking for demos: which face or vertex of a soup a ray (from Viewer::on_pick) hits.
#include <cstddef>
#include <optional>

#include "geolab/render/camera.hpp"
#include "geolab/soup.hpp"

namespace geolab::render {

//! Where a ray hits a soup.
struct PickHit {
    std::size_t face = 0;    //!< the nearest face hit
    std::size_t vertex = 0;  //!< the vertex of that face nearest to the hit point
    glm::vec3 point{0.0f};   //!< the hit point
    float t = 0.0f;          //!< ray parameter of the hit
};

//! The nearest face the ray hits (both sides count; faces triangulated as fans), or nullopt.
std::optional<PickHit> pick(const PolygonSoup& soup, const Ray& ray);

}  // namespace geolab::render
