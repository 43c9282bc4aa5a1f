// Lab 02 demo: look inside a volume mesh. A clipping plane that [ and ] move cuts a tetgen bunny (or any volume
// mesh) and shows the cells behind it (a cut-away view), coloured by their quality, by region or plain; the cells
// around an edge in the radial order of your edge_cells, stepped with N; the region complex of your
// region_complex, one dimension at a time; Laplacian smoothing of the interior with your volume_smoothing.
// Headless: --png FILE renders the current view; --figures DIR renders the handout's figures.
//
// The same file runs against the student's code and the reference: it calls only the lab's public API and lib.
// A function that throws geolab::NotImplemented is named in the status line; what does not need it still shows
// (before build_mesh works, the cut-away draws every face of the cells behind the plane).
#include "geolab/render/demo.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "geolab/halfface.hpp"
#include "geolab/models.hpp"
#include "geolab/render/render.hpp"
#include "geolab/tet_quality.hpp"
#include "geolab/volume_fixtures.hpp"
#include "geolab/volume_io.hpp"

namespace {

using namespace geolab::halfface;
using geolab::PolygonSoup;
using geolab::VolumeCell;
using geolab::VolumeMesh;
namespace gr = geolab::render;
using glm::dvec3;
using glm::vec3;
using gr::attempt;
using gr::fmt;
using gr::Issues;

// ---- colours (the handout's captions use these names) -----------------------------------------------------------
const vec3 kPlain{0.80f, 0.80f, 0.84f};    // cells without colouring
const vec3 kWire{0.25f, 0.25f, 0.28f};     // cell edges
const vec3 kShell{0.70f, 0.75f, 0.85f};    // the removed part's boundary surface, translucent
const vec3 kEdge{0.05f, 0.05f, 0.05f};     // the circulated edge: black
const vec3 kCurrent{1.00f, 0.55f, 0.10f};  // the current cell of the circulation: orange
const vec3 kCurve{0.75f, 0.05f, 0.10f};    // 1-cells (single colour mode): dark red
const vec3 kCorner{0.05f, 0.05f, 0.05f};   // 0-cells: black

// The radius ratio's colour: red (flat, 0) → yellow (0.35) → green (0.7 and better); magenta when inverted.
vec3 quality_color(double q) {
    if (!(q > 0)) return {0.85f, 0.10f, 0.85f};
    const float t = float(std::min(1.0, q / 0.7));
    const vec3 red{0.85f, 0.12f, 0.10f}, yellow{0.98f, 0.85f, 0.25f}, green{0.20f, 0.65f, 0.35f};
    return t < 0.5f ? glm::mix(red, yellow, 2 * t) : glm::mix(yellow, green, 2 * t - 1);
}
// Dark → light along the radial order (the first cell darkest), as lab 01's walks.
vec3 order_color(std::size_t i, std::size_t n) {
    const float s = n > 1 ? float(i) / float(n - 1) : 0.0f;
    return glm::mix(vec3(0.00f, 0.10f, 0.45f), vec3(0.55f, 0.80f, 1.00f), s);
}

const char* kKeys =
    "Window keys:\n"
    "  [ / ]           move the clipping plane back / forward\n"
    "  X               the plane's axis: x, y, z\n"
    "  C               cut-away on / off (off: the whole mesh)\n"
    "  Q               colour cells by quality (radius ratio), by region, or plain\n"
    "  L               labels: the file's, x halves, xy quadrants, octants (each times the file's)\n"
    "  R               the radial view: the cells around an edge (your edge_cells) on / off\n"
    "  E / N / B       in the radial view: next edge / next cell around it / interior or boundary edges\n"
    "  D               the region complex (your region_complex): 3-cells, 2-cells, 1- and 0-cells, off\n"
    "  Space / J / O   one smoothing step (t = 0.5) / jitter the interior / original positions\n"
    "  W               cell edges on / off\n"
    "  Home, S, Esc    re-frame, screenshot (out/screenshots/), quit";

enum class Colouring { quality, region, plain };
enum class Labels { file, halves, quadrants, octants };
const char* labels_name(Labels l) {
    switch (l) {
        case Labels::file:
            return "the file's labels";
        case Labels::halves:
            return "labels × x halves";
        case Labels::quadrants:
            return "labels × xy quadrants";
        case Labels::octants:
            return "labels × octants";
    }
    return "";
}

// ---- the input ---------------------------------------------------------------------------------------------------

// A procedural mesh (kuhn_cube, tet_grid:N, hex_grid:N, ball_with_torus:N), a .mesh file, TetGen files or their
// base, or a fetched TetGen model's base ("bunny00.1").
VolumeMesh load(const std::string& arg) {
    namespace vf = geolab::volume_fixtures;
    const auto colon = arg.find(':');
    const std::string name = arg.substr(0, colon);
    const int n = colon == std::string::npos ? 0 : std::stoi(arg.substr(colon + 1));
    if (name == "kuhn_cube") return vf::kuhn_cube();
    if (name == "tet_grid") return vf::tet_grid(n ? n : 6);
    if (name == "hex_grid") return vf::hex_grid(n ? n : 6);
    if (name == "ball_with_torus") return vf::ball_with_torus(n ? n : 10);
    const std::filesystem::path p = arg;
    if (p.extension() == ".mesh") return geolab::read_medit(p);
    if (p.extension() == ".node" || p.extension() == ".ele" || p.extension() == ".face") return geolab::read_tetgen(p);
    for (const std::filesystem::path& base : {p, geolab::models_dir() / p})
        if (std::filesystem::exists(base.string() + ".ele")) return geolab::read_tetgen(base);
    throw std::runtime_error(arg +
                             ": not a volume mesh (.mesh, .node/.ele), a fetched tetgen model (bunny00.1: "
                             "tools/fetch_models.sh) or a procedural one (ball_with_torus:10, tet_grid:6, ...)");
}

// ---- the demo's state ---------------------------------------------------------------------------------------------

struct Demo {
    std::string name;
    CellList cells;               // the input (labels: the file's)
    std::vector<dvec3> original;  // positions as read
    std::optional<Mesh> mesh;     // your build_mesh's result
    Issues build_issues;
    std::vector<std::uint8_t> on_boundary;    // per vertex (kernel only), for the jitter
    std::vector<std::uint8_t> boundary_edge;  // per edge (kernel only), for the radial view

