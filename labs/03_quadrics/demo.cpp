// Lab 03 demo: change a quadric's ten coefficients (or a superquadric's two exponents) with the sliders or keys, and
// watch the surface and its type follow. The quadric is drawn as the hits of a grid of rays through its clipping box (your intersect_in_box),
// its type is your classify; the superquadric is your tessellate_superquadric. --figures renders the handout's
// figures with your render_lambert: one image per type (17) and the superquadric family over (ε₁, ε₂).
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <stb/stb_easy_font.h>

#include "geolab/quadrics.hpp"
#include "geolab/render/demo.hpp"
#include "geolab/render/render.hpp"

namespace {
namespace gr = geolab::render;
namespace q = geolab::quadrics;

const char* kKeys =
    "Window keys:\n"
    "  sliders         drag a coefficient a ... d (superquadric: e1, e2) with the mouse, top left\n"
    "  N / P           next / previous example quadric (one of each of the 17 types)\n"
    "  1 ... 9, 0      select coefficient a b c f g h p q r d (superquadric: 1 = ε₁, 2 = ε₂)\n"
    "  + / -           change the selected coefficient by 0.1 (exponent: by 0.1, kept > 0.05)\n"
    "  Z               set the selected coefficient to 0\n"
    "  Q               quadric <-> superquadric\n"
    "  Home, S, Esc    re-frame, screenshot (out/screenshots/), quit";

// One example of each type: name, the ten coefficients a b c f g h p q r d (the handout's table).
struct Example {
    const char* file;
    std::array<double, 10> k;
};
const Example kExamples[17] = {
    {"real_ellipsoid", {0.444, 1, 1.778, 0, 0, 0, 0, 0, 0, -1}},
    {"imaginary_ellipsoid", {1, 1, 1, 0, 0, 0, 0, 0, 0, 1}},
    {"hyperboloid_one_sheet", {1, 1, -1, 0, 0, 0, 0, 0, 0, -1}},
    {"hyperboloid_two_sheets", {1, 1, -1, 0, 0, 0, 0, 0, 0, 1}},
    {"real_cone", {1, 1, -1, 0, 0, 0, 0, 0, 0, 0}},
    {"imaginary_cone", {1, 1, 1, 0, 0, 0, 0, 0, 0, 0}},
    {"elliptic_paraboloid", {1, 1, 0, 0, 0, 0, 0, 0, -0.5, 0}},
    {"hyperbolic_paraboloid", {1, -1, 0, 0, 0, 0, 0, 0, -0.5, 0}},
    {"real_elliptic_cylinder", {1, 0.5, 0, 0, 0, 0, 0, 0, 0, -1}},
    {"imaginary_elliptic_cylinder", {1, 1, 0, 0, 0, 0, 0, 0, 0, 1}},
    {"hyperbolic_cylinder", {1, -1, 0, 0, 0, 0, 0, 0, 0, -0.5}},
    {"parabolic_cylinder", {1, 0, 0, 0, 0, 0, 0, 0, -0.5, 0}},
    {"real_intersecting_planes", {1, -1, 0, 0, 0, 0, 0, 0, 0, 0}},
    {"imaginary_intersecting_planes", {1, 1, 0, 0, 0, 0, 0, 0, 0, 0}},
    {"real_parallel_planes", {1, 0, 0, 0, 0, 0, 0, 0, 0, -1}},
    {"imaginary_parallel_planes", {1, 0, 0, 0, 0, 0, 0, 0, 0, 1}},
    {"coincident_planes", {1, 0, 0, 0, 0, 0, 0, 0, 0, 0}},
};
const char* kNames[10] = {"a", "b", "c", "f", "g", "h", "p", "q", "r", "d"};
constexpr double kBox = 2.0;  // the clipping box [-2, 2]³

q::Coefficients coefficients(const std::array<double, 10>& v) {
    return {v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9]};
}

struct Demo {
    int example = 0;
    std::array<double, 10> k = kExamples[0].k;
    bool superquadric = false;
    double e1 = 1.0, e2 = 1.0;
    int selected = 0;  // coefficient index, or 0/1 = ε₁/ε₂
};

// The quadric's matrix as the lecture writes it (the demo's own, so that the picture does not hang on to_matrix).
glm::dmat4 matrix(const std::array<double, 10>& v) {
    const double a = v[0], b = v[1], c = v[2], f = v[3], g = v[4], h = v[5], p = v[6], qq = v[7], r = v[8], d = v[9];
    return glm::dmat4(a, h, g, p, h, b, f, qq, g, f, c, r, p, qq, r, d);
}

