// Lab 09 demo: dual contouring on a Cartesian and on a spherical-coordinate octree. Five views, switched with the
// keys 1-5: (1) the spherical octree's curved cells around the surface, in a slice; (2) the origin moving off the
// surface step by step (eq. 6, the paper's Fig. 6); (3) the holes around the polar axis and the two ways to fill
// them (Fig. 7); (4) Cartesian and spherical meshes side by side at the same level; (5) the Cartesian octree's
// refinement band. Headless: --png FILE renders the current view; --figures DIR renders the handout's figures.
//
// The same file runs against the student's code and the reference: it calls only the lab's public API and lib.
// A function that throws geolab::NotImplemented is named in the status line; what does not need it still shows.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"
#include "geolab/implicits.hpp"
#include "geolab/io.hpp"
#include "geolab/mesh_field.hpp"
#include "geolab/models.hpp"
#include "geolab/render/demo.hpp"
#include "geolab/render/render.hpp"

namespace {

using namespace geolab::dc;
using geolab::PolygonSoup;
using geolab::ScalarField;
namespace gr = geolab::render;
using glm::dvec3;
using glm::vec3;
using gr::box_around;
using gr::camera_from;
using gr::fmt;
using gr::Frame;
using gr::Issues;

// ---- colours (the handout's legend uses these names) ------------------------------------------------------------
const vec3 kGrey{0.80f, 0.80f, 0.83f};        // surfaces
const vec3 kWire{0.30f, 0.30f, 0.34f};        // polygon edges
const vec3 kSection{0.62f, 0.62f, 0.66f};     // cells cut by the slice: their boundary in the slice, grey
const vec3 kCell{0.10f, 0.35f, 0.90f};        // finest cells with a sign change, drawn whole: blue
const vec3 kDual{0.85f, 0.10f, 0.10f};        // their dual vertices: red
const vec3 kStart{0.85f, 0.10f, 0.10f};       // origin path: x0 (on the surface) red
const vec3 kStep{1.00f, 0.55f, 0.00f};        //              intermediate steps orange
const vec3 kFinal{0.05f, 0.60f, 0.15f};       //              the corrected origin green
const vec3 kCurve{0.05f, 0.05f, 0.05f};       // the zero level set in a plane: black
const vec3 kMargin{0.55f, 0.55f, 0.60f};      // the level sets f = ±margin·h: grey
const vec3 kHole{0.90f, 0.10f, 0.10f};        // hole boundaries (PoleFill::none): red
const vec3 kNormalFill{1.00f, 0.62f, 0.20f};  // fan of normal_projection: orange
const vec3 kVerticalFill{0.70f, 0.45f, 0.95f};  // fan of vertical_projection: purple
const vec3 kGhost{0.05f, 0.05f, 0.05f};       // ghost vertex: black
const vec3 kAxis{0.05f, 0.55f, 0.25f};        // the polar axis: green
const vec3 kCartesian{0.96f, 0.80f, 0.58f};   // the Cartesian mesh: sand
const vec3 kSphericalMesh{0.62f, 0.78f, 0.96f};  // the spherical mesh: light blue

constexpr double kPi = 3.14159265358979323846;

// ---- calling the student's code -------------------------------------------------------------------------------------

// The function a NotImplemented names ("not implemented: NAME (this is yours ...)"); stubs pass __func__, so a
// member function shows as its bare name (add, solve) — we add which step needed it.
std::string missing_function(const std::string& what, const std::string& step) {
    std::string name = gr::not_implemented_name(what);
    if (name == "add" || name == "solve" || name == "error") name = "Qef::" + name;
    return name == step ? name : name + " (needed by " + step + ")";
}

// gr::attempt, naming the missing function as missing_function does.
template <class F>
bool attempt_step(Issues& issues, const std::string& step, F&& f) {
    return gr::attempt(issues, step, std::forward<F>(f), missing_function);
}

// ---- input ---------------------------------------------------------------------------------------------------------

struct Input {
    std::string name;
    geolab::FieldPtr field;
    bool is_mesh = false;  // a MeshField (signed distance to a mesh; y up in the CGAL models)
    std::vector<dvec3> vertices;  // a mesh's vertex positions (the spherical origin starts at their enclosing sphere)
};

std::string implicit_list() {
    std::string s;
    for (const auto& n : geolab::implicit_names()) s += (s.empty() ? "" : ", ") + n;
    return s;
}

// A named implicit, a mesh file, or a fetched model name. Throws std::runtime_error with one clear sentence.
Input load(const std::string& arg) {
    const auto names = geolab::implicit_names();
    if (std::find(names.begin(), names.end(), arg) != names.end()) return {arg, geolab::named_implicit(arg), false};
    std::optional<std::filesystem::path> path;
    if (std::filesystem::exists(arg)) path = arg;
    else path = geolab::model_path(arg);
    if (!path)
        throw std::runtime_error("'" + arg + "' is not a named implicit (" + implicit_list() +
                                 "), a mesh file, or a fetched model (run tools/fetch_models.sh for bunny00, cow, ...)");
    const PolygonSoup soup = geolab::read_mesh(*path);
    return {path->stem().string(), std::make_shared<geolab::MeshField>(soup), true, soup.positions};
}

// ---- geometry helpers (the demo's own, so that drawing does not depend on the student's to_cartesian) ----------

// origin + (r sinθ cosφ, r sinθ sinφ, r cosθ), exact on the polar axis.
dvec3 sph(const dvec3& o, double r, double t, double p) {
    const double st = (t == 0.0 || t == kPi) ? 0.0 : std::sin(t), ct = t == 0.0 ? 1.0 : t == kPi ? -1.0 : std::cos(t);
    return o + r * dvec3(st * std::cos(p), st * std::sin(p), ct);
}

// θ of the direction q (from +Z), as to_spherical defines it.
double to_theta(const dvec3& q) { return std::atan2(std::hypot(q.x, q.y), q.z); }

// The path a + s (b − a) in (r, θ, φ), sampled with `n` segments, appended as segment pairs.
void add_arc(std::vector<vec3>& seg, const dvec3& o, const Spherical& a, const Spherical& b, int n) {
    dvec3 prev = sph(o, a.r, a.theta, a.phi);
    for (int i = 1; i <= n; ++i) {
        const double s = double(i) / n;
        const dvec3 p = sph(o, a.r + s * (b.r - a.r), a.theta + s * (b.theta - a.theta), a.phi + s * (b.phi - a.phi));
        seg.push_back(vec3(prev)), seg.push_back(vec3(p));
        prev = p;
    }
}

// The 12 curved edges of spherical cell [S0, S1]: 4 radial segments, 4 θ-arcs (meridians), 4 φ-arcs (circles).
void add_spherical_cell(std::vector<vec3>& seg, const dvec3& o, const Spherical& S0, const Spherical& S1) {
    const double r[2] = {S0.r, S1.r}, t[2] = {S0.theta, S1.theta}, p[2] = {S0.phi, S1.phi};
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
            add_arc(seg, o, {r[0], t[i], p[j]}, {r[1], t[i], p[j]}, 1);  // radial
            add_arc(seg, o, {r[i], t[0], p[j]}, {r[i], t[1], p[j]}, 8);  // θ-arc
            add_arc(seg, o, {r[i], t[j], p[0]}, {r[i], t[j], p[1]}, 8);  // φ-arc
        }
}

