// geolab info MESH: a mesh's topology, computed with lab 01's half-edge mesh (the variant being built: the
// reference in the instructor's tree, the student's own code in the student release).
#include <iostream>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "geolab/io.hpp"
#include "geolab/models.hpp"
#ifdef GEOLAB_HAS_LAB_01
#include "geolab/halfedge.hpp"
#endif

namespace geolab::cli {
namespace {

// A path, or the name of a fetched model ("bunny00").
std::filesystem::path mesh_path(const std::string& arg) {
    if (std::filesystem::exists(arg)) return arg;
    if (auto p = model_path(arg)) return *p;
    throw std::runtime_error(arg + ": no such file, and no fetched model of that name (tools/fetch_models.sh)");
}

#ifdef GEOLAB_HAS_LAB_01
int run_info(const std::string& arg, bool as_json, std::uint64_t max_file_mb) {
    const auto path = mesh_path(arg);
    const PolygonSoup soup = read_mesh(path, ReadOptions{.max_file_bytes = max_file_mb << 20});
    nlohmann::json j{{"file", path.string()}, {"soup_vertices", soup.n_vertices()}, {"soup_faces", soup.n_faces()}};
    int status = 0;
    try {
        const halfedge::Mesh mesh = halfedge::build_mesh(soup);
        const auto loops = halfedge::boundary_loops(mesh);
        const auto components = halfedge::connected_components(mesh);
        j.update({{"manifold", true},
                  {"V", mesh.n_vertices()},
                  {"E", mesh.n_edges()},
                  {"F", mesh.n_faces()},
                  {"boundary_loops", loops.size()},
                  {"euler_characteristic", halfedge::euler_characteristic(mesh)},
                  {"genus", halfedge::genus(mesh)},
                  {"components", components.count}});
    } catch (const TopologyError& e) {
        j.update({{"manifold", false}, {"reason", e.what()}});
        status = 1;
    } catch (const std::invalid_argument& e) {
        j.update({{"manifold", false}, {"reason", e.what()}});
        status = 1;
    }
    if (as_json) {
        std::cout << j.dump(2) << "\n";
        return status;
    }
    std::cout << path.string() << "\n";
    if (!j["manifold"].get<bool>()) {
        std::cout << "  " << soup.n_vertices() << " vertices, " << soup.n_faces() << " faces\n"
                  << "  not a manifold mesh: " << j["reason"].get<std::string>() << "\n";
        return status;
    }
    std::cout << "  V " << j["V"] << "   E " << j["E"] << "   F " << j["F"] << "\n"
              << "  boundary loops " << j["boundary_loops"] << "   χ " << j["euler_characteristic"] << "   genus "
              << j["genus"] << "   components " << j["components"] << "\n"
              << "  manifold: yes" << (j["boundary_loops"] == 0 ? " (closed)" : " (with boundary)") << "\n";
    return status;
}
#endif

}  // namespace

void add_info(CLI::App& app, int& status) {
#ifdef GEOLAB_HAS_LAB_01
    auto mesh = std::make_shared<std::string>();
    auto json = std::make_shared<bool>(false);
    auto max_file_mb = std::make_shared<std::uint64_t>(0);
    auto* cmd = app.add_subcommand("info", "Topology of a mesh (V, E, F, boundary loops, χ, genus, components)");
    cmd->add_option("mesh", *mesh, "A mesh file (.obj .off .ply .stl) or a fetched model name (bunny00)")->required();
    cmd->add_flag("--json", *json, "Print JSON");
    cmd->add_option("--max-file-mb", *max_file_mb,
                    "Refuse mesh files larger than this many MiB (default: $GEOLAB_MAX_FILE_MB, else 1024)")
        ->check(CLI::Range(std::uint64_t(1), std::uint64_t(1) << 40));
    cmd->callback([mesh, json, max_file_mb, &status] { status = run_info(*mesh, *json, *max_file_mb); });
#else
    (void)app;
    (void)status;
#endif
}

}  // namespace geolab::cli
