// Lab 04 demo: blobby objects polygonized by your marching cubes. Three blobs drift on circles through each other
// (the lecture's drops that merge and split; Space plays the animation), the kernel, the threshold, the lattice
// and the time are chosen with sliders (or keys).
// Headless: --png FILE renders the current state, --sequence DIR writes the animation's frames, --figures DIR the
// handout's figures (kernels, merging, the 15 base cases, an ambiguous face, the crack of an inconsistent table).
//
// The same file runs against the student's code and the reference: it calls only the lab's public API and lib.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "geolab/blobby.hpp"
#include "geolab/mc_tables.hpp"
#include "geolab/render/demo.hpp"
#include "geolab/render/headless.hpp"
#include "geolab/render/render.hpp"

namespace {

using namespace geolab::blobby;
using geolab::PolygonSoup;
namespace gr = geolab::render;
using glm::dvec3;
using glm::vec3;

const vec3 kBlob{0.62f, 0.78f, 0.96f};     // blob surfaces: light blue
const vec3 kAxes{0.25f, 0.25f, 0.28f};     // plot axes: dark grey
const vec3 kThreshold{0.55f, 0.55f, 0.6f}; // the threshold line T: grey
const vec3 kCurve{0.85f, 0.10f, 0.10f};    // a kernel's D(r): red
const vec3 kInside{0.85f, 0.10f, 0.10f};   // inside corners: red
const vec3 kOutside{0.2f, 0.2f, 0.25f};    // outside corners: dark
const vec3 kCrack{0.95f, 0.45f, 0.0f};     // boundary edges (cracks): orange
const vec3 kSurface{0.96f, 0.80f, 0.58f};  // case polygons: sand

const char* kKeys =
    "Window keys:\n"
    "  sliders         kernel, threshold T, lattice cells, time (top left)\n"
    "  Space           play / pause the animation\n"
    "  N / B           step the animation forward / back\n"
    "  K               kernel: Blinn, Nishimura, Wyvill\n"
    "  [ / ]           threshold down / up\n"
    "  + / -           finer / coarser lattice\n"
    "  W               wireframe on/off\n"
    "  Home, S, Esc    re-frame, screenshot (out/screenshots/), quit";

struct Demo {
    int kernel = int(Kernel::wyvill);
    double threshold = 0.5;
    double step = 0;    // animation time, 48 steps a period
    int cells = 48;     // lattice cells along the box side
    bool wire = false;
    bool playing = false;
    double play_from = -1;  // the animation clock's seconds at step 0 (< 0: not started)
};
constexpr double kStepsPerSecond = 8;  // the animation's speed: a period in 6 s

// Three blobs on circles that pass through each other. Their shape parameters make the three kernels comparable:
// Blinn's a gives the same isolated radius as Wyvill's R at T = 1/2 (a = 4 ln 2 / R²).
BlobScene scene_at(const Demo& d) {
    BlobScene s;
    s.kernel = Kernel(d.kernel);
    s.threshold = d.threshold;
    const double t = 2 * 3.14159265358979 * d.step / 48.0;
    const dvec3 c[3] = {{0.55 * std::cos(t), 0.55 * std::sin(t), 0.0},
                        {-0.55 * std::cos(t), 0.0, 0.55 * std::sin(t)},
                        {0.0, 0.45 * std::sin(2 * t), -0.2}};
    for (const dvec3& p : c) {
        Blob b;
        b.center = p;
        b.radius = 0.8;
        b.a = 4 * std::log(2.0) / (0.8 * 0.8);
        s.blobs.push_back(b);
    }
    return s;
}

// Sample with the student's sample_lattice and polygonize with the student's marching_cubes.
std::optional<McMesh> polygonize(gr::Issues& issues, const BlobScene& s, double half, int cells) {
    std::optional<McMesh> out;
    gr::attempt(issues, "sample_lattice / marching_cubes", [&] {
        std::uint64_t evals = 0;
        const double h = 2 * half / cells;
        const Lattice L = sample_lattice(s, dvec3(-half), h, glm::ivec3(cells + 1), evals);
        out = marching_cubes(L, 0.0);
    });
    return out;
}

gr::Frame draw(const Demo& d) {
    gr::Frame fr;
    gr::Issues issues;
    const BlobScene s = scene_at(d);
    const auto m = polygonize(issues, s, 1.6, d.cells);
    std::vector<vec3> box;
    gr::add_box_edges(box, dvec3(-1.6), dvec3(1.6));
    fr.scene.add_lines(box, kAxes, 1.0f);
    if (m) fr.scene.add_mesh(m->soup, {.color = kBlob, .smooth = false, .wireframe = d.wire});
    fr.camera = gr::camera_from(gr::box_around(dvec3(0.0), 1.6), dvec3(0.4, 0.5, 1.0));
    fr.status = kernel_name(Kernel(d.kernel)) + ", T " + gr::fmt(d.threshold) + ", step " + gr::fmt(d.step) + ", " +
                std::to_string(d.cells) + "³ cells" +
                (m ? ", " + std::to_string(m->soup.n_faces()) + " triangles" : std::string()) +
                (issues.any() ? " | " + issues.str() : "");
    return fr;
}

bool on_key(Demo& d, int key) {
    if (key == 'N') d.step = std::fmod(std::floor(d.step) + 1, 48.0);
    if (key == 'B') d.step = std::fmod(std::ceil(d.step) + 47, 48.0);
    if (key == ' ') d.playing = !d.playing, d.play_from = -1;
    if (key == 'K') d.kernel = (d.kernel + 1) % 3;
    if (key == '[') d.threshold = std::max(0.05, d.threshold - 0.05);
    if (key == ']') d.threshold = std::min(0.95, d.threshold + 0.05);
    if (key == '=' || key == '+') d.cells = std::min(128, d.cells + 8);
    if (key == '-') d.cells = std::max(8, d.cells - 8);
    if (key == 'W') d.wire = !d.wire;
    return false;
}

// The animation: while playing, the time runs at kStepsPerSecond from where it was.
bool animate(Demo& d, double seconds) {
    if (!d.playing) return false;
    if (d.play_from < 0) d.play_from = seconds - d.step / kStepsPerSecond;
    d.step = std::fmod((seconds - d.play_from) * kStepsPerSecond, 48.0);
    return true;
}

std::vector<gr::Slider> sliders(Demo& d) {
    std::vector<gr::Slider> s{gr::choice("kernel", d.kernel, {"Blinn", "Nishimura", "Wyvill"}),
                              gr::slider("T", d.threshold, 0.05, 0.95, 0.01), gr::slider("cells", d.cells, 8, 128),
                              gr::slider("time", d.step, 0.0, 48.0, 0.25)};
    s[2].live = false;  // a finer lattice is slower: polygonized when released
    return s;
}

// ---- figures --------------------------------------------------------------------------------------------------

gr::Image vstack(const std::vector<gr::Image>& rows, int gap) {
    gr::Image out;
    for (const auto& r : rows) out.width = std::max(out.width, r.width);
    for (const auto& r : rows) out.height += r.height;
    out.height += gap * int(rows.size() - 1);
    out.rgba.assign(std::size_t(out.width) * out.height * 4, 255);
    int y0 = 0;
    for (const auto& r : rows) {
        for (int y = 0; y < r.height; ++y)
            std::copy_n(r.rgba.begin() + std::size_t(y) * r.width * 4, std::size_t(r.width) * 4,
                        out.rgba.begin() + (std::size_t(y0 + y) * out.width) * 4);
        y0 += r.height + gap;
    }
    return out;
}

// A plot of the kernel's D(r) for r in [0, 1.6], b = 1 (student's density), with the axes and the line D = 1/2.
gr::Scene kernel_plot(gr::Issues& issues, Kernel k) {
    gr::Scene sc;
    Blob b;
    b.radius = 1.0;
    b.a = 4 * std::log(2.0);  // D(1/2) = 1/2 for all three
    const double sx = 2.0, sy = 1.5;  // plot scale
    sc.add_lines({vec3(0, 0, 0), vec3(1.6 * sx, 0, 0), vec3(0, 0, 0), vec3(0, 1.1 * sy, 0)}, kAxes, 2.0f);
    for (int i = 1; i <= 3; ++i)  // ticks at r = 0.5, 1, 1.5
        sc.add_lines({vec3(0.5f * i * sx, 0, 0), vec3(0.5f * i * sx, -0.06f, 0)}, kAxes, 2.0f);
    sc.add_lines({vec3(0, 0.5 * sy, 0), vec3(1.6 * sx, 0.5 * sy, 0), vec3(0, sy, 0), vec3(-0.06f, sy, 0)}, kThreshold, 1.5f);
    gr::attempt(issues, "density", [&] {
        std::vector<vec3> pts;
        for (int i = 0; i <= 320; ++i) {
            const double r = 1.6 * i / 320;
            pts.push_back(vec3(r * sx, density(k, b, r) * sy, 0));
        }
        sc.add_polyline(pts, kCurve, 3.0f);
    });
    return sc;
}

// The triangles of one case of a table, vertices at the edge midpoints, in the unit cube at `offset`.
PolygonSoup case_soup(const geolab::McTables& t, int cs, dvec3 offset) {
    PolygonSoup s;
    std::map<int, std::uint32_t> vid;
    auto corner = [](int c) { return dvec3(c & 1, (c >> 1) & 1, (c >> 2) & 1); };
    for (int i = 0; i < t.n_triangles[cs]; ++i) {
        std::uint32_t tri[3];
        for (int m = 0; m < 3; ++m) {
            const int e = t.triangles[cs][3 * i + m];
            if (!vid.count(e)) {
                vid[e] = std::uint32_t(s.positions.size());
                s.positions.push_back(offset + 0.5 * (corner(geolab::mc_edge_corners[e][0]) +
                                                      corner(geolab::mc_edge_corners[e][1])));
            }
            tri[m] = vid[e];
        }
        s.add_face({tri[0], tri[1], tri[2]});
    }
    return s;
}

void add_cube(gr::Scene& sc, int cs, dvec3 offset) {
    std::vector<vec3> box;
    gr::add_box_edges(box, offset, offset + 1.0);
    sc.add_lines(box, kAxes, 1.5f);
    std::vector<vec3> in, out;
    for (int c = 0; c < 8; ++c)
        (((cs >> c) & 1) ? in : out).push_back(vec3(offset + dvec3(c & 1, (c >> 1) & 1, (c >> 2) & 1)));
    if (!in.empty()) sc.add_points(in, kInside, 14.0f);
    if (!out.empty()) sc.add_points(out, kOutside, 7.0f);
}

gr::Image cube_panel(const geolab::McTables& t, int cs, int w, int h, dvec3 eye = dvec3(-0.9, -1.4, 0.8)) {
    gr::Scene sc;
    add_cube(sc, cs, dvec3(0.0));
    const PolygonSoup s = case_soup(t, cs, dvec3(0.0));
    if (s.n_faces()) sc.add_mesh(s, {.color = kSurface, .smooth = false, .wireframe = true});
    const gr::Camera cam = gr::camera_from(gr::box_around(dvec3(0.5), 0.9), eye, dvec3(0, 0, 1));
    return gr::render_image(sc, cam, w, h);
}

// The 24 rotations of the cube as corner permutations (closure of two quarter turns).
std::vector<std::array<int, 8>> rotations() {
    auto turn = [](int axis) {
        std::array<int, 8> p{};
        for (int c = 0; c < 8; ++c) {
            int x = c & 1, y = (c >> 1) & 1, z = (c >> 2) & 1;
            int nx = x, ny = y, nz = z;
            if (axis == 0) ny = 1 - z, nz = y;  // quarter turn about x
            else nx = 1 - y, ny = x;            // quarter turn about z
            p[c] = nx | (ny << 1) | (nz << 2);
        }
        return p;
    };
    std::set<std::array<int, 8>> all{{0, 1, 2, 3, 4, 5, 6, 7}};
    const std::array<int, 8> gens[2] = {turn(0), turn(2)};
    for (bool grew = true; grew;) {
        grew = false;
        for (auto p : std::vector<std::array<int, 8>>(all.begin(), all.end()))
            for (const auto& g : gens) {
                std::array<int, 8> q{};
                for (int c = 0; c < 8; ++c) q[c] = g[p[c]];
                grew |= all.insert(q).second;
            }
    }
    return {all.begin(), all.end()};
}

// The smallest case of each class under rotations and complement: the 15 base cases.
std::vector<int> base_cases() {
    const auto rots = rotations();
    std::set<int> reps;
    for (int cs = 0; cs < 256; ++cs) {
        int best = 256;
        for (int comp = 0; comp < 2; ++comp)
            for (const auto& r : rots) {
                int m = 0;
                for (int c = 0; c < 8; ++c)
                    if (((comp ? ~cs : cs) >> c) & 1) m |= 1 << r[c];
                best = std::min(best, m);
            }
        reps.insert(best);
    }
    return {reps.begin(), reps.end()};
}

int render_figures(gr::FigureWriter w) {
    const int W = w.width(), H = w.height();
    gr::Issues issues;
    // 1. The three kernels side by side.
    {
        std::vector<gr::Image> panels;
        for (Kernel k : {Kernel::blinn, Kernel::nishimura, Kernel::wyvill}) {
            const gr::Scene sc = kernel_plot(issues, k);
            const gr::Camera cam = gr::camera_from(geolab::Box{dvec3(-0.2, -0.2, 0), dvec3(3.3, 1.75, 0)}, dvec3(0, 0, 1));
            panels.push_back(gr::render_image(sc, cam, W / 2, H / 2));
        }
        w.write("kernels.png", gr::hstack(panels, 8), "the three kernels");
    }
    // 2. Two Blinn blobs (a = b = 1, T = 1/2) at several distances: they merge at d ≤ 2.35482.
    {
        std::vector<gr::Image> panels;
        for (double dist : {2.0, 2.3, 2.4, 2.8}) {
            BlobScene s;
            s.kernel = Kernel::blinn;
            s.threshold = 0.5;
            Blob a, b;
            a.center = {-dist / 2, 0, 0};
            b.center = {dist / 2, 0, 0};
            s.blobs = {a, b};
            gr::Scene sc;
            if (const auto m = polygonize(issues, s, 2.4, 96)) sc.add_mesh(m->soup, {.color = kBlob});
            const gr::Camera cam = gr::camera_from(gr::box_around(dvec3(0.0), 2.3), dvec3(0.0, 0.3, 1.0));
            panels.push_back(gr::render_image(sc, cam, W / 2, H / 2));
        }
        w.write("merging.png", gr::hstack(panels, 8), "two Blinn blobs at d = 2.0, 2.3, 2.4, 2.8");
    }
    // 3. The 15 base cases of the consistent table, 5 per row.
    {
        const auto reps = base_cases();
        std::vector<gr::Image> rows;
        for (std::size_t r = 0; r < reps.size(); r += 5) {
            std::vector<gr::Image> row;
            for (std::size_t i = r; i < std::min(reps.size(), r + 5); ++i)
                row.push_back(cube_panel(geolab::mc_tables, reps[i], W / 3, W / 3));
            rows.push_back(gr::hstack(row, 6));
        }
        w.write("cases.png", vstack(rows, 6), std::to_string(reps.size()) + " base cases");
    }
    // 4. An ambiguous face (corners 0 and 3 inside, on the face z = 0) under both rules.
    {
        const int cs = 1 | 8;
        w.write("ambiguous.png",
                gr::hstack({cube_panel(geolab::mc_tables, cs, W * 3 / 4, H, dvec3(-0.6, -0.9, -1.4)),
                           cube_panel(geolab::mc_tables_join, cs, W * 3 / 4, H, dvec3(-0.6, -0.9, -1.4))}, 8),
                "case 9: separated and joined");
    }
    // 5. The crack: two cubes sharing the ambiguous face x = 1. Cube A has six inside corners (the complement
    //    table treats it as the complement of a two-corner case), cube B two.
    {
        const int a = 0xFF & ~(1 << 3) & ~(1 << 5);  // A: all but corners 3 (1,1,0) and 5 (1,0,1)
        const int b = (1 << 0) | (1 << 6);           // B: corners 0 (1,0,0) and 6 (1,1,1)
        std::vector<gr::Image> panels;
        for (const geolab::McTables* t : {&geolab::mc_tables_complement, &geolab::mc_tables}) {
            gr::Scene sc;
            add_cube(sc, a, dvec3(0.0));
            add_cube(sc, b, dvec3(1, 0, 0));
            PolygonSoup s = case_soup(*t, a, dvec3(0.0));
            const PolygonSoup sb = case_soup(*t, b, dvec3(1, 0, 0));
            // Weld the two cubes' vertices by position (midpoints are exact).
            std::map<std::array<double, 3>, std::uint32_t> at;
            for (std::uint32_t v = 0; v < s.positions.size(); ++v) at[{s.positions[v].x, s.positions[v].y, s.positions[v].z}] = v;
            std::vector<std::uint32_t> map(sb.positions.size());
            for (std::uint32_t v = 0; v < sb.positions.size(); ++v) {
                const std::array<double, 3> key{sb.positions[v].x, sb.positions[v].y, sb.positions[v].z};
                if (!at.count(key)) {
                    at[key] = std::uint32_t(s.positions.size());
                    s.positions.push_back(sb.positions[v]);
                }
                map[v] = at[key];
            }
            for (std::size_t f = 0; f < sb.n_faces(); ++f) {
                const auto fc = sb.face(f);
                s.add_face({map[fc[0]], map[fc[1]], map[fc[2]]});
            }
            sc.add_mesh(s, {.color = kSurface, .smooth = false, .wireframe = true});
            // Only the edges on the shared face x = 1 matter: a crack is a boundary edge there.
            std::vector<vec3> crack;
            const auto be = gr::boundary_edges(s);
            for (std::size_t i = 0; i + 1 < be.size(); i += 2)
                if (be[i].x == 1.0f && be[i + 1].x == 1.0f) crack.push_back(be[i]), crack.push_back(be[i + 1]);
            if (!crack.empty()) sc.add_lines(crack, kCrack, 5.0f);
            const gr::Camera cam = gr::camera_from(geolab::Box{dvec3(0.0), dvec3(2, 1, 1)}, dvec3(0.5, -1.2, 0.8), dvec3(0, 0, 1));
            panels.push_back(gr::render_image(sc, cam, W * 3 / 4, H * 3 / 4));
        }
        w.write("crack.png", gr::hstack(panels, 8), "complement-symmetric table (crack) and the consistent table");
    }
    if (issues.any()) std::fprintf(stderr, "figures: %s\n", issues.str().c_str());
    return w.finish();
}

}  // namespace