// The level set f = level in the plane c + a u + b w, (a, b) ∈ [−R, R]², by marching squares on an n × n grid.
std::vector<vec3> plane_contour(const ScalarField& f, const dvec3& c, const dvec3& u, const dvec3& w, double R, int n,
                                double level) {
    std::vector<double> v((n + 1) * (n + 1));
    auto at = [&](int i, int j) { return c + (-R + 2 * R * i / n) * u + (-R + 2 * R * j / n) * w; };
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) v[j * (n + 1) + i] = f.value(at(i, j)) - level;
    std::vector<vec3> seg;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int ci[4] = {i, i + 1, i + 1, i}, cj[4] = {j, j, j + 1, j + 1};
            std::vector<dvec3> x;
            for (int e = 0; e < 4; ++e) {
                const int k = (e + 1) % 4;
                const double va = v[cj[e] * (n + 1) + ci[e]], vb = v[cj[k] * (n + 1) + ci[k]];
                if ((va <= 0) == (vb <= 0)) continue;
                const double s = va / (va - vb);
                x.push_back(at(ci[e], cj[e]) + s * (at(ci[k], cj[k]) - at(ci[e], cj[e])));
            }
            for (std::size_t e = 0; e + 1 < x.size(); e += 2) seg.push_back(vec3(x[e])), seg.push_back(vec3(x[e + 1]));
        }
    return seg;
}

// A point on the surface: the first sign change on a ray from the centre of bounds() (bisected), trying a few
// directions; the centre itself when none changes sign.
dvec3 surface_point(const ScalarField& f) {
    const geolab::Box b = f.bounds();
    const dvec3 c = b.center();
    const double len = 0.75 * glm::length(b.hi - b.lo);
    const dvec3 dirs[] = {glm::normalize(dvec3(-0.35, -1.0, 0.3)), {0, -1, 0}, {1, 0, 0}, {-1, 0, 0}, {0, 0, 1}, {0, 1, 0}};
    for (const dvec3& d : dirs) {
        double t0 = 0.0, f0 = f.value(c);
        for (int i = 1; i <= 400; ++i) {
            const double t1 = len * i / 400, f1 = f.value(c + t1 * d);
            if ((f0 <= 0) != (f1 <= 0)) {
                double lo = t0, hi = t1;
                for (int k = 0; k < 60; ++k) {
                    const double m = 0.5 * (lo + hi);
                    ((f.value(c + m * d) <= 0) == (f0 <= 0) ? lo : hi) = m;
                }
                return c + 0.5 * (lo + hi) * d;
            }
            t0 = t1, f0 = f1;
        }
    }
    return c;
}

// ---- the pipelines, run once per level and cached ----------------------------------------------------------------

const char* kFillName[3] = {"none", "normal_projection", "vertical_projection"};

// The spherical pipeline step by step (what dual_contour_spherical chains), keeping what the views draw.
struct SphRun {
    Issues issues;
    std::vector<dvec3> path;  // correct_origin's steps from the start (handout §5: the origin's rule)
    dvec3 origin{0.0};
    double unit = 0.0, r_max = 0.0;
    std::shared_ptr<Octree> tree;
    bool has_vertices = false;
    std::optional<PolygonSoup> open;  // contour(): holes around the axis
    std::vector<PoleRing> rings;
    std::optional<PolygonSoup> filled[2];  // fill_poles: normal_projection, vertical_projection
    PoleFillResult fill[2];
    double seconds = 0.0;
};

