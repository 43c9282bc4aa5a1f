// Lab 05 demo: Bézier curves and the Utah teapot. Curve mode: the de Casteljau construction at the t slider,
// the two halves of the subdivision, the hodograph beside the curve, all following the control points as you drag
// them (in the plane z = 0). Continuity mode: C⁰, G¹, C¹ and C² joints side by side. Teapot mode: the 32 patches
// tessellated with their control nets. Glyph mode: a word from DejaVu Sans with its control points. Patch mode: one
// bicubic patch whose 16 control points you drag (in the view plane), with the point S(u, v) of the u and v sliders,
// its normal and the two iso-curves through it. Headless: --png FILE renders the current view; --figures DIR
// renders the handout's figures.
//
// The same file runs against the student's code and the reference: it calls only the lab's public API and lib.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "geolab/bezier.hpp"
#include "geolab/bezier_data.hpp"
#include "geolab/render/demo.hpp"
#include "geolab/render/headless.hpp"
#include "geolab/render/render.hpp"

namespace {

namespace gr = geolab::render;
namespace bz = geolab::bezier;
using bz::Poly3;
using glm::dvec3;
using glm::vec3;

const char* kKeys =
    "Window keys:\n"
    "  1 2 3 4 5       curve / continuity / teapot / glyphs / patch\n"
    "  drag a point    move a control point (curve: in z = 0; patch: in the view plane); elsewhere: orbit\n"
    "  sliders         t (curve), u and v (patch), top left\n"
    "  A D             t − 0.05, t + 0.05 (the construction point)\n"
    "  B               subdivision halves at t on/off (instead of the construction)\n"
    "  H               hodograph on/off\n"
    "  W               teapot control nets on/off\n"
    "  Home, S, Esc    re-frame, screenshot (out/screenshots/), quit";

const vec3 kGrey{0.55f, 0.55f, 0.6f}, kBlue{0.1f, 0.3f, 0.85f}, kRed{0.85f, 0.1f, 0.1f}, kGreen{0.1f, 0.6f, 0.2f},
    kOrange{0.95f, 0.55f, 0.05f}, kBlack{0.05f, 0.05f, 0.05f};

// A bicubic patch over [-3, 3]² with a bump: the control points P_ij at (2i − 3, 2j − 3, h_ij).
geolab::BezierPatch start_patch() {
    geolab::BezierPatch S{3, 3, {}};
    const double h[4][4] = {{0, 0.5, 0.5, 0}, {0.5, 2.5, 1.5, 0.5}, {0.5, 1.5, -1.0, 0}, {0, 0.5, 0, -0.5}};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) S.points.push_back({2.0 * i - 3.0, 2.0 * j - 3.0, h[i][j]});
    return S;
}

struct Demo {
    int mode = 1;
    Poly3 P{{-3, -1, 0}, {-2, 2.5, 0}, {1.5, 3, 0}, {3, -0.5, 0}};
    double t = 0.3;
    bool halves = false, hodo = false, nets = true;
    int selected = -1;  // the control point being dragged (curve or patch)
    geolab::BezierPatch patch = start_patch();
    double u = 0.35, v = 0.6;
};

std::vector<vec3> to_f(const Poly3& P, dvec3 offset = dvec3(0.0)) {
    std::vector<vec3> r;
    for (const auto& p : P) r.emplace_back(p + offset);
    return r;
}

// The curve sampled by the student's de Casteljau (200 steps).
bool add_curve(gr::Scene& s, gr::Issues& issues, const Poly3& P, vec3 color, float width, dvec3 offset = dvec3(0.0)) {
    return gr::attempt(issues, "de_casteljau", [&] {
        Poly3 pts;
        for (int i = 0; i <= 200; ++i) pts.push_back(bz::de_casteljau(P, i / 200.0));
        s.add_polyline(to_f(pts, offset), color, width);
    });
}

void add_polygon(gr::Scene& s, const Poly3& P, vec3 color, float size = 9.0f, dvec3 offset = dvec3(0.0)) {
    s.add_polyline(to_f(P, offset), color, 1.5f);
    s.add_points(to_f(P, offset), color, size);
}

gr::Camera flat_camera(const gr::Scene& s, double aspect) {
    return gr::fit(gr::camera_from(s.bounds(), {0, 0, 1}, {0, 1, 0}), s, aspect);
}

