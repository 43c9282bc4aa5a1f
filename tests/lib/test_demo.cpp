// Tests of the demo framework (geolab/render/demo.hpp): number formatting, collecting what student code did not
// do, arrows and boxes, cameras (orbit angles, fitting known boxes, close-ups), image stacking, the figure writer,
// the shared command line, and a headless render of a known scene checked by its pixels.
#include <doctest/doctest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "geolab/errors.hpp"
#include "geolab/render/demo.hpp"
#include "geolab/render/headless.hpp"

using namespace geolab::render;
using glm::dvec3;
using glm::vec3;

namespace {

// The axis-aligned box [lo, hi] as 6 quads.
geolab::PolygonSoup box_soup(dvec3 lo, dvec3 hi) {
    geolab::PolygonSoup s;
    for (int i = 0; i < 8; ++i) s.positions.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
    s.add_face({0, 2, 3, 1});
    s.add_face({4, 5, 7, 6});
    s.add_face({0, 1, 5, 4});
    s.add_face({2, 6, 7, 3});
    s.add_face({0, 4, 6, 2});
    s.add_face({1, 3, 7, 5});
    return s;
}

// Normalised device coordinates (x, y) of p seen by cam in an image of the given aspect.
glm::dvec2 ndc(const Camera& cam, double aspect, vec3 p) {
    const glm::vec4 c = cam.proj(static_cast<float>(aspect)) * cam.view() * glm::vec4(p, 1.0f);
    return {c.x / c.w, c.y / c.w};
}

// The NDC extent of the scene's mesh vertices: lo.x, hi.x, lo.y, hi.y.
std::array<double, 4> extent(const Camera& cam, double aspect, const Scene& scene) {
    std::array<double, 4> e{1e300, -1e300, 1e300, -1e300};
    for (const auto& m : scene.meshes())
        for (const vec3& p : m.position) {
            const auto q = ndc(cam, aspect, p);
            e[0] = std::min(e[0], q.x), e[1] = std::max(e[1], q.x), e[2] = std::min(e[2], q.y), e[3] = std::max(e[3], q.y);
        }
    return e;
}

// Runs a DemoProgram's parse on the arguments, capturing stdout and stderr.
struct Parsed {
    std::optional<int> status;
    std::string out, err;
};
Parsed parse(DemoProgram& p, std::vector<std::string> args) {
    args.insert(args.begin(), "demo_test");
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    std::ostringstream out, err;
    auto* old_out = std::cout.rdbuf(out.rdbuf());
    auto* old_err = std::cerr.rdbuf(err.rdbuf());
    Parsed r;
    r.status = p.parse(static_cast<int>(argv.size()), argv.data());
    std::cout.rdbuf(old_out), std::cerr.rdbuf(old_err);
    r.out = out.str(), r.err = err.str();
    return r;
}

const char* kKeys = "Window keys:\n  Q  a test key";

}  // namespace

TEST_CASE("fmt: significant digits as ostream prints them") {
    CHECK(fmt(1.0 / 3.0) == "0.333");
    CHECK(fmt(2.0) == "2");
    CHECK(fmt(-2.5) == "-2.5");
    CHECK(fmt(1.5e6) == "1.5e+06");
    CHECK(fmt(123456.0) == "1.23e+05");
    CHECK(fmt(-0.00012345, 2) == "-0.00012");
    CHECK(fmt(3.14159265, 6) == "3.14159");
    CHECK(fmt(0.0) == "0");
    CHECK(fmt(std::numeric_limits<double>::quiet_NaN()) == "nan");
    CHECK(fmt(-std::numeric_limits<double>::infinity()) == "-inf");
    CHECK(fmt(dvec3(1.0, 0.5, -2.0)) == "(1, 0.5, -2)");
    CHECK(fmt(dvec3(1.0 / 3.0, 2.0 / 3.0, 1e-7), 2) == "(0.33, 0.67, 1e-07)");
}

TEST_CASE("attempt and Issues: what student code did not do, once each, for the status line") {
    Issues issues;
    CHECK_FALSE(issues.any());
    CHECK(issues.str().empty());
    CHECK(attempt(issues, "valence", [] {}));
    CHECK_FALSE(issues.any());
    CHECK_FALSE(attempt(issues, "valence", [] { throw geolab::NotImplemented("valence"); }));
    CHECK_FALSE(attempt(issues, "valence", [] { throw geolab::NotImplemented("valence"); }));  // recorded once
    CHECK_FALSE(attempt(issues, "genus", [] { throw geolab::NotImplemented("genus"); }));
    CHECK_FALSE(attempt(issues, "face_area", [] { throw std::runtime_error("face 3 has 2 vertices"); }));
    CHECK_FALSE(attempt(issues, "contour", [] { throw std::bad_alloc(); }));
    CHECK(issues.any());
    CHECK(issues.missing == std::vector<std::string>{"valence", "genus"});
    REQUIRE(issues.errors.size() == 2);
    CHECK(issues.errors[0] == "face_area threw: face 3 has 2 vertices");
    CHECK(issues.errors[1].find("memory limit") == 0);
    CHECK(issues.errors[1].find("contour") != std::string::npos);
    CHECK(issues.str().rfind("not implemented yet: valence, genus | face_area threw: face 3 has 2 vertices | ", 0) == 0);

    SUBCASE("a namer sees the exception's message and the step") {
        Issues named;
        attempt(named, "place_vertices", [] { throw geolab::NotImplemented("solve"); },
                [](const std::string& what, const std::string& step) { return not_implemented_name(what) + " in " + step; });
        CHECK(named.missing == std::vector<std::string>{"solve in place_vertices"});
    }
    SUBCASE("add merges without duplicates") {
        Issues other;
        other.add_missing("genus");
        other.add_missing("contour");
        other.add_error("face_area threw: face 3 has 2 vertices");
        issues.add(other);
        CHECK(issues.missing == std::vector<std::string>{"valence", "genus", "contour"});
        CHECK(issues.errors.size() == 2);
    }
    SUBCASE("errors only") {
        Issues e;
        e.add_error("x threw: y");
        CHECK(e.str() == "x threw: y");
    }
}

TEST_CASE("not_implemented_name: the function a NotImplemented names") {
    CHECK(not_implemented_name(geolab::NotImplemented("build_mesh").what()) == "build_mesh");
    CHECK(not_implemented_name("not implemented: add (this is yours)") == "add");
    CHECK(not_implemented_name("something else") == "something else");
}