int main(int argc, char** argv) {
    gr::DemoProgram program("demo_04_blobby", "Lab 04 demo: blobby objects (three kernels) and marching cubes", kKeys);
    Demo d;
    std::string sequence;
    int kernel = 2;
    program.cli().add_option("--kernel", kernel, "0 Blinn, 1 Nishimura, 2 Wyvill")->capture_default_str()->check(CLI::Range(0, 2));
    program.cli().add_option("--threshold", d.threshold, "The threshold T")->capture_default_str()->check(CLI::Range(0.01, 0.99));
    program.cli().add_option("--step", d.step, "Animation step (48 a period)")->capture_default_str()->check(CLI::Range(0, 47));
    program.cli().add_option("--cells", d.cells, "Lattice cells along the box side")->capture_default_str()->check(CLI::Range(4, 256));
    program.cli().add_option("--sequence", sequence, "Write the 48 animation frames as PNGs into this folder");
    if (const auto status = program.parse(argc, argv)) return *status;
    d.kernel = kernel;
    return program.run([&] {
        if (!program.figures().empty()) return render_figures(program.figure_writer());
        if (!sequence.empty()) {
            std::filesystem::create_directories(sequence);
            for (int step = 0; step < 48; ++step) {
                d.step = step;
                const gr::Frame fr = draw(d);
                char name[32];
                std::snprintf(name, sizeof name, "frame_%02d.png", step);
                gr::render_image(fr.scene, fr.camera, program.width(), program.height()).write_png(std::filesystem::path(sequence) / name);
            }
            std::printf("48 frames written to %s\n", sequence.c_str());
            return 0;
        }
        return program.show({.title = "geolab demo 04: blobby objects",
                             .draw = [&] { return draw(d); },
                             .key = [&](int key) { return on_key(d, key); },
                             .sliders = [&] { return sliders(d); },
                             .animate = [&](double seconds) { return animate(d, seconds); }});
    });
}
