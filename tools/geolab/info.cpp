// geolab info MESH: a mesh's topology, computed with lab 01's half-edge mesh for surfaces and lab 02's half-face
// mesh for volume meshes (the variant being built: the reference in the instructor's tree, the student's own code
// in the student release, where a function not written yet is reported as such).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <set>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "geolab/io.hpp"
#include "geolab/models.hpp"
#ifdef GEOLAB_HAS_LAB_01
#include "geolab/halfedge.hpp"
#endif
#ifdef GEOLAB_HAS_LAB_02
#include "geolab/halfface.hpp"
#include "geolab/surface_checks.hpp"
#include "geolab/tet_quality.hpp"
#include "geolab/volume_fixtures.hpp"
#include "geolab/volume_io.hpp"
#endif

namespace geolab::cli {
namespace {

// A path, or the name of a fetched model ("bunny00").
std::filesystem::path mesh_path(const std::string& arg) {
    if (std::filesystem::exists(arg)) return arg;
    if (auto p = model_path(arg)) return *p;
    throw std::runtime_error(arg + ": no such file, and no fetched model of that name (tools/fetch_models.sh)");
}


#ifdef GEOLAB_HAS_LAB_02
// ---- volume meshes (lab 02) ---------------------------------------------------------------------------------

// "ball_with_torus:8" → {"ball_with_torus", 8}; the procedural meshes of geolab/volume_fixtures.hpp by name.
std::optional<VolumeMesh> procedural_volume(const std::string& arg) {
    const auto colon = arg.find(':');
    const std::string name = arg.substr(0, colon);
    int n = 0;
    if (colon != std::string::npos) {
        try {
            std::size_t used = 0;
            n = std::stoi(arg.substr(colon + 1), &used);
            if (used != arg.size() - colon - 1) throw std::invalid_argument("trailing text");
        } catch (const std::exception&) {
            throw std::runtime_error(arg + ": the size after ':' is not a whole number");
        }
    }
    if (name == "kuhn_cube") return volume_fixtures::kuhn_cube();
    if (name == "tet_grid") return volume_fixtures::tet_grid(colon == std::string::npos ? 4 : n);
    if (name == "hex_grid") return volume_fixtures::hex_grid(colon == std::string::npos ? 4 : n);
    if (name == "ball_with_torus") return volume_fixtures::ball_with_torus(colon == std::string::npos ? 10 : n);
    return std::nullopt;
}

// The volume mesh `arg` names: a procedural one, a .mesh file, TetGen files (any of .node/.ele/.face or their
// base), or a fetched TetGen model's base ("bunny00.1"). nullopt when `arg` names none of these (a surface).
std::optional<std::pair<VolumeMesh, std::string>> read_volume(const std::string& arg, std::uint64_t max_file_mb) {
    if (auto m = procedural_volume(arg))
        return std::pair{std::move(*m), arg + " (procedural, geolab/volume_fixtures.hpp)"};
    const ReadOptions options{.max_file_bytes = max_file_mb << 20};
    const std::filesystem::path p = arg;
    const std::string ext = p.extension().string();
    if (ext == ".mesh") return std::pair{read_medit(p, options), p.string()};
    if (ext == ".node" || ext == ".ele" || ext == ".face") return std::pair{read_tetgen(p, options), p.string()};
    for (const std::filesystem::path& base : {p, models_dir() / p})
        if (std::filesystem::exists(base.string() + ".ele"))
            return std::pair{read_tetgen(base, options), base.string() + ".{node,ele}"};
    return std::nullopt;
}

// "1 patch", "2 patches".
std::string count(std::size_t n, const std::string& one, const std::string& many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

const char* cell_type_name(VolumeCell t) {
    switch (t) {
        case VolumeCell::tetrahedron: return "tetrahedron";
        case VolumeCell::hexahedron: return "hexahedron";
        case VolumeCell::prism: return "prism";
        case VolumeCell::pyramid: return "pyramid";
    }
    return "?";
}

// What needs no student code: vertices, cells per type, labels, tetrahedron quality.
void plain_figures(const VolumeMesh& vm, nlohmann::json& j) {
    std::map<std::string, std::size_t> per_type{{"tetrahedron", 0}, {"hexahedron", 0}, {"prism", 0}, {"pyramid", 0}};
    for (VolumeCell t : vm.types) ++per_type[cell_type_name(t)];
    j["cells_per_type"] = per_type;
    j["labels"] = std::set<std::int32_t>(vm.labels.begin(), vm.labels.end()).size();
    double lo = std::numeric_limits<double>::infinity(), hi = -lo, sum = 0;
    std::size_t tets = 0, inverted = 0, not_finite = 0;
    for (std::size_t c = 0; c < vm.n_cells(); ++c) {
        if (vm.types[c] != VolumeCell::tetrahedron) continue;
        const auto v = vm.cell(c);
        const auto& p = vm.positions;
        const double q = tet_radius_ratio(p[v[0]], p[v[1]], p[v[2]], p[v[3]]);
        if (!std::isfinite(q)) {  // finite coordinates near 1e308 overflow the radii: counted, not averaged
            ++not_finite;
            continue;
        }
        lo = std::min(lo, q), hi = std::max(hi, q), sum += q, ++tets, inverted += q < 0;
    }
    if (tets)
        j["tet_quality"] = {{"measure", "radius ratio 3r/R (1 regular, 0 flat, < 0 inverted)"},
                            {"min", lo}, {"max", hi}, {"mean", sum / double(tets)}, {"inverted", inverted}};
    if (not_finite) j["tet_quality_not_finite"] = not_finite;
}

// V, E, F, C, boundary faces, the boundary surface's topology and the region complex: lab 02's functions.
void halfface_figures(const VolumeMesh& vm, nlohmann::json& j, std::vector<std::string>& missing) {
    using namespace geolab::halfface;
    auto step = [&](const char* name, auto&& f) {
        try {
            f();
            return true;
        } catch (const NotImplemented&) {
            missing.push_back(name);
        }
        return false;
    };
    Mesh mesh;
    if (!step("build_mesh", [&] { mesh = build_mesh(cells_from(vm)); })) return;
    j.update({{"V", mesh.n_alive(Kind::vertex)}, {"E", mesh.n_alive(Kind::edge)}, {"F", mesh.n_alive(Kind::face)},
              {"C", mesh.n_alive(Kind::cell)}});
    step("boundary_halffaces", [&] {
        std::vector<HalfFace> hfs;
        boundary_halffaces(mesh, hfs);
        j["boundary_faces"] = hfs.size();
    });
    step("boundary_surface", [&] {
        const SurfaceCheck s = check_surface(boundary_surface(mesh), {.self_intersections = false});
        j["boundary_surface"] = {{"V", s.vertices}, {"E", s.edges}, {"F", s.faces},
                                 {"euler_characteristic", s.euler_characteristic}, {"components", s.components},
                                 {"closed", s.boundary_edges == 0 && s.non_manifold_edges == 0},
                                 {"oriented", s.misoriented_edges == 0}};
    });
    step("region_complex", [&] {
        const RegionComplex rc = region_complex(mesh, vm.labels);
        nlohmann::json patches = nlohmann::json::array();
        for (const Patch& p : rc.patches)
            patches.push_back({{"faces", p.F}, {"euler_characteristic", p.chi}, {"boundary_loops", p.boundary_loops},
                               {"outside", p.regions[1] == invalid_index}});
        j["regions"] = {{"regions", rc.regions.size()}, {"patches", rc.patches.size()}, {"curves", rc.curves.size()},
                        {"corners", rc.corners.size()}, {"patch_list", patches}};
    });
}

int run_volume_info(const VolumeMesh& vm, const std::string& what, bool as_json) {
    nlohmann::json j{
        {"file", what}, {"kind", "volume"}, {"file_vertices", vm.n_vertices()}, {"file_cells", vm.n_cells()}};
    plain_figures(vm, j);
    std::vector<std::string> missing;
    try {
        halfface_figures(vm, j, missing);
    } catch (const std::exception& e) {  // TopologyError, invalid_argument: the cells do not make a half-face mesh
        j["error"] = e.what();
    }
    if (!missing.empty()) j["not_implemented"] = missing;
    const int status = j.contains("error") || !missing.empty() ? 1 : 0;
    if (as_json) {
        std::cout << j.dump(2) << "\n";
        return status;
    }
    std::cout << what << "\n  volume mesh: " << vm.n_vertices() << " vertices, " << vm.n_cells() << " cells (";
    bool first = true;
    for (auto& [type, n] : j["cells_per_type"].items())
        if (n.get<std::size_t>())
            std::cout << (first ? "" : ", ") << count(n, type, type == "tetrahedron" ? "tetrahedra" : type + "s"),
                first = false;
    std::cout << "), " << count(j["labels"], "label", "labels") << "\n";
    if (j.contains("tet_quality")) {
        const auto& q = j["tet_quality"];
        std::cout << "  tet quality (radius ratio 3r/R: 1 regular, 0 flat): min " << q["min"].get<double>() << "   max "
                  << q["max"].get<double>() << "   mean " << q["mean"].get<double>() << "   inverted " << q["inverted"]
                  << "\n";
    }
    if (j.contains("tet_quality_not_finite"))
        std::cout << "  tet quality not computable (overflow): " << j["tet_quality_not_finite"] << " tetrahedra\n";
    if (j.contains("V"))
        std::cout << "  half-face mesh: V " << j["V"] << "   E " << j["E"] << "   F " << j["F"] << "   C " << j["C"]
                  << (j.contains("boundary_faces") ? "   boundary faces " + j["boundary_faces"].dump() : "") << "\n";
    if (j.contains("boundary_surface")) {
        const auto& s = j["boundary_surface"];
        std::cout << "  boundary surface: V " << s["V"] << "   E " << s["E"] << "   F " << s["F"] << "   χ "
                  << s["euler_characteristic"] << "   components " << s["components"] << "   "
                  << (s["closed"].get<bool>() ? "closed" : "not closed") << ", "
                  << (s["oriented"].get<bool>() ? "oriented" : "not oriented") << "\n";
    }
    if (j.contains("regions")) {
        const auto& r = j["regions"];
        std::cout << "  region complex: " << count(r["regions"], "region", "regions") << " (3-cells), "
                  << count(r["patches"], "patch", "patches") << " (2-cells), " << count(r["curves"], "curve", "curves")
                  << " (1-cells), " << count(r["corners"], "corner", "corners") << " (0-cells)\n";
        std::size_t i = 0;
        for (const auto& p : r["patch_list"]) {
            if (i == 12) {
                std::cout << "    ... (" << r["patch_list"].size() - 12 << " more patches: --json lists them all)\n";
                break;
            }
            std::cout << "    patch " << i++ << ": " << count(p["faces"], "face", "faces") << ", χ "
                      << p["euler_characteristic"] << ", "
                      << count(p["boundary_loops"], "boundary loop", "boundary loops")
                      << (p["outside"].get<bool>() ? ", on the boundary of the mesh" : "") << "\n";
        }
    }
    if (j.contains("error")) std::cout << "  not a half-face mesh: " << j["error"].get<std::string>() << "\n";
    if (!missing.empty()) {
        std::cout << "  not implemented yet:";
        for (std::size_t i = 0; i < missing.size(); ++i) std::cout << (i ? ", " : " ") << missing[i];
        std::cout << " (lab 02; the figures that need them are left out)\n";
    }
    return status;
}
#endif

int run_info(const std::string& arg, bool as_json, std::uint64_t max_file_mb) {
#ifdef GEOLAB_HAS_LAB_02
    if (auto vm = read_volume(arg, max_file_mb)) return run_volume_info(vm->first, vm->second, as_json);
#endif
#ifndef GEOLAB_HAS_LAB_01
    throw std::runtime_error(arg + ": not a volume mesh, and surfaces need lab 01 (not in this build)");
#else
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
#endif
}

}  // namespace

void add_info(CLI::App& app, int& status) {
#if defined(GEOLAB_HAS_LAB_01) || defined(GEOLAB_HAS_LAB_02)
    auto mesh = std::make_shared<std::string>();
    auto json = std::make_shared<bool>(false);
    auto max_file_mb = std::make_shared<std::uint64_t>(0);
    auto* cmd = app.add_subcommand("info",
                                   "Topology of a surface (V, E, F, boundary loops, χ, genus, components) or a "
                                   "volume mesh (V, E, F, C, boundary surface, cells per type, tet quality, "
                                   "region complex)");
    cmd->add_option("mesh", *mesh,
                    "A surface (.obj .off .ply .stl, or a fetched model name: bunny00), a volume mesh (.mesh, TetGen "
                    ".node/.ele/.face or their base, a fetched one: bunny00.1) or a procedural one (kuhn_cube, "
                    "tet_grid:N, hex_grid:N, ball_with_torus:N)")
        ->required();
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
