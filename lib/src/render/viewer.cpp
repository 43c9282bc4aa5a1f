// Interactive back end: a GLFW window with a GL 3.3 core context and an orbit camera.
#define GLFW_INCLUDE_NONE  // GL comes only through the function table (see gl.hpp)
#include "geolab/render/viewer.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <glm/trigonometric.hpp>
#include <optional>
#include <string>
#include <utility>

#include <sys/resource.h>

#include "context.hpp"
#include "geolab/config.hpp"
#include "geolab/grading/runner.hpp"
#include "renderer.hpp"

namespace geolab::render {
namespace {

std::string g_glfw_error;  // the last GLFW error, for NoDisplay messages
int g_glfw_users = 0;      // open Viewers; GLFW is terminated when the last one closes

void on_glfw_error(int, const char* description) { g_glfw_error = description ? description : ""; }

bool env_set(const char* name) {
    const char* v = std::getenv(name);
    return v && *v;
}

const char* kHeadlessHint = "Run headless instead: pass --png FILE to write the picture to a PNG file.";
constexpr int kFrameMargin = 16, kTitleMargin = 48;  // screen units kept free around a window that fits the screen

// Initializes GLFW (reference counted). Throws NoDisplay when there is no display.
void acquire_glfw() {
    if (g_glfw_users > 0) {
        ++g_glfw_users;
        return;
    }
    if (!env_set("DISPLAY") && !env_set("WAYLAND_DISPLAY"))
        throw NoDisplay(std::string("cannot open a window: no display (DISPLAY and WAYLAND_DISPLAY are unset). ") +
                        kHeadlessHint);
    glfwSetErrorCallback(on_glfw_error);
    g_glfw_error.clear();
    if (!glfwInit())
        throw NoDisplay("cannot open a window: no usable display (GLFW: " + g_glfw_error + "). " + kHeadlessHint);
    ++g_glfw_users;
}

void release_glfw() {
    if (--g_glfw_users == 0) glfwTerminate();
}

detail::GlProc glfw_get_proc(const char* name) { return glfwGetProcAddress(name); }

}  // namespace

bool display_available() {
    try {
        acquire_glfw();
        release_glfw();
        return true;
    } catch (const NoDisplay&) {
        return false;
    }
}

// The window's GL context.
class GlfwContext final : public detail::Context {
public:
    explicit GlfwContext(GLFWwindow* window) : window_(window) {}
    void make_current() override { glfwMakeContextCurrent(window_); }
    detail::GetProc get_proc() const override { return glfw_get_proc; }

private:
    GLFWwindow* window_;
};

struct Viewer::Impl {
    std::string title, status;
    GLFWwindow* window = nullptr;
    std::optional<GlfwContext> context;
    detail::Gl gl;
    std::optional<detail::Renderer> renderer;
    Scene scene;
    Camera camera, home;  // home: the framing of the current scene
    bool scene_dirty = true, has_scene = false;
    std::function<void(int)> key_cb;
    std::function<void(const Ray&)> pick_cb;
    std::function<bool(const MouseEvent&)> mouse_cb;
    std::function<bool(double)> frame_cb;
    std::function<void()> before_draw_cb;
    std::vector<Scene::Rect> overlay;
    bool overlay_dirty = false;
    double start_time = 0.0;
    int screenshot_count = 0;
    // mouse state
    int button = -1;                                      // GLFW_MOUSE_BUTTON_LEFT / RIGHT while pressed
    bool pan = false, dragged = false, captured = false;  // captured: the press went to mouse_cb
    double press_x = 0, press_y = 0, last_x = 0, last_y = 0;
    // an exception thrown by a user callback: it must not unwind through GLFW's C frames, so it is kept here
    // and rethrown once GLFW returns
    std::exception_ptr error;

    static Impl& of(GLFWwindow* w) { return *static_cast<Impl*>(glfwGetWindowUserPointer(w)); }

    void update_title() {
        std::string t = status.empty() ? title : title + " \xe2\x80\x94 " + status;
        glfwSetWindowTitle(window, t.c_str());
    }

