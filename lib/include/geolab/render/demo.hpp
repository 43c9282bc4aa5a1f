#pragma once
//! \file render/demo.hpp
//! The machinery every lab demo shares, so that a lab's demo.cpp holds only the lab's content (its state, what
//! it draws, its keys and its figures). docs/demo-framework.md shows a whole demo written on it.
//!
//! - DemoProgram: the command line every demo has (--png, --widgets, --figures, --size, --memory-mb and the hidden
//!   testing options --frames, --screenshot, --keys), the memory cap, the figure folder check, clear one-line
//!   errors, and the window (show: a 960 × 720 window drawn from the demo's Frame, its keys, sliders, drags,
//!   picking, scripted input; with --png the same input applied headless).
//! - Widgets: Slider (a label, a range, a value of the demo's state; drawn over the picture, dragged with the
//!   mouse), Drag (a mouse drag handed to the demo, with helpers to pick a point and move it in the view plane),
//!   overlay text, and DemoSession, the window's input handling without the GL window (for scripts and tests).
//! - Frame: one picture of a demo (scene, camera, status line), drawn the same in the window, --png and figures.
//! - Issues / attempt: call student code, collect "not implemented yet: f, g" and "f threw: ..." for the status
//!   line instead of crashing.
//! - Cameras: orbit angles from a direction, a box seen from a direction, tight fitting of a scene, close-ups.
//! - Drawing: arrows, harpoons and normals as line segments; box edges; a soup's boundary edges; a subset of its
//!   faces (cut-away views); a categorical palette.
//! - Figures: FigureWriter (writes, reports, counts), hstack (panels side by side), first_model.
//! - fmt: the numbers of status lines (3 significant digits by default).
#include <chrono>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <iosfwd>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "geolab/errors.hpp"
#include "geolab/field.hpp"
#include "geolab/render/camera.hpp"
#include "geolab/render/image.hpp"
#include "geolab/render/scene.hpp"
#include "geolab/render/viewer.hpp"

