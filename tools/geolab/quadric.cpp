// geolab quadric classify a b c f g h p q r d: the type of a quadric (lab 03) and its canonical form.
// geolab quadric render a b c f g h p q r d --png F | --superquadric e1 e2 --png F: a Lambert-shaded image.
// Both run the variant being built (the reference in the instructor's tree, the student's code in the release).
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#ifdef GEOLAB_HAS_LAB_03
#include "geolab/quadrics.hpp"
#endif

namespace geolab::cli {

void add_quadric(CLI::App& app, int& status);

#ifdef GEOLAB_HAS_LAB_03
namespace {
quadrics::Coefficients coefficients_of(const std::vector<double>& v) {
    return {v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9]};
}

int run_classify(const std::vector<double>& v, bool as_json) {
    const glm::dmat4 Q = quadrics::to_matrix(coefficients_of(v));
    const quadrics::QuadricType t = quadrics::classify(Q);
    if (as_json) {
        std::cout << nlohmann::json{{"coefficients", v},
                                    {"type", quadrics::type_name(t)},
                                    {"type_index", static_cast<int>(t)},
                                    {"canonical_form", quadrics::canonical_form(t)}}
                         .dump()
                  << "\n";
    } else {
        std::cout << "type            " << quadrics::type_name(t) << "\n"
                  << "canonical form  " << quadrics::canonical_form(t) << "\n";
    }
    return 0;
}

struct RenderOpts {
    std::vector<double> coefficients, superquadric, radii{1, 1, 1};
    std::string png;
    double box = 2.0, yaw = 35, pitch = 25;
    int width = 480, height = 360;
};

int run_render(const RenderOpts& o) {
    quadrics::Scene scene;
    if (!o.superquadric.empty()) {
        scene.is_superquadric = true;
        scene.sq = {{o.radii[0], o.radii[1], o.radii[2]}, o.superquadric[0], o.superquadric[1]};
    } else {
        scene.Q = quadrics::to_matrix(coefficients_of(o.coefficients));
        scene.box = {glm::dvec3(-o.box), glm::dvec3(o.box)};
    }
    scene.light = {0.4, 0.6, 1.0};
    // z up; the eye on a sphere around the box, by yaw (about z) and pitch (above the xy plane)
    const double extent = scene.is_superquadric ? std::max({o.radii[0], o.radii[1], o.radii[2]}) : o.box;
    const double y = o.yaw * 3.14159265358979323846 / 180, p = o.pitch * 3.14159265358979323846 / 180;
    quadrics::PinholeCamera cam;
    cam.up = {0, 0, 1};
    cam.target = glm::dvec3(0.0);
    cam.fov_deg = 30;
    cam.eye = 5.5 * extent * glm::dvec3(std::cos(p) * std::cos(y), std::cos(p) * std::sin(y), std::sin(p));
    const auto img = quadrics::render_lambert(scene, cam, o.width, o.height);
    img.write_png(o.png);
    std::cout << "wrote " << o.png << " (" << o.width << "x" << o.height << ")\n";
    return 0;
}
}  // namespace
#endif

void add_quadric(CLI::App& app, int& status) {
#ifdef GEOLAB_HAS_LAB_03
    auto* q = app.add_subcommand("quadric", "Quadric surfaces (lab 03): classify a quadric, render one to PNG");
    q->require_subcommand(1);

    auto cv = std::make_shared<std::vector<double>>();
    auto json = std::make_shared<bool>(false);
    auto* c = q->add_subcommand("classify", "The type and canonical form of a x² + b y² + c z² + 2f yz + 2g zx + "
                                            "2h xy + 2p x + 2q y + 2r z + d = 0");
    c->add_option("coefficients", *cv, "a b c f g h p q r d")->expected(10)->required()->allow_extra_args(false);
    c->add_flag("--json", *json, "Print one JSON object");
    c->callback([cv, json, &status] {
        try {
            status = run_classify(*cv, *json);
        } catch (const std::exception& e) {
            std::cerr << "geolab quadric classify: " << e.what() << "\n";
            status = 1;
        }
    });

    auto ro = std::make_shared<RenderOpts>();
    auto* r = q->add_subcommand("render", "Render a quadric clipped to a box, or a superquadric, Lambert-shaded, to PNG");
    r->add_option("coefficients", ro->coefficients, "a b c f g h p q r d (not with --superquadric)")->expected(10);
    r->add_option("--superquadric", ro->superquadric, "e1 e2: render Barr's superquadric instead")->expected(2);
    r->add_option("--radii", ro->radii, "a1 a2 a3 of the superquadric")->expected(3)->capture_default_str();
    r->add_option("--png", ro->png, "The PNG file to write")->required();
    r->add_option("--box", ro->box, "Half the side of the clipping box [-s, s]³")->capture_default_str();
    r->add_option("--width", ro->width, "Image width")->check(CLI::Range(1, 8192))->capture_default_str();
    r->add_option("--height", ro->height, "Image height")->check(CLI::Range(1, 8192))->capture_default_str();
    r->add_option("--yaw", ro->yaw, "Camera yaw about z, degrees")->capture_default_str();
    r->add_option("--pitch", ro->pitch, "Camera pitch above the xy plane, degrees")->capture_default_str();
    r->callback([ro, &status] {
        if (ro->superquadric.empty() == ro->coefficients.empty()) {
            std::cerr << "geolab quadric render: give either the 10 coefficients or --superquadric e1 e2\n";
            status = 2;
            return;
        }
        try {
            status = run_render(*ro);
        } catch (const std::exception& e) {
            std::cerr << "geolab quadric render: " << e.what() << "\n";
            status = 1;
        }
    });
#else
    (void)app;
    (void)status;
#endif
}

}  // namespace geolab::cli
