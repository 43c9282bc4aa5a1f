// attach_mesh_figure: the student's mesh next to the reference, rendered headless, linked from the reports.
#include <cctype>
#include <cstdlib>

#include "geolab/grading/test.hpp"
#include "geolab/render/render.hpp"
#include "geolab/soup.hpp"

namespace geolab {

void attach_mesh_figure(const std::string& name, const PolygonSoup& student, const PolygonSoup& reference) {
    const char* dir = std::getenv("GEOLAB_FIGURE_DIR");
    if (!dir || !*dir) return;  // not asked for: free
    try {
        // Reference on the left (grey), the student's mesh beside it (orange), one bounding-box width apart.
        glm::dvec3 lo(1e300), hi(-1e300);
        for (const auto& p : reference.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
        for (const auto& p : student.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
        const double shift = reference.positions.empty() && student.positions.empty() ? 1.0 : 1.25 * (hi.x - lo.x) + 1e-9;
        PolygonSoup moved = student;
        for (auto& p : moved.positions) p.x += shift;
        render::Scene scene;
        if (reference.n_faces()) scene.add_mesh(reference, {.color = {0.75f, 0.75f, 0.80f}, .wireframe = true});
        if (moved.n_faces()) scene.add_mesh(moved, {.color = {0.95f, 0.55f, 0.20f}, .wireframe = true});
        std::string file;
        for (char c : detail::current_test() + "-" + name) file += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
        const std::string path = std::string(dir) + "/" + file.substr(0, 120) + ".png";
        render::render_png(scene, render::Camera::framing(scene.bounds()), path, 800, 400);
        detail::attached_figures().push_back(path);
    } catch (...) {
        // A figure is feedback, never a reason to fail a test.
    }
}

}  // namespace geolab
