// Tests of the drawing layer: headless rendering (OSMesa), the orbit camera, picking, and the window back end's
// behaviour without a display.
#include <doctest/doctest.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <map>
#include <optional>
#include <string>

#include "geolab/errors.hpp"
#include "geolab/render/render.hpp"

using namespace geolab::render;

namespace {

// The cube [-1,1]³ as 6 quads, outward orientation.
geolab::PolygonSoup test_cube() {
    geolab::PolygonSoup s;
    for (int i = 0; i < 8; ++i) s.positions.push_back({i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
    s.add_face({0, 2, 3, 1});
    s.add_face({4, 5, 7, 6});
    s.add_face({0, 1, 5, 4});
    s.add_face({2, 6, 7, 3});
    s.add_face({0, 4, 6, 2});
    s.add_face({1, 3, 7, 5});
    return s;
}

// Unit icosphere: an icosahedron subdivided n times, vertices pushed to the sphere.
geolab::PolygonSoup test_sphere(int n) {
    geolab::PolygonSoup s;
    const double t = (1 + std::sqrt(5.0)) / 2;
    const double v[12][3] = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                             {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    for (auto& p : v) s.positions.push_back(glm::normalize(glm::dvec3(p[0], p[1], p[2])));
    std::vector<std::array<std::uint32_t, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                                   {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                                   {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                                   {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int k = 0; k < n; ++k) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
        auto m = [&](std::uint32_t a, std::uint32_t b) {
            auto key = std::minmax(a, b);
            if (auto it = mid.find(key); it != mid.end()) return it->second;
            s.positions.push_back(glm::normalize(s.positions[a] + s.positions[b]));
            return mid[key] = std::uint32_t(s.positions.size() - 1);
        };
        std::vector<std::array<std::uint32_t, 3>> g;
        for (auto [a, b, c] : f) {
            auto ab = m(a, b), bc = m(b, c), ca = m(c, a);
            g.insert(g.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
        }
        f = g;
    }
    for (auto [a, b, c] : f) s.add_face({a, b, c});
    return s;
}

// One triangle in the plane z = 0.
geolab::PolygonSoup test_triangle() {
    geolab::PolygonSoup s;
    s.positions = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    s.add_face({0, 1, 2});
    return s;
}

std::array<int, 3> rgb(const Image& img, int x, int y) {
    auto p = img.pixel(x, y);
    return {p[0], p[1], p[2]};
}

std::array<int, 3> to_bytes(glm::vec3 c) {
    return {int(std::lround(c.r * 255)), int(std::lround(c.g * 255)), int(std::lround(c.b * 255))};
}

bool near_color(std::array<int, 3> a, std::array<int, 3> b, int tol = 2) {
    for (int i = 0; i < 3; ++i)
        if (std::abs(a[i] - b[i]) > tol) return false;
    return true;
}

std::string str(std::array<int, 3> c) {
    return "(" + std::to_string(c[0]) + "," + std::to_string(c[1]) + "," + std::to_string(c[2]) + ")";
}

// Sets or unsets an environment variable for one scope.
class EnvOverride {
public:
    EnvOverride(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        if (value)
            setenv(name, value, 1);
        else
            unsetenv(name);
    }
    ~EnvOverride() {
        if (old_)
            setenv(name_, old_->c_str(), 1);
        else
            unsetenv(name_);
    }

private:
    const char* name_;
    std::optional<std::string> old_;
};

}  // namespace

TEST_SUITE("render") {
    TEST_CASE("render: image has the requested size and a background of the scene's colour") {
        Scene scene;
        scene.background = {0.2f, 0.4f, 0.6f};
        scene.add_mesh(test_triangle());
        for (bool aa : {false, true}) {
            CAPTURE(aa);
            Image img = render_image(scene, Camera::framing(scene.bounds(), 0, 0), 64, 48, aa);
            REQUIRE(img.width == 64);
            REQUIRE(img.height == 48);
            REQUIRE(img.rgba.size() == 4u * 64 * 48);
            const auto bg = to_bytes(scene.background);
            for (auto [x, y] : {std::pair{0, 0}, {63, 0}, {0, 47}, {63, 47}}) {
                INFO("corner (", x, ",", y, ") is ", str(rgb(img, x, y)), ", background ", str(bg));
                CHECK(near_color(rgb(img, x, y), bg));
                CHECK(img.pixel(x, y)[3] == 255);
            }
        }
    }

    TEST_CASE("render: the object covers the centre, not the corners") {
        Scene scene;
        scene.add_mesh(test_cube(), {.smooth = false, .wireframe = true});
        Image img = render_image(scene, Camera::framing(scene.bounds()), 120, 90);
        const auto white = to_bytes({1, 1, 1});
        INFO("centre pixel ", str(rgb(img, 60, 45)));
        CHECK_FALSE(near_color(rgb(img, 60, 45), white, 10));
        CHECK(near_color(rgb(img, 1, 1), white));
        // the framed cube fills a fair part of the image but stays inside it: the border rows are background
        int covered = 0;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x) covered += !near_color(rgb(img, x, y), white, 3);
        CHECK(covered > img.width * img.height / 5);
        for (int x = 0; x < img.width; ++x) {
            CHECK(near_color(rgb(img, x, 0), white, 3));
            CHECK(near_color(rgb(img, x, img.height - 1), white, 3));
        }
    }

    TEST_CASE("render: per-face red shows up red-dominant, per-vertex colours are interpolated") {
        const auto cube = test_cube();
        Scene faces;
        faces.add_mesh_face_colors(cube, std::vector<glm::vec3>(cube.n_faces(), {0.9f, 0.1f, 0.1f}), {.smooth = false});
        Image img = render_image(faces, Camera::framing(faces.bounds()), 80, 60);
        auto c = rgb(img, 40, 30);
        INFO("centre pixel ", str(c));
        CHECK(c[0] > c[1] + 60);
        CHECK(c[0] > c[2] + 60);

        // the triangle's vertices are red, green, blue: each corner region takes its vertex's hue
        Scene verts;
        verts.add_mesh_vertex_colors(test_triangle(), {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {.smooth = false});
        Image tri = render_image(verts, Camera::framing(verts.bounds(), 0, 0), 100, 100);
        Camera cam = Camera::framing(verts.bounds(), 0, 0);
        glm::mat4 pv = cam.proj(1.0f) * cam.view();
        auto pixel_of = [&](glm::vec3 p) {  // a point 20% of the way from vertex p to the centroid
            glm::vec4 q = pv * glm::vec4(0.8f * p + 0.2f * glm::vec3(0, -1.0f / 3, 0), 1.0f);
            return std::pair{int((q.x / q.w * 0.5f + 0.5f) * 100), int((0.5f - q.y / q.w * 0.5f) * 100)};
        };
        auto [rx, ry] = pixel_of({-1, -1, 0});
        auto [gx, gy] = pixel_of({1, -1, 0});
        auto [bx, by] = pixel_of({0, 1, 0});
        auto r = rgb(tri, rx, ry), g = rgb(tri, gx, gy), b = rgb(tri, bx, by);
        INFO("near red vertex ", str(r), ", near green ", str(g), ", near blue ", str(b));
        CHECK((r[0] > r[1] && r[0] > r[2]));
        CHECK((g[1] > g[0] && g[1] > g[2]));
        CHECK((b[2] > b[0] && b[2] > b[1]));
    }

    TEST_CASE("render: a smooth sphere is shaded with a gradient, flat shading gives facets") {
        Scene scene;
        scene.add_mesh(test_sphere(3), {.color = {0.8f, 0.8f, 0.8f}, .smooth = true});
        Image img = render_image(scene, Camera::framing(scene.bounds(), 0, 0), 100, 100);
        // brightness along the horizontal diameter: it varies, brightest towards the key light (upper left)
        int lo = 1000, hi = -1, x_hi = 0;
        for (int x = 30; x < 70; ++x) {
            auto c = rgb(img, x, 50);
            int v = c[0] + c[1] + c[2];
            if (v < lo) lo = v;
            if (v > hi) hi = v, x_hi = x;
        }
        INFO("brightness on the diameter in [", lo, ", ", hi, "], brightest at x = ", x_hi);
        CHECK(hi - lo > 60);
        CHECK(x_hi < 50);
        // smooth: neighbouring pixels differ little anywhere on the diameter
        int max_step = 0;
        for (int x = 30; x < 69; ++x) {
            auto a = rgb(img, x, 50), b = rgb(img, x + 1, 50);
            max_step = std::max(max_step, std::abs((a[0] + a[1] + a[2]) - (b[0] + b[1] + b[2])));
        }
        CHECK(max_step < 30);
    }

    TEST_CASE("render: the back of an open surface is lit (two-sided lighting)") {
        Scene front, back;
        auto tri = test_triangle();
        front.add_mesh(tri, {.smooth = false});
        back.add_mesh(tri, {.smooth = false});
        Camera cf = Camera::framing(front.bounds(), 0, 0), cb = cf;
        cb.yaw_deg = 180;  // the same triangle seen from behind
        auto a = rgb(render_image(front, cf, 60, 60), 30, 35), b = rgb(render_image(back, cb, 60, 60), 30, 35);
        INFO("front ", str(a), ", back ", str(b));
        CHECK(near_color(a, b, 3));
        CHECK(a[0] > 100);
    }

    TEST_CASE("render: lines and points are drawn in their colours") {
        Scene scene;
        scene.add_lines({{-1, 0, 0}, {1, 0, 0}}, glm::vec3{0, 0, 1}, 3.0f);
        scene.add_points({{0, 0.5f, 0}}, glm::vec3{1, 0, 0}, 12.0f);
        Camera cam = Camera::framing(scene.bounds(), 0, 0);
        Image img = render_image(scene, cam, 100, 100);
        auto pixel_of = [&](glm::vec3 p) {
            glm::vec4 q = cam.proj(1.0f) * cam.view() * glm::vec4(p, 1.0f);
            return std::pair{int((q.x / q.w * 0.5f + 0.5f) * 100), int((0.5f - q.y / q.w * 0.5f) * 100)};
        };
        auto [lx, ly] = pixel_of({0.5f, 0, 0});
        auto [px, py] = pixel_of({0, 0.5f, 0});
        auto line = rgb(img, lx, ly), point = rgb(img, px, py);
        INFO("line pixel (", lx, ",", ly, ") ", str(line), ", point pixel (", px, ",", py, ") ", str(point));
        CHECK((line[2] > 150 && line[0] < 100));
        CHECK((point[0] > 150 && point[1] < 100));
    }

    TEST_CASE("render: write_png writes a file with the PNG signature") {
        Scene scene;
        scene.add_mesh(test_cube());
        auto file =
            std::filesystem::temp_directory_path() / ("geolab_test_render_" + std::to_string(getpid()) + ".png");
        render_png(scene, Camera::framing(scene.bounds()), file, 40, 30);
        std::ifstream in(file, std::ios::binary);
        REQUIRE(in.good());
        char sig[8] = {};
        in.read(sig, 8);
        CHECK(std::string(sig, 8) == std::string("\x89PNG\r\n\x1a\n", 8));
        in.close();
        std::filesystem::remove(file);
        CHECK_THROWS_AS(Image{}.write_png(file), geolab::IoError);
    }

    TEST_CASE("render: bad input is rejected with a message") {
        Scene scene;
        const auto cube = test_cube();
        CHECK_THROWS_AS(scene.add_mesh_vertex_colors(cube, std::vector<glm::vec3>(3)), std::invalid_argument);
        CHECK_THROWS_AS(scene.add_mesh_face_colors(cube, std::vector<glm::vec3>(7)), std::invalid_argument);
        CHECK_THROWS_AS(scene.add_lines({{0, 0, 0}}, glm::vec3(1)), std::invalid_argument);
        CHECK_THROWS_AS(render_image(scene, Camera{}, 0, 10), std::invalid_argument);
        CHECK(scene.empty());
        // an empty scene renders as background
        Image img = render_image(scene, 8, 8);
        CHECK(near_color(rgb(img, 4, 4), {255, 255, 255}));
    }

    TEST_CASE("camera: framing keeps the box in view, rays go through pixels") {
        geolab::Box box{{-1, -2, 0}, {3, 1, 0.5}};
        for (glm::vec3 up : {glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)}) {
            for (float aspect : {0.5f, 1.0f, 2.0f}) {
                Camera cam = Camera::framing(box, 40, 25, up);
                glm::mat4 pv = cam.proj(aspect) * cam.view();
                float extent = 0, fill = 0;  // largest |ndc| of a corner; the same across the shorter side
                for (int i = 0; i < 8; ++i) {
                    glm::vec4 q = pv * glm::vec4(i & 1 ? 3 : -1, i & 2 ? 1 : -2, i & 4 ? 0.5f : 0, 1);
                    glm::vec2 ndc = glm::vec2(q) / q.w;
                    extent = std::max({extent, std::abs(ndc.x), std::abs(ndc.y)});
                    fill = std::max({fill, std::abs(ndc.x) * std::max(aspect, 1.0f),
                                     std::abs(ndc.y) * std::max(1.0f / aspect, 1.0f)});
                }
                INFO("up ", up.z, ", aspect ", aspect, ": largest |ndc| of a corner ", extent, ", fill ", fill);
                CHECK(extent <= 1.0f);
                CHECK(fill > 0.7f);  // tight, not tiny
            }
        }
        Camera cam = Camera::framing(box);
        Ray r = cam.ray(400, 300, 800, 600);  // the centre of the image
        CHECK(glm::length(r.origin - cam.eye()) < 1e-4f);
        CHECK(glm::dot(r.direction, glm::normalize(cam.target - cam.eye())) > 0.99999f);
    }

    TEST_CASE("pick: the ray through the centre hits the front face of the cube") {
        const auto cube = test_cube();
        Camera cam = Camera::framing({{-1, -1, -1}, {1, 1, 1}}, 0, 0);  // looks along −z at the face z = +1
        auto hit = pick(cube, cam.ray(50, 50, 100, 100));
        REQUIRE(hit.has_value());
        CHECK(hit->face == 1);  // {4,5,7,6}: z = +1
        CHECK(std::abs(hit->point.z - 1.0f) < 1e-4f);
        CHECK(!pick(cube, Ray{{0, 5, 5}, {0, 0, 1}}).has_value());
    }

    TEST_CASE("viewer: without a display a window request throws NoDisplay pointing to --png") {
        EnvOverride display("DISPLAY", nullptr), wayland("WAYLAND_DISPLAY", nullptr);
        CHECK_FALSE(display_available());
        try {
            Viewer viewer("test");
            FAIL("Viewer opened a window without a display");
        } catch (const NoDisplay& e) {
            std::string msg = e.what();
            INFO("message: ", msg);
            CHECK(msg.find("no display") != std::string::npos);
            CHECK(msg.find("--png") != std::string::npos);
        }
    }
}
