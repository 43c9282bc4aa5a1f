// Lab 07 demo: a CSG tree (the logo, or a .scad scene) ray-cast through the student's interval lists and
// polygonized through their signed distance; keys toggle the operation at each inner node. --figures writes the
// handout's figures (the logo's tree with an image at each node, PMC vs SDF, the smooth-min family, the interval
// lists along one ray, the polygonized logo).
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "geolab/csg.hpp"
#include "geolab/render/demo.hpp"
#include "geolab/render/render.hpp"
#include "geolab/scad.hpp"

namespace {
namespace gr = geolab::render;
using namespace geolab::csg;
using glm::dvec3;

const char* kKeys =
    "Window keys:\n"
    "  1 .. 9          cycle the operation (union, intersection, difference) of inner node 1 .. 9\n"
    "                  (inner nodes numbered in the tree's order; the status line lists them)\n"
    "  sliders         each inner node's operation, the rays per axis or the resolution (top left)\n"
    "  M               ray-cast points (the interval lists) / polygonized mesh (the SDF)\n"
    "  + / -           finer / coarser (rays per axis, or polygonizer resolution)\n"
    "  Home, S, Esc    re-frame, screenshot (out/screenshots/), quit";

glm::dmat4 rot(double deg, dvec3 axis) { return glm::rotate(glm::dmat4(1.0), glm::radians(deg), axis); }

// The CSG logo: (cube ∩ sphere) − (cylinder x ∪ cylinder y ∪ cylinder z), as in data/scenes/csg_logo.scad.
Tree logo() {
    const Tree body = combine_trees(Op::intersect, leaf(Shape::box, dvec3(1.0)), leaf(Shape::sphere, {1.3, 0, 0}));
    const Tree cz = leaf(Shape::cylinder, {0.55, 0.55, 2.0});
    const Tree cx = leaf(Shape::cylinder, {0.55, 0.55, 2.0}, rot(90, {0, 1, 0}));
    const Tree cy = leaf(Shape::cylinder, {0.55, 0.55, 2.0}, rot(90, {1, 0, 0}));
    return combine_trees(Op::subtract, body, combine_trees(Op::unite, combine_trees(Op::unite, cx, cy), cz));
}

const char* op_name(Op o) {
    switch (o) {
        case Op::unite: return "∪";
        case Op::intersect: return "∩";
        case Op::subtract: return "−";
        case Op::blend: return "blend";
        default: return "leaf";
    }
}

struct Demo {
    Tree tree;
    std::string name = "logo";
    bool mesh = false;
    int rays = 160, res = 64;
    std::vector<int> inner() const {
        std::vector<int> v;
        for (int i = 0; i < int(tree.nodes.size()); ++i)
            if (tree.nodes[i].op != Op::leaf) v.push_back(i);
        return v;
    }
};

Tree subtree(const Tree& t, int root) {
    Tree s = t;
    s.root = root;
    return s;
}

// Ray-cast points: grids of parallel rays along three directions, each hit a point shaded by its normal.
void add_raycast_points(gr::Scene& scene, gr::Issues& issues, const Tree& t, int n) {
    const geolab::Box b = bounds(t);
    const dvec3 c = b.center(), ext = b.hi - b.lo;
    const double r = 0.6 * glm::length(ext);
    std::vector<glm::vec3> pts, cols;
    const dvec3 light = glm::normalize(dvec3(0.4, 0.6, 1.0));
    gr::attempt(issues, "first_hit", [&] {
        for (dvec3 dir : {dvec3(-1, -0.3, -0.2), dvec3(0.2, -1, -0.3), dvec3(-0.3, 0.2, -1)}) {
            dir = glm::normalize(dir);
            const dvec3 u = glm::normalize(glm::cross(dir, std::abs(dir.z) < 0.9 ? dvec3(0, 0, 1) : dvec3(1, 0, 0)));
            const dvec3 v = glm::cross(dir, u);
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    const dvec3 o = c - 2 * r * dir + r * ((2.0 * (i + 0.5) / n - 1) * u + (2.0 * (j + 0.5) / n - 1) * v);
                    const auto h = first_hit(t, Ray{o, dir}, 0.0);
                    if (!h) continue;
                    const float g = float(0.15 + 0.75 * std::abs(glm::dot(h->normal, light)));
                    pts.push_back(glm::vec3(h->point));
                    cols.push_back(glm::vec3(0.35f, 0.55f, 0.95f) * g + glm::vec3(0.1f));
                }
        }
    });
    if (!pts.empty()) scene.add_points(pts, cols, 3.0f);
}