namespace geolab::render {

// ---- numbers ---------------------------------------------------------------------------------------------------

//! x with `precision` significant digits, as an ostream prints it by default (0.333, 1.5e+06, 2, nan, inf).
std::string fmt(double x, int precision = 3);
//! "(x, y, z)", each as fmt(·, precision).
std::string fmt(const glm::dvec3& v, int precision = 3);

// ---- calling student code ----------------------------------------------------------------------------------------

//! What went wrong while a demo called student code: functions not written yet (in the order met, no
//! duplicates) and errors (messages of other exceptions, no duplicates).
struct Issues {
    std::vector<std::string> missing, errors;
    bool any() const { return !missing.empty() || !errors.empty(); }
    //! Records a missing function (once).
    void add_missing(const std::string& function);
    //! Records an error message (once).
    void add_error(const std::string& message);
    //! Adds the other's missing functions and errors (no duplicates).
    void add(const Issues& other);
    //! "not implemented yet: f, g | f threw: ... | ..."; empty when nothing went wrong.
    std::string str() const;
};

//! The function a geolab::NotImplemented names: "not implemented: NAME (...)" → NAME (stubs pass __func__, so a
//! member function shows as its bare name). The whole message when it has another form.
std::string not_implemented_name(const std::string& what);

//! Runs f(). On geolab::NotImplemented records `step` as missing (or, with `name_missing`, what it returns for
//! the exception's message and `step`); on std::bad_alloc records memory_limit_message(step); on another
//! exception records "STEP threw: MESSAGE". \return true when f() returned normally.
template <class F>
bool attempt(Issues& issues, const std::string& step, F&& f,
             const std::function<std::string(const std::string& what, const std::string& step)>& name_missing = {}) {
    try {
        f();
        return true;
    } catch (const geolab::NotImplemented& e) {
        issues.add_missing(name_missing ? name_missing(e.what(), step) : step);
    } catch (const std::bad_alloc&) {
        issues.errors.push_back(memory_limit_message(step));
    } catch (const std::exception& e) {
        issues.errors.push_back(step + " threw: " + e.what());
    }
    return false;
}

// ---- drawing -------------------------------------------------------------------------------------------------------

//! Line segments with one colour each, collected before they go into a Scene (one Scene::add_lines per width).
struct Segments {
    std::vector<glm::vec3> endpoints;  //!< a0, b0, a1, b1, ...
    std::vector<glm::vec3> colors;     //!< one per segment
    void add(const glm::dvec3& a, const glm::dvec3& b, glm::vec3 color);
    bool empty() const { return colors.empty(); }
    //! Scene::add_lines(endpoints, colors, width) when not empty.
    void draw(Scene& scene, float width) const;
};

//! How add_arrow draws: the shaft is a→b shortened by `shrink` × |b − a| at both ends; the head is `head` × the
//! shaft long (0: no head) and 0.45 × that wide on each side; a harpoon (`one_sided`) has one barb, 1.6 × as wide.
struct ArrowStyle {
    double shrink = 0.12;
    double head = 0.22;
    bool one_sided = false;
};

//! The arrow a→b with its barbs along ±side (a unit vector ⟂ b − a, e.g. side_towards(a, b, c)): three
//! segments (or two for a harpoon, one without head), all in `color`.
void add_arrow(Segments& seg, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& side, glm::vec3 color,
               const ArrowStyle& style = {});
//! The normal n at p as an arrow of `length` (no shrink, head 0.25). Nothing when |n| ≤ 0.5 (a zero normal of a
//! degenerate element, or not a unit vector).
void add_normal(Segments& seg, const glm::dvec3& p, const glm::dvec3& n, double length, glm::vec3 color);
//! A unit vector in the plane of the triangle (a, b, c), orthogonal to b − a, on c's side; (0, 0, 1) when c is on
//! the line ab. \pre a ≠ b.
glm::dvec3 side_towards(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);
//! The 12 edges of the axis-aligned box [a, b] as endpoint pairs.
void add_box_edges(std::vector<glm::vec3>& endpoints, const glm::dvec3& a, const glm::dvec3& b);

//! The faces of `soup` whose centroid c satisfies keep(c), e.g. one side of a clipping plane (positions are all
//! kept, so indices stay valid; unreferenced ones are not drawn).
template <class Keep>
PolygonSoup keep_faces(const PolygonSoup& soup, Keep keep) {
    PolygonSoup out;
    out.positions = soup.positions;
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        glm::dvec3 c(0.0);
        for (auto i : soup.face(f)) c += soup.positions[i];
        if (keep(c / double(soup.face(f).size()))) out.add_face(soup.face(f));
    }
    return out;
}
//! The undirected edges used by exactly one face (holes, cuts), as endpoint pairs, ordered by vertex indices.
std::vector<glm::vec3> boundary_edges(const PolygonSoup& soup);
//! Colour number i of a 9-colour categorical palette (red, blue, green, orange, purple, teal, brown, pink, grey),
//! cycling: boundary loops, regions, components.
glm::vec3 category_color(std::size_t i);

// ---- cameras -------------------------------------------------------------------------------------------------------

//! The cube of half side r around c.
Box box_around(const glm::dvec3& c, double r);
//! Yaw and pitch (degrees) of the orbit camera whose eye lies in direction `eye_dir` from its target, for the world
//! up axis `up`; the pitch is kept within ±85° (the orbit camera degenerates looking straight along up).
void orbit_angles(const glm::dvec3& eye_dir, const glm::dvec3& up, float& yaw_deg, float& pitch_deg);
//! Camera::framing(box) seen from direction `eye_dir` (from the box towards the eye) with world up `up`.
Camera camera_from(const Box& box, const glm::dvec3& eye_dir, const glm::dvec3& up = {0, 1, 0});
//! `cam` (its angles, up and field of view kept) moved so that every point of `scene` just fits a width : height =
//! `aspect` image, centred, with a 6% margin: tighter than Camera::framing, which fits the bounding box's corners.
//! An empty scene returns `cam` unchanged.
Camera fit(Camera cam, const Scene& scene, double aspect);
//! The whole scene seen from (yaw, pitch), y up, fitted tightly: fit(Camera::framing(bounds, yaw, pitch), ...).
Camera whole(const Scene& scene, double aspect, float yaw_deg = 30.0f, float pitch_deg = 20.0f);
//! `cam` looking at `center` from the distance at which a ball of radius `radius` around it spans the field of
//! view (the shorter image side); angles and up kept.
Camera close_up(Camera cam, const glm::dvec3& center, double radius);