TEST_CASE("add_arrow: a shortened shaft and a head along the side vector") {
    const dvec3 a(1, 2, 3), b(1, 2, 13), side(1, 0, 0);
    SUBCASE("two barbs") {
        Segments s;
        add_arrow(s, a, b, side, vec3(1, 0, 0), {.shrink = 0.1, .head = 0.25});
        REQUIRE(s.colors.size() == 3);
        REQUIRE(s.endpoints.size() == 6);
        CHECK(glm::length(s.endpoints[0] - vec3(1, 2, 4)) < 1e-5f);   // a + 0.1 (b − a)
        CHECK(glm::length(s.endpoints[1] - vec3(1, 2, 12)) < 1e-5f);  // b − 0.1 (b − a)
        // head 0.25 × 8 = 2 long, 0.45 × 2 = 0.9 wide on each side, both barbs from the tip
        CHECK(glm::length(s.endpoints[2] - vec3(1, 2, 12)) < 1e-5f);
        CHECK(glm::length(s.endpoints[3] - vec3(1.9f, 2, 10)) < 1e-5f);
        CHECK(glm::length(s.endpoints[5] - vec3(0.1f, 2, 10)) < 1e-5f);
        for (const vec3& c : s.colors) CHECK(c == vec3(1, 0, 0));
    }
    SUBCASE("a harpoon has one wider barb, on +side") {
        Segments s;
        add_arrow(s, a, b, side, vec3(0), {.shrink = 0.0, .head = 0.25, .one_sided = true});
        REQUIRE(s.colors.size() == 2);
        CHECK(glm::length(s.endpoints[3] - vec3(1 + 1.6f * 0.45f * 2.5f, 2, 10.5f)) < 1e-5f);
    }
    SUBCASE("no head: the shaft only") {
        Segments s;
        add_arrow(s, a, b, side, vec3(0), {.shrink = 0.0, .head = 0.0});
        CHECK(s.colors.size() == 1);
    }
    SUBCASE("draw adds one Lines with the colours, nothing when empty") {
        Segments s;
        Scene scene;
        s.draw(scene, 3.0f);
        CHECK(scene.empty());
        add_arrow(s, a, b, side, vec3(0, 0, 1));
        s.draw(scene, 3.0f);
        REQUIRE(scene.lines().size() == 1);
        CHECK(scene.lines()[0].width == 3.0f);
        CHECK(scene.lines()[0].position.size() == 6);
    }
}

TEST_CASE("add_normal and side_towards") {
    Segments s;
    add_normal(s, dvec3(0), dvec3(0), 1.0, vec3(0));  // a zero normal (degenerate face): nothing
    CHECK(s.empty());
    add_normal(s, dvec3(1, 1, 1), dvec3(0, 0, 1), 2.0, vec3(0.5f));
    REQUIRE(s.colors.size() == 3);
    CHECK(glm::length(s.endpoints[0] - vec3(1, 1, 1)) < 1e-6f);
    CHECK(glm::length(s.endpoints[1] - vec3(1, 1, 3)) < 1e-6f);
    // the barbs lie in a plane containing the normal, symmetric about it
    CHECK(std::abs((s.endpoints[3].x + s.endpoints[5].x) * 0.5f - 1.0f) < 1e-6f);

    const dvec3 u = side_towards(dvec3(0), dvec3(2, 0, 0), dvec3(5, -3, 0));
    CHECK(glm::length(u - dvec3(0, -1, 0)) < 1e-12);
    const dvec3 v = side_towards(dvec3(1, 1, 1), dvec3(1, 2, 3), dvec3(4, 0, 2));
    CHECK(std::abs(glm::length(v) - 1.0) < 1e-12);
    CHECK(std::abs(glm::dot(v, dvec3(0, 1, 2))) < 1e-12);
    CHECK(glm::dot(v, dvec3(3, -1, 1)) > 0);
    CHECK(side_towards(dvec3(0), dvec3(1, 0, 0), dvec3(3, 0, 0)) == dvec3(0, 0, 1));  // c on the line
}

TEST_CASE("add_box_edges: 12 edges along the axes between corners") {
    std::vector<vec3> seg;
    const dvec3 lo(-1, 0, 2), hi(3, 0.5, 7);
    add_box_edges(seg, lo, hi);
    REQUIRE(seg.size() == 24);
    int per_axis[3] = {0, 0, 0};
    for (std::size_t i = 0; i < seg.size(); i += 2) {
        const vec3 d = seg[i + 1] - seg[i];
        int axis = -1;
        for (int k = 0; k < 3; ++k)
            if (d[k] != 0.0f) axis = k;
        REQUIRE(axis >= 0);
        ++per_axis[axis];
        CHECK(d[axis] == doctest::Approx(hi[axis] - lo[axis]));
        for (const vec3& p : {seg[i], seg[i + 1]})
            for (int k = 0; k < 3; ++k) CHECK((p[k] == float(lo[k]) || p[k] == float(hi[k])));
    }
    CHECK(per_axis[0] == 4);
    CHECK(per_axis[1] == 4);
    CHECK(per_axis[2] == 4);
    CHECK(box_around(dvec3(1, 2, 3), 0.5).lo == dvec3(0.5, 1.5, 2.5));
    CHECK(box_around(dvec3(1, 2, 3), 0.5).hi == dvec3(1.5, 2.5, 3.5));
}

TEST_CASE("orbit_angles and camera_from: the eye lies in the asked direction, for y and z up") {
    const dvec3 dirs[] = {{0, 0, 1}, {1, 0, 0}, {0.3, -1, 0.35}, {-2, 0.5, -1}, {1, 0.8, 0.9}, {0, -0.25, 1}};
    for (const dvec3 up : {dvec3(0, 1, 0), dvec3(0, 0, 1), dvec3(1, 1, 0)}) {
        for (const dvec3& d : dirs) {
            if (std::abs(glm::dot(glm::normalize(d), glm::normalize(up))) > 0.99) continue;  // the pole: below
            INFO("eye direction " << fmt(d) << ", up " << fmt(up));
            const geolab::Box box{dvec3(-1, -2, -3), dvec3(5, 4, 3)};
            const Camera cam = camera_from(box, d, up);
            const vec3 eye_dir = glm::normalize(cam.eye() - cam.target);
            CHECK(glm::length(eye_dir - vec3(glm::normalize(d))) < 1e-5f);
            CHECK(glm::length(cam.target - vec3(box.center())) < 1e-5f);
        }
    }
    // straight along up: the pitch stops short of the pole (the orbit camera degenerates there)
    float yaw = 0, pitch = 0;
    orbit_angles(dvec3(0, 5, 0), dvec3(0, 1, 0), yaw, pitch);
    CHECK(pitch < 85.0f);
    CHECK(pitch > 84.0f);
    orbit_angles(dvec3(0, 0, -1), dvec3(0, 0, 1), yaw, pitch);
    CHECK(pitch > -85.0f);
    // yaw 0 looks from +z (y up) and from −y (z up), as Camera documents
    orbit_angles(dvec3(0, 0, 1), dvec3(0, 1, 0), yaw, pitch);
    CHECK(yaw == doctest::Approx(0.0));
    orbit_angles(dvec3(0, -1, 0), dvec3(0, 0, 1), yaw, pitch);
    CHECK(yaw == doctest::Approx(0.0));
    CHECK(pitch == doctest::Approx(0.0));
}

