// Lab 08 demo: a mesh voxelized at a resolution chosen with a slider (or + / −), its surface or solid voxels drawn as
// cubes (only the faces between a set and an unset voxel), cut by a section plane z = const that a second slider (or
// [ and ]) moves; the plane's outline is drawn. Headless: --png FILE renders the current view; --figures DIR renders
// the handout's figures.
//
// The same file runs against the student's code and the reference: it calls only the lab's public API and lib.
// A function that throws geolab::NotImplemented is named in the status line; what does not need it still shows.
#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "geolab/io.hpp"
#include "geolab/models.hpp"
#include "geolab/render/demo.hpp"
#include "geolab/render/render.hpp"
#include "geolab/render/slicer.hpp"
#include "geolab/voxels.hpp"

namespace {

using namespace geolab::voxels;
using geolab::PolygonSoup;
namespace gr = geolab::render;
using glm::vec3;

const vec3 kVoxel{0.80f, 0.80f, 0.83f};    // voxel faces: grey
const vec3 kCut{0.95f, 0.55f, 0.10f};      // faces on the section plane: orange
const vec3 kMeshWire{0.15f, 0.35f, 0.85f};  // the input mesh's edges: blue
const vec3 kPlane{0.85f, 0.35f, 0.05f};     // the section plane's outline: dark orange
const vec3 kDiffer{0.85f, 0.10f, 0.10f};    // voxels where the GPU and the CPU differ: red
const vec3 kSlab{0.10f, 0.45f, 0.20f};      // a depth slab's planes: green

const char* kKeys =
    "Window keys:\n"
    "  sliders         resolution (8 .. 256, voxelized when released), section plane height (top left)\n"
    "  + / -           resolution x 2 / x 1/2 (8 .. 256)\n"
    "  [ / ]           move the section plane down / up one voxel layer\n"
    "  V               surface / solid voxels\n"
    "  M               the mesh's edges on / off\n"
    "  Home, S, Esc    re-frame, screenshot (out/screenshots/), quit";

// The visible faces of the set voxels with k < k_cut (the section: voxels above it are not drawn), as quads in world
// coordinates; faces lying on the section plane are listed in `cut`.
// Voxels also set in `highlight` are drawn red (Task 7's figure: where the GPU and the CPU differ).
PolygonSoup voxel_faces(const BitGrid& g, const Grid& grid, std::int64_t k_cut, std::vector<vec3>& colors,
                        const BitGrid* highlight = nullptr) {
    PolygonSoup s;
    const Dims d = g.dims;
    auto on = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
        return i >= 0 && j >= 0 && k >= 0 && i < d.nx && j < d.ny && k < d.nz && k < k_cut && g.get(i, j, k);
    };
    const int dirs[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (std::int64_t k = 0; k < std::min(k_cut, d.nz); ++k)
        for (std::int64_t j = 0; j < d.ny; ++j)
            for (std::int64_t i = 0; i < d.nx; ++i) {
                if (!g.get(i, j, k)) continue;
                for (const auto& dir : dirs) {
                    if (on(i + dir[0], j + dir[1], k + dir[2])) continue;
                    // the face's four corners, counter-clockwise seen from outside
                    const int a = dir[0] != 0 ? 0 : dir[1] != 0 ? 1 : 2;  // the face's normal axis
                    const int b = (a + 1) % 3, c = (a + 2) % 3;
                    const bool positive = dir[a] > 0;
                    glm::dvec3 corner[4];
                    const double base[3] = {double(i), double(j), double(k)};
                    for (int q = 0; q < 4; ++q) {
                        glm::dvec3 p(base[0], base[1], base[2]);
                        p[a] += positive ? 1 : 0;
                        const int u = (q == 1 || q == 2), v = (q >= 2);
                        p[b] += positive ? u : v;
                        p[c] += positive ? v : u;
                        corner[q] = grid.origin + grid.voxel_size * p;
                    }
                    const auto n = std::uint32_t(s.positions.size());
                    for (const auto& p : corner) s.positions.push_back(p);
                    s.add_face({n, n + 1, n + 2, n + 3});
                    const bool cut = a == 2 && positive && k + 1 == k_cut && k + 1 < d.nz && g.get(i, j, k + 1);
                    colors.push_back(highlight && highlight->get(i, j, k) ? kDiffer : cut ? kCut : kVoxel);
                }
            }
    return s;
}

// The voxels of one resolution and mode, kept while only the section plane moves.
struct Voxels {
    std::int64_t res = 0;
    bool solid = false;
    BitGrid grid;
    std::string method;
    gr::Issues issues;
};

struct Demo {
    PolygonSoup mesh;
    std::string name;
    std::int64_t res = 64;
    bool solid = true, show_mesh = false;
    double cut = 0.55;  // the section plane's height, as a fraction of the grid
    bool outline = true;  // draw the section plane's outline (the window; not the handout's figures)
    int res_slider = 64;  // the resolution slider's value (applied to res when released)
    mutable Voxels cache;
};

// Your voxelization of the demo's mesh at its resolution and mode (computed once for each).
const Voxels& voxels(const Demo& d, const Grid& grid) {
    if (d.cache.res == d.res && d.cache.solid == d.solid) return d.cache;
    Voxels v{d.res, d.solid, {}, {}, {}};
    const PolygonSoup u = to_grid_units(d.mesh, grid);
    gr::attempt(v.issues, d.solid ? "voxelize_solid" : "voxelize_surface", [&] {
        if (d.solid) {
            const SolidResult r = voxelize_solid(u, grid.dims, 2);
            v.grid = r.grid;
            v.method = (r.method == SolidMethod::parity ? "parity" : "flood fill (open mesh)");
        } else {
            v.grid = voxelize_surface(u, grid.dims, 2);
            v.method = "surface";
        }
    });
    d.cache = std::move(v);
    return d.cache;
}

gr::Frame draw(const Demo& d, float yaw = 30.0f, float pitch = 25.0f) {
    gr::Frame fr;
    const Grid grid = fit_grid(d.mesh, d.res, 1);
    const Voxels& vox = voxels(d, grid);
    gr::Issues issues = vox.issues;
    const BitGrid& g = vox.grid;
    std::string counts = g.words.empty() ? "no voxels" : vox.method;
    const auto k_cut = std::int64_t(d.cut * double(d.res) + 0.5);
    if (!g.words.empty()) {
        std::vector<vec3> colors;
        const PolygonSoup faces = voxel_faces(g, grid, k_cut, colors);
        if (faces.n_faces() > 0) fr.scene.add_mesh_face_colors(faces, colors, {.smooth = false});
        std::uint64_t n = 0;
        for (auto w : g.words) n += std::uint64_t(__builtin_popcountll(w));
        counts += ", " + std::to_string(n) + " voxels";
    }
    if (d.show_mesh || g.words.empty()) fr.scene.add_mesh(d.mesh, {.color = {0.9f, 0.9f, 0.95f}, .smooth = false, .wireframe = true, .wire_color = kMeshWire, .opacity = g.words.empty() ? 1.0f : 0.25f});
    if (d.outline) {  // the section plane: its rectangle across the grid
        const double z = grid.origin.z + grid.voxel_size * double(std::min(k_cut, grid.dims.nz));
        const glm::dvec3 lo = grid.origin, hi = grid.origin + grid.voxel_size * glm::dvec3(double(grid.dims.nx), double(grid.dims.ny), 0.0);
        fr.scene.add_polyline({vec3(lo.x, lo.y, z), vec3(hi.x, lo.y, z), vec3(hi.x, hi.y, z), vec3(lo.x, hi.y, z)}, kPlane, 2.0f, true);
    }
    fr.camera = gr::whole(fr.scene, 4.0 / 3.0, yaw, pitch);
    fr.status = d.name + " at " + std::to_string(d.res) + "³: " + counts + "; section at layer " + std::to_string(k_cut) +
                (issues.any() ? " | " + issues.str() : "");
    return fr;
}

bool on_key(Demo& d, int key) {
    if (key == '+' || key == '=') d.res = std::min<std::int64_t>(256, d.res * 2);
    if (key == '-') d.res = std::max<std::int64_t>(8, d.res / 2);
    d.res_slider = int(d.res);
    if (key == '[') d.cut = std::max(0.0, d.cut - 1.0 / double(d.res));
    if (key == ']') d.cut = std::min(1.0, d.cut + 1.0 / double(d.res));
    if (key == 'V') d.solid = !d.solid;
    if (key == 'M') d.show_mesh = !d.show_mesh;
    return key == '+' || key == '=' || key == '-';
}

// The resolution (logarithmic, 8 .. 256; voxelized when released: a fine grid takes a while) and the section
// plane's height (0 .. 1 of the grid, redrawn live from the kept voxels).
std::vector<gr::Slider> sliders(Demo& d) {
    gr::Slider res = gr::slider("resolution", d.res_slider, 8, 256, true);
    res.set = [&d](double v) { d.res_slider = int(std::lround(v)), d.res = d.res_slider; };
    res.live = false;
    res.reframe = true;
    return {res, gr::slider("section", d.cut, 0.0, 1.0, 0.01)};
}

PolygonSoup load(const std::string& name) {
    if (const auto p = geolab::model_path(name)) return geolab::read_mesh(*p);
    return geolab::read_mesh(name);
}

gr::Image render(const gr::Frame& f, int w, int h) { return gr::render_image(f.scene, f.camera, w, h); }

// ---- Task 7's figures: the slicing pipeline of seed 002 through OpenGL, and where it can differ from the CPU ----

// An n_u × n_v pixel image (row 0 at the bottom, 0 or 1) drawn as cells on a w × h white panel: set pixels in
// `on`, the others off-white, thin grey lines between cells.
gr::Image pixel_panel(const std::vector<std::uint8_t>& img, int n_u, int n_v, vec3 on, int w, int h) {
    gr::Image out{w, h, std::vector<std::uint8_t>(4 * std::size_t(w) * std::size_t(h), 255)};
    const int cell = std::max(1, std::min((w - 16) / n_u, (h - 16) / n_v));
    const int x0 = (w - cell * n_u) / 2, y0 = (h - cell * n_v) / 2;
    for (int j = 0; j < n_v; ++j)
        for (int i = 0; i < n_u; ++i) {
            const bool set = img[std::size_t(j * n_u + i)] != 0;
            for (int dy = 0; dy < cell; ++dy)
                for (int dx = 0; dx < cell; ++dx) {
                    const bool line = cell >= 4 && (dx == 0 || dy == 0);
                    const int x = x0 + i * cell + dx, y = y0 + (n_v - 1 - j) * cell + dy;  // row 0 at the bottom
                    std::uint8_t* p = out.rgba.data() + 4 * (std::size_t(y) * std::size_t(w) + std::size_t(x));
                    const vec3 c = line ? vec3(0.86f) : set ? on : vec3(0.97f);
                    for (int ch = 0; ch < 3; ++ch) p[ch] = std::uint8_t(255.0f * c[ch] + 0.5f);
                }
        }
    return out;
}

// The figures of handout §9 (each needs your Task 7 functions; skipped with the reason otherwise).
void render_gl_figures(gr::FigureWriter& w, const PolygonSoup& bunny, int pw, int ph) {
    // The pipeline: the slicing camera looks down z through a 64 × 64 image; slab k's crossings XORed alone give
    // the slice's outline; XORed onto all the slabs below, the filled section; every layer read back, the solid.
    {
        const Grid grid = fit_grid(bunny, 64, 1);
        const PolygonSoup u = to_grid_units(bunny, grid);
        const std::int64_t k = 26, n = grid.dims.nx;
        std::vector<gr::Image> panels;
        gr::Issues issues;
        gr::attempt(issues, "slicing_camera", [&] {
            std::vector<glm::dvec3> corners;
            for (std::size_t f = 0; f < u.n_faces(); ++f) {
                const auto vs = u.face(f);
                for (std::size_t t = 1; t + 1 < vs.size(); ++t)
                    corners.insert(corners.end(), {u.positions[vs[0]], u.positions[vs[t]], u.positions[vs[t + 1]]});
            }
            gr::SliceRasterizer raster{int(n), int(n)};
            raster.set_triangles(corners, slicing_camera(grid.dims, 2));
            raster.draw_xor(0, raster.triangle_count(), float(k) - 0.5f, float(k) + 0.5f);
            const auto outline = raster.read();
            raster.clear();
            raster.draw_xor(0, raster.triangle_count(), -std::numeric_limits<float>::infinity(), float(k) + 0.5f);
            const auto section = raster.read();
            // panel 1: the mesh, the grid's box and slab k's two planes
            gr::Frame fr;
            fr.scene.add_mesh(bunny, {.color = {0.9f, 0.9f, 0.95f}, .smooth = true, .opacity = 0.45f});
            const glm::dvec3 lo = grid.origin, hi = grid.origin + grid.voxel_size * double(n);
            for (double z : {double(k) - 0.5, double(k) + 0.5}) {
                const double wz = grid.origin.z + grid.voxel_size * z;
                fr.scene.add_polyline({vec3(lo.x, lo.y, wz), vec3(hi.x, lo.y, wz), vec3(hi.x, hi.y, wz), vec3(lo.x, hi.y, wz)}, kSlab, 2.5f, true);
            }
            fr.camera = gr::whole(fr.scene, double(pw) / ph, 20.0f, 55.0f);  // the view of bunny_sections.png
            panels.push_back(render(fr, pw, ph));
            panels.push_back(pixel_panel(outline, int(n), int(n), {0.15f, 0.35f, 0.85f}, pw, ph));
            panels.push_back(pixel_panel(section, int(n), int(n), kCut, pw, ph));
        });
        gr::attempt(issues, "voxelize_gl", [&] {
            if (panels.size() != 3) return;
            gr::Frame fr;
            std::vector<vec3> colors;
            fr.scene.add_mesh_face_colors(voxel_faces(voxelize_gl(u, grid.dims, 2), grid, k + 1, colors), colors, {.smooth = false});
            fr.camera = gr::whole(fr.scene, double(pw) / ph, 20.0f, 55.0f);
            panels.push_back(render(fr, pw, ph));
        });
        if (panels.size() == 4)
            w.write("gl_pipeline.png", gr::hstack(panels, 4),
                    "bunny00 at 64³ sliced along z: slab 26 in the view volume, its crossings XORed alone (the outline), "
                    "XORed onto the slabs below (the section), the solid read back layer by layer (cut above layer 26)");
        else
            w.skip("gl_pipeline.png", issues.str());
    }
    // Where GPU and CPU agree and differ: an octahedron with every vertex on a voxel centre, sliced along x (ties
    // decided like parity_fill: identical); a box whose wall x = 2.5 + 1/1024 the rasterizer snaps to 2.5 (red: the
    // layer the GPU adds, every centre 1/1024 voxel from the wall).
    {
        std::vector<gr::Image> panels;
        gr::Issues issues;
        gr::attempt(issues, "voxelize_gl", [&] {
            PolygonSoup oct;
            const glm::dvec3 c(4.5, 4.5, 4.5);
            for (int a = 0; a < 3; ++a)
                for (double sgn : {1.0, -1.0}) {
                    glm::dvec3 p = c;
                    p[a] += 3 * sgn;
                    oct.positions.push_back(p);
                }
            for (std::uint32_t xi : {0u, 1u})
                for (std::uint32_t yi : {2u, 3u})
                    for (std::uint32_t zi : {4u, 5u}) {
                        if ((xi == 0) == (yi == 2) == (zi == 4)) oct.add_face({xi, yi, zi});
                        else oct.add_face({xi, zi, yi});
                    }
            Grid g9;
            g9.dims = {9, 9, 9};
            const BitGrid gl = voxelize_gl(oct, g9.dims, 0), cpu = parity_fill(oct, g9.dims, 2, 1);
            gr::Frame fr;
            std::vector<vec3> colors;
            const BitGrid differ = bits_difference(bits_union(gl, cpu), bits_intersection(gl, cpu));
            fr.scene.add_mesh_face_colors(voxel_faces(gl, g9, 5, colors, &differ), colors, {.smooth = false, .wireframe = true, .wire_color = {0.3f, 0.3f, 0.3f}});
            fr.scene.add_mesh(oct, {.color = {0.9f, 0.9f, 0.95f}, .smooth = false, .wireframe = true, .wire_color = kMeshWire, .opacity = 0.2f});
            fr.camera = gr::whole(fr.scene, double(pw) / ph, 30.0f, 35.0f);
            panels.push_back(render(fr, pw, ph));
        });
        gr::attempt(issues, "voxelize_gl", [&] {
            Grid g8;
            g8.dims = {8, 8, 8};
            const glm::dvec3 lo(2.5 + 1.0 / 1024, 1.5, 2.5), hi(6.5, 6.5, 5.5);
            PolygonSoup box;
            for (int q = 0; q < 8; ++q) box.positions.push_back({q & 1 ? hi.x : lo.x, q & 2 ? hi.y : lo.y, q & 4 ? hi.z : lo.z});
            for (const auto& f : {std::array<std::uint32_t, 4>{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}})
                box.add_face({f[0], f[1], f[2], f[3]});
            const BitGrid gl = voxelize_gl(box, g8.dims, 2), cpu = parity_fill(box, g8.dims, 2, 1);
            const BitGrid differ = bits_difference(gl, cpu);
            std::optional<gr::Camera> camera;  // one view for both panels: the GPU's, which holds the CPU's
            for (const BitGrid* g : {&gl, &cpu}) {
                gr::Frame fr;
                std::vector<vec3> colors;
                fr.scene.add_mesh_face_colors(voxel_faces(*g, g8, 4, colors, &differ), colors, {.smooth = false, .wireframe = true, .wire_color = {0.3f, 0.3f, 0.3f}});
                fr.scene.add_mesh(box, {.color = {0.9f, 0.9f, 0.95f}, .smooth = false, .wireframe = true, .wire_color = kMeshWire, .opacity = 0.15f});
                if (!camera) camera = gr::whole(fr.scene, double(pw) / ph, -35.0f, 30.0f);
                panels.push_back(render({fr.scene, *camera, ""}, pw, ph));
            }
            std::swap(panels[panels.size() - 1], panels[panels.size() - 2]);  // CPU, then GPU
        });
        if (panels.size() == 3)
            w.write("gl_vs_cpu.png", gr::hstack(panels, 4),
                    "left: octahedron with vertices at voxel centres, GPU along x = CPU (ties alike); middle, right: a box "
                    "whose wall lies 1/1024 voxel right of the centres x = 2.5, CPU and GPU (red: the snapped layer)");
        else
            w.skip("gl_vs_cpu.png", issues.str());
    }
}

int render_figures(gr::FigureWriter w) {
    const auto bunny = gr::first_model({"bunny00"});
    if (!bunny) {
        w.skip("surface_vs_solid.png", "bunny00 not fetched (tools/fetch_models.sh)");
        return w.finish();
    }
    Demo d{load(*bunny), *bunny};
    d.outline = false;
    const int pw = 480, ph = 400;
    // surface vs solid, cut at the middle
    d.res = 64;
    d.cut = 0.5;
    d.solid = false;
    const gr::Image surf = render(draw(d), pw, ph);
    d.solid = true;
    const gr::Image sol = render(draw(d), pw, ph);
    w.write("surface_vs_solid.png", gr::hstack({surf, sol}, 4), "bunny00 at 64³ cut at half height: surface voxels (left), solid voxels (right)");
    // sections of the bunny
    std::vector<gr::Image> secs;
    for (double c : {0.3, 0.5, 0.7}) {
        d.cut = c;
        secs.push_back(render(draw(d, 20.0f, 55.0f), pw, ph));
    }
    w.write("bunny_sections.png", gr::hstack(secs, 4), "bunny00 solid at 64³, sections at 30 %, 50 %, 70 % of the height");
    render_gl_figures(w, d.mesh, pw, ph);
    // per-axis parity: the three parity fills of the bunny, cut at the middle
    {
        const Grid grid = fit_grid(d.mesh, 48, 1);
        const PolygonSoup u = to_grid_units(d.mesh, grid);
        std::vector<gr::Image> panels;
        for (int axis = 0; axis < 3; ++axis) {
            gr::Frame fr;
            gr::Issues issues;
            gr::attempt(issues, "parity_fill", [&] {
                std::vector<vec3> colors;
                const PolygonSoup faces = voxel_faces(parity_fill(u, grid.dims, axis, 2), grid, 24, colors);
                fr.scene.add_mesh_face_colors(faces, colors, {.smooth = false});
            });
            if (issues.any()) return w.finish();
            fr.camera = gr::whole(fr.scene, double(pw) / ph, 30.0f, 25.0f);
            panels.push_back(render(fr, pw, ph));
        }
        w.write("per_axis_parity.png", gr::hstack(panels, 4), "bunny00 at 48³: parity along x, y and z (identical voxel for voxel), cut at layer 24");
    }
    // a tie case: an octahedron whose vertices are voxel centres (rays through its vertices and edges)
    {
        const PolygonSoup oct = [] {
            PolygonSoup s;
            const glm::dvec3 c(4.5, 4.5, 4.5);
            const double r = 3;
            s.positions = {c + glm::dvec3(r, 0, 0), c - glm::dvec3(r, 0, 0), c + glm::dvec3(0, r, 0),
                           c - glm::dvec3(0, r, 0), c + glm::dvec3(0, 0, r), c - glm::dvec3(0, 0, r)};
            for (std::uint32_t xi : {0u, 1u})
                for (std::uint32_t yi : {2u, 3u})
                    for (std::uint32_t zi : {4u, 5u}) {
                        const double sgn = (xi == 0 ? 1 : -1) * (yi == 2 ? 1 : -1) * (zi == 4 ? 1 : -1);
                        if (sgn > 0) s.add_face({xi, yi, zi});
                        else s.add_face({xi, zi, yi});
                    }
            return s;
        }();
        Grid grid;
        grid.dims = {9, 9, 9};
        gr::Frame fr;
        gr::Issues issues;
        gr::attempt(issues, "parity_fill", [&] {
            std::vector<vec3> colors;
            const PolygonSoup faces = voxel_faces(parity_fill(oct, grid.dims, 2, 1), grid, 5, colors);
            fr.scene.add_mesh_face_colors(faces, colors, {.smooth = false, .wireframe = true, .wire_color = {0.3f, 0.3f, 0.3f}});
        });
        fr.scene.add_mesh(oct, {.color = {0.9f, 0.9f, 0.95f}, .smooth = false, .wireframe = true, .wire_color = kMeshWire, .opacity = 0.2f});
        fr.camera = gr::whole(fr.scene, 4.0 / 3.0, 30.0f, 35.0f);
        w.write("tie_case.png", fr.scene, fr.camera, "octahedron |x−4.5|+|y−4.5|+|z−4.5| = 3 in 9³: every vertex is a voxel centre; cut at layer 5");
    }
    // voxel CSG of two spheres: union, intersection, difference of the packed solids
    {
        const Grid grid{{0, 0, 0}, 1.0, {40, 40, 40}};
        auto sphere = [](glm::dvec3 c, double r) {
            // an octahedron subdivided twice and pushed to the sphere
            PolygonSoup s;
            std::vector<glm::dvec3> p = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
            std::vector<std::array<std::uint32_t, 3>> f = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
            for (int l = 0; l < 4; ++l) {
                std::vector<std::array<std::uint32_t, 3>> g;
                for (auto& t : f) {
                    const auto a = std::uint32_t(p.size());
                    p.push_back(glm::normalize(p[t[0]] + p[t[1]]));
                    p.push_back(glm::normalize(p[t[1]] + p[t[2]]));
                    p.push_back(glm::normalize(p[t[2]] + p[t[0]]));
                    g.push_back({t[0], a, a + 2});
                    g.push_back({t[1], a + 1, a});
                    g.push_back({t[2], a + 2, a + 1});
                    g.push_back({a, a + 1, a + 2});
                }
                f = g;
            }
            for (auto& q : p) s.positions.push_back(c + r * q);
            for (auto& t : f) s.add_face({t[0], t[1], t[2]});
            return s;
        };
        std::vector<gr::Image> panels;
        gr::Issues issues;
        gr::attempt(issues, "bits_union", [&] {
            // triangles have their own vertices (not shared): fine for parity, whose edges pair up by position
            const BitGrid a = voxelize_solid(sphere({16, 20, 20}, 11), grid.dims, 2).grid;
            const BitGrid b = voxelize_solid(sphere({25, 20, 20}, 9), grid.dims, 2).grid;
            for (const BitGrid& g : {bits_union(a, b), bits_intersection(a, b), bits_difference(a, b)}) {
                gr::Frame fr;
                std::vector<vec3> colors;
                fr.scene.add_mesh_face_colors(voxel_faces(g, grid, 20, colors), colors, {.smooth = false});
                fr.camera = gr::whole(fr.scene, double(pw) / ph, 25.0f, 35.0f);
                panels.push_back(render(fr, pw, ph));
            }
        });
        if (!panels.empty())
            w.write("csg.png", gr::hstack(panels, 4), "two voxelized spheres (40³): A ∪ B, A ∩ B, A − B, cut at layer 20");
        else
            w.skip("csg.png", issues.str());
    }
    return w.finish();
}
}  // namespace

int main(int argc, char** argv) {
    gr::DemoProgram program("demo_08_voxelize", "Lab 08 demo: a mesh voxelized at a chosen resolution, cut by a section plane", kKeys);
    std::string mesh = "bunny00";
    std::int64_t res = 64;
    program.cli().add_option("--mesh", mesh, "A mesh file or a fetched model's name")->capture_default_str();
    program.cli().add_option("--res", res, "Voxels along the longest side")->check(CLI::Range(std::int64_t(4), std::int64_t(512)))->capture_default_str();
    if (const auto status = program.parse(argc, argv)) return *status;
    return program.run([&] {
        if (!program.figures().empty()) return render_figures(program.figure_writer());
        Demo d{load(mesh), mesh};
        d.res = res;
        d.res_slider = int(res);
        return program.show({.title = "geolab demo 08: voxelization",
                             .draw = [&] { return draw(d); },
                             .key = [&](int key) { return on_key(d, key); },
                             .sliders = [&] { return sliders(d); }});
    });
}
