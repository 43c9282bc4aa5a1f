// The shared machinery of the lab demos (see geolab/render/demo.hpp).
#include "geolab/render/demo.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iostream>
#include <iterator>
#include <map>
#include <sstream>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "geolab/models.hpp"
#include "geolab/render/headless.hpp"

namespace geolab::render {

using glm::dvec3;
using glm::vec3;

// ---- numbers ---------------------------------------------------------------------------------------------------

std::string fmt(double x, int precision) {
    std::ostringstream os;
    os.precision(precision);
    os << x;
    return os.str();
}

std::string fmt(const dvec3& v, int precision) {
    return "(" + fmt(v.x, precision) + ", " + fmt(v.y, precision) + ", " + fmt(v.z, precision) + ")";
}

// ---- calling student code ----------------------------------------------------------------------------------------

void Issues::add_missing(const std::string& function) {
    if (std::find(missing.begin(), missing.end(), function) == missing.end()) missing.push_back(function);
}

void Issues::add_error(const std::string& message) {
    if (std::find(errors.begin(), errors.end(), message) == errors.end()) errors.push_back(message);
}

void Issues::add(const Issues& other) {
    for (const auto& m : other.missing) add_missing(m);
    for (const auto& e : other.errors) add_error(e);
}

std::string Issues::str() const {
    std::string s;
    if (!missing.empty()) {
        s = "not implemented yet: ";
        for (std::size_t i = 0; i < missing.size(); ++i) s += (i ? ", " : "") + missing[i];
    }
    for (const auto& e : errors) s += (s.empty() ? "" : " | ") + e;
    return s;
}

std::string not_implemented_name(const std::string& what) {
    std::string name = what;
    const std::string prefix = "not implemented: ";
    if (name.rfind(prefix, 0) == 0) name = name.substr(prefix.size());
    if (const auto p = name.find(" ("); p != std::string::npos) name = name.substr(0, p);
    return name;
}

// ---- drawing -------------------------------------------------------------------------------------------------------

void Segments::add(const dvec3& a, const dvec3& b, vec3 color) {
    endpoints.push_back(vec3(a)), endpoints.push_back(vec3(b));
    colors.push_back(color);
}

void Segments::draw(Scene& scene, float width) const {
    if (!empty()) scene.add_lines(endpoints, colors, width);
}

void add_arrow(Segments& seg, const dvec3& a, const dvec3& b, const dvec3& side, vec3 color, const ArrowStyle& style) {
    const dvec3 d = b - a;
    const dvec3 p = a + style.shrink * d, q = b - style.shrink * d;
    const double len = glm::length(q - p);
    const dvec3 u = (q - p) / std::max(len, 1e-300);
    const double hl = style.head * len, hw = 0.45 * hl;
    const dvec3 base = q - hl * u;
    seg.add(p, q, color);
    if (style.head <= 0.0) return;
    seg.add(q, base + (style.one_sided ? 1.6 : 1.0) * hw * side, color);
    if (!style.one_sided) seg.add(q, base - hw * side, color);
}

void add_normal(Segments& seg, const dvec3& p, const dvec3& n, double length, vec3 color) {
    if (!(glm::length(n) > 0.5)) return;
    const dvec3 any = std::abs(n.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
    add_arrow(seg, p, p + length * n, glm::normalize(glm::cross(n, any)), color, {.shrink = 0.0, .head = 0.25});
}

dvec3 side_towards(const dvec3& a, const dvec3& b, const dvec3& c) {
    const dvec3 u = glm::normalize(b - a);
    const dvec3 s = (c - a) - glm::dot(c - a, u) * u;
    const double l = glm::length(s);
    return l > 0 ? s / l : dvec3(0, 0, 1);
}

void add_box_edges(std::vector<vec3>& seg, const dvec3& a, const dvec3& b) {
    for (int axis = 0; axis < 3; ++axis)
        for (int c = 0; c < 4; ++c) {
            dvec3 p = a, q = a;
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            p[u] = q[u] = (c & 1) ? b[u] : a[u];
            p[v] = q[v] = (c & 2) ? b[v] : a[v];
            q[axis] = b[axis];
            seg.push_back(vec3(p)), seg.push_back(vec3(q));
        }
}

std::vector<vec3> boundary_edges(const PolygonSoup& soup) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        const auto c = soup.face(f);
        for (std::size_t i = 0; i < c.size(); ++i) {
            const auto a = c[i], b = c[(i + 1) % c.size()];
            ++count[{std::min(a, b), std::max(a, b)}];
        }
    }
    std::vector<vec3> seg;
    for (const auto& [e, n] : count)
        if (n == 1) seg.push_back(vec3(soup.positions[e.first])), seg.push_back(vec3(soup.positions[e.second]));
    return seg;
}