TEST_CASE("fit and whole: known boxes fill the image to the 6% margin, centred, at any aspect") {
    struct Case {
        dvec3 lo, hi;
        float yaw, pitch;
    };
    const Case cases[] = {{{-1, -1, -1}, {1, 1, 1}, 30, 20},
                          {{-1, -1, -1}, {1, 1, 1}, 0, 0},
                          {{0, 0, 0}, {10, 1, 1}, 0, 0},        // long and flat: width-limited
                          {{0, 0, 0}, {0.5, 8, 0.5}, 45, 10},    // tall: height-limited
                          {{100, 50, -3}, {100.02, 50.01, -2.99}, -60, 35}};  // far away and tiny
    for (const Case& c : cases)
        for (const double aspect : {4.0 / 3.0, 1.0, 0.5, 2.5}) {
            INFO("box " << fmt(c.lo) << " – " << fmt(c.hi) << ", yaw " << c.yaw << ", aspect " << aspect);
            Scene scene;
            scene.add_mesh(box_soup(c.lo, c.hi));
            const Camera cam = whole(scene, aspect, c.yaw, c.pitch);
            CHECK(cam.yaw_deg == c.yaw);
            CHECK(cam.pitch_deg == c.pitch);
            const auto e = extent(cam, aspect, scene);
            // everything inside, the larger extent near 1/1.06 (the margin), centred
            CHECK(std::max({-e[0], e[1], -e[2], e[3]}) < 1.0);
            CHECK(std::max({e[1] - e[0], e[3] - e[2]}) / 2 > 0.88);
            CHECK(std::abs(e[0] + e[1]) < 0.03);
            CHECK(std::abs(e[2] + e[3]) < 0.03);
            // tighter than (or as tight as) the bounding box's framing
            CHECK(cam.distance <= Camera::framing(scene.bounds(), c.yaw, c.pitch).distance * 1.0001f);
        }
    Scene empty;
    Camera cam;
    cam.distance = 7.0f;
    CHECK(fit(cam, empty, 1.0).distance == 7.0f);
}

TEST_CASE("close_up: a ball of the given radius spans the shorter image side") {
    Camera cam;
    cam.yaw_deg = 40, cam.pitch_deg = -15;
    const dvec3 c(3, -2, 1);
    const double r = 0.25;
    const Camera z = close_up(cam, c, r);
    CHECK(z.yaw_deg == 40.0f);
    CHECK(glm::length(z.target - vec3(c)) < 1e-6f);
    const glm::mat4 v = z.view();
    const vec3 cam_up(v[0][1], v[1][1], v[2][1]), cam_right(v[0][0], v[1][0], v[2][0]);
    CHECK(ndc(z, 4.0 / 3.0, vec3(c) + float(r) * cam_up).y == doctest::Approx(1.0).epsilon(1e-4));
    CHECK(ndc(z, 0.5, vec3(c) + float(r) * cam_right).x == doctest::Approx(1.0).epsilon(1e-4));
}

TEST_CASE("hstack: panels side by side with a grey gap, on white") {
    Image a{2, 3, std::vector<std::uint8_t>(4 * 2 * 3, 10)}, b{3, 1, std::vector<std::uint8_t>(4 * 3 * 1, 20)};
    const Image s = hstack({a, b}, 2);
    CHECK(s.width == 7);
    CHECK(s.height == 3);
    CHECK(s.pixel(0, 2) == std::array<std::uint8_t, 4>{10, 10, 10, 10});
    CHECK(s.pixel(2, 1) == std::array<std::uint8_t, 4>{200, 200, 200, 255});
    CHECK(s.pixel(3, 0) == std::array<std::uint8_t, 4>{200, 200, 200, 255});
    CHECK(s.pixel(4, 0) == std::array<std::uint8_t, 4>{20, 20, 20, 20});
    CHECK(s.pixel(6, 0) == std::array<std::uint8_t, 4>{20, 20, 20, 20});
    CHECK(s.pixel(5, 1) == std::array<std::uint8_t, 4>{255, 255, 255, 255});  // below the shorter panel
    const Image t = hstack({a, a, a});
    CHECK(t.width == 6);
    CHECK(t.rgba == std::vector<std::uint8_t>(4 * 6 * 3, 10));
}

TEST_CASE("a known scene rendered headless: the fitted square is centred, red, and fills the height") {
    // a red square facing +z, and a blue horizontal arrow in front of it through its middle
    geolab::PolygonSoup square;
    square.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    square.add_face({0, 1, 2, 3});
    Scene scene;
    scene.add_mesh(square, {.color = {1, 0, 0}, .smooth = false});
    const int w = 160, h = 120;
    const Camera cam = whole(scene, double(w) / h, 0.0f, 0.0f);
    Segments arrow;
    add_arrow(arrow, dvec3(-0.8, 0, 0.01), dvec3(0.8, 0, 0.01), dvec3(0, 1, 0), vec3(0, 0, 1), {.shrink = 0.0});
    arrow.draw(scene, 3.0f);
    const Image im = render_image(scene, cam, w, h);
    REQUIRE(im.width == w);
    auto is_red = [](std::array<std::uint8_t, 4> p) { return p[0] > 100 && p[1] < 60 && p[2] < 60; };
    auto is_white = [](std::array<std::uint8_t, 4> p) { return p[0] > 245 && p[1] > 245 && p[2] > 245; };
    int x0 = w, x1 = -1, y0 = h, y1 = -1;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (is_red(im.pixel(x, y))) x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    // the square spans 1/1.06 of the height (the limiting side at 4:3), square in pixels, centred
    CHECK((y1 - y0 + 1) == doctest::Approx(h / 1.06).epsilon(0.03));
    CHECK((x1 - x0 + 1) == doctest::Approx(y1 - y0 + 1).epsilon(0.03));
    CHECK(std::abs((x0 + x1) - (w - 1)) <= 2);
    CHECK(std::abs((y0 + y1) - (h - 1)) <= 2);
    CHECK(is_white(im.pixel(2, 2)));
    CHECK(is_white(im.pixel(w - 3, h - 3)));
    CHECK(is_red(im.pixel(w / 2, h / 4)));
    // the arrow's shaft crosses the middle row in blue
    const auto mid = im.pixel(w / 2 - 10, h / 2);
    CHECK(mid[2] > 150);
    CHECK(mid[0] < 100);
}