glm::vec3 shade(const glm::dvec3& n) {
    const glm::dvec3 l = glm::normalize(glm::dvec3(0.4, -0.6, 1.0));
    const float v = float(std::abs(glm::dot(n, l)));
    return glm::vec3(0.18f, 0.3f, 0.55f) + v * glm::vec3(0.5f, 0.55f, 0.45f);
}

std::string coefficient_line(const std::array<double, 10>& v) {
    std::string s;
    for (int i = 0; i < 10; ++i) s += std::string(i ? " " : "") + kNames[i] + "=" + gr::fmt(v[i], 3);
    return s;
}

gr::Frame draw(const Demo& d) {
    gr::Frame fr;
    gr::Issues issues;
    std::vector<glm::vec3> box;
    if (d.superquadric) {
        const q::Superquadric s{{1.0, 1.0, 1.0}, d.e1, d.e2};
        gr::add_box_edges(box, glm::dvec3(-1.0), glm::dvec3(1.0));
        fr.scene.add_lines(box, {0.55f, 0.55f, 0.6f}, 1.0f);
        std::string volume;
        gr::attempt(issues, "tessellate_superquadric", [&] {
            fr.scene.add_mesh(q::tessellate_superquadric(s, 48, 96),
                              {.color = {0.35f, 0.55f, 0.85f}, .smooth = true, .wireframe = false});
        });
        gr::attempt(issues, "superquadric_volume", [&] { volume = ", volume " + gr::fmt(q::superquadric_volume(s), 4); });
        fr.camera = gr::camera_from({glm::dvec3(-1.0), glm::dvec3(1.0)}, {1.0, -1.3, 0.9}, {0, 0, 1});
        fr.status = "superquadric ε₁ = " + gr::fmt(d.e1, 2) + ", ε₂ = " + gr::fmt(d.e2, 2) + volume + " | selected " +
                    (d.selected == 1 ? "ε₂" : "ε₁");
    } else {
        const glm::dmat4 Q = matrix(d.k);
        gr::add_box_edges(box, glm::dvec3(-kBox), glm::dvec3(kBox));
        fr.scene.add_lines(box, {0.55f, 0.55f, 0.6f}, 1.0f);
        // a grid of rays along each axis through the box: every hit is a point of the surface
        std::vector<glm::vec3> points, colors;
        const int n = 110;
        gr::attempt(issues, "intersect_in_box", [&] {
            for (int axis = 0; axis < 3; ++axis)
                for (int i = 0; i < n; ++i)
                    for (int j = 0; j < n; ++j) {
                        glm::dvec3 o(0.0), dir(0.0);
                        o[axis] = -kBox - 1;
                        o[(axis + 1) % 3] = -kBox + 2 * kBox * (i + 0.5) / n;
                        o[(axis + 2) % 3] = -kBox + 2 * kBox * (j + 0.5) / n;
                        dir[axis] = 1;
                        for (const q::Hit& h : q::intersect_in_box(Q, {o, dir}, {glm::dvec3(-kBox), glm::dvec3(kBox)})) {
                            points.push_back(glm::vec3(h.point));
                            colors.push_back(shade(h.normal));
                        }
                    }
        });
        if (!points.empty()) fr.scene.add_points(points, colors, 2.5f);
        std::string type = "?";
        gr::attempt(issues, "classify", [&] {
            const q::QuadricType t = q::classify(Q);
            type = q::type_name(t) + "  (" + q::canonical_form(t) + ")";
        });
        fr.camera = gr::camera_from({glm::dvec3(-kBox), glm::dvec3(kBox)}, {1.0, -1.3, 0.9}, {0, 0, 1});
        fr.status = type + " | " + coefficient_line(d.k) + " | selected " + kNames[d.selected] + " | " +
                    std::to_string(points.size()) + " ray hits";
    }
    if (issues.any()) fr.status += " | " + issues.str();
    return fr;
}

// The sliders: the ten coefficients in [-2, 2] by 0.01, or the superquadric's exponents on a log scale.
std::vector<gr::Slider> sliders(Demo& d) {
    std::vector<gr::Slider> s;
    if (d.superquadric) {
        s.push_back(gr::slider("ε₁", d.e1, 0.05, 5.0, 0.01, true));
        s.push_back(gr::slider("ε₂", d.e2, 0.05, 5.0, 0.01, true));
    } else {
        for (int i = 0; i < 10; ++i) s.push_back(gr::slider(kNames[i], d.k[std::size_t(i)], -2.0, 2.0, 0.01));
    }
    return s;
}

