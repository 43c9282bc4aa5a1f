// geolab csg SCENE.scad --png F: ray-cast an OpenSCAD scene (lab 07's subset) to a Lambert-shaded PNG.
// geolab csg SCENE.scad --mesh out.stl --res N: polygonize it (lib's reference polygonizer on the tree's SDF).
// --json: one JSON object with the figures (nodes, image size and time, mesh counts, volume) on stdout; the
// progress lines stay on stderr. Both run the variant being built (the reference in the instructor's tree, the student's code in the release).
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <memory>
#include <numbers>
#include <string>

#include <glm/geometric.hpp>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "geolab/io.hpp"
#ifdef GEOLAB_HAS_LAB_07
#include "geolab/csg.hpp"
#endif

namespace geolab::cli {

void add_csg(CLI::App& app, int& status);

#ifdef GEOLAB_HAS_LAB_07
namespace {
struct CsgOpts {
    std::string scene, png, mesh;
    int res = 128, width = 640, height = 480;
    double yaw = 35, pitch = 25;
    bool json = false;
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

int run_csg(const CsgOpts& o) {
    const auto t0 = std::chrono::steady_clock::now();
    const csg::Tree tree = csg::from_scad(scad::read(o.scene));
    const Box b = csg::bounds(tree);
    std::cerr << "read " << o.scene << ": " << tree.nodes.size() << " nodes\n";
    nlohmann::json report{{"scene", o.scene}, {"nodes", tree.nodes.size()}};
    if (!o.png.empty()) {
        // z up (OpenSCAD's convention); the eye on a sphere around the scene by yaw and pitch
        const double y = o.yaw * std::numbers::pi / 180, p = o.pitch * std::numbers::pi / 180;
        const glm::dvec3 c = b.center();
        const double r = 0.5 * glm::length(b.hi - b.lo);
        if (!std::isfinite(r)) throw std::invalid_argument("the scene is unbounded: nothing to frame");
        csg::PinholeCamera cam;
        cam.up = {0, 0, 1};
        cam.target = c;
        cam.fov_deg = 30;
        cam.eye = c + 4.2 * r * glm::dvec3(std::cos(p) * std::cos(y), std::cos(p) * std::sin(y), std::sin(p));
        // Row by row (the same shading as render_image) so that long runs show their progress; the tree is
        // prepared once and one SpanLists serves every ray.
        const csg::PreparedTree prepared = csg::prepare(tree);
        csg::SpanLists lists;
        const glm::dvec3 l = glm::normalize(glm::dvec3(0.4, 0.6, 1.0));
        render::Image img;
        img.width = o.width;
        img.height = o.height;
        img.rgba.assign(std::size_t(4) * o.width * o.height, 255);
        int shown = -1;
        for (int row = 0; row < o.height; ++row) {
            for (int x = 0; x < o.width; ++x) {
                const auto h = csg::first_hit(prepared, cam.ray(x, row, o.width, o.height), 0.0, lists);
                if (!h) continue;
                const auto g = static_cast<std::uint8_t>(std::lround(255 * (0.1 + 0.8 * std::abs(glm::dot(h->normal, l)))));
                std::uint8_t* px = &img.rgba[4 * (std::size_t(row) * o.width + x)];
                px[0] = px[1] = px[2] = g;
            }
            const int pct = 100 * (row + 1) / o.height;
            if (seconds_since(t0) > 1.0 && pct / 10 != shown) {
                shown = pct / 10;
                std::cerr << "ray casting: " << pct << "% (" << seconds_since(t0) << " s)\n";
            }
        }
        img.write_png(o.png);
        report["png"] = o.png;
        report["width"] = o.width;
        report["height"] = o.height;
        report["raycast_seconds"] = seconds_since(t0);
        if (!o.json)
            std::cout << "wrote " << o.png << " (" << o.width << "x" << o.height << ", " << seconds_since(t0) << " s)\n";
    }
    if (!o.mesh.empty()) {
        std::cerr << "polygonizing at resolution " << o.res << " (about " << double(o.res + 1) * (o.res + 1) * (o.res + 1)
                  << " samples of the tree's SDF) ...\n";
        const auto t1 = std::chrono::steady_clock::now();
        const PolygonSoup m = csg::mesh_tree(tree, o.res);
        const double volume = csg::volume(m);
        std::cerr << "polygonized in " << seconds_since(t1) << " s: " << m.n_vertices() << " vertices, "
                  << m.n_faces() << " triangles, volume " << volume << "\n";
        write_mesh(o.mesh, m);
        report["mesh"] = o.mesh;
        report["res"] = o.res;
        report["polygonize_seconds"] = seconds_since(t1);
        report["vertices"] = m.n_vertices();
        report["triangles"] = m.n_faces();
        report["volume"] = volume;
        if (!o.json) std::cout << "wrote " << o.mesh << "\n";
    }
    if (o.json) std::cout << report.dump() << "\n";
    return 0;
}
}  // namespace
#endif

void add_csg(CLI::App& app, int& status) {
#ifdef GEOLAB_HAS_LAB_07
    auto o = std::make_shared<CsgOpts>();
    auto* c = app.add_subcommand("csg", "Constructive solid geometry (lab 07): ray-cast an OpenSCAD scene to PNG, or "
                                        "polygonize it to a mesh");
    c->add_option("scene", o->scene, "The .scad file (the subset of lib/include/geolab/scad.hpp)")->required();
    c->add_option("--png", o->png, "Ray-cast to this PNG file");
    c->add_option("--mesh", o->mesh, "Polygonize to this mesh file (.stl, .obj, .off, .ply)");
    c->add_option("--res", o->res, "Cells along the longest side for --mesh")->check(CLI::Range(2, 1024))->capture_default_str();
    c->add_option("--width", o->width, "Image width")->check(CLI::Range(1, 8192))->capture_default_str();
    c->add_option("--height", o->height, "Image height")->check(CLI::Range(1, 8192))->capture_default_str();
    c->add_option("--yaw", o->yaw, "Camera yaw about z, degrees")->capture_default_str();
    c->add_option("--pitch", o->pitch, "Camera pitch above the xy plane, degrees")->capture_default_str();
    c->add_flag("--json", o->json, "Print one JSON object with the figures (stable names) instead of the text lines");
    c->callback([o, &status] {
        if (o->png.empty() && o->mesh.empty()) {
            std::cerr << "geolab csg: give --png F and/or --mesh F\n";
            status = 2;
            return;
        }
        try {
            status = run_csg(*o);
        } catch (const std::exception& e) {
            std::cerr << "geolab csg: " << e.what() << "\n";
            status = 1;
        }
    });
#else
    (void)app;
    (void)status;
#endif
}

}  // namespace geolab::cli