TEST_CASE("FigureWriter: writes, skips, counts") {
    const auto dir = std::filesystem::temp_directory_path() / ("geolab_figwriter_" + std::to_string(::getpid())) / "sub";
    std::ostringstream out;
    auto* old = std::cout.rdbuf(out.rdbuf());
    {
        FigureWriter w(dir, 64, 48);
        CHECK(std::filesystem::is_directory(dir));
        CHECK(w.aspect() == doctest::Approx(4.0 / 3.0));
        Scene scene;
        scene.add_mesh(box_soup(dvec3(0), dvec3(1)));
        w.write("a.png", scene, whole(scene, w.aspect()), "a box");
        w.write("b.png", Image{2, 2, std::vector<std::uint8_t>(16, 255)}, "white");
        w.skip("c.png", "no model fetched");
        CHECK(w.written() == 2);
        CHECK(w.skipped() == 1);
        CHECK(w.finish() == 0);
    }
    std::cout.rdbuf(old);
    CHECK(std::filesystem::file_size(dir / "a.png") > 0);
    CHECK(std::filesystem::exists(dir / "b.png"));
    CHECK_FALSE(std::filesystem::exists(dir / "c.png"));
    const std::string log = out.str();
    CHECK(log.find("wrote " + (dir / "a.png").string() + "  (a box)") != std::string::npos);
    CHECK(log.find("skipped " + (dir / "c.png").string() + ": no model fetched") != std::string::npos);
    CHECK(log.find("2 figures in " + dir.string()) != std::string::npos);
    CHECK(log.find("1 skipped") != std::string::npos);
    std::filesystem::remove_all(dir.parent_path());
}

TEST_CASE("DemoProgram: the shared options, the lab's own, --help with the window keys, bad options") {
    SUBCASE("defaults") {
        DemoProgram p("demo_test", "A test demo.", kKeys, 1000);
        const auto r = parse(p, {"--memory-mb", "0"});  // (no cap on the test process)
        CHECK_FALSE(r.status);
        CHECK(p.png().empty());
        CHECK(p.figures().empty());
        CHECK(p.width() == 1000);
        CHECK(p.height() == 750);
    }
    SUBCASE("shared and lab options together") {
        DemoProgram p("demo_test", "A test demo.", kKeys);
        int level = 5;
        std::string input;
        p.cli().add_option("input", input);
        p.cli().add_option("--level", level);
        const auto r = parse(p, {"bunny00", "--png", "x.png", "--size", "640", "--level", "7", "--memory-mb", "0",
                                 "--frames", "3", "--keys", "ZS"});
        CHECK_FALSE(r.status);
        CHECK(input == "bunny00");
        CHECK(level == 7);
        CHECK(p.png() == "x.png");
        CHECK(p.width() == 640);
        CHECK(p.height() == 480);
        CHECK(p.aspect() == doctest::Approx(4.0 / 3.0));
    }
    SUBCASE("--help lists the options, the grader's memory cap and the window keys; status 0") {
        DemoProgram p("demo_test", "A test demo.", kKeys);
        const auto r = parse(p, {"--help"});
        REQUIRE(r.status);
        CHECK(*r.status == 0);
        CHECK(r.out.find("A test demo.") != std::string::npos);
        for (const char* s : {"--png", "--figures", "--size", "--memory-mb", "Window keys:", "a test key"})
            CHECK_MESSAGE(r.out.find(s) != std::string::npos, s);
        CHECK(r.out.find(std::to_string(default_demo_memory_mb())) != std::string::npos);
        CHECK(r.out.find("--frames") == std::string::npos);  // the testing options stay hidden
    }
    SUBCASE("bad options: a message and a non-zero status") {
        for (const std::vector<std::string>& args :
             {std::vector<std::string>{"--size", "4"}, {"--size", "wide"}, {"--no-such-option"}, {"--png"}}) {
            DemoProgram p("demo_test", "A test demo.", kKeys);
            const auto r = parse(p, args);
            REQUIRE(r.status);
            CHECK(*r.status != 0);
            CHECK_FALSE(r.err.empty());
        }
    }
}

TEST_CASE("DemoProgram::run: one clear line for what escapes, status 1") {
    DemoProgram p("demo_test", "A test demo.", kKeys);
    REQUIRE_FALSE(parse(p, {"--memory-mb", "0"}).status);
    std::ostringstream err;
    auto* old = std::cerr.rdbuf(err.rdbuf());
    const int ok = p.run([] { return 0; });
    const int e1 = p.run([]() -> int { throw std::runtime_error("'x' is not a fixture"); });
    const int e2 = p.run([]() -> int { throw std::bad_alloc(); });
    p.no_display_hint = "(try --png view.png)";
    const int e3 = p.run([]() -> int { throw NoDisplay("no display"); });
    std::cerr.rdbuf(old);
    CHECK(ok == 0);
    CHECK(e1 == 1);
    CHECK(e2 == 1);
    CHECK(e3 == 1);
    const std::string s = err.str();
    CHECK(s.find("demo_test: 'x' is not a fixture\n") != std::string::npos);
    CHECK(s.find("demo_test: memory limit") != std::string::npos);
    CHECK(s.find("demo_test: no display\n(try --png view.png)\n") != std::string::npos);
}

TEST_CASE("keep_faces and boundary_edges: a cut-away cube and its rim") {
    const geolab::PolygonSoup cube = box_soup(dvec3(-1), dvec3(1));
    CHECK(boundary_edges(cube).empty());  // closed
    // keep the faces whose centroid is below z = 0.5: all but the top (z = +1) face
    const geolab::PolygonSoup open = keep_faces(cube, [](const dvec3& c) { return c.z < 0.5; });
    CHECK(open.n_faces() == 5);
    CHECK(open.positions.size() == cube.positions.size());  // indices stay valid
    const auto rim = boundary_edges(open);
    REQUIRE(rim.size() == 8);  // the top square's four edges
    for (const vec3& p : rim) CHECK(p.z == 1.0f);
    CHECK(keep_faces(cube, [](const dvec3&) { return false; }).n_faces() == 0);
    // a single triangle: all three edges
    geolab::PolygonSoup tri;
    tri.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    tri.add_face({0, 1, 2});
    CHECK(boundary_edges(tri).size() == 6);
}