bool on_key(Demo& d, int key) {
    const int count = d.superquadric ? 2 : 10;
    auto change = [&](double by) {
        if (d.superquadric) {
            double& e = d.selected == 1 ? d.e2 : d.e1;
            e = std::max(0.05, std::round((e + by) * 100) / 100);
        } else {
            d.k[d.selected] = std::round((d.k[d.selected] + by) * 1000) / 1000;
        }
    };
    switch (key) {
        case 'N': case 'P':
            d.example = (d.example + (key == 'N' ? 1 : 16)) % 17;
            d.k = kExamples[d.example].k;
            d.superquadric = false;
            return false;
        case 'Q':
            d.superquadric = !d.superquadric;
            d.selected = 0;
            return true;
        case '=': case '+': case 334: change(0.1); return false;
        case '-': case 333: change(-0.1); return false;
        case 'Z':
            if (!d.superquadric) d.k[d.selected] = 0;
            return false;
        default:
            if (key >= '0' && key <= '9') {
                const int i = key == '0' ? 9 : key - '1';
                if (i < count) d.selected = i;
            }
            return false;
    }
}

// ---- figures: render_lambert's image, on a light background, tinted, with the box and a label -----------------

// The pixel where the camera sees the point x (the inverse of PinholeCamera::ray); false behind the camera.
bool project(const q::PinholeCamera& cam, const glm::dvec3& x, int w, int h, double& px, double& py) {
    const glm::dvec3 forward = glm::normalize(cam.target - cam.eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, cam.up));
    const glm::dvec3 upv = glm::cross(right, forward);
    const glm::dvec3 v = x - cam.eye;
    const double z = glm::dot(v, forward);
    if (z <= 1e-9) return false;
    const double t = std::tan(cam.fov_deg * 3.14159265358979323846 / 360.0), aspect = double(w) / h;
    const double sx = glm::dot(v, right) / z / (t * aspect), sy = glm::dot(v, upv) / z / t;
    px = (sx + 1) / 2 * w - 0.5;
    py = (1 - sy) / 2 * h - 0.5;
    return true;
}

void put(gr::Image& img, int x, int y, glm::vec3 c, float alpha = 1.0f) {
    if (x < 0 || y < 0 || x >= img.width || y >= img.height) return;
    std::uint8_t* p = img.rgba.data() + 4 * (std::size_t(y) * img.width + x);
    for (int i = 0; i < 3; ++i) p[i] = std::uint8_t(std::lround((1 - alpha) * p[i] + alpha * 255 * c[i]));
}

void line(gr::Image& img, double x0, double y0, double x1, double y1, glm::vec3 c, float alpha) {
    const int steps = int(std::ceil(std::max(std::abs(x1 - x0), std::abs(y1 - y0)))) + 1;
    for (int i = 0; i <= steps; ++i) {
        const double s = double(i) / steps;
        put(img, int(std::lround(x0 + s * (x1 - x0))), int(std::lround(y0 + s * (y1 - y0))), c, alpha);
    }
}

void segment3(gr::Image& img, const q::PinholeCamera& cam, glm::dvec3 a, glm::dvec3 b, glm::vec3 c, float alpha) {
    double ax, ay, bx, by;
    if (project(cam, a, img.width, img.height, ax, ay) && project(cam, b, img.width, img.height, bx, by))
        line(img, ax, ay, bx, by, c, alpha);
}

// Text with stb_easy_font (its quads are axis-aligned rectangles), scaled by `scale`, at (x, y).
void text(gr::Image& img, const std::string& s, int x, int y, int scale, glm::vec3 c) {
    static char buffer[60000];
    const int quads = stb_easy_font_print(0, 0, const_cast<char*>(s.c_str()), nullptr, buffer, sizeof buffer);
    for (int qd = 0; qd < quads; ++qd) {
        const float* v = reinterpret_cast<const float*>(buffer + qd * 4 * 16);  // 4 vertices of 16 bytes: x y z rgba
        const int x0 = int(v[0]), y0 = int(v[1]), x1 = int(v[8]), y1 = int(v[9]);
        for (int yy = y0 * scale; yy < y1 * scale; ++yy)
            for (int xx = x0 * scale; xx < x1 * scale; ++xx) put(img, x + xx, y + yy, c);
    }
}
int text_width(const std::string& s) { return stb_easy_font_width(const_cast<char*>(s.c_str())); }

