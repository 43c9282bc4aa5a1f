// geolab voxelize MESH --res N [--solid] [--method cpu] [--threads T] [--out x.binvox] [--json]: lab 08's
// voxelization of a mesh file or a fetched model, with the counts and the time of each stage printed (--json: one
// JSON object with the same figures instead). It runs the variant being built
// (the reference in the instructor's tree, the student's code in the release).
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

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
struct VoxelizeOpts {
    std::string mesh, method = "cpu", out;
    std::int64_t res = 128;
    bool solid = false, json = false;
    int threads = 1;
};

// One stage line: "  surface ........ 12.3 ms" (to `out`), and the stage's time in `report` ("<stage>_ms").
struct Stage {
    std::ostream& out;
    nlohmann::json& report;
    std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
    void done(const std::string& what, const std::string& result) {
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        out << "  " << what << std::string(what.size() < 14 ? 14 - what.size() : 1, '.') << " " << result << "  ("
            << ms << " ms)\n"
            << std::flush;
        report[what + "_ms"] = ms;
        t0 = std::chrono::steady_clock::now();
    }
};

int run_voxelize(const VoxelizeOpts& o) {
    namespace vx = geolab::voxels;
    std::filesystem::path path = o.mesh;
    if (!std::filesystem::exists(path)) {
        const auto p = geolab::model_path(o.mesh);
        if (!p) throw std::runtime_error(o.mesh + ": no such file, and no fetched model of that name (tools/fetch_models.sh)");
        path = *p;
    }
    std::ostringstream discard;
    std::ostream& out = o.json ? discard : std::cout;
    nlohmann::json report{{"mesh", path.string()}, {"res", o.res},        {"threads", o.threads},
                          {"solid", o.solid},      {"method", o.method}};
    out << "voxelize " << path.string() << " at " << o.res << "³, " << o.threads << " thread(s), "
        << (o.solid ? "solid" : "surface") << ", method " << o.method << "\n";
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
    if (!o.out.empty()) {
        vx::Binvox b;
        b.grid = result;
        b.translate = grid.origin;
        b.scale = grid.voxel_size * double(o.res);
        vx::write_binvox(o.out, b);
        report["out"] = o.out;
        const auto bytes = std::filesystem::file_size(o.out);
        report["out_bytes"] = bytes;
        st.done("write", o.out + " (" + std::to_string(bytes) + " bytes)");
    }
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
    c->add_option("--method", o->method, "cpu (the OpenGL path of the issue is not built)")
        ->check(CLI::IsMember({"cpu"}))
        ->capture_default_str();
    c->add_option("--threads", o->threads, "Worker threads")->check(CLI::Range(1, 256))->capture_default_str();
    c->add_option("--out", o->out, "Write the voxels (solid with --solid) to this .binvox file");
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