TEST_CASE("category_color: nine distinct colours, cycling") {
    for (std::size_t i = 0; i < 9; ++i)
        for (std::size_t j = i + 1; j < 9; ++j) CHECK(glm::length(category_color(i) - category_color(j)) > 0.2f);
    CHECK(category_color(9) == category_color(0));
    CHECK(category_color(13) == category_color(4));
}

// ---- widgets ---------------------------------------------------------------------------------------------------

TEST_CASE("ascii_text: what the overlay font lacks, spelled in ASCII") {
    CHECK(ascii_text("plain text 0-9 {}") == "plain text 0-9 {}");
    CHECK(ascii_text("ε₁ = 0.5, ε₂ = 2") == "e1 = 0.5, e2 = 2");
    CHECK(ascii_text("64³ cells") == "64^3 cells");
    CHECK(ascii_text("a − b × c · d ≤ e") == "a - b x c * d <= e");
    CHECK(ascii_text("Bézier, θ = 90°") == "Bezier, th = 90deg");
    CHECK(ascii_text("A ∪ B ∩ C") == "A U B n C");
    CHECK(ascii_text("two\nlines\tand a tab") == "two\nlines and a tab");
    CHECK(ascii_text("check ✓") == "check ?");
    CHECK(ascii_text("bad \xff byte, cut \xce") == "bad ? byte, cut ?");  // malformed UTF-8: one '?' a byte
}

TEST_CASE("text_size and add_text: glyph strokes inside the measured box, scaled") {
    const glm::vec2 one = text_size("Ag", 1.0f), two = text_size("Ag", 2.0f);
    CHECK(one.x > 6.0f);
    CHECK(two.x == doctest::Approx(2 * one.x));
    CHECK(two.y == doctest::Approx(2 * one.y));
    CHECK(text_size("Ag\nAg", 1.0f).y == doctest::Approx(one.y + 12.0f));
    CHECK(text_size("Agg", 1.0f).x > one.x);
    CHECK(text_size("ε", 1.0f).x == text_size("e", 1.0f).x);  // drawn as ascii_text spells it
    Scene s;
    const glm::vec2 at(30.0f, 40.0f);
    add_text(s, at, "Ag", 2.0f, {0, 0, 0, 1});
    REQUIRE(s.overlay().size() > 4);
    CHECK_FALSE(s.empty());
    CHECK(s.meshes().empty());
    for (const Scene::Rect& r : s.overlay()) {
        CHECK(r.lo.x >= at.x - 1e-4f);
        CHECK(r.lo.y >= at.y - 1e-4f);
        CHECK(r.hi.x <= at.x + two.x + 1e-4f);
        CHECK(r.hi.y <= at.y + two.y + 2.0f * 2 + 1e-4f);  // descenders reach 2 units below the baseline box
    }
    s.clear();
    CHECK(s.overlay().empty());
    s.add_rect({5, 5}, {5, 9}, {0, 0, 0, 1});  // empty: nothing
    CHECK(s.empty());
}

TEST_CASE("Slider: snapping to the step and range, linear and logarithmic positions") {
    double x = 0.0;
    const Slider lin = slider("a", x, -2.0, 2.0, 0.01);
    CHECK(lin.snap(0.123) == doctest::Approx(0.12));
    CHECK(lin.snap(5.0) == 2.0);
    CHECK(lin.snap(-7.0) == -2.0);
    CHECK(lin.fraction(0.0) == doctest::Approx(0.5));
    CHECK(lin.fraction(-2.0) == 0.0);
    CHECK(lin.fraction(3.0) == 1.0);  // clamped
    CHECK(lin.value_at(0.75) == doctest::Approx(1.0));
    CHECK(lin.value_at(-1.0) == -2.0);
    for (double v : {-1.37, 0.0, 0.5, 1.99, 0.3, -0.1}) CHECK(lin.value_at(lin.fraction(v)) == v);  // decimal, exactly
    CHECK(lin.snap(-0.4999) == -0.5);
    CHECK(lin.snap(1e-9) == 0.0);
    const Slider fine{.label = "e", .min = 0.05, .max = 5.0, .step = 0.01, .log = true};
    for (double v : {0.05, 0.3, 1.0, 1.1, 4.99}) CHECK(fine.value_at(fine.fraction(v)) == v);
    const Slider odd{.label = "o", .min = 0.0, .max = 1.0, .step = 1.0 / 3.0};  // not decimal: plain multiples
    CHECK(odd.snap(0.7) == doctest::Approx(2.0 / 3.0));

    const Slider coarse{.label = "c", .min = 0.0, .max = 1.0, .step = 0.3};
    CHECK(coarse.snap(1.0) == doctest::Approx(0.9));  // 1.2 would leave the range
    CHECK(coarse.snap(0.14) == 0.0);
    CHECK(coarse.snap(0.16) == doctest::Approx(0.3));

    int res = 64;
    const Slider lg = slider("resolution", res, 8, 256, true);
    CHECK(lg.fraction(8) == 0.0);
    CHECK(lg.fraction(256) == doctest::Approx(1.0));
    CHECK(lg.fraction(16) == doctest::Approx(0.2));  // 8 · 2^(5 · 0.2)
    CHECK(lg.value_at(0.2) == 16.0);
    CHECK(lg.value_at(0.61) == 66.0);  // 8 · 32^0.61 = 66.3, rounded to an integer
    CHECK(lg.value_at(0.5) == 45.0);   // 8 · √32 = 45.25
    lg.set(lg.value_at(0.6));
    CHECK(res == 64);
    CHECK(lg.get() == 64.0);
    CHECK(lg.value_text() == "64");

    int kernel = 1;
    const Slider ch = choice("kernel", kernel, {"Blinn", "Nishimura", "Wyvill"});
    CHECK(ch.min == 0.0);
    CHECK(ch.max == 2.0);
    CHECK(ch.value_text() == "Nishimura");
    ch.set(ch.value_at(1.0));
    CHECK(kernel == 2);
    CHECK(ch.value_text() == "Wyvill");
    x = 1.0 / 3.0;
    CHECK(lin.value_text() == "0.333");
}