    void draw() {
        context->make_current();
        if (scene_dirty) {
            renderer->upload(scene);
            scene_dirty = false;
        }
        if (overlay_dirty) {
            renderer->set_overlay(overlay);
            overlay_dirty = false;
        }
        int fw = 0, fh = 0, ww = 0, wh = 0;
        glfwGetFramebufferSize(window, &fw, &fh);
        glfwGetWindowSize(window, &ww, &wh);
        if (fw <= 0 || fh <= 0) return;  // minimized
        renderer->draw(camera, fw, fh, ww > 0 ? float(fw) / float(ww) : 1.0f);
    }

    std::filesystem::path save_screenshot() {
        std::filesystem::path file;
        try {
            const auto dir = screenshot_dir();
            std::filesystem::create_directories(dir);
            do {
                file = dir / ("geolab_screenshot_" + std::to_string(++screenshot_count) + ".png");
            } while (std::filesystem::exists(file));
            capture().write_png(file);
            status = "saved " + file.string();
        } catch (const std::exception& e) {
            status = std::string("screenshot not saved: ") + e.what();
            file.clear();
        }
        update_title();
        return file;
    }

    Image capture() {
        draw();
        int fw = 0, fh = 0;
        glfwGetFramebufferSize(window, &fw, &fh);
        gl.ReadBuffer(GL_BACK);
        gl.Finish();
        return renderer->read_pixels(fw, fh);
    }

    // ---- GLFW callbacks -------------------------------------------------------------------------------------
    // Runs a user callback; keeps its exception for rethrow() and closes the window.
    template <class F>
    void guarded(F&& f) {
        if (error) return;
        try {
            f();
        } catch (...) {
            error = std::current_exception();
            glfwSetWindowShouldClose(window, GLFW_TRUE);
        }
    }
    void rethrow() {
        if (error) std::rethrow_exception(std::exchange(error, nullptr));
    }

    static void key(GLFWwindow* w, int key, int, int action, int) {
        Impl& v = of(w);
        if (action == GLFW_RELEASE) return;
        if (key == GLFW_KEY_ESCAPE) {
            glfwSetWindowShouldClose(w, GLFW_TRUE);
        } else if (key == GLFW_KEY_S) {
            if (action == GLFW_PRESS) v.save_screenshot();
        } else if (key == GLFW_KEY_HOME) {
            v.camera = v.home;
        } else if (v.key_cb) {
            v.guarded([&] { v.key_cb(key); });
        }
    }

    // Sends a mouse event to mouse_cb; its answer (false when there is none or it threw).
    bool send_mouse(MouseEvent::Phase phase, double x, double y) {
        if (!mouse_cb) return false;
        MouseEvent e{phase, x, y, 0, 0, pan};
        glfwGetWindowSize(window, &e.width, &e.height);
        bool taken = false;
        guarded([&] { taken = mouse_cb(e); });
        return taken;
    }

    static void mouse_button(GLFWwindow* w, int button, int action, int mods) {
        Impl& v = of(w);
        double x, y;
        glfwGetCursorPos(w, &x, &y);
        if (action == GLFW_PRESS && v.button < 0) {
            v.button = button;
            v.pan = button == GLFW_MOUSE_BUTTON_RIGHT || (mods & GLFW_MOD_SHIFT);
            v.dragged = false;
            v.press_x = v.last_x = x;
            v.press_y = v.last_y = y;
            v.captured = v.send_mouse(MouseEvent::Phase::press, x, y);
        } else if (action == GLFW_RELEASE && button == v.button) {
            v.button = -1;
            if (v.captured) {
                v.captured = false;
                v.send_mouse(MouseEvent::Phase::release, x, y);
                return;
            }
            if (!v.dragged && button == GLFW_MOUSE_BUTTON_LEFT && v.pick_cb) {
                int ww, wh;
                glfwGetWindowSize(w, &ww, &wh);
                if (ww > 0 && wh > 0) v.guarded([&] { v.pick_cb(v.camera.ray(x, y, ww, wh)); });
            }
        }
    }