    int axis = 2;
    double cut = 0.5;  // the plane's position as a fraction of the bounding box along the axis
    bool cutaway = true, wire = true;
    Colouring colouring = Colouring::quality;
    Labels labels = Labels::file;
    bool radial = false, radial_boundary = false;  // the radial view; of a boundary edge (a fan)
    std::size_t edge_index = 0, step = 0;
    int dimension = -1;  // region complex: 3, 2, 1 (1- and 0-cells), or -1 (off)
    int smoothing_steps = 0;
    double min_volume = 0;  // after the last smoothing step
    std::string message;    // what the last key did

    // cached results of your code for the current labels / positions
    std::optional<RegionComplex> complex;
    Issues complex_issues;
    std::vector<std::int32_t> complex_labels;

    Demo(std::string n, const VolumeMesh& vm) : name(std::move(n)), cells(cells_from(vm)), original(vm.positions) {
        wire = cells.n_cells() <= 20000;  // a denser wireframe hides the colours
        attempt(build_issues, "build_mesh", [&] { mesh = build_mesh(cells); });
        if (mesh) {
            on_boundary.assign(mesh->n_vertices(), 0);
            boundary_edge.assign(mesh->n_edges(), 0);
            for (HalfFace hf : mesh->halffaces())
                if (!mesh->is_deleted(hf) && mesh->is_boundary(hf))
                    walk(hf, [&](HalfEdge h) {
                        on_boundary[mesh->to_vertex(h).idx] = 1;
                        boundary_edge[mesh->edge(h).idx] = 1;
                    });
        }
    }
    const std::vector<dvec3>& positions() const { return mesh ? mesh->positions() : cells.positions; }