// ---- frames ------------------------------------------------------------------------------------------------------

//! One picture of a demo: what to draw, from where, and the status line saying what it shows (and what student
//! code is missing). A demo's draw function returns one; the window, --png and the figures all use it.
struct Frame {
    Scene scene;
    Camera camera;
    std::string status;
};

// ---- widgets: text, sliders, drags ---------------------------------------------------------------------------------

//! `utf8` with the characters the overlay font lacks spelled in ASCII: Greek letters by their Latin look-alikes or
//! names (ε → e, θ → th, π → pi), sub- and superscript digits as digits (ε₁ → e1, ³ → ^3), − – — → -, × → x,
//! · → *, ≤ ≥ → <= >=, ∪ ∩ → U n, ° → deg, accented Latin letters without their accent; any other non-ASCII
//! character → '?'. Control characters other than '\n' → ' '.
std::string ascii_text(const std::string& utf8);
//! The size in pixels of `text` (lines split at '\n') in the overlay font (stb_easy_font: capitals 7 units high,
//! lines 12 apart) scaled by `scale`.
glm::vec2 text_size(const std::string& text, float scale = 2.0f);
//! Adds `text` (through ascii_text) to the scene's overlay with its top-left corner at `at` (pixels), each glyph
//! stroke a rectangle scaled by `scale`.
void add_text(Scene& scene, glm::vec2 at, const std::string& text, float scale, glm::vec4 color);

//! A slider over one number of a demo's state: drawn over the picture at the window's top left (label, track,
//! knob, value), dragged with the mouse (press on its row, move, release), and set by scripted input
//! ("{label=value}" in --keys) and tests through the same mouse path. The value lives in the demo: get reads it,
//! set writes it (the window then redraws the demo's frame).
struct Slider {
    std::string label;  //!< shown left of the track (ASCII spelling, see ascii_text); names it in scripts
    double min = 0.0;   //!< the range [min, max]; min < max, and 0 < min on a log scale
    double max = 1.0;
    double step = 0.0;  //!< values are multiples of step (0: any value; 1: integers)
    bool log = false;   //!< positions along the track are logarithmic in the value (e.g. a resolution)
    std::function<double()> get;
    std::function<void(double)> set;
    //! How the value is shown (default: fmt(value, 3)); e.g. a kernel's name for a choice.
    std::function<std::string(double)> format;
    bool live = true;      //!< redraw the demo while dragging (false: only on release, for slow frames)
    bool reframe = false;  //!< a change moves the camera to the new frame's (as a key returning true)

    //! value clamped to [min, max] and rounded to a multiple of step (staying inside the range).
    double snap(double value) const;
    //! Where `value` sits along the track: 0 at min, 1 at max (logarithmic with `log`).
    double fraction(double value) const;
    //! The value at a position along the track (clamped to [0, 1]), snapped.
    double value_at(double fraction) const;
    //! format(get()), or fmt(get()) without a format.
    std::string value_text() const;
};

//! A slider on `value` (which must outlive the window): range [min, max], multiples of step (0: continuous).
Slider slider(std::string label, double& value, double min, double max, double step = 0.0, bool log = false);
//! A slider on an integer of the demo's state, min ≤ value ≤ max.
Slider slider(std::string label, int& value, int min, int max, bool log = false);
//! A slider choosing one of `names` (index into them, shown by name), e.g. a kernel.
Slider choice(std::string label, int& index, std::vector<std::string> names);

