// geolab contour INPUT: dual contouring (lab 09) of a mesh, a fetched model or a named implicit on the Cartesian or
// the spherical octree, with the mesh checks and timings. It runs the variant being built (the reference in the
// instructor's tree, the student's code in the release).
#include <iostream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "contour_common.hpp"

namespace geolab::cli {

#ifdef GEOLAB_HAS_LAB_09
namespace {

using namespace contour_common;

// ---- geolab contour -------------------------------------------------------------------------------------------------

nlohmann::json run_json(const Input& in, const Run& r, const std::string& out, dc::PoleFill::Method pf) {
    nlohmann::json j;
    j["input"] = {{"name", in.arg}, {"kind", in.kind}};
    if (in.mesh)
        j["input"].update({{"path", in.path.string()},
                           {"vertices", in.mesh->n_vertices()},
                           {"faces", in.mesh->n_faces()},
                           {"volume", in.volume}});
    j["warnings"] = nlohmann::json::array();
    if (!in.warning.empty()) j["warnings"].push_back(in.warning);
    j["octree"] = octree_name(r.octree);
    j["level"] = r.level;
    j["vertices"] = r.soup.n_vertices();
    j["faces"] = r.soup.n_faces();
    j["checks"] = {{"boundary_edges", r.check.boundary_edges},
                   {"non_manifold_edges", r.check.non_manifold_edges},
                   {"misoriented_edges", r.check.misoriented_edges},
                   {"degenerate_faces", r.check.degenerate_faces},
                   {"non_manifold_vertices", r.surface.non_manifold_vertices},
                   {"zero_area_faces", r.surface.zero_area_faces},
                   {"coincident_vertices", r.surface.coincident_vertices},
                   {"components", r.surface.components},
                   {"euler_characteristic", r.surface.euler_characteristic},
                   {"self_intersecting_pairs", r.surface.self_intersecting_pairs()},
                   {"self_intersecting_pairs_by_kind",
                    {{"disjoint", r.surface.intersecting_disjoint},
                     {"vertex_sharing", r.surface.intersecting_vertex_sharing},
                     {"edge_sharing", r.surface.intersecting_edge_sharing}}},
                   // every count above must allow it (lib's check_surface), not only the edge counts
                   {"closed_manifold", r.surface.closed_manifold()},
                   {"max_abs_f", r.max_abs_f},
                   {"cell", r.cell},
                   {"max_abs_f_per_cell", r.cell > 0 ? r.max_abs_f / r.cell : 0.0},
                   {"volume", r.volume}};
    j["octree_stats"] = {{"cells", r.stats.cells},     {"leaves", r.stats.leaves},
                         {"samples", r.stats.samples}, {"crossings", r.stats.crossings},
                         {"collapses", r.stats.collapses}};
    if (r.octree == dc::Coordinates::cartesian) {
        j["simplify_tolerance_per_cell"] = default_cartesian.simplify_tolerance;
    } else {
        auto v = [](const glm::dvec3& p) { return nlohmann::json::array({p.x, p.y, p.z}); };
        j["spherical"] = {{"pole_fill", pole_fill_name(pf)},
                          {"origin_start", v(r.origin_start)},
                          {"origin_start_is", r.origin_start_what},
                          {"origin_steps", r.stats.origin_path.empty() ? 0 : r.stats.origin_path.size() - 1},
                          {"origin", v(r.stats.origin)},
                          // f < 0: inside the solid. An origin outside is allowed (eq. 6 only moves it off the
                          // surface) but then every radial ray enters and leaves: see the lab 09 handout §5
                          {"f_at_origin", in.field->value(r.stats.origin)},
                          {"origin_inside", in.field->value(r.stats.origin) < 0.0},
                          {"r_min", r.stats.r_min},
                          {"r_max", r.stats.r_max},
                          {"pole_rings", r.stats.pole_rings},
                          {"ghost_vertices", r.stats.ghost_vertices}};
    }
    j["seconds"] = {{"read", in.read_seconds},
                    {"field_build", in.field_seconds},
                    {"contour", r.contour_seconds},
                    {"checks", r.check_seconds}};
    j["out"] = out.empty() ? nlohmann::json(nullptr) : nlohmann::json(out);
    return j;
}

void print_run(const Input& in, const Run& r, const std::string& out, dc::PoleFill::Method pf) {
    auto& o = std::cout;
    o << "input       " << in.arg << " (" << in.kind;
    if (in.mesh)
        o << ": " << in.path.string() << ", " << grouped(in.mesh->n_vertices()) << " vertices, "
          << grouped(in.mesh->n_faces()) << " faces";
    o << ")\n";
    o << "octree      " << octree_name(r.octree) << ", level " << r.level << " (" << (1 << r.level)
      << (r.octree == dc::Coordinates::cartesian ? " cells per axis" : " divisions of r, θ and φ") << ")\n";
    if (r.octree == dc::Coordinates::cartesian) {
        o << "            simplification on (tolerance " << fmt("%g", default_cartesian.simplify_tolerance)
          << " cell): " << grouped(r.stats.collapses) << " collapses\n";
    } else {
        const std::size_t steps = r.stats.origin_path.empty() ? 0 : r.stats.origin_path.size() - 1;
        o << "origin      " << vec_str(r.origin_start) << " (" << r.origin_start_what << "), eq. (6): " << steps
          << (steps == 1 ? " step" : " steps");
        if (steps) o << " → " << vec_str(r.stats.origin);
        o << "\n            shell r ∈ [" << fmt("%.4g", r.stats.r_min) << ", " << fmt("%.4g", r.stats.r_max)
          << "]; pole fill " << pole_fill_name(pf) << ": " << r.stats.pole_rings << " polar hole(s), "
          << r.stats.ghost_vertices << " ghost vertex(es)\n";
    }
    o << "octree      " << grouped(r.stats.cells) << " cells, " << grouped(r.stats.leaves) << " leaves, "
      << grouped(r.stats.samples) << " field samples, " << grouped(r.stats.crossings) << " crossings\n";
    o << "result      " << grouped(r.soup.n_vertices()) << " vertices, " << grouped(r.soup.n_faces())
      << " faces\n";
    o << "checks      boundary edges " << r.check.boundary_edges << ", non-manifold edges "
      << r.check.non_manifold_edges << ", misoriented edges " << r.check.misoriented_edges
      << ", degenerate faces " << r.check.degenerate_faces << "\n"
      << "            non-manifold vertices " << r.surface.non_manifold_vertices << ", zero-area faces "
      << r.surface.zero_area_faces << ", coincident vertices " << r.surface.coincident_vertices << ", components "
      << r.surface.components << ", χ " << r.surface.euler_characteristic << "\n"
      << "            self-intersecting face pairs " << r.surface.self_intersecting_pairs() << " ("
      << r.surface.intersecting_disjoint << " disjoint, " << r.surface.intersecting_vertex_sharing
      << " sharing a vertex, " << r.surface.intersecting_edge_sharing << " sharing an edge; exact predicates)\n"
      << "            closed manifold: " << (r.surface.closed_manifold() ? "yes" : "no") << "\n"
      << "            max |f(v)| " << fmt("%.3g", r.max_abs_f) << " = " << fmt("%.3g", r.max_abs_f / r.cell)
      << " × the " << (r.octree == dc::Coordinates::cartesian ? "cell size " : "radial cell step ")
      << fmt("%.3g", r.cell) << "\n"
      << "            volume " << fmt("%.6g", r.volume);
    if (in.mesh) o << " (input mesh " << fmt("%.6g", in.volume) << ")";
    o << "\n";
    o << "time        ";
    if (in.mesh) o << "read " << fmt("%.3f", in.read_seconds) << " s, ";
    o << "field build " << fmt("%.3f", in.field_seconds) << " s, contour " << fmt("%.3f", r.contour_seconds)
      << " s, checks " << fmt("%.3f", r.check_seconds) << " s\n";
    o << "output      " << (out.empty() ? "not written (no --out)" : out) << "\n";
    if (!in.warning.empty()) o << "warning     " << in.warning << "\n";
}

int run_contour(const std::string& arg, const std::string& octree, int level, const std::string& out, bool as_json,
                const std::string& pole_fill) {
    const auto coords = octree == "spherical" ? dc::Coordinates::spherical : dc::Coordinates::cartesian;
    const auto pf = pole_fill == "vertical" ? dc::PoleFill::vertical_projection
                    : pole_fill == "none"   ? dc::PoleFill::none
                                            : dc::PoleFill::normal_projection;
    std::ostream* log = &std::cerr;
    Input in;
    Run r;
    try {
        *log << "geolab contour: " << arg << std::endl;
        in = load_input(arg, log);
        *log << "  dual contouring on the " << octree << " octree, level " << level << " ..." << std::endl;
        r = run_dc(in, coords, level, pf);
        *log << "  done: " << grouped(r.soup.n_vertices()) << " vertices in " << fmt("%.2f", r.contour_seconds)
             << " s" << std::endl;
        if (!out.empty()) {
            *log << "  writing " << out << " ..." << std::endl;
            write_mesh(out, r.soup);
        }
    } catch (const std::exception& e) {
        const std::string what = e.what();
        // load_input's messages already name the input
        const bool named = what.find(arg) != std::string::npos;
        std::cerr << "geolab contour: " << (named ? "" : arg + ": ") << what << "\n";
        return 1;
    }
    if (as_json)
        std::cout << run_json(in, r, out, pf).dump(2) << "\n";
    else
        print_run(in, r, out, pf);
    return 0;
}

}  // namespace
#endif

void add_contour(CLI::App& app, int& status) {
#ifdef GEOLAB_HAS_LAB_09
    struct Opts {
        std::string input, octree = "cartesian", out, pole_fill = "normal";
        int level = 6;
        bool json = false;
    };
    auto o = std::make_shared<Opts>();
    auto* cmd = app.add_subcommand(
        "contour", "Dual contouring (lab 09) of a mesh, a fetched model or a named implicit on the Cartesian or "
                   "the spherical-coordinate octree, with mesh checks and times");
    cmd->add_option("input", o->input,
                    "A mesh file (.obj .off .ply .stl), a fetched model (" + join(table_models) +
                        ", ...) or a named implicit: " + join(implicit_names()) +
                        " (a named implicit wins over a fetched model of the same name; give the model's path)")
        ->required();
    cmd->add_option("--octree", o->octree, "cartesian or spherical")
        ->check(CLI::IsMember({"cartesian", "spherical"}))
        ->capture_default_str();
    cmd->add_option("--level", o->level, "Octree level L: 2^L divisions per axis (Cartesian) or of r, θ, φ")
        ->check(CLI::Range(1, 10))
        ->capture_default_str();
    cmd->add_option("--out", o->out, "Write the output mesh here (.obj .off .ply .stl)");
    cmd->add_flag("--json", o->json, "Print JSON instead of text (progress still goes to stderr)");
    cmd->add_option("--pole-fill", o->pole_fill,
                    "Spherical octree: close the polar holes by normal projection (the paper), vertical projection "
                    "(the earlier ghost node) or none")
        ->check(CLI::IsMember({"normal", "vertical", "none"}))
        ->capture_default_str();
    cmd->callback([o, &status] {
        status = run_contour(o->input, o->octree, o->level, o->out, o->json, o->pole_fill);
    });
#else
    (void)app;
    (void)status;
#endif
}

}  // namespace geolab::cli