vec3 category_color(std::size_t i) {
    static const vec3 palette[] = {{0.90f, 0.10f, 0.10f}, {0.10f, 0.35f, 0.95f}, {0.05f, 0.65f, 0.15f},
                                   {0.95f, 0.55f, 0.00f}, {0.70f, 0.10f, 0.80f}, {0.00f, 0.65f, 0.70f},
                                   {0.55f, 0.35f, 0.10f}, {0.95f, 0.30f, 0.65f}, {0.45f, 0.45f, 0.45f}};
    return palette[i % std::size(palette)];
}

// ---- cameras -------------------------------------------------------------------------------------------------------

Box box_around(const dvec3& c, double r) { return {c - dvec3(r), c + dvec3(r)}; }

void orbit_angles(const dvec3& eye_dir, const dvec3& up, float& yaw_deg, float& pitch_deg) {
    // the orbit camera's frame (camera.cpp): yaw 0 looks from `front`, positive yaw turns towards `right`
    const dvec3 u = glm::normalize(up);
    const dvec3 ref = std::abs(u.z) < 0.9 ? dvec3(0, 0, 1) : dvec3(0, -1, 0);
    const dvec3 front = glm::normalize(ref - glm::dot(ref, u) * u), right = glm::cross(u, front);
    const dvec3 e = glm::normalize(eye_dir);
    pitch_deg = static_cast<float>(glm::degrees(std::asin(std::clamp(glm::dot(e, u), -0.996, 0.996))));
    yaw_deg = static_cast<float>(glm::degrees(std::atan2(glm::dot(e, right), glm::dot(e, front))));
}

Camera camera_from(const Box& box, const dvec3& eye_dir, const dvec3& up) {
    const vec3 u = glm::normalize(vec3(up));  // as the camera keeps it
    float yaw = 0.0f, pitch = 0.0f;
    orbit_angles(eye_dir, dvec3(u), yaw, pitch);
    return Camera::framing(box, yaw, pitch, u);
}

Camera fit(Camera cam, const Scene& scene, double aspect) {
    std::vector<vec3> pts;
    for (const auto& m : scene.meshes()) pts.insert(pts.end(), m.position.begin(), m.position.end());
    for (const auto& l : scene.lines()) pts.insert(pts.end(), l.position.begin(), l.position.end());
    for (const auto& p : scene.points()) pts.insert(pts.end(), p.position.begin(), p.position.end());
    if (pts.empty()) return cam;
    // half the field of view's tangent across the image's height (ty) and width (tx)
    const double ty = std::tan(glm::radians(cam.fov_deg) * 0.5) * (aspect < 1 ? 1 / aspect : 1.0);
    const double tx = ty * aspect;
    for (int pass = 0; pass < 3; ++pass) {
        const glm::mat4 view = cam.view();
        const dvec3 right(view[0][0], view[1][0], view[2][0]), up(view[0][1], view[1][1], view[2][1]),
            back(view[0][2], view[1][2], view[2][2]);
        // the distance at which every point is inside the view cone around the target
        double d = 0.0;
        for (const auto& p : pts) {
            const dvec3 q = dvec3(p) - dvec3(cam.target);
            const double z = glm::dot(q, back);
            d = std::max({d, z + std::abs(glm::dot(q, right)) / tx, z + std::abs(glm::dot(q, up)) / ty});
        }
        cam.distance = static_cast<float>(d);
        if (pass == 2) break;
        // centre the image: move the target by the middle of the projected extent
        double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
        for (const auto& p : pts) {
            const dvec3 q = dvec3(p) - dvec3(cam.target);
            const double depth = d - glm::dot(q, back);
            const double sx = glm::dot(q, right) / depth, sy = glm::dot(q, up) / depth;
            lo_x = std::min(lo_x, sx), hi_x = std::max(hi_x, sx), lo_y = std::min(lo_y, sy), hi_y = std::max(hi_y, sy);
        }
        cam.target += vec3(0.5 * (lo_x + hi_x) * d * right + 0.5 * (lo_y + hi_y) * d * up);
    }
    cam.distance *= 1.06f;
    return cam;
}