TEST_CASE("slider_rect and add_sliders: rows stacked, the knob where the value is") {
    double a = 0.5, b = -1.0;
    const std::vector<Slider> sliders{slider("a", a, 0.0, 1.0), slider("a long label", b, -1.0, 1.0)};
    const SliderRect r0 = slider_rect(sliders, 0), r1 = slider_rect(sliders, 1);
    CHECK(r1.row_lo.y == doctest::Approx(r0.row_hi.y));
    CHECK(r0.row_lo.x == r1.row_lo.x);
    CHECK(r0.track_lo.x == r1.track_lo.x);  // one label column, as wide as the widest label
    CHECK(r0.track_lo.x - r0.row_lo.x >= text_size("a long label").x);
    CHECK(r0.track_hi.x - r0.track_lo.x > 100.0f);
    CHECK(r0.contains(r0.track_lo.x, 0.5 * (r0.track_lo.y + r0.track_hi.y)));
    CHECK_FALSE(r0.contains(r0.row_hi.x + 1, r0.row_lo.y + 1));
    CHECK_FALSE(r0.contains(r0.track_lo.x, r1.row_lo.y + 2));
    Scene s;
    add_sliders(s, sliders);
    // the knobs: the rectangles 10 pixels wide centred on the tracks' value positions
    int knobs = 0;
    for (const Scene::Rect& r : s.overlay()) {
        if (r.hi.x - r.lo.x != 10.0f) continue;
        const float cx = 0.5f * (r.lo.x + r.hi.x), cy = 0.5f * (r.lo.y + r.hi.y);
        if (r0.contains(cx, cy)) {
            CHECK(cx == doctest::Approx(0.5 * (r0.track_lo.x + r0.track_hi.x)));
            ++knobs;
        }
        if (r1.contains(cx, cy)) {
            CHECK(cx == doctest::Approx(r1.track_lo.x));
            ++knobs;
        }
    }
    CHECK(knobs == 2);
    Scene none;
    add_sliders(none, {});
    CHECK(none.empty());
}

TEST_CASE("add_status: wrapped at spaces, at most four lines, along the bottom") {
    Scene s;
    add_status(s, "short", 400, 300);
    REQUIRE_FALSE(s.overlay().empty());
    const Scene::Rect band = s.overlay().front();
    CHECK(band.hi.y == 300.0f);
    CHECK(band.hi.x == 400.0f);
    CHECK(band.lo.y > 250.0f);  // one line
    Scene many;
    std::string words;
    for (int i = 0; i < 200; ++i) words += "word" + std::to_string(i) + " ";
    add_status(many, words, 400, 300);
    const Scene::Rect tall = many.overlay().front();
    CHECK(tall.lo.y < band.lo.y - 60.0f);
    CHECK(tall.lo.y > 300.0f - 4.0f * 24.0f - 30.0f);  // four lines at most
    for (const Scene::Rect& r : many.overlay()) CHECK(r.hi.x <= 400.0f);
    Scene empty;
    add_status(empty, "", 400, 300);
    CHECK(empty.empty());
}

TEST_CASE("Camera::pixel inverts Camera::ray; orbit and pan move the camera as the mouse does") {
    Camera cam = Camera::framing({dvec3(-1), dvec3(1)}, 35.0f, 25.0f);
    for (auto [x, y] : {std::pair{10.0, 20.0}, {320.0, 240.0}, {633.5, 470.25}}) {
        const Ray r = cam.ray(x, y, 640, 480);
        const dvec3 p = dvec3(r.origin) + 3.7 * dvec3(r.direction);
        const dvec3 q = cam.pixel(p, 640, 480);
        CHECK(std::abs(q.x - x) < 0.02);  // (the ray is in float)
        CHECK(std::abs(q.y - y) < 0.02);
        CHECK(q.z > 0.0);
    }
    CHECK(cam.pixel(dvec3(cam.eye()) - 2.0 * (dvec3(cam.target) - dvec3(cam.eye())), 640, 480).z < 0.0);  // behind
    const Camera before = cam;
    cam.orbit(10, -5);
    CHECK(cam.yaw_deg == doctest::Approx(before.yaw_deg - 4.0f));
    CHECK(cam.pitch_deg == doctest::Approx(before.pitch_deg - 2.0f));
    cam.orbit(0, 1000);
    CHECK(cam.pitch_deg == 89.0f);
    Camera p = before;
    const dvec3 on_target = p.pixel(dvec3(p.target), 640, 480);
    p.pan(20, 0, 640, 480);
    // the old target now appears 20 pixels to the right (it moved with the cursor)
    CHECK(p.pixel(dvec3(before.target), 640, 480).x == doctest::Approx(on_target.x + 20).epsilon(1e-3));
}

namespace {

// A toy demo for the session: a point at (x, y, 0) that a slider moves along x and a drag moves in z = 0, a
// resolution slider, keys and picks counted; seen from +z.
struct Toy {
    double x = 0.0, y = 0.0;
    int res = 16, keys = 0, picks = 0, drags = 0, draws = 0;
    bool dragging = false;
    DemoProgram::Window window() {
        return {.title = "toy",
                .draw =
                    [this] {
                        ++draws;
                        Frame f;
                        f.scene.add_points({vec3(float(x), float(y), 0.0f)}, vec3(1, 0, 0), 20.0f);
                        f.scene.add_lines({vec3(-2, -2, 0), vec3(2, 2, 0)}, vec3(0, 0, 1));
                        f.camera = camera_from({dvec3(-2, -2, 0), dvec3(2, 2, 0)}, {0, 0, 1});
                        f.status = "x = " + fmt(x) + ", y = " + fmt(y) + ", res " + std::to_string(res);
                        return f;
                    },
                .key = [this](int) { return ++keys, false; },
                .pick = [this](const Ray&) { return ++picks, false; },
                .sliders = [this] { return std::vector<Slider>{slider("x", x, -2.0, 2.0), slider("ε₁", res, 4, 64, true)}; },
                .drag = [this](const Drag& d) {
                    ++drags;
                    if (d.phase == MouseEvent::Phase::press) {
                        dragging = d.nearest({dvec3(x, y, 0)}).has_value();
                        return dragging;
                    }
                    if (const auto p = d.on_plane(dvec3(0.0), dvec3(0, 0, 1))) x = p->x, y = p->y;
                    return false;
                }};
    }
};

}  // namespace