// The origin's rule (handout §5), as geolab contour and table1 apply it: a mesh starts at the centre of the smallest
// enclosing sphere of its vertices (the paper), a field without vertices at the centre of bounds()
// (dual_contour_spherical's default); correct_origin then moves it with unit h = largest extent / 2^L.
// r_max = 1.05 × the distance to the farthest corner of bounds(); r_min = 0.
SphRun run_spherical(const ScalarField& f, int level, const std::vector<dvec3>& vertices) {
    const auto t0 = std::chrono::steady_clock::now();
    SphRun run;
    const geolab::Box b = f.bounds();
    const dvec3 ext = b.hi - b.lo;
    run.unit = std::max({ext.x, ext.y, ext.z}) / double(1 << level);
    dvec3 start = b.center();
    if (!vertices.empty())
        attempt_step(run.issues, "minimal_enclosing_sphere", [&] { start = minimal_enclosing_sphere(vertices).center; });
    run.path = {start};
    attempt_step(run.issues, "correct_origin", [&] {
        auto p = correct_origin(f, start, {.unit = run.unit});
        if (!p.empty()) run.path = std::move(p);
    });
    run.origin = run.path.back();
    for (int c = 0; c < 8; ++c) {
        const dvec3 q((c & 1) ? b.hi.x : b.lo.x, (c & 2) ? b.hi.y : b.lo.y, (c & 4) ? b.hi.z : b.lo.z);
        run.r_max = std::max(run.r_max, glm::length(q - run.origin));
    }
    run.r_max *= 1.05;
    attempt_step(run.issues, "build_spherical_octree", [&] {
        run.tree = std::make_shared<Octree>(build_spherical_octree(f, level, run.origin, 0.0, run.r_max));
    });
    if (run.tree)
        run.has_vertices = attempt_step(run.issues, "place_vertices", [&] { place_vertices(*run.tree, {}); });
    if (run.has_vertices) attempt_step(run.issues, "contour", [&] { run.open = contour(*run.tree, &run.rings); });
    if (run.open)
        for (int k = 0; k < 2; ++k)
            attempt_step(run.issues, "fill_poles", [&] {
                PolygonSoup s = *run.open;
                run.fill[k] = fill_poles(s, run.rings, f, run.origin,
                                         k == 0 ? PoleFill::normal_projection : PoleFill::vertical_projection);
                run.filled[k] = std::move(s);
            });
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return run;
}

struct CartRun {
    Issues issues;
    std::optional<PolygonSoup> soup;
    DcStats stats;
    std::shared_ptr<Octree> tree;  // build_octree alone (the refinement band view)
};

CartRun run_cartesian(const ScalarField& f, int level, double tau = 0.01, double simplify_tolerance = 1e-5) {
    CartRun run;
    CartesianParams p;
    p.max_level = level;
    p.tau = tau;
    p.simplify_tolerance = simplify_tolerance;
    attempt_step(run.issues, "dual_contour_cartesian", [&] { run.soup = dual_contour_cartesian(f, p, &run.stats); });
    attempt_step(run.issues, "build_octree", [&] { run.tree = std::make_shared<Octree>(build_octree(f, p)); });
    return run;
}

// ---- the demo's state ---------------------------------------------------------------------------------------------

enum class ViewKind { cells = 1, origin, poles, compare, octree };
const char* kViewName[6] = {"", "spherical cells", "origin correction", "pole holes", "Cartesian vs spherical",
                            "Cartesian octree"};

struct Demo {
    Input in;
    int level = 5;
    ViewKind view = ViewKind::cells;
    bool equator = false;  // cells: slice along a θ cone (θ-band) instead of a meridian plane
    int slice = 0;         // cells / octree: offset of the slice in finest cells
    int steps = -1;        // origin: steps shown (−1: all)
    double delta = 1.5, margin = 2.0;
    int fill = 1;       // poles: 0 none, 1 normal_projection, 2 vertical_projection
    int pole_zoom = 0;  // poles: 0 north, 1 south, 2 whole mesh
    bool wire = true;
    std::string message;
    std::map<int, SphRun> sph;
    std::map<int, CartRun> cart;

    const ScalarField& f() const { return *in.field; }
    const SphRun& spherical() {
        if (!sph.count(level)) sph.emplace(level, run_spherical(f(), level, in.vertices));
        return sph.at(level);
    }
    const CartRun& cartesian() {
        if (!cart.count(level)) cart.emplace(level, run_cartesian(f(), level));
        return cart.at(level);
    }
    dvec3 model_up() const { return in.is_mesh ? dvec3(0, 1, 0) : dvec3(0, 0, 1); }
};

// Adds a soup to the scene, recording a bad soup (from student code) instead of throwing.
void add_soup(gr::Scene& scene, Issues& issues, const PolygonSoup& s, const gr::MeshStyle& style,
              const std::vector<vec3>* face_colors = nullptr) {
    if (s.n_faces() == 0) return;
    try {
        if (face_colors) scene.add_mesh_face_colors(s, *face_colors, style);
        else scene.add_mesh(s, style);
    } catch (const std::exception& e) {
        issues.errors.push_back(std::string("bad mesh: ") + e.what());
    }
}

// ---- view 1: the spherical octree's curved cells, in a slice ----------------------------------------------------