gr::Frame draw(const Demo& d) {
    gr::Frame fr;
    gr::Issues issues;
    std::string what;
    if (d.mesh) {
        geolab::PolygonSoup m;
        gr::attempt(issues, "mesh_tree", [&] { m = mesh_tree(d.tree, d.res); });
        if (m.n_faces() > 0) fr.scene.add_mesh(m, {.smooth = false, .wireframe = d.res <= 48});
        what = "polygonized at " + std::to_string(d.res) + ": " + std::to_string(m.n_faces()) + " triangles";
        double v = 0;
        if (m.n_faces() > 0 && gr::attempt(issues, "volume", [&] { v = volume(m); })) what += ", volume " + gr::fmt(v, 4);
    } else {
        add_raycast_points(fr.scene, issues, d.tree, d.rays);
        what = "ray-cast, " + std::to_string(d.rays) + "² rays from 3 directions";
    }
    const geolab::Box b = bounds(d.tree);
    fr.camera = gr::camera_from(b, dvec3(1, 0.8, 0.7), dvec3(0, 0, 1));
    std::string ops;
    const auto in = d.inner();
    for (std::size_t k = 0; k < in.size() && k < 9; ++k) ops += " " + std::to_string(k + 1) + ":" + op_name(d.tree.nodes[in[k]].op);
    fr.status = d.name + " | " + what + " | nodes" + ops + (issues.any() ? " | " + issues.str() : "");
    return fr;
}

bool on_key(Demo& d, int key) {
    if (key >= '1' && key <= '9') {
        const auto in = d.inner();
        const std::size_t k = std::size_t(key - '1');
        if (k < in.size()) {
            Node& n = d.tree.nodes[in[k]];
            n.op = n.op == Op::unite ? Op::intersect : n.op == Op::intersect ? Op::subtract : Op::unite;
        }
    } else if (key == 'M') {
        d.mesh = !d.mesh;
    } else if (key == '+' || key == '=') {
        d.rays = std::min(d.rays * 2, 640);
        d.res = std::min(d.res * 2, 256);
    } else if (key == '-') {
        d.rays = std::max(d.rays / 2, 20);
        d.res = std::max(d.res / 2, 8);
    }
    return false;
}

// The sliders: each inner node's operation (up to 9), and the ray grid or the polygonizer's resolution. Redrawn
// when released (a ray-cast view takes a while).
std::vector<gr::Slider> sliders(Demo& d) {
    static const Op kOps[3] = {Op::unite, Op::intersect, Op::subtract};
    std::vector<gr::Slider> s;
    const auto in = d.inner();
    for (std::size_t k = 0; k < in.size() && k < 9; ++k) {
        Node& n = d.tree.nodes[std::size_t(in[k])];
        if (n.op == Op::blend) continue;
        gr::Slider op;
        op.label = "node " + std::to_string(k + 1);
        op.min = 0, op.max = 2, op.step = 1;
        op.get = [&n] { return n.op == Op::unite ? 0.0 : n.op == Op::intersect ? 1.0 : 2.0; };
        op.set = [&n](double v) { n.op = kOps[std::clamp(int(std::lround(v)), 0, 2)]; };
        op.format = [](double v) { return std::string(v < 0.5 ? "union" : v < 1.5 ? "intersection" : "difference"); };
        s.push_back(op);
    }
    s.push_back(d.mesh ? gr::slider("resolution", d.res, 8, 256, true) : gr::slider("rays", d.rays, 20, 640, true));
    for (gr::Slider& x : s) x.live = false;
    return s;
}

