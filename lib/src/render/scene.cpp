#include "geolab/render/scene.hpp"

#include <algorithm>
#include <glm/geometric.hpp>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

namespace geolab::render {
namespace {

// Newell's normal of face f: its direction is the polygon's normal, its length twice its area.
glm::dvec3 newell_normal(const PolygonSoup& soup, std::size_t f) {
    auto vs = soup.face(f);
    glm::dvec3 n(0.0);
    for (std::size_t i = 0; i < vs.size(); ++i) {
        const glm::dvec3& a = soup.positions[vs[i]];
        const glm::dvec3& b = soup.positions[vs[(i + 1) % vs.size()]];
        n += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    return n;
}

glm::vec3 unit_or_zero(glm::dvec3 n) {
    double len = glm::length(n);
    return len > 0.0 ? glm::vec3(n / len) : glm::vec3(0.0f);
}

void check_count(const char* function, const char* what, std::size_t got, std::size_t expected) {
    if (got != expected)
        throw std::invalid_argument(std::string("geolab::render::Scene::") + function + ": " + std::to_string(got) +
                                    " " + what + " given, expected " + std::to_string(expected));
}

}  // namespace

void Scene::add_soup(const PolygonSoup& soup, ColorMode mode, const std::vector<glm::vec3>& colors,
                     const MeshStyle& style) {
    check_soup(soup);
    Mesh m;
    m.style = style;
    // smooth: area-weighted vertex normals (sum of Newell normals of the incident faces)
    std::vector<glm::dvec3> face_normal(soup.n_faces());
    for (std::size_t f = 0; f < soup.n_faces(); ++f) face_normal[f] = newell_normal(soup, f);
    std::vector<glm::vec3> vertex_normal;
    if (style.smooth) {
        std::vector<glm::dvec3> sum(soup.n_vertices(), glm::dvec3(0.0));
        for (std::size_t f = 0; f < soup.n_faces(); ++f)
            for (std::uint32_t v : soup.face(f)) sum[v] += face_normal[f];
        vertex_normal.reserve(sum.size());
        for (const glm::dvec3& n : sum) vertex_normal.push_back(unit_or_zero(n));
    }
    // triangles: fans (v0, v_i, v_i+1)
    const std::size_t n_tris = soup.indices.size() - 2 * soup.n_faces();
    m.position.reserve(3 * n_tris);
    m.normal.reserve(3 * n_tris);
    m.color.reserve(3 * n_tris);
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        auto vs = soup.face(f);
        const glm::vec3 fn = unit_or_zero(face_normal[f]);
        for (std::size_t i = 1; i + 1 < vs.size(); ++i) {
            for (std::uint32_t v : {vs[0], vs[i], vs[i + 1]}) {
                m.position.emplace_back(soup.positions[v]);
                m.normal.push_back(style.smooth ? vertex_normal[v] : fn);
                m.color.push_back(mode == ColorMode::Uniform     ? style.color
                                  : mode == ColorMode::PerVertex ? colors[v]
                                                                 : colors[f]);
            }
        }
    }
    // wireframe: every polygon edge once
    if (style.wireframe) {
        std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
        for (std::size_t f = 0; f < soup.n_faces(); ++f) {
            auto vs = soup.face(f);
            for (std::size_t i = 0; i < vs.size(); ++i) {
                std::uint32_t a = vs[i], b = vs[(i + 1) % vs.size()];
                if (!seen.insert(std::minmax(a, b)).second) continue;
                m.wire.emplace_back(soup.positions[a]);
                m.wire.emplace_back(soup.positions[b]);
            }
        }
    }
    meshes_.push_back(std::move(m));
}

void Scene::add_mesh(const PolygonSoup& soup, const MeshStyle& style) { add_soup(soup, ColorMode::Uniform, {}, style); }

void Scene::add_mesh_vertex_colors(const PolygonSoup& soup, const std::vector<glm::vec3>& vertex_colors,
                                   const MeshStyle& style) {
    check_count("add_mesh_vertex_colors", "vertex colours", vertex_colors.size(), soup.n_vertices());
    add_soup(soup, ColorMode::PerVertex, vertex_colors, style);
}

void Scene::add_mesh_face_colors(const PolygonSoup& soup, const std::vector<glm::vec3>& face_colors,
                                 const MeshStyle& style) {
    check_count("add_mesh_face_colors", "face colours", face_colors.size(), soup.n_faces());
    add_soup(soup, ColorMode::PerFace, face_colors, style);
}

void Scene::add_lines(const std::vector<glm::vec3>& endpoints, glm::vec3 color, float width) {
    add_lines(endpoints, std::vector<glm::vec3>(endpoints.size() / 2, color), width);
}

void Scene::add_lines(const std::vector<glm::vec3>& endpoints, const std::vector<glm::vec3>& segment_colors,
                      float width) {
    if (endpoints.size() % 2 != 0)
        throw std::invalid_argument("geolab::render::Scene::add_lines: " + std::to_string(endpoints.size()) +
                                    " endpoints given, expected pairs (an even number)");
    check_count("add_lines", "segment colours", segment_colors.size(), endpoints.size() / 2);
    Lines l;
    l.position = endpoints;
    l.color.reserve(endpoints.size());
    for (glm::vec3 c : segment_colors) l.color.insert(l.color.end(), {c, c});
    l.width = width;
    lines_.push_back(std::move(l));
}

void Scene::add_polyline(const std::vector<glm::vec3>& points, glm::vec3 color, float width, bool closed) {
    std::vector<glm::vec3> ends;
    for (std::size_t i = 0; i + 1 < points.size(); ++i) ends.insert(ends.end(), {points[i], points[i + 1]});
    if (closed && points.size() > 2) ends.insert(ends.end(), {points.back(), points.front()});
    add_lines(ends, color, width);
}

void Scene::add_points(const std::vector<glm::vec3>& points, glm::vec3 color, float size) {
    add_points(points, std::vector<glm::vec3>(points.size(), color), size);
}

void Scene::add_points(const std::vector<glm::vec3>& points, const std::vector<glm::vec3>& colors, float size) {
    check_count("add_points", "colours", colors.size(), points.size());
    points_.push_back(Points{points, colors, size});
}

void Scene::add_rect(glm::vec2 lo, glm::vec2 hi, glm::vec4 color) {
    if (lo.x < hi.x && lo.y < hi.y) overlay_.push_back(Rect{lo, hi, color});
}

Box Scene::bounds() const {
    constexpr double inf = std::numeric_limits<double>::infinity();
    Box box{glm::dvec3(inf), glm::dvec3(-inf)};
    auto grow = [&](const std::vector<glm::vec3>& ps) {
        for (glm::vec3 p : ps) {
            box.lo = glm::min(box.lo, glm::dvec3(p));
            box.hi = glm::max(box.hi, glm::dvec3(p));
        }
    };
    for (const Mesh& m : meshes_) grow(m.position);
    for (const Lines& l : lines_) grow(l.position);
    for (const Points& p : points_) grow(p.position);
    if (box.lo.x > box.hi.x) return Box{glm::dvec3(-1.0), glm::dvec3(1.0)};
    return box;
}

void Scene::clear() {
    meshes_.clear();
    lines_.clear();
    points_.clear();
    overlay_.clear();
}

}  // namespace geolab::render
