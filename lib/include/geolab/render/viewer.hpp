#pragma once
//! \file render/viewer.hpp
//! An interactive window (GLFW, GL 3.3 core) for demos and lectures.
//!
//! Mouse: left drag orbits, right drag (or shift + left drag) pans, scroll zooms; a left click without drag
//! calls the pick callback with the world-space ray under the cursor. A mouse callback (on_mouse) sees every
//! press first and may capture that drag (a slider, a control point) instead. Keys: Esc closes, S saves a screenshot
//! (out/screenshots/geolab_screenshot_N.png under the working directory), Home re-frames the scene; every other
//! key goes to the key callback. An exception thrown by a callback closes the window and is rethrown by run() /
//! run_frames(). Without a display the constructor throws NoDisplay; programs catch it and suggest `--png FILE`.
//! The window never opens larger than the screen's work area (it shrinks, keeping its aspect ratio).
//!
//! Demos run student code: limit_demo_memory() gives them the grader's memory cap, memory_limit_message() the
//! sentence to show when an allocation fails under it.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "geolab/render/camera.hpp"
#include "geolab/render/image.hpp"
#include "geolab/render/scene.hpp"

namespace geolab::render {

//! No window can be opened (no DISPLAY / WAYLAND_DISPLAY, or GLFW cannot connect or create a GL 3.3 context).
//! what() says why and points to the headless option (`--png FILE`).
class NoDisplay : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

//! A mouse button event or a move of a captured drag (Viewer::on_mouse), in the window's screen units with
//! (0, 0) the top-left corner (what Camera::ray takes with `width`, `height`).
struct MouseEvent {
    enum class Phase { press, move, release };
    Phase phase = Phase::press;
    double x = 0.0, y = 0.0;    //!< the cursor
    int width = 0, height = 0;  //!< the window
    bool secondary = false;     //!< the right button, or the left one with Shift (the pan gesture)
};

//! True when a display is configured and GLFW can connect to it (a window can probably be opened).
bool display_available();

//! The memory cap of a demo process, MiB: the grader's default cap per test (grading::RunOptions::memory_mb).
std::size_t default_demo_memory_mb();
//! Caps this process's address space (RLIMIT_AS) at `mb` MiB (0: no cap), so that student code that runs away
//! in a demo fails as it does when graded (std::bad_alloc), not by swapping the machine. \return false when the
//! system refused the limit (the demo then runs uncapped).
bool limit_demo_memory(std::size_t mb);
//! "memory limit (N MiB) exceeded in WHERE: ...": the sentence for a std::bad_alloc under limit_demo_memory().
std::string memory_limit_message(const std::string& where);
//! How many times memory_limit_message() was asked for in this process: a step ran out of memory each time (a demo
//! that carries on past it, drawing the rest, still ends with status 1: DemoProgram::run compares the counts).
std::size_t memory_limit_reports();

//! The folder the S key writes screenshots into: out/screenshots under the working directory.
std::filesystem::path screenshot_dir();

//! Checks a demo's --figures folder. In the student release (a build without solutions/) the handouts' figures
//! under docs/ are the reference's and must stay: a folder inside the course tree's docs/ is refused.
//! \throw std::runtime_error naming the folder and pointing to out/figures/.
void check_figure_dir(const std::filesystem::path& dir);

//! A window showing a Scene with an orbit camera. One Viewer at a time per thread; all calls from the thread
//! that created it.
class Viewer {
public:
    //! Opens the window (width × height screen units, shrunk to fit the screen's work area with room for the
    //! title bar). \throw NoDisplay when no window can be opened.
    explicit Viewer(std::string title, int width = 1024, int height = 768);
    ~Viewer();
    Viewer(const Viewer&) = delete;
    Viewer& operator=(const Viewer&) = delete;

    //! Replaces what is shown. The camera is re-framed on the new bounds when `reframe` or on the first scene.
    void set_scene(Scene scene, bool reframe = false);
    const Scene& scene() const;
    void set_camera(const Camera& camera);
    const Camera& camera() const;
    //! A status line shown in the title bar after the title ("title — status").
    void set_status(std::string status);
    //! Rectangles drawn over the scene (widgets, text; see Scene::Rect), kept when the scene is replaced.
    void set_overlay(std::vector<Scene::Rect> overlay);

    //! Called on key press (and repeat) with the GLFW key code; letters are their upper-case ASCII code
    //! ('N'), digits '0'..'9', arrows GLFW_KEY_RIGHT etc. (262..265). Not called for Esc, S and Home.
    void on_key(std::function<void(int key)> callback);
    //! Called on a left click without drag with the world-space ray under the cursor (see pick.hpp).
    void on_pick(std::function<void(const Ray& ray)> callback);
    //! Called first when a mouse button goes down (Phase::press). Returning true captures the drag: its moves
    //! and its release go to this callback too (returns ignored), and the camera does not move, nor is a pick
    //! made. Returning false leaves the press to orbit, pan and pick.
    void on_mouse(std::function<bool(const MouseEvent&)> callback);
    //! Called before every frame with the seconds since run() started. While it returns true the window redraws
    //! continuously (an animation); after false it waits for input before the next frame.
    void on_frame(std::function<bool(double seconds)> callback);
    //! Called before every frame is drawn, after the input that came in since the last one (e.g. to redraw a
    //! demo once for a burst of mouse moves).
    void on_before_draw(std::function<void()> callback);

    //! Shows the window until it is closed (Esc, the close button or close()). Sleeps until input arrives
    //! unless on_frame is set.
    void run();
    //! Processes input and draws `frames` frames, then returns; false once the window has been closed.
    //! For scripted runs (e.g. draw, then screenshot()).
    bool run_frames(int frames);
    //! Draws the current scene and returns the window's pixels (framebuffer size).
    Image capture();
    //! capture() written as PNG. \throw geolab::IoError if the file cannot be written.
    void screenshot(const std::filesystem::path& file);
    //! What the S key does: capture() into screenshot_dir()/geolab_screenshot_N.png (the first free N), and
    //! says so in the status line. \return the file written (empty if it could not be written).
    std::filesystem::path save_screenshot();
    //! The window's size in screen units (after fitting the screen) and its framebuffer's size in pixels.
    void size(int& width, int& height, int& fb_width, int& fb_height) const;
    //! Asks the window to close; run() returns after the current frame.
    void close();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace geolab::render
