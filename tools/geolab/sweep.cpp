// geolab sweep PROFILE (--extrude H | --revolve DEG | --path FILE | --helix R H TURNS N | --trefoil N SCALE)
//       --out MESH: a closed mesh swept from a 2D profile (lab 06), written as STL, OBJ, PLY or OFF (by extension),
// with its checks (lib's check_surface, volume, area). Runs the variant being built (the reference in the
// instructor's tree, the student's code in the release).
//
// Profile file (text): '#' starts a comment; a line `outer` or `hole` starts a loop; every other non-empty line is
// one point "x y" of the current loop. The outer loop counter-clockwise, holes clockwise (validate_profile checks).
// Path file (text): '#' comments; a line `closed` makes the path closed; every other non-empty line a point "x y z".
// Tangents by central differences (polyline_path).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "geolab/errors.hpp"
#include "geolab/io.hpp"
#include "geolab/surface_checks.hpp"
#ifdef GEOLAB_HAS_LAB_06
#include "geolab/sweeps.hpp"
#endif

namespace geolab::cli {

void add_sweep(CLI::App& app, int& status);

#ifdef GEOLAB_HAS_LAB_06
namespace {
struct SweepOpts {
    std::string profile, path_file, out, frames = "rmf";
    std::vector<double> helix, trefoil;
    double extrude = 0, revolve_deg = 0, twist = 0, scale = 1;
    int steps = 1, segments = 64;
    bool force = false, json = false;  // json: one JSON object with the figures instead of the text lines
};

// Reads the lines of a text file; a parse error names FILE:LINE and the reason.
std::vector<std::string> read_lines(const std::string& file) {
    const std::string text = read_text_file(file);
    std::vector<std::string> lines;
    std::string cur;
    // a UTF-8 byte order mark is skipped, as in every reader of lib
    for (std::size_t i = text.starts_with("\xEF\xBB\xBF") ? 3 : 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\n' || c == '\r') {
            lines.push_back(cur);
            cur.clear();
            if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
        } else {
            cur += c;
        }
    }
    if (!cur.empty()) lines.push_back(cur);
    return lines;
}
std::string strip(std::string s) {
    if (const auto h = s.find('#'); h != std::string::npos) s.erase(h);
    const auto a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
    return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}
// Keywords (outer, hole, closed) in any case, as in every reader of lib.
bool is_keyword(const std::string& s, const char* word) {
    const std::string w = word;
    return s.size() == w.size() &&
           std::equal(s.begin(), s.end(), w.begin(), [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; });
}
// A token for a message: quoted, at most 40 bytes, unprintable bytes shown as '?'.
std::string token_quote(const std::string& t) {
    std::string q = "'";
    for (char c : t.substr(0, 40)) q += (c >= 32 && c < 127) ? c : '?';
    return q + (t.size() > 40 ? "...'" : "'");
}
[[noreturn]] void parse_error(const std::string& file, std::size_t line, const std::string& why) {
    throw IoError(file, line, why);
}
// Exactly `n` finite numbers on the line.
std::vector<double> numbers(const std::string& s, int n, const std::string& file, std::size_t line) {
    std::istringstream in(s);
    std::vector<double> v;
    std::string tok;
    while (in >> tok) {
        std::size_t used = 0;
        double x = 0;
        try {
            x = std::stod(tok, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != tok.size()) parse_error(file, line, token_quote(tok) + " is not a number");
        if (!std::isfinite(x)) parse_error(file, line, token_quote(tok) + " is not finite");
        v.push_back(x);
    }
    if (static_cast<int>(v.size()) != n)
        parse_error(file, line, "expected " + std::to_string(n) + " numbers, found " + std::to_string(v.size()));
    return v;
}

sweeps::Profile read_profile(const std::string& file) {
    sweeps::Profile p;
    sweeps::Loop* cur = nullptr;
    bool have_outer = false;
    const auto lines = read_lines(file);
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string s = strip(lines[i]);
        if (s.empty()) continue;
        if (is_keyword(s, "outer")) {
            if (have_outer) parse_error(file, i + 1, "a second 'outer' loop (one outer loop, then holes)");
            have_outer = true;
            cur = &p.outer;
        } else if (is_keyword(s, "hole")) {
            if (!have_outer) parse_error(file, i + 1, "'hole' before the 'outer' loop");
            p.holes.emplace_back();
            cur = &p.holes.back();
        } else {
            if (!cur) parse_error(file, i + 1, "a point before any 'outer' line");
            const auto v = numbers(s, 2, file, i + 1);
            cur->push_back({v[0], v[1]});
        }
    }
    if (!have_outer) throw IoError(file, 0, "no 'outer' loop");
    try {
        sweeps::validate_profile(p);
    } catch (const std::invalid_argument& e) {
        throw IoError(file, 0, e.what());
    }
    return p;
}

sweeps::Path read_path(const std::string& file) {
    std::vector<glm::dvec3> pts;
    bool closed = false;
    const auto lines = read_lines(file);
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string s = strip(lines[i]);
        if (s.empty()) continue;
        if (is_keyword(s, "closed")) {
            closed = true;
            continue;
        }
        const auto v = numbers(s, 3, file, i + 1);
        pts.push_back({v[0], v[1], v[2]});
    }
    try {
        return sweeps::polyline_path(pts, closed);
    } catch (const std::invalid_argument& e) {
        throw IoError(file, 0, e.what());
    }
}