//! Where slider i of `sliders` is drawn (pixels, top-left origin): its row (label, track, value) and its track,
//! along which the value runs from track_lo.x (min) to track_hi.x (max). The rows stack from (10, 10), 26 pixels
//! apart, all with the label column the widest label needs.
struct SliderRect {
    glm::vec2 row_lo, row_hi, track_lo, track_hi;
    bool contains(double x, double y) const { return x >= row_lo.x && x <= row_hi.x && y >= row_lo.y && y <= row_hi.y; }
    //! True where a press takes the slider: over the track (8 pixels beyond its ends) within the row's height.
    //! A press on the label or the value goes through to the picture (a control point there, or the camera).
    bool grabs(double x, double y) const {
        return x >= track_lo.x - 8.0 && x <= track_hi.x + 8.0 && y >= row_lo.y && y <= row_hi.y;
    }
};
SliderRect slider_rect(const std::vector<Slider>& sliders, std::size_t i);
//! Adds the sliders to the scene's overlay: a translucent panel, each label, track, knob and value; slider
//! `active` (being dragged) highlighted.
void add_sliders(Scene& scene, const std::vector<Slider>& sliders, int active = -1);
//! Adds a status line to the overlay along the bottom of a width × height picture: wrapped at spaces to the
//! width, at most 4 lines (the rest cut with "..."), on a translucent band.
void add_status(Scene& scene, const std::string& status, int width, int height);

//! A mouse drag handed to a demo (DemoProgram::Window::drag): its press, its moves and its release, with the ray
//! under the cursor and the camera and image it was seen in.
struct Drag {
    MouseEvent::Phase phase = MouseEvent::Phase::press;
    glm::dvec2 cursor{0.0};  //!< pixels, (0, 0) the top-left corner
    int width = 1, height = 1;
    Camera camera;
    Ray ray;  //!< camera.ray through the cursor

    //! The index of the point of `points` that appears nearest to the cursor, if it is within `radius` pixels
    //! and in front of the eye (ties: the nearer to the eye); nullopt otherwise. For picking control points.
    std::optional<std::size_t> nearest(const std::vector<glm::dvec3>& points, double radius = 14.0) const;
    //! Where the ray meets the plane through `p` facing the camera (orthogonal to its viewing direction): a point
    //! moved there follows the cursor at its own depth ("dragged in the view plane").
    glm::dvec3 on_view_plane(const glm::dvec3& p) const;
    //! Where the ray meets the plane through `p` with normal `n` (e.g. z = 0 for a planar curve), if it does in
    //! front of the eye and not at a grazing angle (|cos| ≥ 1e-3); nullopt otherwise.
    std::optional<glm::dvec3> on_plane(const glm::dvec3& p, const glm::dvec3& n) const;
};

// ---- figures -------------------------------------------------------------------------------------------------------

//! Images side by side, top-aligned, on white, separated by `gap` columns of grey (200). \pre no image is empty.
Image hstack(const std::vector<Image>& images, int gap = 0);

//! The first of `names` that is a fetched model (geolab::model_path), else nullopt.
std::optional<std::string> first_model(std::initializer_list<const char*> names);

//! Writes a demo's figures into one folder and reports each on stdout ("wrote PATH  (WHAT)" or
//! "skipped PATH: WHY"); finish() prints how many and how long.
class FigureWriter {
public:
    //! Creates `dir`. \throw std::filesystem::filesystem_error when it cannot.
    FigureWriter(std::filesystem::path dir, int width, int height);
    //! Renders the scene into dir/file at the default size (or w × h when given).
    void write(const std::string& file, const Scene& scene, const Camera& camera, const std::string& what, int w = 0,
               int h = 0);
    //! write(file, frame.scene, frame.camera, frame.status).
    void write(const std::string& file, const Frame& frame) { write(file, frame.scene, frame.camera, frame.status); }
    //! Writes an image composed by the demo (e.g. hstack of panels).
    void write(const std::string& file, const Image& image, const std::string& what);
    //! Reports a figure that cannot be made here (a model not fetched, a function not written yet).
    void skip(const std::string& file, const std::string& why);
    //! Prints "N figures in DIR (T s)" and returns 0 (a demo's exit status).
    int finish() const;