// ---- figures: images drawn pixel by pixel ----------------------------------------------------------------

gr::Image blank(int w, int h, std::uint8_t v = 255) {
    gr::Image im;
    im.width = w;
    im.height = h;
    im.rgba.assign(std::size_t(4) * w * h, v);
    for (std::size_t i = 3; i < im.rgba.size(); i += 4) im.rgba[i] = 255;
    return im;
}
void put(gr::Image& im, int x, int y, glm::vec3 c) {
    if (x < 0 || y < 0 || x >= im.width || y >= im.height) return;
    std::uint8_t* p = &im.rgba[4 * (std::size_t(y) * im.width + x)];
    for (int k = 0; k < 3; ++k) p[k] = std::uint8_t(std::clamp(c[k], 0.0f, 1.0f) * 255 + 0.5f);
}
void rect(gr::Image& im, int x0, int y0, int x1, int y1, glm::vec3 c) {
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) put(im, x, y, c);
}
// Images stacked top to bottom, centred, on white with grey gaps.
gr::Image vstack(const std::vector<gr::Image>& ims, int gap) {
    int w = 0, h = 0;
    for (const auto& im : ims) {
        w = std::max(w, im.width);
        h += im.height;
    }
    h += gap * (int(ims.size()) - 1);
    gr::Image out = blank(w, h);
    int y0 = 0;
    for (std::size_t k = 0; k < ims.size(); ++k) {
        if (k > 0) {
            rect(out, 0, y0, w, y0 + gap, {0.78f, 0.78f, 0.78f});
            y0 += gap;
        }
        const auto& im = ims[k];
        const int x0 = (w - im.width) / 2;
        for (int y = 0; y < im.height; ++y)
            for (int x = 0; x < im.width; ++x)
                for (int c = 0; c < 4; ++c)
                    out.rgba[4 * (std::size_t(y0 + y) * w + x0 + x) + c] = im.rgba[4 * (std::size_t(y) * im.width + x) + c];
        y0 += im.height;
    }
    return out;
}

PinholeCamera logo_camera() {
    PinholeCamera cam;
    cam.up = {0, 0, 1};
    cam.eye = 7.5 * glm::normalize(dvec3(1.0, 0.75, 0.65));
    cam.fov_deg = 30;
    return cam;
}

// Colours for a slice z = 0 of the plane [-s, s]².
glm::vec3 sdf_color(double v, double band) {
    const glm::vec3 in(0.35f, 0.55f, 0.95f), out(0.98f, 0.75f, 0.45f);
    glm::vec3 c = v < 0 ? in : out;
    const double f = std::abs(v) / band;
    const float stripe = float(0.75 + 0.25 * std::cos(2 * 3.14159265358979 * f));
    c = c * stripe + glm::vec3(1.0f) * (1 - stripe) * 0.6f;
    if (std::abs(v) < 0.02 * band) c = {0.1f, 0.1f, 0.1f};
    return c;
}
gr::Image sdf_slice(const Tree& t, double s, int n, double band, gr::Issues& issues, double z = 0.0) {
    gr::Image im = blank(n, n);
    gr::attempt(issues, "sdf", [&] {
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const dvec3 p(s * (2.0 * (x + 0.5) / n - 1), s * (1 - 2.0 * (y + 0.5) / n), z);
                put(im, x, y, sdf_color(sdf(t, p), band));
            }
    });
    return im;
}
gr::Image pmc_slice(const Tree& t, double s, int n, double rel_tol, gr::Issues& issues, double z = 0.0) {
    gr::Image im = blank(n, n);
    gr::attempt(issues, "classify", [&] {
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const dvec3 p(s * (2.0 * (x + 0.5) / n - 1), s * (1 - 2.0 * (y + 0.5) / n), z);
                const Membership m = classify(t, p, rel_tol);
                put(im, x, y, m == Membership::in ? glm::vec3(0.35f, 0.55f, 0.95f)
                              : m == Membership::on ? glm::vec3(0.85f, 0.1f, 0.1f)
                                                    : glm::vec3(0.97f, 0.97f, 0.95f));
            }
    });
    return im;
}