// The curve with the de Casteljau triangle at t (construction lines coloured by row), optionally the two halves.
void draw_curve(gr::Frame& fr, gr::Issues& issues, const Demo& d, bool hodograph_panel) {
    auto& s = fr.scene;
    add_polygon(s, d.P, kGrey);
    if (d.selected >= 0 && d.selected < int(d.P.size())) s.add_points({vec3(d.P[d.selected])}, kOrange, 16.0f);
    add_curve(s, issues, d.P, kBlue, 3.0f);
    if (!d.halves) gr::attempt(issues, "de_casteljau_triangle", [&] {
        const auto rows = bz::de_casteljau_triangle(d.P, d.t);
        for (std::size_t r = 1; r < rows.size(); ++r) {
            const vec3 c = gr::category_color(r);
            if (rows[r].size() > 1) s.add_polyline(to_f(rows[r]), c, 2.0f);
            s.add_points(to_f(rows[r]), r + 1 == rows.size() ? kRed : c, r + 1 == rows.size() ? 14.0f : 8.0f);
        }
    });
    if (d.halves)
        gr::attempt(issues, "subdivide", [&] {
            const bz::Split sp = bz::subdivide(d.P, d.t);
            add_polygon(s, sp.left, kGreen, 9.0f);
            add_polygon(s, sp.right, kOrange, 9.0f);
            s.add_points({vec3(sp.left.back())}, kRed, 14.0f);
        });
    if (hodograph_panel)
        gr::attempt(issues, "hodograph", [&] {
            // the hodograph beside the curve (scaled by 1/3 so that both fit), its origin marked
            const Poly3 H = bz::hodograph(d.P);
            Poly3 Hs;
            for (const auto& h : H) Hs.push_back(h / 3.0);
            const dvec3 at(9, 0, 0);
            add_polygon(s, Hs, kGrey, 8.0f, at);
            add_curve(s, issues, Hs, kGreen, 3.0f, at);
            s.add_points({vec3(at)}, kBlack, 10.0f);
            const dvec3 v = bz::derivative(d.P, d.t);
            s.add_lines({vec3(at), vec3(at + v / 3.0)}, kRed, 2.5f);
            const dvec3 c = bz::de_casteljau(d.P, d.t);
            s.add_lines({vec3(c), vec3(c + v / 3.0)}, kRed, 2.5f);
        });
}

// Two cubics joined with a given class; the joint marked.
Poly3 joint_b(const Poly3& a, int kind) {
    const dvec3 a3 = a[3], a2 = a[2], a1 = a[1];
    switch (kind) {
        case 0: return {a3, a3 + dvec3(0.6, 1.2, 0), {4.5, 1.5, 0}, {6, 0, 0}};                                // C0
        case 1: return {a3, a3 + 0.4 * (a3 - a2), {4.5, 1.5, 0}, {6, 0, 0}};                                  // G1
        case 2: return {a3, 2.0 * a3 - a2, {4.5, 1.5, 0}, {6, 0, 0}};                                         // C1
        default: return {a3, 2.0 * a3 - a2, (a3 - 2.0 * a2 + a1) + 2.0 * (2.0 * a3 - a2) - a3, {6, 0.5, 0}};  // C2
    }
}
const Poly3 kJointA{{-3, 0, 0}, {-2, 2, 0}, {0, 2, 0}, {1, 0.5, 0}};

gr::Frame draw_continuity_panel(int kind) {
    gr::Frame fr;
    gr::Issues issues;
    const Poly3 b = joint_b(kJointA, kind);
    add_polygon(fr.scene, kJointA, kGrey, 7.0f);
    add_polygon(fr.scene, b, kGrey, 7.0f);
    add_curve(fr.scene, issues, kJointA, kBlue, 3.0f);
    add_curve(fr.scene, issues, b, kOrange, 3.0f);
    fr.scene.add_points({vec3(kJointA[3])}, kRed, 12.0f);
    std::string cls = "?";
    gr::attempt(issues, "continuity", [&] {
        const bz::Continuity c = bz::continuity(kJointA, b, 1e-9);
        cls = "C" + std::to_string(c.c_order) + ", G" + std::to_string(c.g_order);
    });
    fr.camera = flat_camera(fr.scene, 4.0 / 3.0);
    fr.status = "joint: " + cls + (issues.any() ? " | " + issues.str() : "");
    return fr;
}