Frame draw_cells(Demo& d) {
    Frame out;
    const SphRun& run = d.spherical();
    Issues issues = run.issues;
    std::ostringstream st;
    const dvec3 o = run.origin;
    if (!run.tree) {
        out.camera = gr::Camera::framing(d.f().bounds(), 0, 10, vec3(0, 0, 1));
        out.status = "no spherical octree";
        if (issues.any()) out.status += " | " + issues.str();
        return out;
    }
    const Octree& t = *run.tree;
    const int n = t.resolution();
    // the slice: meridian plane through the polar axis at φ_s (both half-planes φ_s and φ_s + π), or the cone θ = θ_s
    const int ip = ((d.slice % n) + n) % n, ip2 = (ip + n / 2) % n;
    const int it = std::clamp(n / 2 + d.slice, 1, n - 1);
    const double phi_s = 2 * kPi * ip / n, theta_s = kPi * it / n;
    const dvec3 normal(-std::sin(phi_s), std::cos(phi_s), 0.0);  // meridian plane normal: increasing φ at φ_s
    std::vector<vec3> section, cells, duals;
    std::size_t n_cells = 0;
    for (std::uint32_t li : t.leaves()) {
        const OctreeNode& nd = t.nodes[li];
        const glm::ivec3 lo = t.corner(nd, 0), hi = t.corner(nd, 7);
        const Spherical S0 = t.lattice_spherical(lo), S1 = t.lattice_spherical(hi);
        bool sign_change = false;
        if (nd.level == t.max_level) {
            const bool in0 = inside(t.value(lo));
            for (int c = 1; c < 8 && !sign_change; ++c) sign_change = inside(t.value(t.corner(nd, c))) != in0;
        }
        // finest sign-changing cells in the layer just behind the slice: drawn whole
        const bool behind = d.equator ? lo.y == it : (lo.z == ip || hi.z == ip2 || (ip2 == 0 && hi.z == n));
        if (sign_change && behind) {
            add_spherical_cell(cells, o, S0, S1);
            ++n_cells;
            if (nd.vertex != invalid_index && nd.vertex < t.vertices.size())
                duals.push_back(vec3(t.vertices[nd.vertex].position));
            continue;
        }
        // every other leaf cut by the slice: its boundary in the slice
        if (d.equator) {
            if (!(lo.y <= it && it < hi.y)) continue;
            for (double p : {S0.phi, S1.phi}) add_arc(section, o, {S0.r, theta_s, p}, {S1.r, theta_s, p}, 1);
            for (double r : {S0.r, S1.r}) add_arc(section, o, {r, theta_s, S0.phi}, {r, theta_s, S1.phi}, 12);
        } else {
            for (int k : {ip, ip2}) {
                if (!(lo.z <= k && k < hi.z)) continue;
                const double p = 2 * kPi * k / n;
                for (double th : {S0.theta, S1.theta}) add_arc(section, o, {S0.r, th, p}, {S1.r, th, p}, 1);
                for (double r : {S0.r, S1.r}) add_arc(section, o, {r, S0.theta, p}, {r, S1.theta, p}, 12);
            }
        }
    }
    // the surface behind the slice
    const PolygonSoup* mesh = run.filled[0] ? &*run.filled[0] : run.open ? &*run.open : nullptr;
    if (mesh) {
        const PolygonSoup back = d.equator ? gr::keep_faces(*mesh, [&](const dvec3& c) { return to_theta(c - o) > theta_s; })
                                           : gr::keep_faces(*mesh, [&](const dvec3& c) { return glm::dot(c - o, normal) > 0; });
        add_soup(out.scene, issues, back, {.color = kGrey, .smooth = false, .wireframe = false});
    }
    out.scene.add_lines(section, kSection, 1.2f);
    if (!cells.empty()) out.scene.add_lines(cells, kCell, 2.0f);
    if (!duals.empty()) out.scene.add_points(duals, kDual, 7.0f);
    // camera: perpendicular to the slice
    const geolab::Box b = box_around(o, 0.8 * run.r_max);  // the shell; its outermost coarse cells may be cut
    if (d.equator) out.camera = camera_from(b, dvec3(0.0, -0.25, 1.0), dvec3(0, 1, 0));
    else out.camera = camera_from(b, -normal + dvec3(0, 0, 0.15), dvec3(0, 0, 1));
    st << "L " << d.level << ", origin " << fmt(o) << ", " << t.reachable_nodes() << " cells, " << t.leaves().size()
       << " leaves | slice: " << (d.equator ? "θ = " + fmt(theta_s * 180 / kPi) + "°" : "meridian φ = " + fmt(phi_s * 180 / kPi) + "°")
       << ", " << n_cells << " finest sign-changing cells drawn whole (blue), dual vertices red";
    out.status = st.str();
    if (issues.any()) out.status += " | " + issues.str();
    return out;
}

// ---- view 2: the origin moving off the surface (eq. 6) ------------------------------------------------------------