TEST_CASE("DemoSession: sliders moved by the mouse and by scripts, the demo's drags, orbits, keys, clicks") {
    Toy toy;
    DemoSession s(toy.window(), 640, 480);
    std::ostringstream log;
    s.log = &log;
    REQUIRE(s.sliders().size() == 2);
    CHECK(toy.draws == 1);
    const int v0 = s.frame_version();
    const SliderRect r = slider_rect(s.sliders(), 0);
    const double ty = 0.5 * (r.track_lo.y + r.track_hi.y);
    using P = MouseEvent::Phase;

    SUBCASE("a press on the track sets the value there, moves follow, one redraw a flush, the release reports") {
        CHECK(s.mouse({P::press, r.track_lo.x, ty, 640, 480, false}));
        CHECK(toy.x == -2.0);
        CHECK(s.mouse({P::move, r.track_hi.x + 50, ty + 40, 640, 480, false}));  // beyond the end: clamped
        CHECK(s.mouse({P::move, 0.75 * r.track_lo.x + 0.25 * r.track_hi.x, ty, 640, 480, false}));
        CHECK(toy.x == doctest::Approx(-1.0));
        CHECK(toy.draws == 1);  // not yet: moves are drawn at the flush
        s.flush();
        CHECK(toy.draws == 2);
        s.flush();
        CHECK(toy.draws == 2);
        s.mouse({P::release, 0.75 * r.track_lo.x + 0.25 * r.track_hi.x, ty, 640, 480, false});
        CHECK(s.frame().status.rfind("x = -1,", 0) == 0);
        CHECK(log.str() == "x = -1, y = 0, res 16\n");
        CHECK(toy.drags == 0);
        CHECK(toy.keys == 0);
    }
    SUBCASE("a press on the label or the value goes through to the demo's drag (and then the camera)") {
        CHECK_FALSE(r.grabs(r.row_lo.x + 3, ty));
        CHECK_FALSE(r.grabs(r.row_hi.x - 3, ty));
        CHECK(r.grabs(r.track_lo.x - 5, ty));
        CHECK_FALSE(s.mouse({P::press, r.row_lo.x + 3, ty, 640, 480, false}));
        CHECK(toy.drags == 1);  // asked, and the point is not there
        s.mouse({P::release, r.row_lo.x + 3, ty, 640, 480, false});
        CHECK(toy.x == 0.0);
    }
    SUBCASE("set_slider: by label or its ASCII spelling, exact values, through the mouse path") {
        s.set_slider("x", 0.625);
        CHECK(toy.x == doctest::Approx(0.625).epsilon(1e-12));
        s.set_slider("e1", 32);  // the label "ε₁", an integer log slider
        CHECK(toy.res == 32);
        s.set_slider("ε₁", 1000);
        CHECK(toy.res == 64);
        CHECK(s.frame_version() > v0);
        CHECK(log.str() == "x = 0.625, y = 0, res 16\nx = 0.625, y = 0, res 32\nx = 0.625, y = 0, res 64\n");
        CHECK_THROWS_WITH_AS(s.set_slider("y", 1), "no slider 'y' here (sliders: x, e1)", std::invalid_argument);
    }
    SUBCASE("the demo's drag: a press on the point takes it, moves it in z = 0") {
        const glm::dvec2 from = s.pixel_of({0.0, 0.0, 0.0}), to = s.pixel_of({1.0, -0.5, 0.0});
        CHECK(from.x == doctest::Approx(320).epsilon(0.01));
        CHECK(from.y == doctest::Approx(240).epsilon(0.01));
        const Camera cam = s.camera;
        s.drag(from, to);
        CHECK(toy.dragging);
        CHECK(toy.x == doctest::Approx(1.0).epsilon(1e-4));
        CHECK(toy.y == doctest::Approx(-0.5).epsilon(1e-4));
        CHECK(s.camera.yaw_deg == cam.yaw_deg);  // the camera stayed
        CHECK(s.camera.pitch_deg == cam.pitch_deg);
        CHECK(log.str().rfind("x = 1, y = -0.5", 0) == 0);
        // a drag that does not start on the point orbits
        const int drags = toy.drags;
        s.drag({100, 100}, {150, 100});
        CHECK(toy.drags == drags + 1);  // asked at the press only
        CHECK(toy.x == doctest::Approx(1.0).epsilon(1e-4));
        CHECK(s.camera.yaw_deg == doctest::Approx(cam.yaw_deg - 20.0f));
    }
    SUBCASE("a secondary (pan) press is never captured; keys and clicks reach the demo and redraw") {
        CHECK_FALSE(s.mouse({P::press, r.track_lo.x, ty, 640, 480, true}));
        CHECK(toy.x == 0.0);
        s.key('N');
        s.click(20, 400);
        CHECK(toy.keys == 1);
        CHECK(toy.picks == 1);
        CHECK(toy.draws == 3);
    }
    SUBCASE("scripts: parse_script's steps run through the session") {
        for (const ScriptStep& step : parse_script("{x=-0.5}N{drag 0.5,0.5 0.75,0.25}{click 0.9,0.9}")) s.run(step);
        CHECK(toy.keys == 1);
        CHECK(toy.picks == 1);
        CHECK_FALSE(toy.dragging);  // the point sat at (-0.5, 0): the drag at the centre missed it and orbited
        CHECK(toy.x == -0.5);
        CHECK_THROWS_WITH_AS(s.run(parse_script("{click 0,0,100}")[0]), doctest::Contains("behind the camera"),
                             std::invalid_argument);
    }
    SUBCASE("overlay: the sliders and the status line") {
        const auto with = s.overlay(true), without = s.overlay(false);
        CHECK(without.size() > 10);
        CHECK(with.size() > without.size());
        CHECK(with.back().hi.y <= 480.0f);
    }
}

TEST_CASE("parse_script: keys, screenshots and commands; clear errors") {
    const auto steps = parse_script("n_S{a=-0.5}{drag 0.1,0.2 1,2,3}{click 0.5,0.5}");
    REQUIRE(steps.size() == 6);
    using K = ScriptStep::Kind;
    CHECK(steps[0].kind == K::key);
    CHECK(steps[0].key == 'N');
    CHECK(steps[1].key == ' ');
    CHECK(steps[2].kind == K::screenshot);
    CHECK(steps[3].kind == K::slider);
    CHECK(steps[3].label == "a");
    CHECK(steps[3].value == -0.5);
    CHECK(steps[4].kind == K::drag);
    CHECK(steps[4].from == std::vector<double>{0.1, 0.2});
    CHECK(steps[4].to == std::vector<double>{1, 2, 3});
    CHECK(steps[5].kind == K::click);
    CHECK(steps[5].from == std::vector<double>{0.5, 0.5});
    CHECK(parse_script("").empty());
    for (auto [script, message] : {std::pair{"{a=x}", "{a=x}: 'x' is not a number"},
                                   {"{a=1.5.2}", "'1.5.2' is not a number"},
                                   {"{=3}", "not a command"},
                                   {"{jump 1,2}", "not a command"},
                                   {"{drag 1,2}", "drag takes two points"},
                                   {"{click 1}", "a point is x,y"},
                                   {"{drag 1,2 3,y}", "'y' is not a number"},
                                   {"N{a=1", "'{' at 1 has no matching '}'"},
                                   {"N}", "'}' at 1 closes nothing"}})
        CHECK_THROWS_WITH_AS(parse_script(script), doctest::Contains(message), std::invalid_argument);
}