gr::Frame draw_teapot(const Demo& d, int n = 12) {
    gr::Frame fr;
    gr::Issues issues;
    const auto patches = geolab::read_bpt(geolab::teapot_path());
    gr::attempt(issues, "tessellate_patches", [&] {
        const bz::PatchMesh m = bz::tessellate_patches(patches, n, 1e-9, true);
        fr.scene.add_mesh(m.soup, {.color = {0.85f, 0.8f, 0.7f}, .smooth = false});
    });
    if (d.nets) {
        std::vector<vec3> seg;
        for (const auto& S : patches)
            for (int i = 0; i <= S.degree_u; ++i)
                for (int j = 0; j <= S.degree_v; ++j) {
                    const dvec3 p = S.points[i * (S.degree_v + 1) + j];
                    if (i < S.degree_u) seg.push_back(vec3(p)), seg.push_back(vec3(S.points[(i + 1) * (S.degree_v + 1) + j]));
                    if (j < S.degree_v) seg.push_back(vec3(p)), seg.push_back(vec3(S.points[i * (S.degree_v + 1) + j + 1]));
                }
        fr.scene.add_lines(seg, kBlue, 1.2f);
    }
    fr.camera = gr::fit(gr::camera_from(fr.scene.bounds(), {1.0, -1.6, 0.9}, {0, 0, 1}), fr.scene, 4.0 / 3.0);
    fr.status = "Utah teapot: 32 bicubic patches at " + std::to_string(n) + " x " + std::to_string(n) +
                (d.nets ? ", control nets in blue" : "") + (issues.any() ? " | " + issues.str() : "");
    return fr;
}

// A word (or one glyph) from DejaVu Sans: the flattened outline, the control polygon, on-curve points black and
// off-curve points red. Font units scaled to an em of 10.
gr::Frame draw_glyphs(const std::u32string& text, bool points) {
    gr::Frame fr;
    gr::Issues issues;
    double x = 0;
    for (char32_t ch : text) {
        const geolab::GlyphOutline g = geolab::read_glyph(geolab::default_font_path(), ch);
        const double s = 10.0 / g.units_per_em;
        auto P = [&](const glm::dvec2& p) { return vec3(float(x + s * p.x), float(s * p.y), 0.0f); };
        for (const auto& c : g.contours) {
            gr::attempt(issues, "flatten_contour", [&] {
                const bz::Poly2 poly = bz::flatten_contour(c, 2.0);
                std::vector<vec3> pts;
                for (const auto& p : poly) pts.push_back(P(p));
                fr.scene.add_polyline(pts, kBlue, 2.5f, true);
            });
            if (points) {
                std::vector<vec3> ctrl, on, off;
                for (const auto& q : c) {
                    ctrl.push_back(P(q[0])), ctrl.push_back(P(q[1])), ctrl.push_back(P(q[1])), ctrl.push_back(P(q[2]));
                    on.push_back(P(q[0]));
                    if (glm::length(q[1] - 0.5 * (q[0] + q[2])) > 1e-9) off.push_back(P(q[1]));
                }
                fr.scene.add_lines(ctrl, kGrey, 1.0f);
                fr.scene.add_points(on, kBlack, 6.0f);
                if (!off.empty()) fr.scene.add_points(off, kRed, 6.0f);
            }
        }
        x += 10.0 * g.advance / g.units_per_em;
    }
    fr.camera = flat_camera(fr.scene, 4.0 / 3.0);
    fr.status = "DejaVu Sans outlines: quadratic Bézier segments" + std::string(points ? "; on-curve points black, "
                                                                                         "off-curve red" : "") +
                (issues.any() ? " | " + issues.str() : "");
    return fr;
}