    const std::filesystem::path& dir() const { return dir_; }
    int width() const { return width_; }
    int height() const { return height_; }
    double aspect() const { return static_cast<double>(width_) / height_; }
    int written() const { return written_; }
    int skipped() const { return skipped_; }

private:
    std::filesystem::path dir_;
    int width_, height_, written_ = 0, skipped_ = 0;
    std::chrono::steady_clock::time_point start_;
};

// ---- the program ---------------------------------------------------------------------------------------------------

//! One step of scripted input (the hidden --keys option; parse_script).
struct ScriptStep {
    enum class Kind { key, screenshot, slider, drag, click };
    Kind kind = Kind::key;
    int key = 0;         //!< key: the key code sent (letters upper case, '_' → Space ' ')
    std::string label;   //!< slider: the slider's label (or its ascii_text)
    double value = 0.0;  //!< slider: the value to drag it to
    //! drag: from, to; click: at. Each point is 2 numbers, a place in the window as fractions of its width and
    //! height ((0, 0) the top-left corner), or 3, a world point seen through the current camera.
    std::vector<double> from, to;
};
//! Parses scripted input: each character is a key press ('_' is Space; S saves a screenshot into
//! out/screenshots/ as the window's S key does), except for commands in braces:
//!   {LABEL=VALUE}       drag slider LABEL to VALUE (as the mouse does: press on the track, release)
//!   {drag A B}          a left-button drag from A to B: a slider, the demo's drag (a control point) or an orbit
//!   {click A}           a left click at A (the demo's pick)
//! where a point A is "x,y" (fractions of the window) or "x,y,z" (a world point). E.g. "N{a=-0.5}{drag
//! -2,2.5,0 0,4,0}S". \throw std::invalid_argument naming the command and what is wrong with it.
std::vector<ScriptStep> parse_script(const std::string& keys);

//! A demo's command line and run. The demo adds its own options to cli() before parse(); the shared ones are:
//!   --png FILE       render the current view into FILE instead of opening a window
//!   --widgets        with --png: draw the sliders and the status line into it, as the window shows them
//!   --figures DIR    render the handout's figures into DIR (check_figure_dir refuses docs/ in a student release)
//!   --size W         PNG width, height = 3/4 of it (default: the constructor's)
//!   --memory-mb N    cap on the address space (default: the grader's, default_demo_memory_mb())
//!   --frames N, --screenshot FILE, --keys KEYS   (hidden, for tests) draw N frames after the scripted input
//!                    KEYS (parse_script), save the window; with --png (no --frames), KEYS is applied headless
//!                    before the PNG is written (show() only)
//! `--help` lists all options with `window_keys` as footer.
class DemoProgram {
public:
    //! `program`: the name errors start with (demo_01_halfedge); `description`: --help's first line;
    //! `window_keys`: "Window keys:\n  ..." printed in --help and when the window opens.
    DemoProgram(std::string program, std::string description, std::string window_keys, int default_width = 800);

    //! The parser, for the lab's own options (positional input, --level, ...).
    CLI::App& cli() { return app_; }

    //! Parses the command line and caps the memory. \return an exit status when the program must stop now
    //! (--help: 0 after printing it; a bad option: its message on stderr and a non-zero status), else nullopt.
    std::optional<int> parse(int argc, char** argv);

    const std::string& png() const { return png_; }
    const std::string& figures() const { return figures_; }
    int width() const { return width_; }
    int height() const { return width_ * 3 / 4; }
    double aspect() const { return static_cast<double>(width()) / height(); }
    const std::string& program() const { return program_; }
    const std::string& window_keys() const { return keys_help_; }
    //! Printed after "PROGRAM: <why no window>" when no window can be opened (e.g. which --png to try).
    std::string no_display_hint;

