// geolab voxelize MESH --res N [--solid] [--method cpu|gl [--axis A] [--compare]] [--threads T]
// [--out x.binvox|x.raw] [--out-of-core] [--slab-layers L] [--json]: lab 08's voxelization of a mesh file or a fetched model, with the counts, the time of
// each stage (wall and CPU) and the peak memory printed (--json: one JSON object with the same figures instead).
// --out-of-core streams the grid slab by slab to a raw file (voxelize_to_file) with a progress bar, so that 2048³
// runs in bounded memory. It runs the variant being built (the reference in the instructor's tree, the student's
// code in the release).
#include <unistd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "geolab/io.hpp"
#include "geolab/models.hpp"
#ifdef GEOLAB_HAS_LAB_08
#include "geolab/voxels.hpp"
#endif

namespace geolab::cli {

void add_voxelize(CLI::App& app, int& status);

#ifdef GEOLAB_HAS_LAB_08
namespace {
namespace vx = geolab::voxels;
struct VoxelizeOpts {
    std::string mesh, method = "cpu", out;
    std::int64_t res = 128, slab_layers = 32;
    bool solid = false, json = false, out_of_core = false;
    int threads = 1;
    int axis = 2;          // --method gl: the slicing axis
    bool compare = false;  // --method gl: count the voxels where the GL solid differs from the CPU's
};

// The process's peak resident memory (VmHWM of /proc/self/status) in MiB, or -1 where /proc does not tell.
double peak_rss_mib() {
    std::FILE* f = std::fopen("/proc/self/status", "r");
    if (!f) return -1;
    char line[256];
    double mib = -1;
    while (std::fgets(line, sizeof line, f))
        if (std::strncmp(line, "VmHWM:", 6) == 0) mib = double(std::atol(line + 6)) / 1024;
    std::fclose(f);
    return mib;
}

// A progress bar on stderr for runs longer than a second: redrawn in place on a terminal, else a line every 10 %.
struct Progress {
    std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
    bool tty = ::isatty(2) != 0;
    int shown = -1;
    void operator()(std::int64_t done, std::int64_t total) {
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const int pct = total > 0 ? int(100 * done / total) : 100;
        if (s < 1.0 && shown < 0) return;  // a short run shows no bar
        if (tty) {
            shown = pct;
            const int bar = pct * 30 / 100;
            std::cerr << "\r  [" << std::string(std::size_t(bar), '#') << std::string(std::size_t(30 - bar), '.') << "] "
                      << done << "/" << total << " slabs, " << int(s) << " s" << (done == total ? "\n" : "") << std::flush;
        } else if (pct / 10 != shown || done == total) {
            shown = pct / 10;
            std::cerr << "  " << done << "/" << total << " slabs (" << pct << " %, " << s << " s)\n";
        }
    }
};

// The output format by the file's extension: ".binvox" or ".raw" (anything else is an error).
bool is_raw(const std::string& out) {
    const std::string ext = std::filesystem::path(out).extension().string();
    if (ext == ".raw") return true;
    if (ext == ".binvox") return false;
    throw std::invalid_argument("--out " + out + ": the extension must be .binvox or .raw");
}

// The CPU time of the whole process (all threads), in ms.
double cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

// One stage line: "  surface ........ 12.3 ms" (to `out`), and the stage's wall and CPU time in `report`
// ("<stage>_ms", "<stage>_cpu_ms": on a shared machine the CPU time is the steadier figure).
struct Stage {
    std::ostream& out;
    nlohmann::json& report;
    std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
    double c0 = cpu_ms();
    void done(const std::string& what, const std::string& result) {
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        const double cpu = cpu_ms() - c0;
        out << "  " << what << std::string(what.size() < 14 ? 14 - what.size() : 1, '.') << " " << result << "  ("
            << ms << " ms, CPU " << cpu << " ms)\n"
            << std::flush;
        report[what + "_ms"] = ms;
        report[what + "_cpu_ms"] = cpu;
        t0 = std::chrono::steady_clock::now();
        c0 = cpu_ms();
    }
};

// Writes `voxels` to --out (.raw or .binvox, by its extension) and reports the file's size.
void write_grid(const VoxelizeOpts& o, const voxels::BitGrid& voxels, const voxels::Grid& grid, Stage& st,
                nlohmann::json& report) {
    if (is_raw(o.out)) {
        vx::write_raw(o.out, voxels);
    } else {
        vx::Binvox b;
        b.grid = voxels;
        b.translate = grid.origin;
        b.scale = grid.voxel_size * double(o.res);
        vx::write_binvox(o.out, b);
    }
    report["out"] = o.out;
    const auto bytes = std::filesystem::file_size(o.out);
    report["out_bytes"] = bytes;
    st.done("write", o.out + " (" + std::to_string(bytes) + " bytes)");
}

// ---- --method gl: Task 7's voxelization through OSMesa, and its comparison with the CPU (--compare) ----------

// The distance from p to triangle (a, b, c): to its plane when p projects inside it, else to the nearest edge.
double distance_to_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    auto segment = [&](const glm::dvec3& x, const glm::dvec3& y) {
        const glm::dvec3 e = y - x;
        const double l2 = glm::dot(e, e);
        return glm::length(p - (x + (l2 > 0 ? std::clamp(glm::dot(p - x, e) / l2, 0.0, 1.0) : 0.0) * e));
    };
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double n2 = glm::dot(n, n);
    if (n2 > 0) {
        const glm::dvec3 q = p - glm::dot(p - a, n) / n2 * n;
        if (glm::dot(glm::cross(b - a, q - a), n) >= 0 && glm::dot(glm::cross(c - b, q - b), n) >= 0 &&
            glm::dot(glm::cross(a - c, q - c), n) >= 0)
            return std::abs(glm::dot(p - a, n)) / std::sqrt(n2);
    }
    return std::min({segment(a, b), segment(b, c), segment(c, a)});
}

// GL's solid voxelization (always solid), the CPU's for comparison when asked, then --out and --json.
int run_gl(const VoxelizeOpts& o, const PolygonSoup& u, const voxels::Grid& grid, Stage& st,
           nlohmann::json& report) {
    const char* axis_name[3] = {"x", "y", "z"};
    const vx::BitGrid gl = vx::voxelize_gl(u, grid.dims, o.axis);
    const std::uint64_t gl_voxels = vx::count_set(gl);
    report["axis"] = o.axis;
    report["gl_voxels"] = gl_voxels;
    st.done("gl", std::to_string(gl_voxels) + " voxels (OSMesa, slices along " + axis_name[o.axis] + ")");
    if (o.compare) {
        const vx::SolidResult s = vx::voxelize_solid(u, grid.dims, o.threads);
        const bool parity = s.method == vx::SolidMethod::parity;
        report["solid_voxels"] = vx::count_set(s.grid);
        report["solid_method"] = parity ? "parity" : "flood_fill";
        st.done("cpu", std::to_string(vx::count_set(s.grid)) + " voxels (" +
                                 (parity ? "parity" : "outside flood fill: the mesh is not closed") + ")");
        // the differing voxels, and how far the farthest of their centres lies from the mesh (up to 1000 of them)
        std::vector<std::array<std::int64_t, 3>> differ;
        std::uint64_t mismatches = 0;
        for (std::size_t w = 0; w < gl.words.size(); ++w) {
            std::uint64_t bits = gl.words[w] ^ s.grid.words[w];
            mismatches += std::uint64_t(std::popcount(bits));
            for (; bits && differ.size() < 1000; bits &= bits - 1) {
                const std::uint64_t n = 64 * w + std::uint64_t(std::countr_zero(bits));
                const auto nx = std::uint64_t(grid.dims.nx), ny = std::uint64_t(grid.dims.ny);
                differ.push_back({std::int64_t(n % nx), std::int64_t(n / nx % ny), std::int64_t(n / (nx * ny))});
            }
        }
        double farthest = 0;
        for (const auto& [i, j, k] : differ) {
            const glm::dvec3 c(double(i) + 0.5, double(j) + 0.5, double(k) + 0.5);
            double d = std::numeric_limits<double>::infinity();
            for (std::size_t f = 0; f < u.n_faces(); ++f) {
                const auto vs = u.face(f);
                for (std::size_t t = 1; t + 1 < vs.size(); ++t)
                    d = std::min(d, distance_to_triangle(c, u.positions[vs[0]], u.positions[vs[t]], u.positions[vs[t + 1]]));
            }
            farthest = std::max(farthest, d);
        }
        report["mismatches"] = mismatches;
        report["mismatch_max_distance"] = farthest;  // in voxels, over the first 1000 differing voxels
        std::ostringstream msg;
        msg << mismatches << " voxels differ from the CPU's solid";
        if (mismatches) {
            msg << " (centres within " << farthest << " voxel of the mesh";
            if (mismatches > differ.size()) msg << ", the first " << differ.size() << " measured";
            msg << ")";
        }
        if (!parity) msg << "; parity and flood fill differ on open meshes by design";
        st.done("compare", msg.str());
    }
    if (!o.out.empty()) write_grid(o, gl, grid, st, report);
    const double peak = peak_rss_mib();
    report["peak_rss_mib"] = peak;
    st.out << "  peak memory... " << peak << " MiB (the process's peak resident size)\n";
    if (o.json) std::cout << report.dump() << "\n";
    return 0;
}

int run_voxelize(const VoxelizeOpts& o) {
    if (o.compare && o.method != "gl") throw std::runtime_error("--compare compares the gl method with the cpu: add --method gl");
    if (o.method == "gl" && o.out_of_core) throw std::invalid_argument("--out-of-core is the cpu method's");
    if (!o.out.empty()) (void)is_raw(o.out);  // a bad extension is refused before the work
    std::filesystem::path path = o.mesh;
    if (!std::filesystem::exists(path)) {
        const auto p = geolab::model_path(o.mesh);
        if (!p) throw std::runtime_error(o.mesh + ": no such file, and no fetched model of that name (tools/fetch_models.sh)");
        path = *p;
    }
    std::ostringstream discard;
    std::ostream& out = o.json ? discard : std::cout;
    nlohmann::json report{{"mesh", path.string()}, {"res", o.res},        {"threads", o.threads},
                          {"solid", o.solid || o.method == "gl"}, {"method", o.method}};
    out << "voxelize " << path.string() << " at " << o.res << "³, " << o.threads << " thread(s), "
        << (o.solid || o.method == "gl" ? "solid" : "surface") << ", method " << o.method << "\n";
    Stage st{out, report};
    const PolygonSoup mesh = read_mesh(path);
    std::size_t tris = 0;
    for (std::size_t f = 0; f < mesh.n_faces(); ++f) tris += mesh.face(f).size() - 2;
    report["vertices"] = mesh.n_vertices();
    report["faces"] = mesh.n_faces();
    report["triangles"] = tris;
    st.done("read", std::to_string(mesh.n_vertices()) + " vertices, " + std::to_string(mesh.n_faces()) + " faces (" +
                        std::to_string(tris) + " triangles)");
    const vx::Grid grid = vx::fit_grid(mesh, o.res, 1);
    const PolygonSoup u = vx::to_grid_units(mesh, grid);
    report["dims"] = {grid.dims.nx, grid.dims.ny, grid.dims.nz};
    report["voxel_size"] = grid.voxel_size;
    st.done("grid", "voxel size " + std::to_string(grid.voxel_size));
    if (o.method == "gl") return run_gl(o, u, grid, st, report);
    if (o.out_of_core) {
        // slab by slab to the raw file: the grid is never whole in memory
        if (o.out.empty() || !is_raw(o.out)) throw std::invalid_argument("--out-of-core needs --out FILE.raw");
        report["out_of_core"] = true;
        Progress progress;
        const vx::FileVoxels f = vx::voxelize_to_file(u, grid.dims, o.solid, o.out, o.threads, o.slab_layers,
                                                      o.json ? std::function<void(std::int64_t, std::int64_t)>{}
                                                             : std::function<void(std::int64_t, std::int64_t)>(std::ref(progress)));
        report[o.solid ? "solid_voxels" : "surface_voxels"] = f.voxels;
        report["slabs"] = f.slabs;
        report["slab_layers"] = f.slab_layers;
        report["out"] = o.out;
        report["out_bytes"] = f.bytes;
        if (o.solid) {
            report["solid_method"] = "parity";
            report["axis_disagreements"] = f.axis_disagreements;
            report["boundary_edges"] = f.boundary_edges;
        }
        st.done(o.solid ? "solid" : "surface",
                std::to_string(f.voxels) + " voxels" +
                    (o.solid ? " (parity, closed mesh, " + std::to_string(f.axis_disagreements) + " axis disagreements)" : "") +
                    ", " + std::to_string(f.slabs) + " slabs of " + std::to_string(f.slab_layers) + " layers to " + o.out +
                    " (" + std::to_string(f.bytes) + " bytes)");
    } else {
        const vx::BitGrid surface = vx::voxelize_surface(u, grid.dims, o.threads);
        const std::uint64_t surface_voxels = vx::count_set(surface);
        report["surface_voxels"] = surface_voxels;
        st.done("surface", std::to_string(surface_voxels) + " voxels");
        vx::BitGrid result = surface;
        if (o.solid) {
            const vx::SolidResult s = vx::voxelize_solid(u, grid.dims, o.threads);
            const bool parity = s.method == vx::SolidMethod::parity;
            const std::string how = parity ? "parity, closed mesh, " + std::to_string(s.axis_disagreements) + " axis disagreements"
                                           : "outside flood fill: the mesh has " + std::to_string(s.boundary_edges) + " boundary edges";
            const std::uint64_t solid_voxels = vx::count_set(s.grid);
            report["solid_voxels"] = solid_voxels;
            report["solid_method"] = parity ? "parity" : "flood_fill";
            report["axis_disagreements"] = s.axis_disagreements;
            report["boundary_edges"] = s.boundary_edges;
            st.done("solid", std::to_string(solid_voxels) + " voxels (" + how + ")");
            result = s.grid;
        }
        if (!o.out.empty()) write_grid(o, result, grid, st, report);
    }
    const double peak = peak_rss_mib();
    report["peak_rss_mib"] = peak;
    out << "  peak memory... " << peak << " MiB (the process's peak resident size)\n";
    if (o.json) std::cout << report.dump() << "\n";
    return 0;
}
}  // namespace
#endif

