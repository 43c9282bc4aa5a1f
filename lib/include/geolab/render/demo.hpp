#pragma once
//! \file render/demo.hpp
//! The machinery every lab demo shares, so that a lab's demo.cpp holds only the lab's content (its state, what
//! it draws, its keys and its figures). docs/demo-framework.md shows a whole demo written on it.
//!
//! - DemoProgram: the command line every demo has (--png, --figures, --size, --memory-mb and the hidden testing
//!   options --frames, --screenshot, --keys), the memory cap, the figure folder check, clear one-line errors, and
//!   the window (show: a 960 × 720 window drawn from the demo's Frame, its keys, picking, scripted keys).
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
#include <new>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <glm/vec3.hpp>

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

// ---- frames and figures ----

//! One picture of a demo: what to draw, from where, and the status line saying what it shows (and what student
//! code is missing). A demo's draw function returns one; the window, --png and the figures all use it.
struct Frame {
    Scene scene;
    Camera camera;
    std::string status;
};

// -------------------------------------------------------------------------------------------------------

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

//! A demo's command line and run. The demo adds its own options to cli() before parse(); the shared ones are:
//!   --png FILE       render the current view into FILE instead of opening a window
//!   --figures DIR    render the handout's figures into DIR (check_figure_dir refuses docs/ in a student release)
//!   --size W         PNG width, height = 3/4 of it (default: the constructor's)
//!   --memory-mb N    cap on the address space (default: the grader's, default_demo_memory_mb())
//!   --frames N, --screenshot FILE, --keys KEYS   (hidden, for tests) draw N frames after pressing KEYS, save
//!                    the window; in KEYS '_' is Space and S saves a screenshot into out/screenshots/ as the S key
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
    //! no_display_hint), std::bad_alloc (memory_limit_message("the demo")), other std::exception.
    //! With --figures, check_figure_dir(figures()) runs first.
    int run(const std::function<int()>& body);

    //! Renders `scene` into --png's file at --size and prints "STATUS\nwrote FILE". \return 0.
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
    };
    //! Opens a 960 × 720 window (shrunk to fit the screen), shows draw() with its camera, prints and shows its
    //! status, and redraws after every key or pick, moving the camera only when they return true (the mouse
    //! orbits otherwise; Home returns to the framing of the first frame). Runs as run_window.
    //! \throw NoDisplay when no window can be opened. \return 0.
    int show(const Window& window) const;

    //! The window loop behind show(), for a demo that drives its Viewer itself: prints the window keys, sends each key press to `press` (letters upper case, Space ' ';
    //! see Viewer::on_key), and runs until the window closes. With --frames N it is scripted instead: presses
    //! --keys one by one (S: saves a screenshot like the window's S key), draws N frames, saves --screenshot
    //! if given, and returns. The demo sets the first scene, the pick callback and the status itself.
    //! \return 0.
    int run_window(Viewer& viewer, const std::function<void(int key)>& press) const;

private:
    int loop(Viewer& viewer, const std::function<void(int key)>& press) const;
    std::string program_, keys_help_;
    CLI::App app_;
    std::string png_, figures_, screenshot_, keys_;
    int width_, frames_ = 0;
    std::size_t memory_mb_;
};

}  // namespace geolab::render