// render_lambert's grey image made readable: misses become a light background, hits a tinted shade.
void recolor(gr::Image& img, glm::vec3 tint) {
    for (std::size_t i = 0; i < img.rgba.size(); i += 4) {
        std::uint8_t* p = img.rgba.data() + i;
        if (p[0] == 0) {
            p[0] = 247, p[1] = 247, p[2] = 250;  // a miss (hits are at least round(255 · 0.1))
        } else {
            const float v = p[0] / 255.0f;
            for (int k = 0; k < 3; ++k) p[k] = std::uint8_t(std::lround(255 * std::min(1.0f, 0.12f + 0.95f * v * tint[k])));
        }
        p[3] = 255;
    }
}

void box_edges(gr::Image& img, const q::PinholeCamera& cam, double s, float alpha) {
    std::vector<glm::vec3> e;
    gr::add_box_edges(e, glm::dvec3(-s), glm::dvec3(s));
    for (std::size_t i = 0; i + 1 < e.size(); i += 2) segment3(img, cam, e[i], e[i + 1], {0.35f, 0.35f, 0.42f}, alpha);
}

q::PinholeCamera figure_camera(double extent) {
    q::PinholeCamera cam;
    cam.up = {0, 0, 1};
    cam.fov_deg = 36;
    cam.eye = 6.2 * extent * glm::normalize(glm::dvec3(1.0, -1.3, 0.75));  // the box [-s, s]³ fits with a margin
    return cam;
}

// What each imaginary type has that is real (drawn in red on its figure), and why the double plane's shading is noise.
std::string imaginary_note(q::QuadricType t) {
    using T = q::QuadricType;
    switch (t) {
        case T::imaginary_ellipsoid: return "no real point: x^2 + y^2 + z^2 = -1";
        case T::imaginary_cone: return "one real point: the origin";
        case T::imaginary_elliptic_cylinder: return "no real point: x^2 + y^2 = -1";
        case T::imaginary_intersecting_planes: return "one real line: the z axis";
        case T::imaginary_parallel_planes: return "no real point: x^2 = -1";
        case T::coincident_planes: return "a double plane: the gradient is 0 on it,\nso the normal (the shading) is rounding noise";
        default: return "";
    }
}