int run_sweep(const SweepOpts& o) {
    const sweeps::Profile prof = read_profile(o.profile);
    const int modes = (o.extrude != 0) + (o.revolve_deg != 0) + !o.path_file.empty() + !o.helix.empty() + !o.trefoil.empty();
    if (modes != 1) {
        std::cerr << "geolab sweep: give exactly one of --extrude, --revolve, --path, --helix, --trefoil\n";
        return 2;
    }
    std::ostringstream discard;
    std::ostream& out = o.json ? discard : std::cout;
    nlohmann::json report{{"profile", o.profile}};
    PolygonSoup mesh;
    if (o.extrude != 0) {
        report["mode"] = "extrude";
        mesh = sweeps::extrude(prof, {{0.0, 0.0, o.extrude}, o.steps, o.twist, o.scale});
    } else if (o.revolve_deg != 0) {
        report["mode"] = "revolve";
        mesh = sweeps::revolve(prof, {o.segments, o.revolve_deg >= 360 ? 2 * 3.14159265358979323846
                                                                        : o.revolve_deg * 3.14159265358979323846 / 180});
    } else {
        sweeps::Path path = !o.path_file.empty() ? read_path(o.path_file)
                            : !o.helix.empty()   ? sweeps::helix_path(o.helix[0], o.helix[1], o.helix[2], static_cast<int>(o.helix[3]))
                                                 : sweeps::trefoil_path(static_cast<int>(o.trefoil[0]), o.trefoil[1]);
        report["mode"] = "path";
        const sweeps::SweepCheck c = sweeps::check_sweep(prof, path);
        report["profile_radius"] = c.profile_radius;
        report["min_radius_of_curvature"] = c.min_radius_of_curvature;
        report["self_intersects"] = c.self_intersects;
        out << "profile radius  " << c.profile_radius << ", smallest radius of curvature " << c.min_radius_of_curvature
                  << " (sample " << c.at_sample << ")\n";
        if (c.self_intersects && !o.force) {
            std::cerr << "geolab sweep: the sweep would intersect itself at sample " << c.at_sample
                      << " (profile radius " << c.profile_radius << " >= radius of curvature " << c.min_radius_of_curvature
                      << "); use a smaller profile or a smoother path (--force writes it anyway)\n";
            return 1;
        }
        std::vector<sweeps::Frame> frames;
        if (o.frames == "frenet") {
            frames = sweeps::frenet_frames(path);
            for (std::size_t i = 0; i < frames.size(); ++i)
                if (frames[i].N == glm::dvec3(0.0)) {
                    std::cerr << "geolab sweep: the Frenet frame is undefined at sample " << i
                              << " (a straight run); use --frames rmf\n";
                    return 1;
                }
        } else {
            const glm::dvec3 t0 = path.tangents[0];
            const sweeps::RmfResult r =
                sweeps::rotation_minimizing_frames(path, std::abs(t0.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0));
            if (path.closed) {
                out << "RMF mismatch    " << r.mismatch << " rad (distributed)\n";
                report["rmf_mismatch"] = r.mismatch;
            }
            frames = r.frames;
        }
        mesh = sweeps::sweep(prof, path, frames);
    }
    // The global check: lib's check_surface counts every pair of faces that meet (exact predicates), so a sweep
    // whose path comes back within the profile's reach of itself (a coil wound too tight) is found too, although
    // no turn of the path is too tight for check_sweep.
    const SurfaceCheck c = check_surface(mesh);
    const double volume = sweeps::mesh_volume(mesh), area = sweeps::mesh_area(mesh);
    const std::size_t crossing = c.self_intersecting_pairs();
    out << "mesh            " << c.summary() << "\n"
        << "volume          " << volume << "\n"
        << "area            " << area << "\n"
        << "self-intersect  " << (crossing ? std::to_string(crossing) + " pairs of faces meet" : std::string("no")) << "\n"
        << "closed manifold " << (c.closed_manifold() ? "yes (printable)" : "NO") << "\n";
    const bool write = crossing == 0 || o.force;
    if (crossing && !o.force)
        std::cerr << "geolab sweep: the swept surface intersects itself (" << crossing << " pairs of faces meet"
                  << (report["mode"] == "path" && !report["self_intersects"].get<bool>()
                          ? "; no turn of the path is too tight, so the path comes back within the profile's reach of itself"
                          : "")
                  << "); not written (--force writes it anyway)\n";
    if (write) {
        write_mesh(o.out, mesh);
        out << "wrote " << o.out << "\n";
    }
    if (o.json) {
        report["vertices"] = c.vertices;
        report["faces"] = c.faces;
        report["euler_characteristic"] = c.euler_characteristic;
        report["components"] = c.components;
        report["self_intersecting_pairs"] = crossing;
        report["closed_manifold"] = c.closed_manifold();
        report["volume"] = volume;
        report["area"] = area;
        report["out"] = write ? nlohmann::json(o.out) : nlohmann::json(nullptr);
        std::cout << report.dump() << "\n";
    }
    return c.closed_manifold() ? 0 : 1;
}
}  // namespace
#endif

