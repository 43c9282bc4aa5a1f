// geolab blobby SCENE.json --res N --out mesh.obj: a blob scene (lab 04) sampled and polygonized by marching cubes.
// Runs the variant being built (the reference in the instructor's tree, the student's code in the release).
//
// The scene format (JSON):
//   { "kernel": "wyvill",            // "blinn", "nishimura" or "wyvill"
//     "threshold": 0.5,              // T > 0
//     "blobs": [ { "center": [0, 0, 0], "strength": 1.0, "radius": 1.0, "a": 1.0 }, ... ] }
// strength (b, default 1; negative subtracts), radius (R of nishimura and wyvill, default 1), a (Blinn's falloff,
// default 1). Unknown keys are errors (a misspelt key would otherwise be silently ignored).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "geolab/errors.hpp"
#include "geolab/io.hpp"
#ifdef GEOLAB_HAS_LAB_04
#include "geolab/blobby.hpp"
#endif

namespace geolab::cli {

void add_blobby(CLI::App& app, int& status);

#ifdef GEOLAB_HAS_LAB_04
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& file, const std::string& where, const std::string& reason) {
    throw std::runtime_error(file + ": " + where + ": " + reason);
}

double number(const std::string& file, const json& j, const std::string& where) {
    if (!j.is_number()) fail(file, where, "expected a number, got " + std::string(j.type_name()));
    const double v = j.get<double>();
    if (!std::isfinite(v)) fail(file, where, "not finite");
    return v;
}

blobby::BlobScene parse_scene(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw IoError(file, 0, "cannot open the file");
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string text = ss.str();
    json j;
    try {
        j = json::parse(text);
    } catch (const json::parse_error& e) {
        const std::size_t at = std::min<std::size_t>(e.byte == 0 ? 0 : e.byte - 1, text.size());
        const std::size_t line = 1 + std::size_t(std::count(text.begin(), text.begin() + long(at), '\n'));
        throw IoError(file, line, std::string("not valid JSON: ") + e.what());
    }
    if (!j.is_object()) fail(file, "top level", "expected an object with \"kernel\", \"threshold\" and \"blobs\"");
    for (const auto& [k, v] : j.items())
        if (k != "kernel" && k != "threshold" && k != "blobs") fail(file, "key \"" + k + "\"", "unknown (kernel, threshold, blobs)");
    blobby::BlobScene s;
    if (!j.contains("kernel") || !j["kernel"].is_string()) fail(file, "kernel", "expected \"blinn\", \"nishimura\" or \"wyvill\"");
    const std::string k = j["kernel"].get<std::string>();
    if (k == "blinn") s.kernel = blobby::Kernel::blinn;
    else if (k == "nishimura") s.kernel = blobby::Kernel::nishimura;
    else if (k == "wyvill") s.kernel = blobby::Kernel::wyvill;
    else fail(file, "kernel", "\"" + k + "\" is not one of blinn, nishimura, wyvill");
    if (!j.contains("threshold")) fail(file, "threshold", "missing");
    s.threshold = number(file, j["threshold"], "threshold");
    if (!(s.threshold > 0)) fail(file, "threshold", "must be > 0");
    if (!j.contains("blobs") || !j["blobs"].is_array() || j["blobs"].empty())
        fail(file, "blobs", "expected a non-empty array of blobs");
    for (std::size_t i = 0; i < j["blobs"].size(); ++i) {
        const json& b = j["blobs"][i];
        const std::string where = "blobs[" + std::to_string(i) + "]";
        if (!b.is_object()) fail(file, where, "expected an object");
        for (const auto& [key, v] : b.items())
            if (key != "center" && key != "strength" && key != "radius" && key != "a")
                fail(file, where + ".\"" + key + "\"", "unknown key (center, strength, radius, a)");
        blobby::Blob blob;
        if (!b.contains("center") || !b["center"].is_array() || b["center"].size() != 3)
            fail(file, where + ".center", "expected [x, y, z]");
        for (int a = 0; a < 3; ++a) blob.center[a] = number(file, b["center"][a], where + ".center[" + std::to_string(a) + "]");
        if (b.contains("strength")) blob.strength = number(file, b["strength"], where + ".strength");
        if (b.contains("radius")) blob.radius = number(file, b["radius"], where + ".radius");
        if (b.contains("a")) blob.a = number(file, b["a"], where + ".a");
        if (s.kernel == blobby::Kernel::blinn && !(blob.a > 0)) fail(file, where + ".a", "Blinn's falloff must be > 0");
        if (s.kernel != blobby::Kernel::blinn && !(blob.radius > 0)) fail(file, where + ".radius", "must be > 0");
        s.blobs.push_back(blob);
    }
    return s;
}