// One bicubic patch: your tessellation, the control net, S(u, v) with its normal and the iso-curves through it.
gr::Frame draw_patch(const Demo& d) {
    gr::Frame fr;
    gr::Issues issues;
    const geolab::BezierPatch& S = d.patch;
    gr::attempt(issues, "tessellate_patches", [&] {
        const bz::PatchMesh m = bz::tessellate_patches({S}, 24, 1e-9, false);
        fr.scene.add_mesh(m.soup, {.color = {0.85f, 0.8f, 0.7f}, .smooth = true, .opacity = 0.85f});
    });
    std::vector<vec3> net;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const dvec3 p = S.points[std::size_t(4 * i + j)];
            if (i < 3) net.push_back(vec3(p)), net.push_back(vec3(S.points[std::size_t(4 * (i + 1) + j)]));
            if (j < 3) net.push_back(vec3(p)), net.push_back(vec3(S.points[std::size_t(4 * i + j + 1)]));
        }
    fr.scene.add_lines(net, kGrey, 1.5f);
    std::vector<vec3> pts, cols;
    for (std::size_t k = 0; k < S.points.size(); ++k) {
        pts.push_back(vec3(S.points[k]));
        cols.push_back(int(k) == d.selected ? kOrange : kBlack);
    }
    fr.scene.add_points(pts, cols, 10.0f);
    std::string at;
    gr::attempt(issues, "patch_point", [&] {
        Poly3 iso_u, iso_v;  // S(·, v) and S(u, ·)
        for (int k = 0; k <= 64; ++k) {
            iso_u.push_back(bz::patch_point(S, k / 64.0, d.v));
            iso_v.push_back(bz::patch_point(S, d.u, k / 64.0));
        }
        fr.scene.add_polyline(to_f(iso_u), kBlue, 3.0f);
        fr.scene.add_polyline(to_f(iso_v), kGreen, 3.0f);
        const dvec3 p = bz::patch_point(S, d.u, d.v);
        fr.scene.add_points({vec3(p)}, kRed, 14.0f);
        at = "S(" + gr::fmt(d.u, 2) + ", " + gr::fmt(d.v, 2) + ") = " + gr::fmt(p);
        gr::attempt(issues, "patch_normal", [&] {
            gr::Segments seg;
            gr::add_normal(seg, p, bz::patch_normal(S, d.u, d.v), 1.5, kRed);
            seg.draw(fr.scene, 3.0f);
        });
    });
    fr.camera = gr::fit(gr::camera_from(fr.scene.bounds(), {0.9, -1.3, 1.1}, {0, 0, 1}), fr.scene, 4.0 / 3.0);
    fr.status = "bicubic patch: drag its control points; u-curve blue, v-curve green, normal red" +
                (at.empty() ? "" : "; " + at) + (issues.any() ? " | " + issues.str() : "");
    return fr;
}

gr::Frame draw(const Demo& d) {
    if (d.mode == 2) return draw_continuity_panel(3);
    if (d.mode == 5) return draw_patch(d);
    if (d.mode == 3) return draw_teapot(d);
    if (d.mode == 4) {
        std::u32string w;
        for (char c : std::string("Bezier")) w.push_back(char32_t(c));
        return draw_glyphs(w, true);
    }
    gr::Frame fr;
    gr::Issues issues;
    draw_curve(fr, issues, d, d.hodo);
    fr.camera = flat_camera(fr.scene, 4.0 / 3.0);
    std::string ctrl;
    for (const dvec3& p : d.P) ctrl += " (" + gr::fmt(p.x, 3) + ", " + gr::fmt(p.y, 3) + ")";
    fr.status = "degree " + std::to_string(d.P.size() - 1) + " curve," + ctrl + ", t = " + gr::fmt(d.t, 2) +
                (d.halves ? "; halves green/orange" : "") + (d.hodo ? "; hodograph (÷3) right, C'(t) red" : "") +
                (issues.any() ? " | " + issues.str() : "");
    return fr;
}

bool on_key(Demo& d, int key) {
    if (key >= '1' && key <= '5') {
        d.mode = key - '0';
        d.selected = -1;
        return true;
    }
    if (key == 'A') d.t = std::max(0.0, d.t - 0.05);
    if (key == 'D') d.t = std::min(1.0, d.t + 0.05);
    if (key == 'B') d.halves = !d.halves;
    if (key == 'H') {
        d.hodo = !d.hodo;
        return true;
    }
    if (key == 'W') d.nets = !d.nets;
    return false;
}