// One row of the interval-list figure: the spans of `t` along the ray as bars over [t0, t1] of the window.
void span_row(gr::Image& im, int y0, int h, const std::vector<Span>& v, double ta, double tb, glm::vec3 c) {
    rect(im, 0, y0 + h / 2, im.width, y0 + h / 2 + 1, {0.7f, 0.7f, 0.7f});
    for (const Span& s : v) {
        const int x0 = int(std::round((std::max(s.t0, ta) - ta) / (tb - ta) * im.width));
        const int x1 = int(std::round((std::min(s.t1, tb) - ta) / (tb - ta) * im.width));
        rect(im, x0, y0 + 4, x1, y0 + h - 4, c);
        rect(im, x0, y0, x0 + 2, y0 + h, {0, 0, 0});
        rect(im, x1 - 2, y0, x1, y0 + h, {0, 0, 0});
    }
}

int render_figures(gr::FigureWriter w) {
    const Tree t = logo();
    const PinholeCamera cam = logo_camera();
    const dvec3 light(0.4, 0.6, 1.0);
    gr::Issues issues;
    // 1. the logo's tree: leaves, inner nodes, the result (node order of logo(): 0 box, 1 sphere, 2 ∩, 3 cyl x,
    //    4 cyl y, 5 ∪, 6 cyl z, 7 ∪, 8 −)
    auto node_image = [&](int i, int size) {
        gr::Image im = blank(size, size);
        gr::attempt(issues, "render_image", [&] { im = render_image(subtree(t, i), cam, size, size, light); });
        return im;
    };
    {
        const int s = 200;
        const gr::Image row3 = node_image(8, 260);
        const gr::Image row2 = gr::hstack({node_image(2, s), node_image(7, s)}, 40);
        const gr::Image row1 = gr::hstack({node_image(0, s), node_image(1, s), node_image(3, s), node_image(4, s),
                                           node_image(6, s)}, 6);
        w.write("logo_tree.png", vstack({row3, row2, row1}, 6),
                "the logo's CSG tree, one ray-cast image per node: result; cube ∩ sphere, union of the cylinders; "
                "the leaves");
    }
    // 2. PMC vs SDF on the slice z = 0 of the logo and of two touching boxes
    {
        const int n = 320;
        const Tree two = combine_trees(Op::unite, leaf(Shape::box, {0.5, 0.5, 0.5}, glm::translate(glm::dmat4(1.0), dvec3(-0.5, 0, 0))),
                                       leaf(Shape::box, {0.5, 0.5, 0.5}, glm::translate(glm::dmat4(1.0), dvec3(0.5, 0.2, 0))));
        const gr::Image top = gr::hstack({pmc_slice(t, 1.5, n, 2e-3, issues, 0.75), sdf_slice(t, 1.5, n, 0.25, issues, 0.75)}, 8);
        const gr::Image bottom = gr::hstack({pmc_slice(two, 1.5, n, 2e-3, issues), sdf_slice(two, 1.5, n, 0.25, issues)}, 8);
        w.write("pmc_vs_sdf.png", vstack({top, bottom}, 8),
                "PMC in/on/out (left) and the SDF's bands (right): the logo at z = 0.75, two touching boxes at z = 0");
    }
    // 3. the smooth-min family: two discs blended with k = 0 (min), 0.1, 0.25, 0.5
    {
        std::vector<gr::Image> panels;
        const Tree a = leaf(Shape::sphere, {0.5, 0, 0}, glm::translate(glm::dmat4(1.0), dvec3(-0.45, -0.1, 0)));
        const Tree b = leaf(Shape::box, {0.3, 0.3, 0.3}, glm::translate(glm::dmat4(1.0), dvec3(0.45, 0.15, 0)));
        for (double k : {0.0, 0.1, 0.25, 0.5}) {
            const Tree u = k == 0 ? combine_trees(Op::unite, a, b) : combine_trees(Op::blend, a, b, k);
            panels.push_back(sdf_slice(u, 1.1, 240, 0.2, issues));
        }
        w.write("smooth_min.png", gr::hstack(panels, 6),
                "sphere ∪ box on z = 0 blended by smooth_min with k = 0 (plain min), 0.1, 0.25, 0.5");
    }
    // 4. interval lists along one ray through the logo: y = 0.7, z = 0.2, along +x (through the y hole only)
    {
        const Ray r{{-2, 0.7, 0.2}, {1, 0, 0}};
        const double ta = 0.5, tb = 3.5;
        const int wd = 720, h = 34;
        const int order[] = {0, 1, 2, 3, 4, 6, 7, 8};  // box, sphere, ∩, cyl x, cyl y, cyl z, ∪ of cylinders, result
        const glm::vec3 colors[] = {{0.55f, 0.7f, 0.95f}, {0.55f, 0.7f, 0.95f}, {0.2f, 0.45f, 0.9f},
                                    {0.95f, 0.7f, 0.45f}, {0.95f, 0.7f, 0.45f}, {0.95f, 0.7f, 0.45f},
                                    {0.9f, 0.5f, 0.15f}, {0.2f, 0.65f, 0.3f}};
        gr::Image im = blank(wd, int(std::size(order)) * (h + 6) + 12);
        gr::attempt(issues, "ray_spans", [&] {
            for (std::size_t k = 0; k < std::size(order); ++k)
                span_row(im, 6 + int(k) * (h + 6), h, ray_spans(subtree(t, order[k]), r), ta, tb, colors[k]);
        });
        // ticks at every 0.5 of t
        for (double tt = ta; tt <= tb + 1e-9; tt += 0.5) {
            const int x = int(std::round((tt - ta) / (tb - ta) * (wd - 1)));
            rect(im, x, 0, x + 1, 6, {0, 0, 0});
        }
        w.write("interval_lists.png", im,
                "spans along the ray (−2, 0.7, 0.2) + t(1, 0, 0), t ∈ [0.5, 3.5]: box, sphere, ∩, cylinders x, y, z, "
                "their ∪, the result");
    }
    // 5. the polygonized logo (lib's polygonizer on the student's SDF)
    {
        Demo d{logo()};
        d.mesh = true;
        d.res = 96;
        w.write("logo_mesh.png", draw(d));
    }
    if (issues.any()) std::printf("missing: %s\n", issues.str().c_str());
    return w.finish();
}
}  // namespace

int main(int argc, char** argv) {
    gr::DemoProgram program("demo_07_csg", "Lab 07 demo: CSG trees ray-cast by interval lists and polygonized by SDF",
                            kKeys);
    std::string scene;
    program.cli().add_option("--scene", scene, "An OpenSCAD file (lab 07's subset) instead of the logo");
    bool mesh = false;
    program.cli().add_flag("--mesh", mesh, "Start in the polygonized view");
    if (const auto status = program.parse(argc, argv)) return *status;
    return program.run([&] {
        if (!program.figures().empty()) return render_figures(program.figure_writer());
        Demo d{logo()};
        if (!scene.empty()) {
            d.tree = from_scad(geolab::scad::read(scene));
            d.name = scene;
        }
        d.mesh = mesh;
        return program.show({.title = "geolab demo 07: CSG",
                             .draw = [&] { return draw(d); },
                             .key = [&](int key) { return on_key(d, key); },
                             .sliders = [&] { return sliders(d); }});
    });
}