Camera whole(const Scene& scene, double aspect, float yaw_deg, float pitch_deg) {
    return fit(Camera::framing(scene.bounds(), yaw_deg, pitch_deg), scene, aspect);
}

Camera close_up(Camera cam, const dvec3& center, double radius) {
    cam.target = vec3(center);
    cam.distance = static_cast<float>(radius / std::tan(glm::radians(cam.fov_deg) * 0.5));
    return cam;
}

// ---- figures -------------------------------------------------------------------------------------------------------

Image hstack(const std::vector<Image>& images, int gap) {
    Image out;
    for (std::size_t i = 0; i < images.size(); ++i) {
        out.width += images[i].width + (i ? gap : 0);
        out.height = std::max(out.height, images[i].height);
    }
    out.rgba.assign(std::size_t(4) * out.width * out.height, 255);
    int x0 = 0;
    for (std::size_t i = 0; i < images.size(); ++i) {
        if (i > 0) {
            for (int y = 0; y < out.height; ++y)
                for (int x = x0; x < x0 + gap; ++x)
                    for (int c = 0; c < 3; ++c) out.rgba[std::size_t(4) * (std::size_t(y) * out.width + x) + c] = 200;
            x0 += gap;
        }
        const Image& im = images[i];
        for (int y = 0; y < im.height; ++y)
            std::copy_n(im.rgba.data() + std::size_t(4) * y * im.width, std::size_t(4) * im.width,
                        out.rgba.data() + std::size_t(4) * (std::size_t(y) * out.width + x0));
        x0 += im.width;
    }
    return out;
}

std::optional<std::string> first_model(std::initializer_list<const char*> names) {
    for (const char* n : names)
        if (geolab::model_path(n)) return std::string(n);
    return std::nullopt;
}

FigureWriter::FigureWriter(std::filesystem::path dir, int width, int height)
    : dir_(std::move(dir)), width_(width), height_(height), start_(std::chrono::steady_clock::now()) {
    std::filesystem::create_directories(dir_);
}

void FigureWriter::write(const std::string& file, const Scene& scene, const Camera& camera, const std::string& what,
                         int w, int h) {
    render_png(scene, camera, dir_ / file, w ? w : width_, h ? h : height_);
    ++written_;
    std::cout << "wrote " << (dir_ / file).string() << "  (" << what << ")" << std::endl;
}

void FigureWriter::write(const std::string& file, const Image& image, const std::string& what) {
    image.write_png(dir_ / file);
    ++written_;
    std::cout << "wrote " << (dir_ / file).string() << "  (" << what << ")" << std::endl;
}

void FigureWriter::skip(const std::string& file, const std::string& why) {
    ++skipped_;
    std::cout << "skipped " << (dir_ / file).string() << ": " << why << std::endl;
}

int FigureWriter::finish() const {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::cout << written_ << " figures in " << dir_.string() << " (" << fmt(s) << " s"
              << (skipped_ ? ", " + std::to_string(skipped_) + " skipped" : "") << ")\n";
    return 0;
}

