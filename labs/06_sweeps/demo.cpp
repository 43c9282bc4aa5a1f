// Lab 06 demo: sweep representations. Four views, switched with the keys 1-4: (1) a profile swept along a curve
// you edit by dragging its control points, Frenet frames (left) beside rotation-minimizing frames (right), frames
// drawn as N (red) and B (blue) ticks; (2) lathe mode: a vase turned from a profile; (3) extrude mode: twist and scale; (4) the swept
// trefoil knot. Headless: --png FILE renders the current view; --figures DIR renders the handout's figures.
//
// The same file runs against the student's code and the reference: it calls only the lab's public API and lib.
// A function that throws geolab::NotImplemented is named in the status line; what does not need it still shows.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "geolab/render/demo.hpp"
#include "geolab/render/headless.hpp"
#include "geolab/render/render.hpp"
#include "geolab/sweeps.hpp"

namespace {

using namespace geolab::sweeps;
using geolab::PolygonSoup;
namespace gr = geolab::render;
using glm::dvec3;
using glm::vec3;

const char* kKeys =
    "Window keys:\n"
    "  1 2 3 4         views: sweep along the editable curve (Frenet | RMF), lathe, extrude, trefoil\n"
    "  drag a point    move a control point of the curve in the view plane (view 1); elsewhere: orbit\n"
    "  sliders         path samples (views 1, 4), twist (view 3), top left\n"
    "  Tab             select the next control point of the curve (view 1)\n"
    "  J L / I K / U O move the selected control point along x / y / z (view 1)\n"
    "  F               frames on/off;  W  wireframe on/off\n"
    "  T / G           more / less twist (view 3);  + / -  more / fewer path samples\n"
    "  Home, S, Esc    re-frame, screenshot (out/screenshots/), quit";

constexpr double kPi = 3.14159265358979323846;
const vec3 kSurface{0.80f, 0.80f, 0.84f};
const vec3 kN{0.85f, 0.10f, 0.10f};       // normals N: red
const vec3 kB{0.10f, 0.30f, 0.90f};       // binormals B: blue
const vec3 kCurve{0.05f, 0.05f, 0.05f};   // the path: black
const vec3 kCtrl{0.95f, 0.55f, 0.05f};    // control points: orange (the selected one green)
const vec3 kSel{0.05f, 0.60f, 0.15f};
const vec3 kUndefined{0.95f, 0.75f, 0.0f};  // samples where Frenet is undefined: yellow

struct Demo {
    int view = 1;
    std::vector<dvec3> ctrl{{-3, 0, 0}, {-1.5, 1.5, 0.5}, {0, 0, 1.5}, {1.5, -1.5, 0.5}, {3, 0, 0}};
    int selected = 0;
    int samples = 80;
    double twist = 1.5;
    bool frames = true, wire = false;
    double shift = 0.0;  // while a control point is dragged: the copies' offset, frozen (0: follows the curve)
};

// Catmull–Rom through the control points (ends repeated), n samples with tangents of the spline.
Path spline_path(const std::vector<dvec3>& c, int n) {
    Path p;
    const int segs = static_cast<int>(c.size()) - 1;
    auto at = [&](int i) { return c[static_cast<std::size_t>(std::clamp(i, 0, segs))]; };
    for (int k = 0; k < n; ++k) {
        const double u = segs * static_cast<double>(k) / (n - 1);
        const int i = std::min(static_cast<int>(u), segs - 1);
        const double t = u - i;
        const dvec3 p0 = at(i - 1), p1 = at(i), p2 = at(i + 1), p3 = at(i + 2);
        const dvec3 a = 2.0 * p1, b = p2 - p0, cc = 2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3, d = -p0 + 3.0 * p1 - 3.0 * p2 + p3;
        p.points.push_back(0.5 * (a + b * t + cc * t * t + d * t * t * t));
        dvec3 tan = 0.5 * (b + 2.0 * cc * t + 3.0 * d * t * t);
        if (glm::length(tan) == 0) tan = p2 - p1;
        p.tangents.push_back(glm::normalize(tan));
    }
    return p;
}

Profile star_profile(double r0, double r1, int points, double hole, int hole_points = 16) {
    Profile p;
    for (int i = 0; i < 2 * points; ++i) {
        const double a = kPi * i / points, r = i % 2 ? r0 : r1;
        p.outer.push_back({r * std::cos(a), r * std::sin(a)});
    }
    if (hole > 0) {
        Loop h = circle_loop({0, 0}, hole, hole_points);
        std::reverse(h.begin(), h.end());
        p.holes.push_back(h);
    }
    return p;
}

// N and B ticks at every k-th sample (frames with N = 0 — Frenet undefined — get a yellow dot instead).
void draw_frames(gr::Frame& fr, const Path& path, const std::vector<Frame>& f, double len, int every, dvec3 shift) {
    gr::Segments seg;
    std::vector<vec3> undefined;
    for (std::size_t i = 0; i < f.size(); i += static_cast<std::size_t>(every)) {
        const dvec3 c = path.points[i] + shift;
        if (glm::length(f[i].N) < 0.5) {
            undefined.push_back(vec3(c));
            continue;
        }
        seg.add(c, c + len * f[i].N, kN);
        seg.add(c, c + len * f[i].B, kB);
    }
    seg.draw(fr.scene, 2.5f);
    if (!undefined.empty()) fr.scene.add_points(undefined, kUndefined, 9.0f);
}

PolygonSoup moved(PolygonSoup m, dvec3 d) {
    for (auto& q : m.positions) q += d;
    return m;
}

void draw_path(gr::Frame& fr, const Path& p, dvec3 shift) {
    std::vector<vec3> pts;
    for (auto q : p.points) pts.push_back(vec3(q + shift));
    fr.scene.add_polyline(pts, kCurve, 2.0f, p.closed);
}

// How far the Frenet (left) and RMF (right) copies of a path sit from the middle: beside each other.
double copy_shift(const Path& path) {
    double width = 0;
    for (auto q : path.points) width = std::max(width, std::abs(q.x));
    return width + 1.5;
}

// View 1: the same profile along the same curve with Frenet frames (left) and RMF (right).
gr::Frame draw_sweep(const Demo& d, const Path& path, const Profile& prof, double frame_len, const char* what,
                     double shift = 0.0, float opacity = 1.0f) {
    gr::Frame fr;
    gr::Issues issues;
    if (!(shift > 0)) shift = copy_shift(path);  // (0: beside each other)
    const dvec3 left{-shift, 0, 0}, right{shift, 0, 0};
    draw_path(fr, path, left);
    draw_path(fr, path, right);
    gr::attempt(issues, "frenet_frames", [&] {
        std::vector<Frame> f = frenet_frames(path);
        if (d.frames) draw_frames(fr, path, f, frame_len, 2, left);
        // Frenet is undefined on straight runs: sweep only when every frame exists.
        bool ok = true;
        for (const Frame& x : f) ok = ok && glm::length(x.N) > 0.5;
        if (ok)
            gr::attempt(issues, "sweep", [&] {
                fr.scene.add_mesh(moved(sweep(prof, path, f), left),
                                  {.color = kSurface, .smooth = false, .wireframe = d.wire, .opacity = opacity});
            });
    });
    gr::attempt(issues, "rotation_minimizing_frames", [&] {
        const RmfResult r = rotation_minimizing_frames(path, path.tangents[0].z < 0.9 ? dvec3(0, 0, 1) : dvec3(1, 0, 0));
        if (d.frames) draw_frames(fr, path, r.frames, frame_len, 2, right);
        gr::attempt(issues, "sweep", [&] {
            fr.scene.add_mesh(moved(sweep(prof, path, r.frames), right),
                              {.color = kSurface, .smooth = false, .wireframe = d.wire, .opacity = opacity});
        });
    });
    std::string warn;
    gr::attempt(issues, "check_sweep", [&] {
        const SweepCheck c = check_sweep(prof, path);
        if (c.self_intersects)
            warn = " | SELF-INTERSECTS at sample " + std::to_string(c.at_sample) + " (radius of curvature " +
                   gr::fmt(c.min_radius_of_curvature) + " < profile radius " + gr::fmt(c.profile_radius) + ")";
    });
    fr.camera = gr::camera_from(fr.scene.bounds(), {0.15, -1, 0.55}, {0, 0, 1});
    fr.status = std::string(what) + ": Frenet (left) | rotation-minimizing (right); N red, B blue" + warn +
                (issues.any() ? " | " + issues.str() : "");
    return fr;
}

gr::Frame draw_editable(const Demo& d) {
    const Path path = spline_path(d.ctrl, d.samples);
    // the tubes translucent, so that the control points inside them show
    gr::Frame fr = draw_sweep(d, path, {circle_loop({0, 0}, 0.25, 12), {}}, 0.5, "editable curve", std::abs(d.shift), 0.45f);
    const double shift = d.shift != 0 ? std::abs(d.shift) : copy_shift(path);
    for (double s : {-shift, shift}) {
        std::vector<vec3> pts, cols;
        for (std::size_t i = 0; i < d.ctrl.size(); ++i) {
            pts.push_back(vec3(d.ctrl[i] + dvec3(s, 0, 0)));
            cols.push_back(static_cast<int>(i) == d.selected ? kSel : kCtrl);
        }
        fr.scene.add_points(pts, cols, 14.0f);
    }
    fr.camera = gr::fit(gr::camera_from(fr.scene.bounds(), {0.15, -1, 0.55}, {0, 0, 1}), fr.scene, 4.0 / 3.0);
    const std::size_t k = static_cast<std::size_t>(d.selected);
    fr.status += " | control point " + std::to_string(k) + " (green) at " + gr::fmt(d.ctrl[k]);
    return fr;
}

// A vase profile (r, z): a wall of thickness 0.15 following r(z) = 1 + 0.45 sin(1.6 z) ... closed at the bottom
// by a foot that reaches the axis.
Profile vase_profile() {
    Loop outer{{0, 0}};
    const int n = 40;
    auto r = [](double z) { return 1.0 + 0.45 * std::sin(1.7 * z + 0.3) - 0.05 * z; };
    for (int i = 0; i <= n; ++i) {
        const double z = 4.0 * i / n;
        outer.push_back({r(z), z});
    }
    for (int i = n; i >= 1; --i) {
        const double z = 0.25 + 3.75 * i / n;
        outer.push_back({r(z) - 0.15, z});
    }
    outer.push_back({0, 0.25});
    return {outer, {}};
}

gr::Frame draw_lathe(const Demo& d, double angle = 2 * kPi) {
    gr::Frame fr;
    gr::Issues issues;
    gr::attempt(issues, "revolve", [&] {
        const PolygonSoup m = revolve(vase_profile(), {64, angle});
        fr.scene.add_mesh(m, {.color = {0.75f, 0.55f, 0.40f}, .smooth = true, .wireframe = d.wire});
        gr::attempt(issues, "mesh_volume", [&] {
            fr.status = "lathe: vase, 64 segments, " + std::to_string(m.n_faces()) + " triangles, volume " + gr::fmt(mesh_volume(m));
        });
    });
    fr.camera = gr::camera_from(fr.scene.bounds(), {1, -1.2, 0.6}, {0, 0, 1});
    if (fr.status.empty()) fr.status = "lathe";
    if (issues.any()) fr.status += " | " + issues.str();
    return fr;
}

gr::Frame draw_extrude(const Demo& d) {
    gr::Frame fr;
    gr::Issues issues;
    const Profile p = star_profile(0.6, 1.0, 5, 0.3);
    gr::attempt(issues, "extrude", [&] {
        const PolygonSoup m = extrude(p, {{0, 0, 3}, 48, d.twist, 0.5});
        fr.scene.add_mesh(m, {.color = {0.55f, 0.70f, 0.90f}, .smooth = false, .wireframe = d.wire});
    });
    fr.camera = gr::camera_from(fr.scene.bounds(), {1, -1.3, 0.9}, {0, 0, 1});
    fr.status = "extrude: star with a hole, height 3, 48 steps, twist " + gr::fmt(d.twist) + " rad, scale 0.5" +
                (issues.any() ? " | " + issues.str() : "");
    return fr;
}

gr::Frame draw_trefoil(const Demo& d) {
    gr::Frame fr;
    gr::Issues issues;
    const Path path = trefoil_path(std::max(d.samples * 5, 60));
    draw_path(fr, path, {0, 0, 0});
    gr::attempt(issues, "rotation_minimizing_frames", [&] {
        const RmfResult r = rotation_minimizing_frames(path, glm::cross(path.tangents[0], dvec3(0, 0, 1)));
        const Profile prof = star_profile(0.22, 0.38, 4, 0.0);
        gr::attempt(issues, "sweep", [&] {
            fr.scene.add_mesh(sweep(prof, path, r.frames), {.color = {0.60f, 0.80f, 0.60f}, .smooth = false, .wireframe = d.wire});
        });
        fr.status = "trefoil: RMF closing mismatch " + gr::fmt(r.mismatch, 4) + " rad, distributed along the knot";
    });
    fr.camera = gr::camera_from(fr.scene.bounds(), {0.2, -0.4, 1}, {0, 1, 0});
    if (fr.status.empty()) fr.status = "trefoil";
    if (issues.any()) fr.status += " | " + issues.str();
    return fr;
}

gr::Frame draw(const Demo& d) {
    switch (d.view) {
        case 2: return draw_lathe(d);
        case 3: return draw_extrude(d);
        case 4: return draw_trefoil(d);
        default: return draw_editable(d);
    }
}

bool on_key(Demo& d, int key) {
    if (key >= '1' && key <= '4') {
        d.view = key - '0';
        return true;
    }
    dvec3& c = d.ctrl[static_cast<std::size_t>(d.selected)];
    switch (key) {
        case '\t': d.selected = (d.selected + 1) % static_cast<int>(d.ctrl.size()); break;
        case 'J': c.x -= 0.25; break;
        case 'L': c.x += 0.25; break;
        case 'I': c.y += 0.25; break;
        case 'K': c.y -= 0.25; break;
        case 'U': c.z += 0.25; break;
        case 'O': c.z -= 0.25; break;
        case 'F': d.frames = !d.frames; break;
        case 'W': d.wire = !d.wire; break;
        case 'T': d.twist = std::min(d.twist + 0.5, 40.0); break;
        case 'G': d.twist = std::max(d.twist - 0.5, -40.0); break;
        case '=': case '+': d.samples = std::min(d.samples * 2, 2000); break;
        case '-': d.samples = std::max(d.samples / 2, 10); break;
        default: break;
    }
    return false;
}

// Dragging a control point of the editable curve, on either copy, in the view plane; the copies stay where they
// were until the release.
bool on_drag(Demo& d, const gr::Drag& g) {
    if (d.view != 1) return false;
    const std::size_t n = d.ctrl.size();
    if (g.phase == gr::MouseEvent::Phase::press) {
        const double shift = copy_shift(spline_path(d.ctrl, d.samples));
        std::vector<dvec3> both;
        for (double s : {-shift, shift})
            for (const dvec3& c : d.ctrl) both.push_back(c + dvec3(s, 0, 0));
        const auto k = g.nearest(both);
        if (!k) return false;
        d.selected = int(*k % n);
        d.shift = *k < n ? -shift : shift;  // signed: which copy holds the cursor
        return true;
    }
    dvec3& c = d.ctrl[std::size_t(d.selected)];
    const dvec3 offset(d.shift, 0, 0);
    c = g.on_view_plane(c + offset) - offset;
    if (g.phase == gr::MouseEvent::Phase::release) d.shift = 0.0;
    return false;
}

std::vector<gr::Slider> sliders(Demo& d) {
    if (d.view == 1 || d.view == 4) return {gr::slider("samples", d.samples, 10, 2000, true)};
    if (d.view == 3) return {gr::slider("twist", d.twist, -20.0, 20.0, 0.1)};
    return {};
}

// The helix: one turn, and a planar S-curve with an inflection (y = sin x), for Frenet vs RMF.
Path s_curve(int n) {
    std::vector<dvec3> pts;
    for (int i = 0; i < n; ++i) {
        const double x = -3 + 6.0 * i / (n - 1);
        pts.push_back({x, 0, 1.2 * std::sin(x * 1.05)});
    }
    return polyline_path(pts, false);
}

int render_figures(gr::FigureWriter w) {
    Demo d;
    const Profile flat{Loop{{-0.3, -0.06}, {0.3, -0.06}, {0.3, 0.06}, {-0.3, 0.06}}, {}};  // a ribbon shows the twist
    w.write("frenet_rmf_helix.png", draw_sweep(d, helix_path(1.2, 0.35, 1.5, 90), flat, 0.45, "helix"));
    w.write("frenet_rmf_inflection.png", draw_sweep(d, s_curve(60), flat, 0.45, "S-curve with an inflection"));
    w.write("twist_extrusion.png", draw_extrude(d));
    w.write("vase.png", draw_lathe(d));
    d.samples = 120;
    w.write("trefoil.png", draw_trefoil(d));
    {  // the Pappus check: the issue's profile revolved by 270° so that the torus-shaped cavity shows
        gr::Frame fr;
        gr::Issues issues;
        Profile p{rectangle_loop(0, -2, 4, 2), {}};
        Loop h = rectangle_loop(1, -1, 3, 1);
        std::reverse(h.begin(), h.end());
        p.holes.push_back(h);
        gr::attempt(issues, "revolve", [&] {
            const PolygonSoup m = revolve(p, {96, 1.5 * kPi});
            fr.scene.add_mesh(m, {.color = {0.85f, 0.70f, 0.45f}, .smooth = false});
            const PolygonSoup full = revolve(p, {96, 2 * kPi});
            gr::attempt(issues, "pappus", [&] {
                const Pappus pp = pappus(p, 2 * kPi);
                fr.status = "Pappus: V = " + gr::fmt(pp.volume / kPi, 6) + " pi (mesh, 96 segments: " +
                            gr::fmt(mesh_volume(full) / kPi, 6) + " pi), A = " + gr::fmt(pp.lateral_area / kPi, 6) +
                            " pi (mesh: " + gr::fmt(mesh_area(full) / kPi, 6) + " pi)";
            });
        });
        fr.camera = gr::camera_from(fr.scene.bounds(), {1, -1.4, 0.8}, {0, 0, 1});
        if (issues.any()) fr.status += " | " + issues.str();
        w.write("pappus.png", fr);
    }
    {  // a print-ready part: a twisted knob with a bore (what `geolab sweep --extrude` writes as STL)
        gr::Frame fr;
        gr::Issues issues;
        gr::attempt(issues, "extrude", [&] {
            const PolygonSoup m = extrude(star_profile(8, 12, 6, 3, 12), {{0, 0, 20}, 40, 1.0, 0.8});
            fr.scene.add_mesh(m, {.color = {0.45f, 0.65f, 0.85f}, .smooth = false});
            fr.status = "print-ready knob: " + std::to_string(m.n_faces()) + " triangles";
        });
        fr.camera = gr::camera_from(fr.scene.bounds(), {1, -1.2, 1.0}, {0, 0, 1});
        if (issues.any()) fr.status += " | " + issues.str();
        w.write("knob.png", fr);
    }
    return w.finish();
}

}  // namespace

int main(int argc, char** argv) {
    gr::DemoProgram program("demo_06_sweeps", "Lab 06 demo: extrusion, revolution, sweeps with Frenet and RMF frames", kKeys);
    int view = 1;
    program.cli().add_option("--view", view, "The view to show first (1-4)")->check(CLI::Range(1, 4))->capture_default_str();
    if (const auto status = program.parse(argc, argv)) return *status;
    return program.run([&] {
        if (!program.figures().empty()) return render_figures(program.figure_writer());
        Demo d;
        d.view = view;
        return program.show({.title = "geolab demo 06: sweeps",
                             .draw = [&] { return draw(d); },
                             .key = [&](int key) { return on_key(d, key); },
                             .sliders = [&] { return sliders(d); },
                             .drag = [&](const gr::Drag& g) { return on_drag(d, g); }});
    });
}