    static void cursor(GLFWwindow* w, double x, double y) {
        Impl& v = of(w);
        if (v.button < 0) return;
        if (v.captured) {
            v.send_mouse(MouseEvent::Phase::move, x, y);
            return;
        }
        if (std::hypot(x - v.press_x, y - v.press_y) > 3.0) v.dragged = true;
        const double dx = x - v.last_x, dy = y - v.last_y;
        v.last_x = x;
        v.last_y = y;
        if (!v.dragged) return;
        if (v.pan) {
            int ww, wh;
            glfwGetWindowSize(w, &ww, &wh);
            v.camera.pan(dx, dy, ww, wh);
        } else {
            v.camera.orbit(dx, dy);
        }
    }

    static void scroll(GLFWwindow* w, double, double dy) {
        Impl& v = of(w);
        v.camera.distance *= std::pow(0.9f, float(dy));
    }
};

Viewer::Viewer(std::string title, int width, int height) : impl_(std::make_unique<Impl>()) {
    acquire_glfw();
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SAMPLES, 4);
    // Fit the screen: the primary monitor's work area less a margin for the window's frame and title bar.
    if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) {
        int x = 0, y = 0, aw = 0, ah = 0;
        glfwGetMonitorWorkarea(monitor, &x, &y, &aw, &ah);
        if (aw > 0 && ah > 0) {
            const double k = std::min({1.0, double(aw - kFrameMargin) / width, double(ah - kTitleMargin) / height});
            width = std::max(64, int(width * k));
            height = std::max(48, int(height * k));
        }
    }
    g_glfw_error.clear();
    GLFWwindow* window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window) {
        release_glfw();
        throw NoDisplay("cannot open a window with an OpenGL 3.3 core context (GLFW: " + g_glfw_error + "). " +
                        kHeadlessHint);
    }
    Impl& v = *impl_;
    v.title = std::move(title);
    v.window = window;
    v.context.emplace(window);
    v.context->make_current();
    try {
        v.gl.load(v.context->get_proc());
        v.renderer.emplace(v.gl);
    } catch (...) {
        glfwDestroyWindow(window);
        release_glfw();
        throw;
    }
    glfwSwapInterval(1);
    glfwSetWindowUserPointer(window, &v);
    glfwSetKeyCallback(window, Impl::key);
    glfwSetMouseButtonCallback(window, Impl::mouse_button);
    glfwSetCursorPosCallback(window, Impl::cursor);
    glfwSetScrollCallback(window, Impl::scroll);
    v.start_time = glfwGetTime();
}

Viewer::~Viewer() {
    if (!impl_ || !impl_->window) return;
    impl_->context->make_current();
    impl_->renderer.reset();  // frees GL objects while the context is current
    glfwDestroyWindow(impl_->window);
    release_glfw();
}

void Viewer::set_scene(Scene scene, bool reframe) {
    Impl& v = *impl_;
    v.scene = std::move(scene);
    v.scene_dirty = true;
    if (reframe || !v.has_scene) {
        v.home = Camera::framing(v.scene.bounds(), 30.0f, 20.0f, v.camera.up);
        v.camera = v.home;
    }
    v.has_scene = true;
}

const Scene& Viewer::scene() const { return impl_->scene; }

void Viewer::set_camera(const Camera& camera) {
    impl_->camera = camera;
    impl_->home = camera;
}

const Camera& Viewer::camera() const { return impl_->camera; }

void Viewer::set_status(std::string status) {
    impl_->status = std::move(status);
    impl_->update_title();
}

void Viewer::on_key(std::function<void(int)> callback) { impl_->key_cb = std::move(callback); }
void Viewer::on_pick(std::function<void(const Ray&)> callback) { impl_->pick_cb = std::move(callback); }
void Viewer::on_mouse(std::function<bool(const MouseEvent&)> callback) { impl_->mouse_cb = std::move(callback); }
void Viewer::on_frame(std::function<bool(double)> callback) { impl_->frame_cb = std::move(callback); }
void Viewer::on_before_draw(std::function<void()> callback) { impl_->before_draw_cb = std::move(callback); }

void Viewer::set_overlay(std::vector<Scene::Rect> overlay) {
    impl_->overlay = std::move(overlay);
    impl_->overlay_dirty = true;
}