    // The half-edges of hf's loop (the kernel's next).
    template <class F>
    void walk(HalfFace hf, F&& f) const {
        const HalfEdge h0 = mesh->halfedge(hf);
        HalfEdge h = h0;
        std::size_t guard = 0;
        do {
            f(h);
            h = mesh->next(h);
        } while (h != h0 && h.idx < mesh->n_halfedges() && ++guard < 64);
    }
    dvec3 centroid(std::size_t c) const {
        dvec3 s(0);
        int k = 0;
        for (std::size_t i = 0; i < cells.n_faces(c); ++i)
            for (auto v : cells.face(c, i)) s += positions()[v], ++k;
        return s / double(k);
    }
    std::pair<dvec3, dvec3> bounds() const {
        dvec3 lo(1e300), hi(-1e300);
        for (const dvec3& p : positions()) lo = glm::min(lo, p), hi = glm::max(hi, p);
        return {lo, hi};
    }
    double plane() const {
        const auto [lo, hi] = bounds();
        return lo[axis] + cut * (hi[axis] - lo[axis]);
    }
    // Cells behind the plane at `at` (their centroid below it along the axis) are kept; all with the cut-away off.
    bool kept(std::size_t c, double at) const { return !cutaway || centroid(c)[axis] <= at; }
    double quality(std::size_t c) const {
        if (cells.types[c] != CellType::tetrahedron) return 1.0;
        // the tet's corners from its first face (a c b) and the fourth vertex
        const auto f0 = cells.face(c, 0);
        std::uint32_t d = 0;
        for (auto v : cells.face(c, 1))
            if (v != f0[0] && v != f0[1] && v != f0[2]) d = v;
        const auto& p = positions();
        return geolab::tet_radius_ratio(p[f0[0]], p[f0[2]], p[f0[1]], p[d]);
    }
    std::vector<std::int32_t> current_labels() const {
        std::vector<std::int32_t> l(cells.n_cells());
        const auto [lo, hi] = bounds();
        const dvec3 mid = 0.5 * (lo + hi);
        for (std::size_t c = 0; c < l.size(); ++c) {
            const dvec3 x = centroid(c);
            const int code = labels == Labels::file     ? 0
                             : labels == Labels::halves ? int(x.x > mid.x)
                             : labels == Labels::quadrants
                                 ? int(x.x > mid.x) + 2 * int(x.y > mid.y)
                                 : int(x.x > mid.x) + 2 * int(x.y > mid.y) + 4 * int(x.z > mid.z);
            l[c] = cells.labels[c] * 8 + code;
        }
        return l;
    }
    // Your region_complex for the current labels (cached).
    const RegionComplex* region_complex_now() {
        const auto l = current_labels();
        if (!mesh) return nullptr;
        if (l != complex_labels || (!complex && !complex_issues.any())) {
            complex_labels = l;
            complex.reset();
            complex_issues = {};
            attempt(complex_issues, "region_complex", [&] { complex = region_complex(*mesh, l); });
        }
        return complex ? &*complex : nullptr;
    }
};

// ---- drawing ------------------------------------------------------------------------------------------------------

// The faces of cell c as a polygon soup over all positions (appended to `soup`, colour per face).
void add_cell_faces(const Demo& d, std::size_t c, PolygonSoup& soup, std::vector<vec3>& colors, vec3 color) {
    for (std::size_t i = 0; i < d.cells.n_faces(c); ++i) {
        soup.add_face(d.cells.face(c, i));
        colors.push_back(color);
    }
}

// The cut-away: the faces of kept cells that do not touch another kept cell (with your mesh; every face of every
// kept cell before build_mesh works), coloured per cell.
void add_cutaway(const Demo& d, gr::Scene& scene, const std::vector<vec3>& cell_color) {
    PolygonSoup soup;
    soup.positions = d.positions();
    std::vector<vec3> colors;
    std::vector<std::uint8_t> keep(d.cells.n_cells());
    const double at = d.plane();
    for (std::size_t c = 0; c < keep.size(); ++c) keep[c] = d.kept(c, at);
    for (std::size_t c = 0; c < keep.size(); ++c) {
        if (!keep[c]) continue;
        if (!d.mesh) {
            add_cell_faces(d, c, soup, colors, cell_color[c]);
            continue;
        }
        const auto hfs = d.mesh->halffaces(Cell{std::uint32_t(c)});
        for (std::size_t i = 0; i < hfs.size(); ++i) {
            const Cell other = d.mesh->cell(Mesh::opposite(hfs[i]));
            if (other.is_valid() && other.idx < keep.size() && keep[other.idx]) continue;
            soup.add_face(d.cells.face(c, i));
            colors.push_back(cell_color[c]);
        }
    }
    if (soup.n_faces() > 0)
        scene.add_mesh_face_colors(soup, colors,
                                   {.smooth = false, .wireframe = d.wire, .wire_color = kWire, .wire_width = 1.0f});
}

// The removed part's boundary (your boundary_surface), translucent, for context.
void add_shell(const Demo& d, gr::Scene& scene, Issues& issues) {
    if (!d.mesh || !d.cutaway) return;
    attempt(issues, "boundary_surface", [&] {
        const PolygonSoup s = boundary_surface(*d.mesh);
        const double at = d.plane();
        const int axis = d.axis;
        const PolygonSoup front = gr::keep_faces(s, [&](const dvec3& c) { return c[axis] > at; });
        if (front.n_faces() > 0) scene.add_mesh(front, {.color = kShell, .smooth = false, .opacity = 0.18f});
    });
}

// The radial view: the cells around the selected edge in your edge_cells order, the edge, and the order as arrows
// around it; seen along the edge from its second vertex, so the order turns counter-clockwise.
std::string draw_radial(Demo& d, gr::Frame& fr, Issues& issues, double aspect, bool& framed) {
    if (!d.mesh) return "";
    const Mesh& m = *d.mesh;
    // candidate edges: interior ones (or boundary ones), nearest to the plane's centre first
    const auto [lo, hi] = d.bounds();
    dvec3 centre = 0.5 * (lo + hi);
    centre[d.axis] = d.plane();
    std::vector<std::pair<double, Edge>> cand;
    for (Edge e : m.edges()) {
        if (m.is_deleted(e) || bool(d.boundary_edge[e.idx]) != d.radial_boundary) continue;
        const auto ev = m.edge_vertices(e);
        cand.push_back({glm::length(0.5 * (m.position(ev[0]) + m.position(ev[1])) - centre), e});
    }
    if (cand.empty()) return d.radial_boundary ? "no boundary edge" : "no interior edge";
    const std::size_t k = std::min<std::size_t>(cand.size(), 256);
    std::partial_sort(cand.begin(), cand.begin() + k, cand.end());
    const Edge e = cand[d.edge_index % k].second;
    std::vector<Cell> around;
    if (!attempt(issues, "edge_cells", [&] { edge_cells(m, e, around); })) return "";
    const auto ev = m.edge_vertices(e);
    const dvec3 a = m.position(ev[0]), b = m.position(ev[1]);
    PolygonSoup soup;
    soup.positions = d.positions();
    std::vector<vec3> colors;
    PolygonSoup current;
    current.positions = d.positions();
    std::vector<dvec3> centres;
    for (std::size_t i = 0; i < around.size(); ++i) {
        if (around[i].idx >= d.cells.n_cells()) continue;  // a handle out of range: skipped
        const dvec3 c = d.centroid(around[i].idx);
        centres.push_back(c);
        if (i == d.step % around.size()) {
            std::vector<vec3> unused;
            add_cell_faces(d, around[i].idx, current, unused, kCurrent);
        } else {
            add_cell_faces(d, around[i].idx, soup, colors, order_color(i, around.size()));
        }
    }
    if (current.n_faces())
        fr.scene.add_mesh(current, {.color = kCurrent, .smooth = false, .wireframe = true, .wire_color = kWire});
    if (soup.n_faces())
        fr.scene.add_mesh_face_colors(soup, colors,
                                      {.smooth = false, .wireframe = true, .wire_color = kWire, .opacity = 0.45f});
    fr.scene.add_lines({vec3(a), vec3(b)}, kEdge, 6.0f);
    // the order: arrows between consecutive cells' centres, moved into a plane just beyond b (in front of the
    // cells for the camera below, which looks from b's side)
    const dvec3 axis = glm::normalize(b - a), mid = b + 0.05 * (b - a);
    gr::Segments seg;
    auto flat = [&](const dvec3& p) { return p - glm::dot(p - mid, axis) * axis; };
    const std::size_t n = centres.size(), arrows = d.boundary_edge[e.idx] ? n - std::min<std::size_t>(n, 1) : n;
    for (std::size_t i = 0; i < arrows && n > 1; ++i) {  // a full turn closes; a fan ends at the boundary
        const dvec3 p = flat(centres[i]), q = flat(centres[(i + 1) % n]);
        if (glm::length(q - p) > 0)
            gr::add_arrow(seg, p, q, gr::side_towards(p, q, mid), order_color(i, n), {.shrink = 0.15, .head = 0.3});
    }
    seg.draw(fr.scene, 4.0f);
    // look along the edge from b towards a, fitted to the cells
    dvec3 up = std::abs(axis.y) < 0.9 ? dvec3(0, 1, 0) : dvec3(1, 0, 0);
    up = glm::normalize(up - glm::dot(up, axis) * axis);
    fr.camera = gr::fit(gr::camera_from(fr.scene.bounds(), axis, up), fr.scene, aspect);
    framed = true;
    std::string order;
    for (std::size_t i = 0; i < around.size() && i < 12; ++i) order += (i ? " " : "") + std::to_string(around[i].idx);
    if (around.size() > 12) order += " ...";
    return std::string(d.boundary_edge[e.idx] ? "boundary" : "interior") + " edge e" + std::to_string(e.idx) + " (v" +
           std::to_string(ev[0].idx) + " → v" + std::to_string(ev[1].idx) + "): " + std::to_string(around.size()) +
           " cells in radial order [" + order + "], step " +
           std::to_string(around.empty() ? 0 : d.step % around.size() + 1) + " (orange)";
}

// The region complex, one dimension at a time: 3-cells (the cut-away by region), 2-cells (each patch in its own
// colour, the part behind the plane), 1- and 0-cells (each curve in its own colour, corners black, over a faint
// shell).
std::string draw_complex(Demo& d, gr::Frame& fr, Issues& issues) {
    const RegionComplex* rc = d.region_complex_now();
    issues.add(d.complex_issues);
    if (!rc) return "";
    const Mesh& m = *d.mesh;
    const std::string counts = std::to_string(rc->regions.size()) + " regions, " + std::to_string(rc->patches.size()) +
                               " patches, " + std::to_string(rc->curves.size()) + " curves, " +
                               std::to_string(rc->corners.size()) + " corners";
    const double at = d.plane();
    if (d.dimension == 3) {
        std::vector<vec3> color(d.cells.n_cells(), kPlain);
        for (std::size_t r = 0; r < rc->regions.size(); ++r)
            for (Cell c : rc->regions[r].cells)
                if (c.idx < color.size()) color[c.idx] = gr::category_color(r);
        add_cutaway(d, fr.scene, color);
        return "3-cells: " + counts;
    }
    PolygonSoup patches, shell;
    patches.positions = shell.positions = d.positions();
    std::vector<vec3> colors;
    std::vector<std::uint32_t> loop;
    for (std::size_t p = 0; p < rc->patches.size(); ++p)
        for (Face f : rc->patches[p].faces) {
            if (f.idx >= m.n_faces()) continue;
            loop.clear();
            d.walk(Mesh::halfface(f, 0), [&](HalfEdge h) { loop.push_back(m.to_vertex(h).idx); });
            dvec3 c(0);
            for (auto v : loop) c += d.positions()[v];
            c /= double(loop.size());
            const bool behind = !d.cutaway || c[d.axis] <= at;
            if (d.dimension == 2 && behind) patches.add_face(loop), colors.push_back(gr::category_color(p));
            if (d.dimension == 1 && rc->patches[p].regions[1] == invalid_index) shell.add_face(loop);
        }
    if (d.dimension == 2) {
        if (patches.n_faces())
            fr.scene.add_mesh_face_colors(
                patches, colors, {.smooth = false, .wireframe = d.wire, .wire_color = kWire, .wire_width = 1.0f});
        return "2-cells (one colour each): " + counts;
    }
    if (shell.n_faces()) fr.scene.add_mesh(shell, {.color = kShell, .smooth = false, .opacity = 0.15f});
    gr::Segments seg;
    for (std::size_t i = 0; i < rc->curves.size(); ++i)
        for (Edge e : rc->curves[i].edges)
            if (e.idx < m.n_edges()) {
                const auto ev = m.edge_vertices(e);
                seg.add(m.position(ev[0]), m.position(ev[1]), rc->curves.size() == 1 ? kCurve : gr::category_color(i));
            }
    seg.draw(fr.scene, 5.0f);
    std::vector<vec3> corners;
    for (const Corner& k : rc->corners)
        if (k.vertex.idx < m.n_vertices()) corners.push_back(vec3(m.position(k.vertex)));
    if (!corners.empty()) fr.scene.add_points(corners, kCorner, 12.0f);
    return "1-cells (one colour each) and 0-cells (black): " + counts;
}

gr::Frame draw(Demo& d, double aspect, float yaw = 30.0f, float pitch = 20.0f) {
    gr::Frame fr;
    Issues issues = d.build_issues;
    std::string view;
    bool framed = false;
    if (d.radial) {
        view = draw_radial(d, fr, issues, aspect, framed);
    } else if (d.dimension > 0) {
        view = draw_complex(d, fr, issues);
        if (d.dimension != 3) add_shell(d, fr.scene, issues);
    } else {
        std::vector<vec3> color(d.cells.n_cells(), kPlain);
        double qmin = 1e300, qsum = 0;
        std::size_t tets = 0;
        for (std::size_t c = 0; c < color.size(); ++c) {
            if (d.cells.types[c] == CellType::tetrahedron) {
                const double q = d.quality(c);
                qmin = std::min(qmin, q), qsum += q, ++tets;
                if (d.colouring == Colouring::quality) color[c] = quality_color(q);
            }
        }
        if (d.colouring == Colouring::region) {
            if (const RegionComplex* rc = d.region_complex_now()) {
                for (std::size_t r = 0; r < rc->regions.size(); ++r)
                    for (Cell c : rc->regions[r].cells)
                        if (c.idx < color.size()) color[c.idx] = gr::category_color(r);
                view = std::to_string(rc->regions.size()) + " regions (" + labels_name(d.labels) + ")";
            } else {  // without your region_complex: one colour per label
                const auto labels = d.current_labels();
                std::vector<std::int32_t> distinct(labels.begin(), labels.end());
                std::sort(distinct.begin(), distinct.end());
                distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
                for (std::size_t c = 0; c < color.size(); ++c)
                    color[c] = gr::category_color(
                        std::size_t(std::lower_bound(distinct.begin(), distinct.end(), labels[c]) - distinct.begin()));
                view = std::to_string(distinct.size()) + " labels (" + labels_name(d.labels) + ")";
            }
            issues.add(d.complex_issues);
        }
        add_cutaway(d, fr.scene, color);
        add_shell(d, fr.scene, issues);
        if (d.colouring == Colouring::quality && tets)
            view = "radius ratio 3r/R (red 0 → yellow 0.35 → green ≥ 0.7): min " + fmt(qmin) + ", mean " +
                   fmt(qsum / double(tets));
    }
    if (!framed && d.cutaway && !d.radial) {
        // from the removed side, a little off the axis, so the section faces the viewer
        const dvec3 eye[3] = {{1.0, 0.35, 0.55}, {0.45, 1.0, 0.6}, {0.55, 0.35, 1.0}};
        fr.camera = gr::fit(gr::camera_from(fr.scene.bounds(), eye[d.axis]), fr.scene, aspect);
    } else if (!framed) {
        fr.camera = gr::whole(fr.scene, aspect, yaw, pitch);
    }
    std::string status = d.name + ": " + std::to_string(d.cells.n_vertices()) + " vertices, " +
                         std::to_string(d.cells.n_cells()) + " cells";
    if (d.mesh)
        status += " (F " + std::to_string(d.mesh->n_alive(Kind::face)) + ", E " +
                  std::to_string(d.mesh->n_alive(Kind::edge)) + ")";
    if (d.cutaway && !d.radial) status += "; cut at " + std::string(1, char('x' + d.axis)) + " = " + fmt(d.plane());
    if (!view.empty()) status += "; " + view;
    if (d.smoothing_steps)
        status += "; " + std::to_string(d.smoothing_steps) + " smoothing steps, min tet volume " + fmt(d.min_volume);
    if (!d.message.empty()) status += "; " + d.message;
    if (issues.any()) status += " | " + issues.str();
    fr.status = status;
    return fr;
}

// ---- keys ---------------------------------------------------------------------------------------------------------

// Moves every interior vertex by up to `amount` × its shortest edge (deterministic), for smoothing to undo.
void jitter(Demo& d, double amount) {
    if (!d.mesh) return;
    Mesh& m = *d.mesh;
    std::vector<double> shortest(m.n_vertices(), 1e300);
    for (Edge e : m.edges())
        if (!m.is_deleted(e)) {
            const auto ev = m.edge_vertices(e);
            const double l = glm::length(m.position(ev[0]) - m.position(ev[1]));
            shortest[ev[0].idx] = std::min(shortest[ev[0].idx], l),
            shortest[ev[1].idx] = std::min(shortest[ev[1].idx], l);
        }
    for (Vertex v : m.vertices()) {
        if (d.on_boundary[v.idx] || shortest[v.idx] > 1e299) continue;
        const double s = std::sin(12.9898 * v.idx + 78.233) * 43758.5453;
        const double r = s - std::floor(s);
        const dvec3 dir(r - 0.5, std::fmod(r * 7.0, 1.0) - 0.5, std::fmod(r * 13.0, 1.0) - 0.5);
        m.position(v) += amount * shortest[v.idx] * dir;
    }
}

void smooth(Demo& d, int steps) {
    if (!d.mesh) return;
    attempt(d.build_issues, "volume_smoothing", [&] {
        d.min_volume = volume_smoothing(*d.mesh, 0.5, steps);
        d.smoothing_steps += steps;
    });
}

// Applies a key; true when the view changed so much that the camera should move to the new frame's.
bool on_key(Demo& d, int key) {
    d.message.clear();
    const bool was_radial = d.radial;
    switch (key) {
        case '[':
            d.cut = std::max(0.0, d.cut - 0.05);
            break;
        case ']':
            d.cut = std::min(1.0, d.cut + 0.05);
            break;
        case 'X':
            d.axis = (d.axis + 1) % 3;
            return true;
        case 'C':
            d.cutaway = !d.cutaway;
            return true;
        case 'Q':
            d.colouring = Colouring((int(d.colouring) + 1) % 3), d.dimension = -1, d.radial = false;
            break;
        case 'L':
            d.labels = Labels((int(d.labels) + 1) % 4), d.message = labels_name(d.labels);
            break;
        case 'R':
            d.radial = !d.radial, d.step = 0;
            return true;
        case 'E':
            d.edge_index++, d.step = 0;
            return d.radial;
        case 'N':
            d.step++;
            break;
        case 'B':
            d.radial_boundary = !d.radial_boundary, d.step = 0, d.edge_index = 0;
            return d.radial;
        case 'D':
            d.dimension = d.dimension == -1 ? 3 : d.dimension == 1 ? -1 : d.dimension - 1, d.radial = false;
            break;
        case ' ':
            smooth(d, 1);
            break;
        case 'J':
            jitter(d, 0.3), d.smoothing_steps = 0, d.message = "interior jittered";
            break;
        case 'O':
            if (d.mesh) d.mesh->positions() = d.original;
            d.cells.positions = d.original, d.smoothing_steps = 0, d.message = "original positions";
            break;
        case 'W':
            d.wire = !d.wire;
            break;
        default:
            break;
    }
    return was_radial && !d.radial;  // back from the close-up around an edge
}

// ---- figures -------------------------------------------------------------------------------------------------------

gr::Image render(const gr::Frame& f, int w, int h) { return gr::render_image(f.scene, f.camera, w, h); }

int render_figures(gr::FigureWriter w) {
    const int pw = w.width() / 2, ph = w.height() * 3 / 4;
    const double aspect = double(pw) / ph;
    std::optional<Demo> bunny;
    if (std::filesystem::exists(geolab::models_dir() / "bunny00.1.ele")) bunny.emplace("bunny00.1", load("bunny00.1"));
    // (1) cut-away views of the bunny at three depths, cells coloured by quality (the paper's cross sections)
    if (!bunny) {
        w.skip("cutaway.png", "bunny00.1 not fetched (tools/fetch_models.sh runs tetgen)");
    } else {
        Demo& d = *bunny;
        d.axis = 2;
        std::vector<gr::Image> panels;
        std::string what;
        for (double c : {0.35, 0.5, 0.65}) {
            d.cut = c;
            const gr::Frame f = draw(d, aspect, 20.0f, 15.0f);
            panels.push_back(render(f, pw, ph));
            what = f.status;
        }
        w.write("cutaway.png", gr::hstack(panels, 4), what + " (cuts at 35, 50, 65 % of the depth)");
    }
    // (2) the paper's example: the ball with a torus region, cut-away by region (3-cells), and its 2-cells
    {
        Demo d("ball_with_torus:10", geolab::volume_fixtures::ball_with_torus(10));
        d.axis = 2, d.cut = 0.5;  // through the torus's equator
        std::vector<gr::Image> panels;
        std::string what;
        for (int dim : {3, 2}) {
            d.dimension = dim;
            const gr::Frame f = draw(d, aspect, 25.0f, 30.0f);
            what += (what.empty() ? "" : " / ") + f.status;
            panels.push_back(render(f, pw, ph));
        }
        if (d.complex_issues.any() || !d.mesh)
            w.skip("region_complex.png", (d.build_issues.any() ? d.build_issues : d.complex_issues).str());
        else
            w.write("region_complex.png", gr::hstack(panels, 4), what);
        // the same ball cut by the planes x = 0, y = 0, z = 0 as well (labels × octants): its 2-cells, and its 1-
        // and 0-cells
        panels.clear(), what.clear();
        d.labels = Labels::octants;
        for (int dim : {2, 1}) {
            d.dimension = dim;
            d.cutaway = dim == 2;
            const gr::Frame f = draw(d, aspect, 25.0f, 30.0f);
            what += (what.empty() ? "" : " / ") + f.status;
            panels.push_back(render(f, pw, ph));
        }
        if (d.complex_issues.any() || !d.mesh)
            w.skip("cw_cuts.png", (d.build_issues.any() ? d.build_issues : d.complex_issues).str());
        else
            w.write("cw_cuts.png", gr::hstack(panels, 4), what);
    }
    // (3) smoothing: the ball with its interior jittered, before and after 10 steps, coloured by quality
    {
        Demo d("ball_with_torus:8", geolab::volume_fixtures::ball_with_torus(8));
        d.axis = 2, d.cut = 0.5;
        jitter(d, 0.6);
        const gr::Frame before = draw(d, aspect, 30.0f, 20.0f);
        smooth(d, 10);
        const gr::Frame after = draw(d, aspect, 30.0f, 20.0f);
        if (d.build_issues.any())
            w.skip("smoothing.png", d.build_issues.str());
        else
            w.write("smoothing.png", gr::hstack({render(before, pw, ph), render(after, pw, ph)}, 4),
                    before.status + " → " + after.status);
    }
    // (4) the radial order around an interior edge (a full turn) and a boundary edge (a fan) of the ball
    {
        Demo d("ball_with_torus:6", geolab::volume_fixtures::ball_with_torus(6));
        d.radial = true;
        std::vector<gr::Image> panels;
        std::string what;
        for (bool boundary : {false, true}) {
            d.radial_boundary = boundary;
            // of the 256 edges nearest to the middle, the first with the most cells around it
            std::size_t best = 0, most = 0;
            for (d.edge_index = 0; d.edge_index < 256; ++d.edge_index) {
                const std::string status = draw(d, aspect).status;
                const auto at = status.find(" cells in radial order");
                if (at == std::string::npos) break;
                const auto from = status.rfind(' ', at - 1) + 1;
                const std::size_t n = std::stoul(status.substr(from, at - from));
                if (n > most) best = d.edge_index, most = n;
            }
            d.edge_index = best;
            const gr::Frame f = draw(d, aspect);
            what += (what.empty() ? "" : " / ") + f.status;
            panels.push_back(render(f, pw, ph));
        }
        if (what.find("radial order") == std::string::npos)
            w.skip("radial_order.png", what);
        else
            w.write("radial_order.png", gr::hstack(panels, 4), what);
    }
    return w.finish();
}

}  // namespace