int render_figures(gr::FigureWriter w) {
    const int W = std::max(480, w.width()), H = W * 3 / 4;  // at least 480 × 360
    int failed = 0;
    for (const Example& ex : kExamples) {
        const std::string file = std::string(ex.file) + ".png";
        try {
            q::Scene scene;
            scene.Q = matrix(ex.k);
            scene.box = {glm::dvec3(-kBox), glm::dvec3(kBox)};
            scene.light = {0.4, -0.6, 1.0};
            const q::PinholeCamera cam = figure_camera(kBox);
            gr::Image img = q::render_lambert(scene, cam, W, H);
            recolor(img, {0.45f, 0.65f, 1.0f});
            box_edges(img, cam, kBox, 0.55f);
            const q::QuadricType t = q::classify(scene.Q);
            const std::string note = imaginary_note(t);
            if (t == q::QuadricType::imaginary_cone) {
                double px, py;
                if (project(cam, glm::dvec3(0.0), W, H, px, py))
                    for (int dy = -4; dy <= 4; ++dy)
                        for (int dx = -4; dx <= 4; ++dx)
                            if (dx * dx + dy * dy <= 16) put(img, int(px) + dx, int(py) + dy, {0.85f, 0.15f, 0.1f});
            }
            if (t == q::QuadricType::imaginary_intersecting_planes)
                for (int k = -1; k <= 1; ++k)
                    segment3(img, cam, {0.004 * k, 0, -kBox}, {0.004 * k, 0, kBox}, {0.85f, 0.15f, 0.1f}, 1.0f);
            text(img, q::type_name(t), 10, 8, 3, {0.1f, 0.1f, 0.15f});
            text(img, q::canonical_form(t) == "" ? "" : coefficient_line(ex.k), 10, H - 22, 2, {0.3f, 0.3f, 0.35f});
            if (!note.empty()) text(img, note, 10, 40, 2, {0.75f, 0.12f, 0.08f});
            w.write(file, img, q::type_name(t) + ", rendered by render_lambert, box [-2, 2]³");
        } catch (const geolab::NotImplemented& e) {
            w.skip(file, std::string("not implemented yet: ") + e.what());
            ++failed;
        } catch (const std::exception& e) {
            w.skip(file, e.what());
            ++failed;
        }
    }
    // the superquadric family: rows ε₁ (north-south), columns ε₂ (east-west)
    try {
        const double es[4] = {0.25, 1.0, 2.0, 3.0};
        const int pw = W / 2, ph = H / 2;
        std::vector<gr::Image> rows;
        for (double e1 : es) {
            std::vector<gr::Image> panels;
            for (double e2 : es) {
                q::Scene scene;
                scene.is_superquadric = true;
                scene.sq = {{1.0, 1.0, 1.0}, e1, e2};
                scene.light = {0.4, -0.6, 1.0};
                const q::PinholeCamera cam = figure_camera(1.0);
                gr::Image img = q::render_lambert(scene, cam, pw, ph);
                recolor(img, {1.0f, 0.7f, 0.4f});
                std::string label = "e1 = " + gr::fmt(e1, 2) + ", e2 = " + gr::fmt(e2, 2);
                text(img, label, (pw - 2 * text_width(label)) / 2, 6, 2, {0.1f, 0.1f, 0.15f});
                panels.push_back(std::move(img));
            }
            rows.push_back(gr::hstack(panels, 4));
        }
        // stack the rows (hstack of transposed images would do; rows are equal in width)
        gr::Image grid;
        grid.width = rows[0].width;
        grid.height = 0;
        for (const auto& r : rows) grid.height += r.height + 4;
        grid.height -= 4;
        grid.rgba.assign(std::size_t(4) * grid.width * grid.height, 200);
        int y0 = 0;
        for (const auto& r : rows) {
            std::copy(r.rgba.begin(), r.rgba.end(), grid.rgba.begin() + std::size_t(4) * y0 * grid.width);
            y0 += r.height + 4;
        }
        w.write("superquadric_grid.png", grid,
                "superquadrics over ε₁ (rows: 0.25, 1, 2, 3) and ε₂ (columns: 0.25, 1, 2, 3), rendered by render_lambert");
    } catch (const geolab::NotImplemented& e) {
        w.skip("superquadric_grid.png", std::string("not implemented yet: ") + e.what());
    } catch (const std::exception& e) {
        w.skip("superquadric_grid.png", e.what());
    }
    // the demo's own view: the ray hits of intersect_in_box for two quadrics
    Demo d;
    d.k = kExamples[2].k;
    w.write("demo_hyperboloid_points.png", draw(d));
    (void)failed;
    return w.finish();
}
}  // namespace

int main(int argc, char** argv) {
    gr::DemoProgram program("demo_03_quadrics",
                            "Lab 03 demo: a quadric's coefficients (or a superquadric's exponents) and the surface they "
                            "make, with its type",
                            kKeys);
    int example = 0;
    std::vector<double> k;
    double e1 = 0, e2 = 0;
    program.cli().add_option("--example", example, "Start with example N (0-16: one per type, the handout's table)")
        ->check(CLI::Range(0, 16))
        ->capture_default_str();
    program.cli().add_option("--coefficients", k, "Start with these ten coefficients a b c f g h p q r d")->expected(10);
    program.cli().add_option("--superquadric", e1, "Start with a superquadric of exponent ε₁ (with --e2)");
    program.cli().add_option("--e2", e2, "The superquadric's ε₂ (default 1)");
    program.no_display_hint = "try --png FILE (this view as a PNG) or --figures DIR (the handout's figures)";
    if (const auto status = program.parse(argc, argv)) return *status;
    return program.run([&] {
        if (!program.figures().empty()) return render_figures(program.figure_writer());
        Demo d;
        d.example = example;
        d.k = kExamples[example].k;
        if (k.size() == 10) std::copy(k.begin(), k.end(), d.k.begin());
        if (e1 > 0 || e2 > 0) {
            d.superquadric = true;
            d.e1 = e1 > 0 ? e1 : 1.0;
            d.e2 = e2 > 0 ? e2 : 1.0;
        }
        return program.show({.title = "geolab demo 03: quadric surfaces",
                             .draw = [&] { return draw(d); },
                             .key = [&](int key) { return on_key(d, key); },
                             .key_hint = [] { return std::string(" | sliders, N/P example, 1-0 select, +/- change, Q superquadric"); },
                             .sliders = [&] { return sliders(d); }});
    });
}