    //! Runs body() and turns what escapes it into one line on stderr and status 1: NoDisplay (plus
    //! no_display_hint), std::bad_alloc (memory_limit_message("the demo")), other std::exception. A body that
    //! returns 0 after a step ran out of memory (attempt() reported it and drew the rest) also ends with 1.
    //! With --figures, check_figure_dir(figures()) runs first.
    int run(const std::function<int()>& body);

    //! Renders `scene` into --png's file at --size and prints "STATUS\nwrote FILE". \return 0; or, when a step of
    //! run()'s body ran out of memory, prints STATUS, draws nothing (the renderer needs memory of its own) and returns 1.
    int write_png(const Scene& scene, const Camera& camera, const std::string& status) const;
    int write_png(const Frame& frame) const { return write_png(frame.scene, frame.camera, frame.status); }
    //! A FigureWriter into --figures' folder at --size.
    FigureWriter figure_writer() const { return FigureWriter(figures_, width(), height()); }

    //! What a demo shows in its window.
    struct Window {
        std::string title;                      //!< e.g. "geolab demo 01: half-edge meshes"
        std::function<Frame()> draw;            //!< the demo's current state as a frame
        std::function<bool(int key)> key;       //!< applies a key (see run_window); true: go to the frame's camera
        std::function<bool(const Ray&)> pick;   //!< optional: a click; true: go to the frame's camera
        std::function<std::string()> key_hint;  //!< optional: a short key reminder appended to the status
        //! Optional: the sliders shown now, asked again after every change (so they may follow the demo's mode).
        std::function<std::vector<Slider>()> sliders;
        //! Optional: mouse drags that do not start on a slider. At the press, true takes the drag (e.g. a control
        //! point is under the cursor: Drag::nearest), so the camera does not orbit and no pick is made; false
        //! leaves it to the camera. Then each move and the release: true goes to the frame's camera.
        std::function<bool(const Drag&)> drag;
        //! Optional: called before each frame with the seconds since the window opened; true: the demo's state
        //! changed (the window redraws it and keeps drawing continuously), false: nothing moves (the window
        //! waits for input). Not called headless (--png), nor by the scripted --frames before they are drawn.
        std::function<bool(double seconds)> animate;
    };
    //! Opens a 960 × 720 window (shrunk to fit the screen), shows draw() with its camera, its sliders and its
    //! status (in the title bar and along the window's bottom; printed on stdout after each key, click and
    //! drag), and redraws after every key, pick, slider move or drag, moving the camera only when they return
    //! true (the mouse orbits otherwise; Home returns to the framing of the first frame). Runs as run_window.
    //! With --png it opens nothing: applies --keys headless (DemoSession), renders the view (with --widgets:
    //! and its sliders and status) into the PNG and prints its status.
    //! \throw NoDisplay when no window can be opened. \return 0.
    int show(const Window& window) const;

    //! The window loop behind show(), for a demo that drives its Viewer itself: prints the window keys, sends
    //! each key press to `press` (letters upper case, Space ' '; see Viewer::on_key), and runs until the window
    //! closes. With --frames N it is scripted instead: presses --keys one by one (S: saves a screenshot like
    //! the window's S key; commands in braces are refused: they need show()), draws N frames, saves
    //! --screenshot if given, and returns. The demo sets the first scene, the pick callback and the status
    //! itself. \return 0.
    int run_window(Viewer& viewer, const std::function<void(int key)>& press) const;

private:
    // Runs the window until closed, or the script then --frames frames. `step` applies one scripted step other
    // than a screenshot (the window's S).
    int loop(Viewer& viewer, const std::function<void(int key)>& press,
             const std::function<void(const ScriptStep&)>& step) const;
    int write_headless(const Window& window) const;
    std::string program_, keys_help_;
    std::size_t memory_reports_at_start_ = 0;  //!< memory_limit_reports() when run() started
    CLI::App app_;
    std::string png_, figures_, screenshot_, keys_;
    int width_, frames_ = 0;
    bool widgets_ = false;
    std::size_t memory_mb_;
};