// Dragging a control point: the curve's in the plane z = 0, the patch's in the view plane.
bool on_drag(Demo& d, const gr::Drag& g) {
    if (d.mode != 1 && d.mode != 5) return false;
    std::vector<dvec3>& pts = d.mode == 1 ? d.P : d.patch.points;
    if (g.phase == gr::MouseEvent::Phase::press) {
        const auto k = g.nearest(pts);
        d.selected = k ? int(*k) : -1;
        return k.has_value();
    }
    if (d.selected >= 0 && d.selected < int(pts.size())) {
        dvec3& p = pts[std::size_t(d.selected)];
        if (d.mode == 1) {
            if (const auto q = g.on_plane(dvec3(0.0), dvec3(0, 0, 1))) p = dvec3(q->x, q->y, 0.0);
        } else {
            p = g.on_view_plane(p);
        }
    }
    if (g.phase == gr::MouseEvent::Phase::release) d.selected = -1;
    return false;
}

std::vector<gr::Slider> sliders(Demo& d) {
    if (d.mode == 1) return {gr::slider("t", d.t, 0.0, 1.0, 0.01)};
    if (d.mode == 5) return {gr::slider("u", d.u, 0.0, 1.0, 0.01), gr::slider("v", d.v, 0.0, 1.0, 0.01)};
    return {};
}

int render_figures(gr::FigureWriter w) {
    Demo d;
    d.t = 0.3;
    w.write("casteljau_t03.png", draw(d));
    d.t = 0.5;
    d.halves = true;
    w.write("subdivision.png", draw(d));
    {
        gr::Frame fr;
        gr::Issues issues;
        Demo h;
        h.t = 0.3;
        h.hodo = true;
        fr.scene = gr::Scene();
        add_polygon(fr.scene, h.P, kGrey);
        add_curve(fr.scene, issues, h.P, kBlue, 3.0f);
        Demo only = h;
        draw_curve(fr, issues, only, true);
        fr.camera = flat_camera(fr.scene, 2.0);
        w.write("hodograph.png", fr.scene, fr.camera, "curve (left) and its hodograph ÷ 3 (right), C'(0.3) red",
                1280, 640);
    }
    {
        std::vector<gr::Image> panels;
        for (int k = 0; k < 4; ++k) {
            const gr::Frame f = draw_continuity_panel(k);
            panels.push_back(gr::render_image(f.scene, f.camera, 480, 360));
        }
        w.write("continuity.png", gr::hstack(panels, 6), "joints C0, G1, C1, C2 (left to right)");
    }
    {
        // repeated degree elevation: the control polygons after 0, 2, 8 and 32 elevations
        gr::Frame fr;
        gr::Issues issues;
        Poly3 Q = d.P;
        add_curve(fr.scene, issues, d.P, kBlue, 3.0f);
        int done = 0;
        for (int target : {0, 2, 8, 32}) {
            gr::attempt(issues, "elevate", [&] {
                while (done < target) Q = bz::elevate(Q), ++done;
            });
            fr.scene.add_polyline(to_f(Q), gr::category_color(std::size_t(target == 0 ? 1 : target == 2 ? 2 : target == 8 ? 3 : 4)), 1.8f);
        }
        fr.camera = flat_camera(fr.scene, 4.0 / 3.0);
        w.write("elevation.png", fr.scene, fr.camera, "control polygons after 0, 2, 8, 32 elevations");
    }
    w.write("teapot.png", draw_teapot(d, 12));
    w.write("glyph.png", draw_glyphs(U"g", true));
    w.write("word.png", draw_glyphs(U"Bézier", false));
    return w.finish();
}

}  // namespace

int main(int argc, char** argv) {
    gr::DemoProgram program("demo_05_bezier", "Lab 05 demo: Bézier curves, de Casteljau, the Utah teapot, glyphs",
                            kKeys);
    int mode = 1;
    double t = 0.3;
    program.cli().add_option("--mode", mode, "1 curve, 2 continuity, 3 teapot, 4 glyphs, 5 patch")->capture_default_str();
    program.cli().add_option("--t", t, "the construction parameter in [0, 1]")->capture_default_str();
    if (const auto status = program.parse(argc, argv)) return *status;
    return program.run([&] {
        if (!program.figures().empty()) return render_figures(program.figure_writer());
        Demo d;
        d.mode = std::clamp(mode, 1, 5);
        d.t = std::clamp(t, 0.0, 1.0);
        return program.show({.title = "geolab demo 05: Bézier curves and surfaces",
                             .draw = [&] { return draw(d); },
                             .key = [&](int key) { return on_key(d, key); },
                             .sliders = [&] { return sliders(d); },
                             .drag = [&](const gr::Drag& g) { return on_drag(d, g); }});
    });
}