Frame draw_origin(Demo& d, bool full_path_in_view = true) {
    Frame out;
    Issues issues;
    const ScalarField& f = d.f();
    const geolab::Box b = f.bounds();
    const dvec3 ext = b.hi - b.lo;
    const double h = std::max({ext.x, ext.y, ext.z}) / double(1 << d.level);
    const dvec3 x0 = surface_point(f);
    std::vector<dvec3> path{x0};
    const OriginParams params{.unit = h, .delta = d.delta, .margin = d.margin};
    attempt_step(issues, "correct_origin", [&] { path = correct_origin(f, x0, params); });
    if (path.empty()) path = {x0};
    const int total = int(path.size()) - 1;
    const int shown = d.steps < 0 ? total : std::min(d.steps, total);
    // the plane of the picture: through x0, spanned by the gradient u and the in-plane up w
    dvec3 u = f.gradient(x0);
    u = glm::length(u) > 0 ? glm::normalize(u) : dvec3(1, 0, 0);
    const dvec3 ref = std::abs(u.z) < 0.9 ? dvec3(0, 0, 1) : dvec3(0, 1, 0);
    const dvec3 w = glm::normalize(ref - glm::dot(ref, u) * u), nrm = glm::cross(u, w);
    double reach = 0.0;
    for (const auto& p : path) reach = std::max(reach, glm::length(p - x0));
    const double R = std::max({2.2 * reach, 3.0 * d.margin * h, 4.0 * h});
    const dvec3 c = x0 + 0.5 * (path.back() - x0);
    out.scene.add_lines(plane_contour(f, c, u, w, R, 160, 0.0), kCurve, 3.0f);
    for (double s : {-1.0, 1.0}) out.scene.add_lines(plane_contour(f, c, u, w, R, 160, s * d.margin * h), kMargin, 1.5f);
    // the lattice of cells of size h around x0, in the plane, for scale
    std::vector<vec3> grid;
    const int k = int(std::ceil(R / h));
    for (int i = -k; i <= k; ++i) {
        grid.push_back(vec3(c + i * h * u - R * w)), grid.push_back(vec3(c + i * h * u + R * w));
        grid.push_back(vec3(c - R * u + i * h * w)), grid.push_back(vec3(c + R * u + i * h * w));
    }
    out.scene.add_lines(grid, vec3(0.90f, 0.90f, 0.93f), 1.0f);
    std::vector<vec3> seg, pts, cols;
    for (int i = 0; i <= shown; ++i) {
        pts.push_back(vec3(path[i]));
        cols.push_back(i == 0 ? kStart : (i == total ? kFinal : kStep));
        if (i > 0) seg.push_back(vec3(path[i - 1])), seg.push_back(vec3(path[i]));
    }
    if (!seg.empty()) out.scene.add_lines(seg, kStep, 3.0f);
    out.scene.add_points(pts, cols, 14.0f);
    // look at the plane face on: the square [−R, R]² fills the shorter image side
    out.camera = gr::close_up(camera_from(box_around(c, R), nrm, w), c, (full_path_in_view ? 0.8 : 1.0) * R);
    std::ostringstream st;
    st << "x0 on the surface " << fmt(x0) << ", f(x0) = " << fmt(f.value(x0), 2) << "; h = " << fmt(h) << ", δ = "
       << fmt(d.delta) << ", margin = " << fmt(d.margin) << " h | step " << shown << " of " << total << ": x = "
       << fmt(path[shown]) << ", f(x)/h = " << fmt(f.value(path[shown]) / h, 3)
       << (shown == total && !issues.any() ? (std::abs(f.value(path[shown])) >= d.margin * h ? " (done: |f| ≥ margin·h)" : " (stopped: max_steps)") : "");
    out.status = st.str();
    if (issues.any()) out.status += " | " + issues.str();
    return out;
}

// ---- view 3: the holes around the polar axis and their fills -----------------------------------------------------

// The ring to zoom on: the outermost ring at the chosen pole.
const PoleRing* zoom_ring(const SphRun& run, bool north) {
    const PoleRing* best = nullptr;
    for (const auto& r : run.rings)
        if (r.north == north && (!best || r.r_hi > best->r_hi)) best = &r;
    return best;
}

Frame draw_poles(Demo& d, int fill, int zoom) {
    Frame out;
    const SphRun& run = d.spherical();
    Issues issues = run.issues;
    const dvec3 o = run.origin;
    std::ostringstream st;
    if (!run.open) {
        out.camera = gr::Camera::framing(d.f().bounds(), 0, 10, vec3(0, 0, 1));
        out.status = "no spherical mesh yet | " + issues.str();
        return out;
    }
    const PolygonSoup* soup = fill == 0 ? &*run.open : run.filled[fill - 1] ? &*run.filled[fill - 1] : nullptr;
    if (!soup) soup = &*run.open;
    std::vector<vec3> colors(soup->n_faces(), kGrey);
    if (fill > 0 && run.filled[fill - 1]) {
        const PoleFillResult& fr = run.fill[fill - 1];
        for (std::size_t i = fr.first_face; i < fr.first_face + fr.n_faces && i < colors.size(); ++i)
            colors[i] = fill == 1 ? kNormalFill : kVerticalFill;
    }
    add_soup(out.scene, issues, *soup, {.color = kGrey, .smooth = false, .wireframe = d.wire, .wire_color = kWire, .wire_width = 1.0f},
             &colors);
    // the hole boundaries (where the fans go), the ring vertices, the ghost vertices, the polar axis
    std::vector<vec3> ring_pts;
    for (const auto& r : run.rings)
        for (auto v : r.ring)
            if (v < run.open->n_vertices()) ring_pts.push_back(vec3(run.open->positions[v]));
    if (fill == 0) {
        const auto hole = gr::boundary_edges(*run.open);
        if (!hole.empty()) out.scene.add_lines(hole, kHole, 3.5f);
    }
    if (!ring_pts.empty()) out.scene.add_points(ring_pts, kHole, 8.0f);
    out.scene.add_lines({vec3(o - run.r_max * dvec3(0, 0, 1)), vec3(o + run.r_max * dvec3(0, 0, 1))}, kAxis, 2.0f);
    std::vector<vec3> ghosts;
    if (fill > 0 && run.filled[fill - 1])
        for (auto g : run.fill[fill - 1].ghost_vertices)
            if (g < run.filled[fill - 1]->n_vertices()) ghosts.push_back(vec3(run.filled[fill - 1]->positions[g]));
    if (!ghosts.empty()) out.scene.add_points(ghosts, kGhost, 14.0f);
    // zoomed on the outermost ring of the chosen pole
    const PoleRing* ring = zoom < 2 ? zoom_ring(run, zoom == 0) : nullptr;
    if (ring) {
        const dvec3 axis(0, 0, zoom == 0 ? 1.0 : -1.0);
        const dvec3 c = o + 0.5 * (ring->r_lo + ring->r_hi) * axis;
        double rad = 0.0;
        for (auto v : ring->ring) {
            const dvec3 q = run.open->positions[v] - o;
            rad = std::max(rad, std::hypot(q.x, q.y));
        }
        rad = std::max({3.0 * rad, 0.5 * (ring->r_hi - ring->r_lo), 1e-9});
        const double tilt = 0.7;  // from above, to look into the hole
        out.camera = gr::close_up(camera_from(box_around(c, rad), dvec3(0.0, -1.0, zoom == 0 ? tilt : -tilt), dvec3(0, 0, 1)),
                                  c, rad);
    } else {
        out.camera = camera_from(d.f().bounds(), dvec3(0.3, -1.0, 0.35), dvec3(0, 0, 1));
    }
    // |f(ghost)| of both fills, in units of h (how far the ghost is from the true surface)
    st << "L " << d.level << ", fill " << kFillName[fill] << " | " << run.rings.size() << " ring(s) on the axis";
    for (int k = 0; k < 2; ++k) {
        if (!run.filled[k] || run.fill[k].ghost_vertices.empty()) continue;
        double worst = 0.0;
        for (auto g : run.fill[k].ghost_vertices)
            if (g < run.filled[k]->n_vertices()) worst = std::max(worst, std::abs(d.f().value(run.filled[k]->positions[g])));
        st << ", " << (k == 0 ? "normal" : "vertical") << ": max |f(ghost)| = " << fmt(worst / run.unit, 2) << " h";
    }
    const MeshCheck mc = check_mesh(*soup);
    st << " | " << soup->n_vertices() << " vertices, " << mc.boundary_edges << " boundary edges"
       << (mc.closed_manifold() ? " (closed manifold)" : "");
    if (run.rings.empty()) st << " | the axis misses the surface here: no holes (try blob, sphere, bunny00)";
    out.status = st.str();
    if (issues.any()) out.status += " | " + issues.str();
    return out;
}