bool Viewer::run_frames(int frames) {
    Impl& v = *impl_;
    for (int i = 0; i < frames; ++i) {
        if (glfwWindowShouldClose(v.window)) break;
        glfwPollEvents();
        v.rethrow();
        if (v.frame_cb) v.guarded([&] { v.frame_cb(glfwGetTime() - v.start_time); });
        if (v.before_draw_cb) v.guarded([&] { v.before_draw_cb(); });
        v.rethrow();
        v.draw();
        glfwSwapBuffers(v.window);
    }
    return !glfwWindowShouldClose(v.window);
}

void Viewer::run() {
    Impl& v = *impl_;
    v.start_time = glfwGetTime();
    bool animating = bool(v.frame_cb);
    while (!glfwWindowShouldClose(v.window)) {
        // animating: redraw continuously; otherwise sleep until input arrives (every event redraws)
        if (animating)
            glfwPollEvents();
        else
            glfwWaitEvents();
        v.rethrow();
        animating = false;
        if (v.frame_cb) v.guarded([&] { animating = v.frame_cb(glfwGetTime() - v.start_time); });
        if (v.before_draw_cb) v.guarded([&] { v.before_draw_cb(); });
        v.rethrow();
        if (glfwWindowShouldClose(v.window)) break;
        v.draw();
        glfwSwapBuffers(v.window);
    }
}

Image Viewer::capture() { return impl_->capture(); }

void Viewer::screenshot(const std::filesystem::path& file) { capture().write_png(file); }

std::filesystem::path Viewer::save_screenshot() { return impl_->save_screenshot(); }

void Viewer::size(int& width, int& height, int& fb_width, int& fb_height) const {
    glfwGetWindowSize(impl_->window, &width, &height);
    glfwGetFramebufferSize(impl_->window, &fb_width, &fb_height);
}

std::filesystem::path screenshot_dir() { return std::filesystem::path("out") / "screenshots"; }

void check_figure_dir(const std::filesystem::path& dir) {
    namespace fs = std::filesystem;
    if (config::has_solutions) return;  // the instructor renders the handouts' figures on purpose
    std::error_code ec;
    const fs::path docs = fs::weakly_canonical(fs::path(config::source_dir) / "docs", ec);
    const fs::path target = fs::weakly_canonical(fs::absolute(dir), ec);
    const auto rel = target.lexically_relative(docs);
    if (!ec && !rel.empty() && *rel.begin() != "..")
        throw std::runtime_error(dir.string() +
                                 " is inside docs/, which holds the handouts' figures (the "
                                 "reference's): write yours elsewhere, e.g. --figures out/figures/NN_name");
}

std::size_t default_demo_memory_mb() { return grading::RunOptions{}.memory_mb; }

bool limit_demo_memory(std::size_t mb) {
    if (mb == 0) return true;
    rlimit r{};
    if (::getrlimit(RLIMIT_AS, &r) != 0) return false;
    const rlim_t want = static_cast<rlim_t>(mb) << 20;
    if (r.rlim_max != RLIM_INFINITY && r.rlim_max < want) return true;  // already capped lower
    r.rlim_cur = want;
    return ::setrlimit(RLIMIT_AS, &r) == 0;
}

namespace {
std::atomic<std::size_t> g_memory_limit_reports{0};
}  // namespace

std::size_t memory_limit_reports() { return g_memory_limit_reports.load(); }

std::string memory_limit_message(const std::string& where) {
    ++g_memory_limit_reports;
    rlimit r{};
    std::string cap;
    if (::getrlimit(RLIMIT_AS, &r) == 0 && r.rlim_cur != RLIM_INFINITY)
        cap = " (" + std::to_string(static_cast<unsigned long long>(r.rlim_cur >> 20)) + " MiB)";
    return "memory limit" + cap + " exceeded in " + where +
           ": the grader stops a test at the same cap (a loop that never ends while it allocates?)";
}

void Viewer::close() { glfwSetWindowShouldClose(impl_->window, GLFW_TRUE); }

}  // namespace geolab::render
