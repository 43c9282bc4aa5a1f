// geolab blobby SCENE.json --res N --out mesh.obj: a blob scene (lab 04) sampled and polygonized by marching cubes.
// Runs the variant being built (the reference in the instructor's tree, the student's code in the release).
// The scene format (JSON) and its reader: blobby_scene.hpp.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "geolab/errors.hpp"
#include "geolab/io.hpp"
#ifdef GEOLAB_HAS_LAB_04
#include "blobby_scene.hpp"
#include "geolab/blobby.hpp"
#endif

namespace geolab::cli {

void add_blobby(CLI::App& app, int& status);

#ifdef GEOLAB_HAS_LAB_04
namespace {

struct Opts {
    std::string scene, out;
    int res = 64;
    bool json = false;  // one JSON object with the figures instead of the text lines
};

int polygonize(const Opts& o, const blobby::BlobScene& s);

int run(const Opts& o) {
    const blobby::BlobScene s = read_blob_scene(o.scene);
    try {
        return polygonize(o, s);
    } catch (const IoError&) {
        throw;
    } catch (const std::exception& e) {  // e.g. sample_lattice or the blob grid refusing the scene: name the file
        throw std::runtime_error(o.scene + ": " + e.what());
    }
}

int polygonize(const Opts& o, const blobby::BlobScene& s) {
    const Box box = blobby::make_field(s)->bounds();
    const glm::dvec3 size = box.size();
    const double longest = std::max({size.x, size.y, size.z});
    if (!(longest > 0)) throw std::runtime_error("no blob reaches the threshold (no surface)");
    if (!std::isfinite(longest))  // the lattice's size below would convert NaN to int
        throw std::runtime_error("the scene's extent is not finite (coordinates near 1e308?)");
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