// ---- view 4: Cartesian and spherical meshes side by side ----------------------------------------------------------

Frame draw_compare(Demo& d) {
    Frame out;
    const SphRun& sr = d.spherical();
    const CartRun& cr = d.cartesian();
    Issues issues = cr.issues;
    issues.add(sr.issues);
    const geolab::Box b = d.f().bounds();
    const dvec3 ext = b.hi - b.lo;
    // Cartesian left, spherical right, across the screen (x for both up axes used here)
    const dvec3 shift(0.58 * std::max(ext.x, 0.6 * std::max(ext.y, ext.z)) + 0.05 * glm::length(ext), 0, 0);
    const PolygonSoup* sph_mesh = sr.filled[0] ? &*sr.filled[0] : sr.open ? &*sr.open : nullptr;
    std::size_t vc = 0, vs = 0;
    if (cr.soup) {
        PolygonSoup s = *cr.soup;
        for (auto& p : s.positions) p -= shift;
        add_soup(out.scene, issues, s, {.color = kCartesian, .smooth = false, .wireframe = d.wire, .wire_color = kWire, .wire_width = 0.8f});
        vc = s.n_vertices();
    }
    if (sph_mesh) {
        PolygonSoup s = *sph_mesh;
        for (auto& p : s.positions) p += shift;
        add_soup(out.scene, issues, s, {.color = kSphericalMesh, .smooth = false, .wireframe = d.wire, .wire_color = kWire, .wire_width = 0.8f});
        vs = s.n_vertices();
    }
    const geolab::Box view{b.lo - shift, b.hi + shift};
    out.camera = d.in.is_mesh ? camera_from(view, dvec3(0, 0.15, 1), dvec3(0, 1, 0))
                              : camera_from(view, dvec3(0, -1, 0.45), dvec3(0, 0, 1));
    out.camera.distance *= 0.72f;  // the framing box's depth corners leave too much margin for two side-by-side shapes
    std::ostringstream st;
    st << "L " << d.level << " | Cartesian (left): " << vc << " vertices";
    if (cr.soup) st << ", " << cr.stats.faces << " faces, " << fmt(cr.stats.seconds, 2) << " s";
    st << " | spherical (right): " << vs << " vertices";
    if (sph_mesh) st << ", " << sph_mesh->n_faces() << " faces, " << fmt(sr.seconds, 2) << " s";
    if (vc && vs) st << " | CR = " << fmt(double(vc) / double(vs), 3);
    out.status = st.str();
    if (issues.any()) out.status += " | " + issues.str();
    return out;
}

// ---- view 5: the Cartesian octree's refinement band ---------------------------------------------------------------

Frame draw_octree(Demo& d) {
    Frame out;
    const CartRun& cr = d.cartesian();
    Issues issues = cr.issues;
    std::ostringstream st;
    const geolab::Box b = d.f().bounds();
    // the slice: the lattice plane across the "front" axis (y for implicits, z for the y-up models)
    const int ax = d.in.is_mesh ? 2 : 1;
    dvec3 eye(0.0);
    eye[ax] = -1.0;
    if (!cr.tree) {
        out.camera = camera_from(b, eye, d.model_up());
        out.status = "no Cartesian octree | " + issues.str();
        return out;
    }
    const Octree& t = *cr.tree;
    const int n = t.resolution(), is = std::clamp(n / 2 + d.slice, 0, n - 1);
    const double ys = t.lattice_point(glm::ivec3(is)).operator[](ax);
    std::vector<vec3> section, cells;
    std::size_t per_level[12] = {};
    for (std::uint32_t li : t.leaves()) {
        const OctreeNode& nd = t.nodes[li];
        const glm::ivec3 lo = t.corner(nd, 0), hi = t.corner(nd, 7);
        if (!(lo[ax] <= is && is < hi[ax])) continue;
        ++per_level[nd.level];
        const dvec3 a = t.lattice_point(lo), c = t.lattice_point(hi);
        bool sign_change = false;
        if (nd.level == t.max_level) {
            const bool in0 = inside(t.value(lo));
            for (int k = 1; k < 8 && !sign_change; ++k) sign_change = inside(t.value(t.corner(nd, k))) != in0;
        }
        if (sign_change && lo[ax] == is) {
            gr::add_box_edges(cells, a, c);
            continue;
        }
        dvec3 a2 = a, c2 = c;
        a2[ax] = c2[ax] = ys;
        std::vector<vec3> box;
        gr::add_box_edges(box, a2, c2);
        for (std::size_t i = 0; i < box.size(); i += 2)
            if (box[i] != box[i + 1]) section.push_back(box[i]), section.push_back(box[i + 1]);
    }
    if (cr.soup) {
        const PolygonSoup back = gr::keep_faces(*cr.soup, [&](const dvec3& p) { return p[ax] > ys; });
        add_soup(out.scene, issues, back, {.color = kGrey, .smooth = false});
    }
    out.scene.add_lines(section, kSection, 1.2f);
    if (!cells.empty()) out.scene.add_lines(cells, kCell, 1.6f);
    const dvec3 up = d.model_up();
    out.camera = camera_from({t.min_corner, t.min_corner + dvec3(t.size)}, eye + 0.12 * up, up);
    st << "L " << d.level << ", " << t.reachable_nodes() << " cells, " << t.leaves().size() << " leaves, "
       << t.samples() << " samples | leaves cut by the slice " << "xyz"[ax] << " = " << fmt(ys) << " per level:";
    for (int l = 0; l <= t.max_level; ++l)
        if (per_level[l]) st << " " << l << ":" << per_level[l];
    st << " (finest sign-changing cells drawn whole, blue)";
    out.status = st.str();
    if (issues.any()) out.status += " | " + issues.str();
    return out;
}