void add_sweep(CLI::App& app, int& status) {
#ifdef GEOLAB_HAS_LAB_06
    auto o = std::make_shared<SweepOpts>();
    auto* s = app.add_subcommand("sweep", "Sweep a 2D profile (lab 06): extrude, revolve, or along a path; write the mesh");
    s->footer(
        "Profile file: '#' comments; 'outer' starts the outer loop (counter-clockwise), 'hole' a hole (clockwise);\n"
        "other lines are points 'x y'. Path file: '#' comments; 'closed' makes it closed; other lines 'x y z'.\n"
        "Revolution: x is the distance from the z-axis, y the height. Errors name FILE:LINE and the reason.");
    s->add_option("profile", o->profile, "The profile file")->required();
    s->add_option("--out", o->out, "The mesh to write (.stl .obj .ply .off)")->required();
    s->add_option("--extrude", o->extrude, "Extrude to this height along z");
    s->add_option("--steps", o->steps, "Extrusion layers")->check(CLI::Range(1, 1000000))->capture_default_str();
    s->add_option("--twist", o->twist, "Extrusion twist, radians")->capture_default_str();
    s->add_option("--scale", o->scale, "Extrusion scale at the top")->capture_default_str();
    s->add_option("--revolve", o->revolve_deg, "Revolve about the z-axis by this angle in degrees (360: full)");
    s->add_option("--segments", o->segments, "Revolution segments")->check(CLI::Range(3, 1000000))->capture_default_str();
    s->add_option("--path", o->path_file, "Sweep along the polyline in this path file");
    s->add_option("--helix", o->helix, "Sweep along a helix: r h turns samples")->expected(4);
    s->add_option("--trefoil", o->trefoil, "Sweep along the trefoil knot: samples scale")->expected(2);
    s->add_option("--frames", o->frames, "Frames along a path: rmf or frenet")->check(CLI::IsMember({"rmf", "frenet"}))->capture_default_str();
    s->add_flag("--force", o->force, "Write a sweep even when it intersects itself (check_sweep's local test or "
                                     "check_surface's face pairs)");
    s->add_flag("--json", o->json, "Print one JSON object with the figures (stable names) instead of the text lines");
    s->callback([o, &status] {
        try {
            status = run_sweep(*o);
        } catch (const std::exception& e) {
            std::cerr << "geolab sweep: " << e.what() << "\n";
            status = 1;
        }
    });
#else
    (void)app;
    (void)status;
#endif
}

}  // namespace geolab::cli