// ---- the program ---------------------------------------------------------------------------------------------------

DemoProgram::DemoProgram(std::string program, std::string description, std::string window_keys, int default_width)
    : program_(std::move(program)),
      keys_help_(std::move(window_keys)),
      app_(std::move(description)),
      width_(default_width),
      memory_mb_(default_demo_memory_mb()) {
    app_.add_option("--png", png_, "Render the view into this PNG instead of opening a window");
    app_.add_option("--figures", figures_, "Render the handout's figures into this folder and exit (headless)");
    app_.add_option("--size", width_, "PNG width (height = 3/4 of it)")->capture_default_str()->check(CLI::Range(8, 8192));
    app_.add_option("--memory-mb", memory_mb_, "Address-space cap for your code, MiB (0: none; default: the grader's)")
        ->capture_default_str();
    app_.add_option("--frames", frames_, "(testing) draw N frames in the window, then exit")->group("");
    app_.add_option("--screenshot", screenshot_, "(testing) with --frames: save the window to this PNG")->group("");
    app_.add_option("--keys", keys_, "(testing) with --frames: press these keys first ('_' = Space)")->group("");
    app_.footer(keys_help_);
}

std::optional<int> DemoProgram::parse(int argc, char** argv) {
    try {
        app_.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app_.exit(e);
    }
    if (!limit_demo_memory(memory_mb_)) std::cerr << program_ << ": could not cap the memory; running without\n";
    return std::nullopt;
}

int DemoProgram::run(const std::function<int()>& body) {
    try {
        if (!figures_.empty()) check_figure_dir(figures_);
        return body();
    } catch (const NoDisplay& e) {
        std::cerr << program_ << ": " << e.what() << "\n";
        if (!no_display_hint.empty()) std::cerr << no_display_hint << "\n";
    } catch (const std::bad_alloc&) {
        std::cerr << program_ << ": " << memory_limit_message("the demo") << "\n";
    } catch (const std::exception& e) {
        std::cerr << program_ << ": " << e.what() << "\n";
    }
    return 1;
}

int DemoProgram::write_png(const Scene& scene, const Camera& camera, const std::string& status) const {
    render_png(scene, camera, png_, width(), height());
    std::cout << status << "\nwrote " << png_ << "\n";
    return 0;
}

int DemoProgram::show(const Window& window) const {
    Viewer viewer(window.title, 960, 720);
    std::cout << keys_help_ << std::endl;
    auto refresh = [&](bool reframe) {
        Frame frame = window.draw();
        viewer.set_scene(std::move(frame.scene), false);  // (the first scene sets Home's framing)
        if (reframe) viewer.set_camera(frame.camera);
        viewer.set_status(frame.status + (window.key_hint ? window.key_hint() : ""));
        std::cout << frame.status << std::endl;
    };
    refresh(true);
    if (window.pick) viewer.on_pick([&](const Ray& ray) { refresh(window.pick(ray)); });
    return loop(viewer, [&](int key) { refresh(window.key(key)); });
}

int DemoProgram::run_window(Viewer& viewer, const std::function<void(int key)>& press) const {
    std::cout << keys_help_ << std::endl;
    return loop(viewer, press);
}

int DemoProgram::loop(Viewer& viewer, const std::function<void(int key)>& press) const {
    viewer.on_key(press);
    if (frames_ <= 0) {
        viewer.run();
        return 0;
    }
    for (const char c : keys_) {  // scripted: keys, a few frames, a screenshot
        if (c == 'S' || c == 's') {  // as the window's S key
            viewer.run_frames(1);
            std::cout << "wrote " << viewer.save_screenshot().string() << "\n";
            continue;
        }
        press(c == '_' ? ' ' : std::toupper(static_cast<unsigned char>(c)));
    }
    viewer.run_frames(frames_);
    if (!screenshot_.empty()) {
        viewer.screenshot(screenshot_);
        std::cout << "wrote " << screenshot_ << "\n";
    }
    return 0;
}

}  // namespace geolab::render