int main(int argc, char** argv) {
    gr::DemoProgram program("demo_02_halfface",
                            "Lab 02 demo: a volume mesh cut open, its cells' quality, the cells "
                            "around an edge, the region complex, smoothing",
                            kKeys);
    std::string input = "bunny00.1";
    int edge = 0, smooth_steps = 0;
    double cut = 0.5;
    std::string view = "quality", axis = "z";
    program.cli()
        .add_option("mesh", input,
                    "bunny00.1 (tetgen, fetched), a .mesh or .node/.ele file, or "
                    "ball_with_torus:N, tet_grid:N, hex_grid:N, kuhn_cube")
        ->capture_default_str();
    program.cli()
        .add_option("--cut", cut, "The clipping plane's position, 0..1 along the axis")
        ->check(CLI::Range(0.0, 1.0))
        ->capture_default_str();
    program.cli()
        .add_option("--axis", axis, "The clipping plane's normal")
        ->check(CLI::IsMember({"x", "y", "z"}))
        ->capture_default_str();
    program.cli()
        .add_option("--view", view,
                    "quality, region, plain (cells coloured so), radial (the cells around an edge), boundary-radial "
                    "(around a boundary edge), cells3, cells2, cells1 (the region complex)")
        ->check(
            CLI::IsMember({"quality", "region", "plain", "radial", "boundary-radial", "cells3", "cells2", "cells1"}))
        ->capture_default_str();
    program.cli()
        .add_option("--edge", edge, "In the radial views: the N-th edge nearest to the plane's centre")
        ->capture_default_str();
    program.cli()
        .add_option("--smooth", smooth_steps, "Smoothing steps (t = 0.5, your volume_smoothing) first")
        ->check(CLI::Range(0, 10000));
    program.no_display_hint = "try --png out.png";
    if (const auto status = program.parse(argc, argv)) return *status;
    return program.run([&] {
        if (!program.figures().empty()) return render_figures(program.figure_writer());
        Demo d(input, load(input));
        d.cut = cut;
        d.axis = axis[0] - 'x';
        d.edge_index = std::size_t(edge);
        if (view == "region") d.colouring = Colouring::region;
        if (view == "plain") d.colouring = Colouring::plain;
        if (view == "radial" || view == "boundary-radial") d.radial = true;
        if (view == "boundary-radial") d.radial_boundary = true;
        if (view == "cells3" || view == "cells2" || view == "cells1") d.dimension = view[5] - '0';
        if (smooth_steps) smooth(d, smooth_steps);
        if (!program.png().empty()) return program.write_png(draw(d, program.aspect()));
        return program.show({.title = "geolab demo 02: half-face volume meshes",
                             .draw = [&] { return draw(d, 4.0 / 3.0); },
                             .key = [&](int key) { return on_key(d, key); }});
    });
}