Frame draw(Demo& d) {
    switch (d.view) {
        case ViewKind::cells: return draw_cells(d);
        case ViewKind::origin: return draw_origin(d);
        case ViewKind::poles: return draw_poles(d, d.fill, d.pole_zoom);
        case ViewKind::compare: return draw_compare(d);
        case ViewKind::octree: return draw_octree(d);
    }
    return {};
}

// ---- figures ----------------------------------------------------------------------------------------------------------

Input load_first(std::initializer_list<const char*> names, const char* fallback) {
    for (const char* n : names)
        if (geolab::model_path(n)) return load(n);
    return load(fallback);
}

int render_figures(gr::FigureWriter w) {
    const int width = w.width(), height = w.height();

    // (a) the spherical octree's curved cells around a surface (meridian slice), and a θ-band
    {
        Demo d{load("blob")};
        d.level = 4;
        d.view = ViewKind::cells;
        w.write("cells.png", draw_cells(d));
        d.equator = true;
        w.write("cells_equator.png", draw_cells(d));
    }
    // (b) the origin moved off the surface (Fig. 6): level 3 (coarse h, large steps) on the blob
    {
        Demo d{load("blob")};
        d.level = 3;
        w.write("origin.png", draw_origin(d));
    }
    // (c) pole holes: none, then normal vs vertical projection, zoomed on the north pole
    {
        Demo d{load("blob")};
        d.level = 4;
        d.wire = true;
        const int fw = width / 2, fh = height;
        w.write("poles_none.png", draw_poles(d, 0, 0));
        const Frame a = draw_poles(d, 1, 0), b = draw_poles(d, 2, 0);
        w.write("poles_fill.png", gr::hstack({gr::render_image(a.scene, a.camera, fw, fh), gr::render_image(b.scene, b.camera, fw, fh)}, 6),
                "left normal_projection, right vertical_projection | " + a.status);
        w.write("poles_whole.png", draw_poles(d, 1, 2));
    }
    // (d) Cartesian vs spherical DC of the same model at the same level
    {
        Demo d{load_first({"bunny00"}, "rounded_union")};
        d.level = 6;
        w.write("compare.png", draw_compare(d));
    }
    // (e) QEF vertex vs mass point on a cube's corner (sharp features)
    {
        const Input in = load("cube");
        const CartRun q = run_cartesian(*in.field, 3, 0.01, 0.0), m = run_cartesian(*in.field, 3, 10.0, 0.0);
        Frame a, b;
        Issues issues = q.issues;
        issues.add(m.issues);
        const gr::MeshStyle st{.color = kGrey, .smooth = false, .wireframe = true, .wire_color = kWire, .wire_width = 1.2f};
        if (q.soup) add_soup(a.scene, issues, *q.soup, st);
        if (m.soup) add_soup(b.scene, issues, *m.soup, st);
        const geolab::Box box = box_around(dvec3(0.0), 0.62);
        a.camera = b.camera = camera_from(box, dvec3(1, 0.8, 0.9), dvec3(0, 0, 1));
        const int fw = width / 2;
        std::string status = "left: QEF minimiser (τ = 0.01), right: mass point (τ = 10, every eigenvalue dropped); level 3";
        if (issues.any()) status += " | " + issues.str();
        w.write("qef_corner.png", gr::hstack({gr::render_image(a.scene, a.camera, fw, height), gr::render_image(b.scene, b.camera, fw, height)}, 6),
                status);
    }
    // (f) the Cartesian octree's refinement band
    {
        Demo d{load("blob")};
        d.level = 5;
        w.write("octree_band.png", draw_octree(d));
    }
    return w.finish();
}

// ---- the window ------------------------------------------------------------------------------------------------------

const char* kKeys =
    "Window keys:\n"
    "  1 2 3 4 5       views: spherical cells, origin correction, pole holes, Cartesian vs spherical, Cartesian octree\n"
    "  + -             level up / down (2..8)\n"
    "  [ ]             cells and octree views: move the slice by one finest cell\n"
    "  T               cells view: meridian slice / θ-band slice\n"
    "  N or Space, B, A  origin view: next step, step back, all steps\n"
    "  D, M            origin view: δ 1.5 / 3; margin 2 / 4 / 8\n"
    "  F, Z            poles view: fill none / normal / vertical; north pole / south pole / whole mesh\n"
    "  W               wireframe on/off\n"
    "  Home, S, Esc    re-frame, screenshot (out/screenshots/), quit\n"
    "  (mouse: left drag orbits, right drag pans, wheel zooms)";