struct Opts {
    std::string scene, out;
    int res = 64;
    bool json = false;  // one JSON object with the figures instead of the text lines
};

int run(const Opts& o) {
    const blobby::BlobScene s = parse_scene(o.scene);
    const Box box = blobby::make_field(s)->bounds();
    const glm::dvec3 size = box.size();
    const double longest = std::max({size.x, size.y, size.z});
    if (!(longest > 0)) throw std::runtime_error(o.scene + ": no blob reaches the threshold (no surface)");
    const double h = longest / o.res;
    // Two cells of margin on every side, so the lattice's boundary samples are outside and the mesh is closed.
    const glm::dvec3 origin = box.lo - 2 * h;
    glm::ivec3 n;
    for (int a = 0; a < 3; ++a) n[a] = int(std::ceil(size[a] / h)) + 5;
    const auto t0 = std::chrono::steady_clock::now();
    std::uint64_t evals = 0;
    const blobby::Lattice L = blobby::sample_lattice(s, origin, h, n, evals);
    const auto t1 = std::chrono::steady_clock::now();
    const blobby::McMesh m = blobby::marching_cubes(L, 0.0);
    const auto t2 = std::chrono::steady_clock::now();
    write_mesh(o.out, m.soup);
    const double samples = double(n.x) * n.y * n.z;
    const double sample_seconds = std::chrono::duration<double>(t1 - t0).count(),
                 polygonize_seconds = std::chrono::duration<double>(t2 - t1).count();
    if (o.json) {
        std::cout << nlohmann::json{{"scene", o.scene},
                                    {"kernel", blobby::kernel_name(s.kernel)},
                                    {"blobs", s.blobs.size()},
                                    {"threshold", s.threshold},
                                    {"lattice", {n.x, n.y, n.z}},
                                    {"cell", h},
                                    {"kernel_evaluations_per_sample", evals / samples},
                                    {"sample_seconds", sample_seconds},
                                    {"polygonize_seconds", polygonize_seconds},
                                    {"vertices", m.soup.n_vertices()},
                                    {"triangles", m.soup.n_faces()},
                                    {"out", o.out}}
                         .dump()
                  << "\n";
        return 0;
    }
    std::cout << blobby::kernel_name(s.kernel) << " scene of " << s.blobs.size() << " blobs, T " << s.threshold << "\n"
              << "lattice " << n.x << "x" << n.y << "x" << n.z << " (cell " << h << "), " << evals / samples
              << " kernel evaluations per sample\n"
              << "sampled in " << sample_seconds << " s, polygonized in " << polygonize_seconds << " s\n"
              << m.soup.n_vertices() << " vertices, " << m.soup.n_faces() << " triangles -> " << o.out << "\n";
    return 0;
}

}  // namespace
#endif

void add_blobby(CLI::App& app, int& status) {
#ifdef GEOLAB_HAS_LAB_04
    auto o = std::make_shared<Opts>();
    auto* c = app.add_subcommand("blobby", "Blobby objects (lab 04): sample a blob scene (JSON) and polygonize it by "
                                           "marching cubes");
    c->add_option("scene", o->scene, "The scene: {\"kernel\": \"wyvill\", \"threshold\": 0.5, \"blobs\": [{\"center\": "
                                     "[x, y, z], \"strength\": b, \"radius\": R, \"a\": a}, ...]}")
        ->required();
    c->add_option("--res", o->res, "Lattice cells along the scene's longest side")->check(CLI::Range(2, 1024))->capture_default_str();
    c->add_option("--out", o->out, "The mesh to write (.obj, .off, .ply, .stl)")->required();
    c->add_flag("--json", o->json, "Print one JSON object with the figures (stable names) instead of the text lines");
    c->callback([o, &status] {
        try {
            status = run(*o);
        } catch (const IoError& e) {
            std::cerr << "geolab blobby: " << e.what() << "\n";
            status = 1;
        } catch (const std::exception& e) {
            std::cerr << "geolab blobby: " << e.what() << "\n";
            status = 1;
        }
    });
#else
    (void)app;
    (void)status;
#endif
}

}  // namespace geolab::cli