TEST_CASE("overlay rectangles rendered headless: over the scene, blended, in output pixels") {
    Scene scene;
    geolab::PolygonSoup square;
    square.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    square.add_face({0, 1, 2, 3});
    scene.add_mesh(square, {.color = {0, 0, 1}, .smooth = false});
    Scene plain = scene;
    scene.add_rect({4, 10}, {18, 20}, {1, 0, 0, 1});         // opaque red over the white margin
    scene.add_rect({60, 40}, {100, 80}, {1, 0, 0, 0.5f});    // half red over the blue square's middle
    const Camera cam = whole(scene, 160.0 / 120.0, 0.0f, 0.0f);
    for (bool aa : {false, true}) {
        const Image im = render_image(scene, cam, 160, 120, aa), base = render_image(plain, cam, 160, 120, aa);
        CHECK(base.pixel(10, 15) == std::array<std::uint8_t, 4>{255, 255, 255, 255});
        CHECK(im.pixel(10, 15) == std::array<std::uint8_t, 4>{255, 0, 0, 255});
        CHECK(im.pixel(10, 25) == std::array<std::uint8_t, 4>{255, 255, 255, 255});
        CHECK(im.pixel(20, 15) == std::array<std::uint8_t, 4>{255, 255, 255, 255});
        const auto mid = im.pixel(80, 60), under = base.pixel(80, 60);
        CHECK(under[2] > 150);  // blue
        for (int c = 0; c < 3; ++c) CHECK(std::abs(int(mid[c]) - 0.5 * ((c == 0) * 255 + under[c])) <= 2.0);
        CHECK(im.pixel(80, 30) == base.pixel(80, 30));  // outside the rectangles: unchanged
    }
}

TEST_CASE("DemoProgram::show with --png: scripted input applied headless, --widgets draws the sliders") {
    const auto dir = std::filesystem::temp_directory_path() / ("geolab_show_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    auto run = [&](std::vector<std::string> args, Toy& toy, std::string& out) {
        DemoProgram p("demo_test", "A test demo.", kKeys);
        args.insert(args.end(), {"--memory-mb", "0", "--size", "160"});
        const Parsed r = parse(p, args);
        REQUIRE_FALSE(r.status);
        std::ostringstream o;
        auto* old = std::cout.rdbuf(o.rdbuf());
        const int status = p.run([&] { return p.show(toy.window()); });
        std::cout.rdbuf(old);
        out = o.str();
        return status;
    };
    const std::string plain = (dir / "plain.png").string(), moved = (dir / "moved.png").string(),
                      widgets = (dir / "widgets.png").string();
    Toy a, b, c;
    std::string out_a, out_b, out_c;
    CHECK(run({"--png", plain}, a, out_a) == 0);
    CHECK(run({"--png", moved, "--keys", "{x=1.5}N"}, b, out_b) == 0);
    CHECK(run({"--png", widgets, "--widgets"}, c, out_c) == 0);
    CHECK(out_a == "x = 0, y = 0, res 16\nwrote " + plain + "\n");
    CHECK(b.x == doctest::Approx(1.5));
    CHECK(b.keys == 1);
    CHECK(out_b.find("x = 1.5, y = 0, res 16\nwrote " + moved) != std::string::npos);
    for (const auto& f : {plain, moved, widgets}) CHECK(std::filesystem::file_size(f) > 100);
    CHECK(std::filesystem::file_size(plain) != std::filesystem::file_size(moved));
    CHECK(std::filesystem::file_size(plain) != std::filesystem::file_size(widgets));
    // the same pictures from a session: the red point moved right; the widgets cover the top left
    Toy t;
    DemoSession s(t.window(), 160, 120);
    auto picture = [&](bool widgets) {
        Scene sc = s.frame().scene;
        if (widgets)
            for (const Scene::Rect& r : s.overlay()) sc.add_rect(r.lo, r.hi, r.color);
        return render_image(sc, s.camera, 160, 120);
    };
    auto red = [](std::array<std::uint8_t, 4> p) { return p[0] > 150 && p[1] < 80 && p[2] < 80; };
    const glm::dvec3 at0 = s.camera.pixel({0, 0, 0}, 160, 120), at1 = s.camera.pixel({1.5, 0, 0}, 160, 120);
    const Image before = picture(false);
    CHECK(red(before.pixel(int(at0.x), int(at0.y))));
    CHECK_FALSE(red(before.pixel(int(at1.x), int(at1.y))));
    const SliderRect track = slider_rect(s.sliders(), 0);
    const int tx = int(track.track_lo.x) + 3, ty = int(0.5f * (track.track_lo.y + track.track_hi.y));
    CHECK(before.pixel(tx, ty) == std::array<std::uint8_t, 4>{255, 255, 255, 255});
    CHECK(picture(true).pixel(tx, ty)[0] < 200);  // the slider's grey track
    s.set_slider("x", 1.5);
    const Image after = picture(false);
    CHECK_FALSE(red(after.pixel(int(at0.x), int(at0.y))));
    CHECK(red(after.pixel(int(at1.x), int(at1.y))));
    SUBCASE("a bad script is a usage error before anything runs") {
        DemoProgram p("demo_test", "A test demo.", kKeys);
        const Parsed r = parse(p, {"--memory-mb", "0", "--png", plain, "--keys", "{x=}"});
        REQUIRE(r.status);
        CHECK(*r.status == 2);
        CHECK(r.err.find("demo_test: --keys: {x=}: '' is not a number") != std::string::npos);
    }
    SUBCASE("a slider that is not there: one line, status 1") {
        Toy t;
        std::string out;
        std::ostringstream err;
        auto* old = std::cerr.rdbuf(err.rdbuf());
        CHECK(run({"--png", plain, "--keys", "{zoom=2}"}, t, out) == 1);
        std::cerr.rdbuf(old);
        CHECK(err.str() == "demo_test: no slider 'zoom' here (sliders: x, e1)\n");
    }
    std::filesystem::remove_all(dir);
}