//! A demo's window without the GL window: the demo's current frame, its sliders and the overlay they make, the
//! camera, and what keys and mouse events do to them. DemoProgram::show feeds it from the GLFW window; with
//! --png it runs the scripted --keys headless; tests drive it directly.
class DemoSession {
public:
    //! Draws the first frame for a width × height view (screen units) and takes its camera.
    DemoSession(DemoProgram::Window window, int width, int height);

    //! The demo's latest frame (its camera: the one the demo asked for).
    const Frame& frame() const { return frame_; }
    //! Moves the latest frame's scene out (the window uploads it; frame().scene is empty until the next redraw),
    //! so that a large scene is not held twice.
    Scene take_scene();
    //! The sliders shown now (Window::sliders at the last redraw).
    const std::vector<Slider>& sliders() const { return sliders_; }
    //! The frame's status with the window's key hint.
    std::string status() const;
    //! What the window draws over the frame: the sliders (the one being dragged highlighted) and, with
    //! `status`, the status line along the bottom.
    std::vector<Scene::Rect> overlay(bool status = true) const;

    Camera camera;      //!< the view: the frame's after a change that asks for it, else moved by the mouse
    int width, height;  //!< the view's size (the window's, in screen units)
    //! Change counters: the frame (a redraw of the demo), the overlay (slider values shown) and the camera
    //! (asked for by the demo, or moved by a scripted drag). The window uploads what changed.
    int frame_version() const { return frame_version_; }
    int overlay_version() const { return overlay_version_; }
    int camera_version() const { return camera_version_; }
    //! Where status lines go after each key, click and drag (nullptr: nowhere).
    std::ostream* log = nullptr;

    //! A key press, as the window sends them (Viewer::on_key): to the demo, then a redraw.
    void key(int key);
    //! A click without drag: the ray under the cursor to the demo's pick, then a redraw.
    void pick(const Ray& ray);
    //! pick(camera.ray(x, y, width, height)).
    void click(double x, double y);
    //! Redraws the demo's frame now (e.g. after an animation step changed its state); with `reframe`, the
    //! camera goes to the new frame's.
    void refresh(bool reframe = false);
    //! A mouse event (the window's on_mouse). A press on a slider's track (SliderRect::grabs) captures the drag
    //! and sets the value under the cursor, and so does every move; elsewhere the demo's drag decides. Moves of a live
    //! slider or of the demo's drag mark the frame for a redraw at the next flush(); the release redraws.
    //! \return at a press: true when captured (the window then does not orbit).
    bool mouse(const MouseEvent& e);
    //! Redraws the demo's frame if a move asked for it (the window calls it before drawing, so a burst of moves
    //! costs one redraw).
    void flush();
    //! Sets the slider called `label` (its label or its ascii_text) to `value` as the mouse does: a press on
    //! its track where the value sits, and a release. \throw std::invalid_argument naming the label and the
    //! sliders there are, when none matches.
    void set_slider(const std::string& label, double value);
    //! A left-button drag from pixel a to pixel b in `steps` moves: taken by a slider or the demo's drag, else
    //! it orbits the camera as the window's mouse does.
    void drag(glm::dvec2 a, glm::dvec2 b, int steps = 8);
    //! Applies one scripted step (parse_script) other than a screenshot. \throw std::invalid_argument when a
    //! world point is behind the camera or a slider does not exist.
    void run(const ScriptStep& step);
    //! The pixel of a script's point (2 numbers: fractions of the view; 3: a world point through the camera).
    glm::dvec2 pixel_of(const std::vector<double>& point) const;

private:
    void report() const;
    Drag drag_event(MouseEvent::Phase phase, double x, double y) const;
    DemoProgram::Window window_;
    Frame frame_;
    std::vector<Slider> sliders_;
    int active_ = -1;         // the slider being dragged
    bool demo_drag_ = false;  // the demo took the drag in progress
    bool pending_ = false, pending_reframe_ = false;
    int frame_version_ = 0, overlay_version_ = 0, camera_version_ = 0;
};

}  // namespace geolab::render