void add_voxelize(CLI::App& app, int& status) {
#ifdef GEOLAB_HAS_LAB_08
    auto o = std::make_shared<VoxelizeOpts>();
    auto* c = app.add_subcommand("voxelize", "Voxelize a mesh (lab 08): surface or solid voxels, counts, .binvox output");
    c->add_option("mesh", o->mesh, "A mesh file (.off, .obj, .stl, .ply) or a fetched model's name")->required();
    c->add_option("--res", o->res, "Voxels along the longest side (a cube res³, one empty layer around)")
        ->check(CLI::Range(std::int64_t(3), std::int64_t(4096)))
        ->capture_default_str();
    c->add_flag("--solid", o->solid, "Also the solid voxelization (parity on closed meshes, flood fill otherwise)");
    c->add_option("--method", o->method, "cpu, or gl: the solid through OpenGL (OSMesa) slices, Task 7")
        ->check(CLI::IsMember({"cpu", "gl"}))
        ->capture_default_str();
    c->add_option("--axis", o->axis, "--method gl: slice along this axis (0 = x, 1 = y, 2 = z)")
        ->check(CLI::Range(0, 2))
        ->capture_default_str();
    c->add_flag("--compare", o->compare, "--method gl: also the CPU's solid, and the voxels where they differ");
    c->add_option("--threads", o->threads, "Worker threads")->check(CLI::Range(1, 256))->capture_default_str();
    c->add_option("--out", o->out, "Write the voxels (solid with --solid) to this .binvox or .raw file (handout §8)");
    c->add_flag("--out-of-core", o->out_of_core,
                "Stream the grid slab by slab to the --out .raw file instead of holding it in memory (res a multiple "
                "of 8; --solid needs a closed mesh)");
    c->add_option("--slab-layers", o->slab_layers, "Layers per slab with --out-of-core")
        ->check(CLI::Range(std::int64_t(1), std::int64_t(4096)))
        ->capture_default_str();
    c->add_flag("--json", o->json, "Print one JSON object with the same figures (stable names) instead of text");
    c->callback([o, &status] {
        try {
            status = run_voxelize(*o);
        } catch (const std::exception& e) {
            std::cerr << "geolab voxelize: " << e.what() << "\n";
            status = 1;
        }
    });
#else
    (void)app;
    (void)status;
#endif
}

}  // namespace geolab::cli