// Applies a key; returns true when the camera should be re-framed.
bool on_key(Demo& d, int key) {
    d.message.clear();
    switch (key) {
        case '1': case '2': case '3': case '4': case '5':
            d.view = ViewKind(key - '0');
            return true;
        case '=': case 334: case '+':  // =/+ and keypad +
            if (d.level < 8) ++d.level;
            else d.message = "level 8 is the demo's limit";
            return true;
        case '-': case 333:
            if (d.level > 2) --d.level;
            return true;
        case '[': --d.slice; return false;
        case ']': ++d.slice; return false;
        case 'T': d.equator = !d.equator, d.slice = 0; return true;
        case 'N': case ' ': d.steps = d.steps < 0 ? 1 : d.steps + 1; return false;
        case 'B': d.steps = d.steps < 0 ? 0 : std::max(0, d.steps - 1); return false;
        case 'A': d.steps = -1; return false;
        case 'D': d.delta = d.delta == 1.5 ? 3.0 : 1.5; return false;
        case 'M': d.margin = d.margin == 2.0 ? 4.0 : d.margin == 4.0 ? 8.0 : 2.0; return true;
        case 'F': d.fill = (d.fill + 1) % 3; return false;
        case 'Z': d.pole_zoom = (d.pole_zoom + 1) % 3; return true;
        case 'W': d.wire = !d.wire; return false;
        default: return false;
    }
}

std::string short_keys(const Demo& d) {
    std::string s = " | 1-5 views, +/- level";
    switch (d.view) {
        case ViewKind::cells: s += ", [ ] slice, T slice kind"; break;
        case ViewKind::origin: s += ", N/Space step, B back, A all, D δ, M margin"; break;
        case ViewKind::poles: s += ", F fill, Z pole/whole, W wire"; break;
        case ViewKind::compare: s += ", W wire"; break;
        case ViewKind::octree: s += ", [ ] slice"; break;
    }
    return s + ", Esc";
}

int run_window(const gr::DemoProgram& program, Demo& d) {
    return program.show({.title = "geolab demo 09: spherical dual contouring",
                         .draw =
                             [&] {
                                 Frame fr = draw(d);
                                 fr.status = std::string(kViewName[int(d.view)]) + ": " + fr.status +
                                             (d.message.empty() ? "" : " | " + d.message);
                                 return fr;
                             },
                         .key = [&](int key) { return on_key(d, key); },
                         .key_hint = [&] { return short_keys(d); }});
}

}  // namespace

int main(int argc, char** argv) {
    gr::DemoProgram program("demo_09_spherical_dc",
                            "Lab 09 demo: dual contouring on Cartesian and spherical octrees — the curved cells, the "
                            "origin correction (eq. 6), the polar holes and their fills, Cartesian vs spherical meshes.",
                            kKeys, 1000);
    CLI::App& app = program.cli();
    std::string input, view = "cells", fill = "normal";
    int level = 5, slice = 0, steps = -1;
    double delta = 1.5, margin = 2.0;
    bool equator = false, no_wire = false;
    app.add_option("input", input,
                   "A named implicit (" + implicit_list() +
                       "), a mesh file (.obj .off .ply .stl) or a fetched model (bunny00, cow, lion, ...). Default: blob");
    app.add_option("--level", level, "Octree level L (2^L divisions per axis / of r, θ, φ)")
        ->check(CLI::Range(1, 10))
        ->capture_default_str();
    app.add_option("--view", view, "Start in this view: cells, origin, poles, compare, octree")
        ->check(CLI::IsMember({"cells", "origin", "poles", "compare", "octree"}))
        ->capture_default_str();
    app.add_option("--fill", fill, "Pole fill shown in the poles view: none, normal, vertical")
        ->check(CLI::IsMember({"none", "normal", "vertical"}))
        ->capture_default_str();
    app.add_option("--slice", slice, "Offset of the slice in finest cells (cells, octree views)");
    app.add_flag("--theta-band", equator, "Cells view: slice along a θ cone (the equator at offset 0), not a meridian");
    app.add_option("--steps", steps, "Origin view: show this many steps of the path (default: all)");
    app.add_option("--delta", delta, "Origin view: δ of eq. (6), in units of h")->capture_default_str();
    app.add_option("--margin", margin, "Origin view: stop when |f| ≥ margin·h")->capture_default_str();
    app.add_flag("--no-wireframe", no_wire, "Do not draw the polygon edges");
    if (const auto status = program.parse(argc, argv)) return *status;

    return program.run([&] {
        if (!program.figures().empty()) return render_figures(program.figure_writer());
        Demo d{load(input.empty() ? "blob" : input)};
        d.level = level;
        const char* views[] = {"", "cells", "origin", "poles", "compare", "octree"};
        for (int i = 1; i <= 5; ++i)
            if (view == views[i]) d.view = ViewKind(i);
        d.fill = fill == "none" ? 0 : fill == "normal" ? 1 : 2;
        d.slice = slice, d.equator = equator, d.steps = steps, d.delta = delta, d.margin = margin, d.wire = !no_wire;
        std::cout << "demo 09: " << d.in.name << (d.in.is_mesh ? " (signed distance to the mesh)" : "") << ", level "
                  << d.level << ", view " << kViewName[int(d.view)] << "\n";
        if (!program.png().empty()) return program.write_png(draw(d));
        program.no_display_hint = std::string("(render headless with --png FILE, e.g. --view ") + views[int(d.view)] +
                                  " --png view.png)";
        return run_window(program, d);
    });
}
