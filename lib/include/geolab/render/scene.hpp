#pragma once
//! \file render/scene.hpp
//! What to draw, described on the CPU: meshes, line segments and points with colours, plus a flat overlay of
//! rectangles in image pixels (widgets, text) drawn over them. A Scene is plain data (copyable, no GL); the back
//! ends (render_image, Viewer) upload it. Polygons are triangulated as fans around
//! their first vertex, so non-convex faces may be drawn wrongly; the wireframe shows the polygon edges only.
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "geolab/field.hpp"
#include "geolab/soup.hpp"

namespace geolab::render {

//! How a mesh looks.
struct MeshStyle {
    glm::vec3 color{0.80f, 0.80f, 0.85f};  //!< used when no per-vertex / per-face colours are given
    bool smooth = true;                    //!< smooth (vertex normals) or flat (face normals) shading
    bool wireframe = false;                //!< draw the polygon edges on top of the faces
    glm::vec3 wire_color{0.1f, 0.1f, 0.1f};
    float wire_width = 1.5f;  //!< in output pixels
    float opacity = 1.0f;     //!< < 1: blended after the opaque geometry (exact only for convex meshes)
};

//! A scene: meshes, lines and points, plus the background colour. Sizes (widths, point sizes) are in output
//! pixels, so a figure looks the same with or without anti-aliasing.
class Scene {
public:
    //! Triangles ready to upload: three entries of each vector per triangle (not indexed), in float.
    struct Mesh {
        std::vector<glm::vec3> position, normal, color;
        std::vector<glm::vec3> wire;  //!< endpoints of the polygon edges, pairs (empty without wireframe)
        MeshStyle style;
    };
    //! Line segments: endpoint pairs (a0, b0, a1, b1, ...) with one colour per endpoint.
    struct Lines {
        std::vector<glm::vec3> position, color;
        float width = 2.0f;
    };
    //! Points drawn as round discs of `size` pixels.
    struct Points {
        std::vector<glm::vec3> position, color;
        float size = 8.0f;
    };

    //! A flat rectangle over the 3D picture, in output pixels with (0, 0) the top-left corner (mouse coordinates):
    //! x in [lo.x, hi.x], y in [lo.y, hi.y]. Blended with its alpha; later rectangles cover earlier ones.
    struct Rect {
        glm::vec2 lo{0.0f}, hi{0.0f};
        glm::vec4 color{0.0f, 0.0f, 0.0f, 1.0f};
    };

    glm::vec3 background{1.0f, 1.0f, 1.0f};  //!< clear colour (white by default, for print)

    //! Adds a mesh in one colour (style.color). \throw std::invalid_argument as check_soup does.
    void add_mesh(const PolygonSoup& soup, const MeshStyle& style = {});
    //! Adds a mesh with one colour per vertex, interpolated over faces. \pre vertex_colors.size() == n_vertices.
    //! \throw std::invalid_argument on a size mismatch or a bad soup.
    void add_mesh_vertex_colors(const PolygonSoup& soup, const std::vector<glm::vec3>& vertex_colors,
                                const MeshStyle& style = {});
    //! Adds a mesh with one colour per face. \pre face_colors.size() == soup.n_faces().
    //! \throw std::invalid_argument on a size mismatch or a bad soup.
    void add_mesh_face_colors(const PolygonSoup& soup, const std::vector<glm::vec3>& face_colors,
                              const MeshStyle& style = {});
    //! Adds segments given as endpoint pairs (a0, b0, a1, b1, ...) in one colour. Width in pixels.
    //! \throw std::invalid_argument if the number of endpoints is odd.
    void add_lines(const std::vector<glm::vec3>& endpoints, glm::vec3 color, float width = 2.0f);
    //! Adds segments with one colour per segment. \pre segment_colors.size() == endpoints.size() / 2.
    void add_lines(const std::vector<glm::vec3>& endpoints, const std::vector<glm::vec3>& segment_colors,
                   float width = 2.0f);
    //! Adds the polyline p0 p1 ... (closed: also p_last p0), e.g. a curve or a control polygon.
    void add_polyline(const std::vector<glm::vec3>& points, glm::vec3 color, float width = 2.0f, bool closed = false);
    //! Adds points drawn as discs of `size` pixels in one colour.
    void add_points(const std::vector<glm::vec3>& points, glm::vec3 color, float size = 8.0f);
    //! Adds points with one colour each. \pre colors.size() == points.size().
    void add_points(const std::vector<glm::vec3>& points, const std::vector<glm::vec3>& colors, float size = 8.0f);

    //! Adds an overlay rectangle (see Rect). Empty or inverted rectangles draw nothing.
    void add_rect(glm::vec2 lo, glm::vec2 hi, glm::vec4 color);

    //! The box around the meshes, lines and points (the overlay has no place in space; a unit box [-1,1]³ when
    //! there are none).
    Box bounds() const;
    //! True when nothing has been added (the overlay included).
    bool empty() const { return meshes_.empty() && lines_.empty() && points_.empty() && overlay_.empty(); }
    //! Removes all meshes, lines, points and overlay rectangles (keeps the background).
    void clear();

    const std::vector<Mesh>& meshes() const { return meshes_; }
    const std::vector<Lines>& lines() const { return lines_; }
    const std::vector<Points>& points() const { return points_; }
    const std::vector<Rect>& overlay() const { return overlay_; }

private:
    enum class ColorMode { Uniform, PerVertex, PerFace };
    void add_soup(const PolygonSoup& soup, ColorMode mode, const std::vector<glm::vec3>& colors,
                  const MeshStyle& style);
    std::vector<Mesh> meshes_;
    std::vector<Lines> lines_;
    std::vector<Points> points_;
    std::vector<Rect> overlay_;
};

}  // namespace geolab::render
