// The shared machinery of the lab demos (see geolab/render/demo.hpp).
#include "geolab/render/demo.hpp"

#include <stb/stb_easy_font.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <iostream>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>
#include <utility>

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

// ---- widgets: text ---------------------------------------------------------------------------------------------

namespace {

// The ASCII spelling of one code point (see ascii_text).
std::string ascii_of(char32_t c) {
    static const std::map<char32_t, const char*> table = {
        {U'α', "a"},  {U'β', "b"},    {U'γ', "g"},   {U'δ', "d"},   {U'ε', "e"},     {U'ζ', "z"},   {U'η', "eta"},
        {U'θ', "th"}, {U'κ', "k"},    {U'λ', "l"},   {U'μ', "mu"},  {U'ν', "nu"},    {U'ξ', "xi"},  {U'π', "pi"},
        {U'ρ', "r"},  {U'σ', "s"},    {U'τ', "t"},   {U'φ', "phi"}, {U'χ', "chi"},   {U'ψ', "psi"}, {U'ω', "w"},
        {U'Δ', "D"},  {U'Σ', "S"},    {U'Φ', "Phi"}, {U'Ω', "W"},   {U'−', "-"},     {U'–', "-"},   {U'—', "-"},
        {U'×', "x"},  {U'·', "*"},    {U'÷', "/"},   {U'≤', "<="},  {U'≥', ">="},    {U'≈', "~"},   {U'∪', "U"},
        {U'∩', "n"},  {U'°', "deg"},  {U'′', "'"},   {U'…', "..."}, {U'→', "->"},    {U'←', "<-"},  {U'∞', "inf"},
        {U'±', "+-"}, {U'√', "sqrt"}, {U'²', "^2"},  {U'³', "^3"},  {U'¹', "^1"},    {U'ⁿ', "^n"},  {U'é', "e"},
        {U'è', "e"},  {U'ë', "e"},    {U'á', "a"},   {U'à', "a"},   {U'ä', "a"},     {U'ö', "o"},   {U'ü', "u"},
        {U'ç', "c"},  {U'É', "E"},    {U'ñ', "n"},   {U'ß', "ss"},  {U'\u00a0', " "}};
    if (c >= U'₀' && c <= U'₉') return std::string(1, char('0' + (c - U'₀')));
    if (c >= U'⁴' && c <= U'⁹') return "^" + std::string(1, char('0' + (c - U'⁰')));
    if (c == U'⁰') return "^0";
    const auto it = table.find(c);
    return it != table.end() ? it->second : "?";
}

// Decodes one UTF-8 sequence at s[i] (advancing i); U+FFFD for a malformed one (one byte consumed).
char32_t next_code_point(const std::string& s, std::size_t& i) {
    const auto b = static_cast<unsigned char>(s[i]);
    const int n = b < 0x80 ? 1 : (b >> 5) == 6 ? 2 : (b >> 4) == 14 ? 3 : (b >> 3) == 30 ? 4 : 0;
    if (n == 0 || i + n > s.size()) return ++i, U'\ufffd';
    char32_t c = n == 1 ? b : b & (0x7f >> n);
    for (int k = 1; k < n; ++k) {
        const auto cont = static_cast<unsigned char>(s[i + k]);
        if ((cont >> 6) != 2) return ++i, U'\ufffd';
        c = (c << 6) | (cont & 0x3f);
    }
    i += n;
    return c;
}

// The glyph quads of ASCII text at (0, 0), unscaled: x0, y0, x1, y1 each.
std::vector<std::array<float, 4>> glyph_quads(const std::string& ascii) {
    std::vector<char> buffer(ascii.size() * 1024 + 64);  // 64 bytes a quad (stroke), at most 16 strokes a glyph
    std::string text = ascii;
    const int quads = stb_easy_font_print(0, 0, text.data(), nullptr, buffer.data(), int(buffer.size()));
    std::vector<std::array<float, 4>> out(std::size_t(std::max(quads, 0)));
    for (std::size_t q = 0; q < out.size(); ++q) {
        float v[16];
        std::memcpy(v, buffer.data() + q * 64, sizeof v);  // 4 vertices of x, y, z, rgba (16 bytes each)
        out[q] = {v[0], v[1], v[8], v[9]};                 // corners 0 and 2 are opposite
    }
    return out;
}

}  // namespace

std::string ascii_text(const std::string& utf8) {
    std::string out;
    for (std::size_t i = 0; i < utf8.size();) {
        const char32_t c = next_code_point(utf8, i);
        if (c == U'\n')
            out += '\n';
        else if (c < 32 || c == 127)
            out += ' ';
        else if (c < 127)
            out += char(c);
        else
            out += ascii_of(c);
    }
    return out;
}

glm::vec2 text_size(const std::string& text, float scale) {
    std::string ascii = ascii_text(text);
    const int lines = 1 + int(std::count(ascii.begin(), ascii.end(), '\n'));
    return {float(stb_easy_font_width(ascii.data())) * scale, float(12 * lines - 4) * scale};
}

void add_text(Scene& scene, glm::vec2 at, const std::string& text, float scale, glm::vec4 color) {
    for (const auto& q : glyph_quads(ascii_text(text)))
        scene.add_rect(at + scale * glm::vec2(q[0], q[1]), at + scale * glm::vec2(q[2], q[3]), color);
}

// ---- widgets: sliders --------------------------------------------------------------------------------------------

double Slider::snap(double value) const {
    double v = std::clamp(value, min, max);
    if (step > 0) {
        v = min + std::round((v - min) / step) * step;
        if (v > max + 1e-12 * std::abs(max)) v -= step;
        // a decimal step gives decimal values: -2 + 150 · 0.01 is 0.5 (not 0.49999999999999956), and 0 is 0
        for (double scale = 1.0; scale <= 1e9; scale *= 10.0) {
            const double s = step * scale, m = min * scale;
            if (std::abs(s - std::round(s)) < 1e-9 * s &&
                std::abs(m - std::round(m)) < 1e-9 * std::max(1.0, std::abs(m))) {
                v = std::round(v * scale) / scale;
                break;
            }
        }
        v = std::clamp(v, min, max);
    }
    return v;
}

double Slider::fraction(double value) const {
    const double v = std::clamp(value, min, max);
    if (log) return (std::log(v) - std::log(min)) / (std::log(max) - std::log(min));
    return (v - min) / (max - min);
}

double Slider::value_at(double f) const {
    f = std::clamp(f, 0.0, 1.0);
    const double v = log ? std::exp(std::log(min) + f * (std::log(max) - std::log(min))) : min + f * (max - min);
    return snap(v);
}

std::string Slider::value_text() const {
    const double v = get ? get() : 0.0;
    return format ? format(v) : fmt(v, 3);
}

Slider slider(std::string label, double& value, double min, double max, double step, bool log) {
    Slider s;
    s.label = std::move(label), s.min = min, s.max = max, s.step = step, s.log = log;
    s.get = [&value] { return value; };
    s.set = [&value](double v) { value = v; };
    return s;
}

Slider slider(std::string label, int& value, int min, int max, bool log) {
    Slider s;
    s.label = std::move(label), s.min = double(min), s.max = double(max), s.step = 1.0, s.log = log;
    s.get = [&value] { return double(value); };
    s.set = [&value](double v) { value = int(std::lround(v)); };
    return s;
}

Slider choice(std::string label, int& index, std::vector<std::string> names) {
    Slider s = slider(std::move(label), index, 0, std::max(0, int(names.size()) - 1));
    s.format = [names = std::move(names)](double v) {
        if (names.empty()) return std::string();
        return names[std::size_t(std::clamp(std::lround(v), 0L, long(names.size()) - 1))];
    };
    return s;
}

namespace {
constexpr float kTextScale = 2.0f;                 // overlay text: stb_easy_font doubled (14-pixel capitals)
constexpr float kPanelX = 10.0f, kPanelY = 10.0f;  // the slider panel's top-left corner
constexpr float kRowHeight = 26.0f, kTrackWidth = 220.0f, kValueWidth = 150.0f, kPad = 8.0f;
const glm::vec4 kPanel{1.0f, 1.0f, 1.0f, 0.78f}, kInk{0.08f, 0.08f, 0.12f, 1.0f}, kTrack{0.55f, 0.56f, 0.62f, 1.0f},
    kKnob{0.15f, 0.35f, 0.85f, 1.0f}, kActive{0.90f, 0.35f, 0.05f, 1.0f};

float label_column(const std::vector<Slider>& sliders) {
    float w = 0.0f;
    for (const Slider& s : sliders) w = std::max(w, text_size(s.label, kTextScale).x);
    return w + 2.0f * kPad;  // (the knob reaches 5 pixels before the track)
}
}  // namespace

SliderRect slider_rect(const std::vector<Slider>& sliders, std::size_t i) {
    const float y0 = kPanelY + kRowHeight * float(i), label = label_column(sliders);
    SliderRect r;
    r.row_lo = {kPanelX, y0};
    r.row_hi = {kPanelX + kPad + label + kTrackWidth + 2.0f * kPad + kValueWidth, y0 + kRowHeight};
    r.track_lo = {kPanelX + kPad + label, y0 + kRowHeight * 0.5f - 2.0f};
    r.track_hi = {r.track_lo.x + kTrackWidth, y0 + kRowHeight * 0.5f + 2.0f};
    return r;
}

void add_sliders(Scene& scene, const std::vector<Slider>& sliders, int active) {
    if (sliders.empty()) return;
    const SliderRect first = slider_rect(sliders, 0), last = slider_rect(sliders, sliders.size() - 1);
    scene.add_rect(first.row_lo - glm::vec2(4.0f), last.row_hi + glm::vec2(4.0f), kPanel);
    const float text_h = text_size("X", kTextScale).y;
    for (std::size_t i = 0; i < sliders.size(); ++i) {
        const Slider& s = sliders[i];
        const SliderRect r = slider_rect(sliders, i);
        const float mid = 0.5f * (r.row_lo.y + r.row_hi.y), ty = mid - 0.5f * text_h;
        const glm::vec4 ink = int(i) == active ? kActive : kInk;
        add_text(scene, {r.row_lo.x + kPad, ty}, s.label, kTextScale, ink);
        scene.add_rect(r.track_lo, r.track_hi, kTrack);
        const double v = s.get ? s.get() : s.min;
        const float x = r.track_lo.x + float(s.fraction(v)) * (r.track_hi.x - r.track_lo.x);
        scene.add_rect({x - 5.0f, mid - 9.0f}, {x + 5.0f, mid + 9.0f}, int(i) == active ? kActive : kKnob);
        add_text(scene, {r.track_hi.x + 2.0f * kPad, ty}, s.value_text(), kTextScale, ink);
    }
}

void add_status(Scene& scene, const std::string& status, int width, int height) {
    if (status.empty()) return;
    // wrap at spaces to the width
    const float max_w = float(width) - 2.0f * kPad;
    std::vector<std::string> lines(1);
    std::istringstream words(ascii_text(status));
    for (std::string w; words >> w;) {
        const std::string longer = lines.back().empty() ? w : lines.back() + " " + w;
        if (!lines.back().empty() && text_size(longer, kTextScale).x > max_w)
            lines.push_back(w);
        else
            lines.back() = longer;
    }
    if (lines.size() > 4) {
        lines.resize(4);
        lines.back() += " ...";
    }
    const float line_h = 12.0f * kTextScale, top = float(height) - kPad - line_h * float(lines.size());
    scene.add_rect({0.0f, top - 4.0f}, {float(width), float(height)}, kPanel);
    for (std::size_t i = 0; i < lines.size(); ++i)
        add_text(scene, {kPad, top + line_h * float(i) + 2.0f}, lines[i], kTextScale, kInk);
}

// ---- widgets: drags ----------------------------------------------------------------------------------------------

std::optional<std::size_t> Drag::nearest(const std::vector<dvec3>& points, double radius) const {
    std::optional<std::size_t> best;
    double best_d = radius, best_z = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const dvec3 p = camera.pixel(points[i], width, height);
        if (!(p.z > 0.0)) continue;
        const double d = glm::length(glm::dvec2(p) - cursor);
        if (d < best_d || (best && d == best_d && p.z < best_z)) best = i, best_d = d, best_z = p.z;
    }
    return best;
}

dvec3 Drag::on_view_plane(const dvec3& p) const {
    const dvec3 forward = glm::normalize(dvec3(camera.target) - dvec3(camera.eye()));
    return on_plane(p, forward).value_or(p);
}

std::optional<dvec3> Drag::on_plane(const dvec3& p, const dvec3& n) const {
    const dvec3 o(ray.origin), d = glm::normalize(dvec3(ray.direction)), u = glm::normalize(n);
    const double cos = glm::dot(d, u);
    if (std::abs(cos) < 1e-3) return std::nullopt;
    const double t = glm::dot(p - o, u) / cos;
    if (!(t > 0.0)) return std::nullopt;
    return o + t * d;
}

// ---- scripted input ----------------------------------------------------------------------------------------------

namespace {

// "x,y" or "x,y,z" → its numbers; throws naming the command.
std::vector<double> parse_point(const std::string& text, const std::string& command) {
    std::vector<double> p;
    std::istringstream in(text);
    for (std::string part; std::getline(in, part, ',');) {
        try {
            std::size_t used = 0;
            p.push_back(std::stod(part, &used));
            if (used != part.size()) throw std::invalid_argument(part);
        } catch (const std::exception&) {
            throw std::invalid_argument("--keys: {" + command + "}: '" + part + "' is not a number");
        }
    }
    if (p.size() != 2 && p.size() != 3)
        throw std::invalid_argument("--keys: {" + command +
                                    "}: a point is x,y (fractions of the window) or x,y,z "
                                    "(a world point), not '" +
                                    text + "'");
    return p;
}

ScriptStep parse_command(const std::string& command) {
    ScriptStep step;
    std::istringstream in(command);
    std::string word;
    in >> word;
    if (word == "drag" || word == "click") {
        std::vector<std::string> args;
        for (std::string a; in >> a;) args.push_back(a);
        const std::size_t want = word == "drag" ? 2 : 1;
        if (args.size() != want)
            throw std::invalid_argument("--keys: {" + command + "}: " + word + " takes " +
                                        (want == 2 ? "two points (from, to)" : "one point"));
        step.kind = word == "drag" ? ScriptStep::Kind::drag : ScriptStep::Kind::click;
        step.from = parse_point(args[0], command);
        if (want == 2) step.to = parse_point(args[1], command);
        return step;
    }
    const auto eq = command.find('=');
    if (eq == std::string::npos || eq == 0)
        throw std::invalid_argument("--keys: {" + command +
                                    "}: not a command (expected {LABEL=VALUE}, {drag A B} or "
                                    "{click A})");
    step.kind = ScriptStep::Kind::slider;
    step.label = command.substr(0, eq);
    const std::string value = command.substr(eq + 1);
    try {
        std::size_t used = 0;
        step.value = std::stod(value, &used);
        if (used != value.size()) throw std::invalid_argument(value);
    } catch (const std::exception&) {
        throw std::invalid_argument("--keys: {" + command + "}: '" + value + "' is not a number");
    }
    return step;
}

}  // namespace

std::vector<ScriptStep> parse_script(const std::string& keys) {
    std::vector<ScriptStep> steps;
    for (std::size_t i = 0; i < keys.size(); ++i) {
        const char c = keys[i];
        if (c == '{') {
            const auto end = keys.find('}', i);
            if (end == std::string::npos)
                throw std::invalid_argument("--keys: '{' at " + std::to_string(i) + " has no matching '}'");
            steps.push_back(parse_command(keys.substr(i + 1, end - i - 1)));
            i = end;
        } else if (c == '}') {
            throw std::invalid_argument("--keys: '}' at " + std::to_string(i) + " closes nothing");
        } else {
            ScriptStep step;
            step.kind = c == 'S' || c == 's' ? ScriptStep::Kind::screenshot : ScriptStep::Kind::key;
            step.key = c == '_' ? ' ' : std::toupper(static_cast<unsigned char>(c));
            steps.push_back(step);
        }
    }
    return steps;
}

// ---- the session: a window's input without the window --------------------------------------------------------------

DemoSession::DemoSession(DemoProgram::Window window, int w, int h) : width(w), height(h), window_(std::move(window)) {
    refresh(true);
}

Scene DemoSession::take_scene() { return std::exchange(frame_.scene, Scene{}); }

std::string DemoSession::status() const { return frame_.status + (window_.key_hint ? window_.key_hint() : ""); }

std::vector<Scene::Rect> DemoSession::overlay(bool with_status) const {
    Scene s;
    add_sliders(s, sliders_, active_);
    if (with_status) add_status(s, frame_.status, width, height);
    return s.overlay();
}

void DemoSession::refresh(bool reframe) {
    frame_ = window_.draw();
    sliders_ = window_.sliders ? window_.sliders() : std::vector<Slider>{};
    if (active_ >= int(sliders_.size())) active_ = -1;
    if (reframe) {
        camera = frame_.camera;
        ++camera_version_;
    }
    ++frame_version_;
    ++overlay_version_;
    pending_ = pending_reframe_ = false;
}

void DemoSession::report() const {
    if (log) *log << frame_.status << std::endl;
}

void DemoSession::flush() {
    if (pending_) refresh(pending_reframe_);
}

void DemoSession::key(int key) {
    flush();
    refresh(window_.key && window_.key(key));
    report();
}

void DemoSession::pick(const Ray& ray) {
    flush();
    if (!window_.pick) return;
    refresh(window_.pick(ray));
    report();
}

void DemoSession::click(double x, double y) { pick(camera.ray(x, y, width, height)); }

Drag DemoSession::drag_event(MouseEvent::Phase phase, double x, double y) const {
    Drag d;
    d.phase = phase;
    d.cursor = {x, y};
    d.width = width, d.height = height;
    d.camera = camera;
    d.ray = camera.ray(x, y, width, height);
    return d;
}

bool DemoSession::mouse(const MouseEvent& e) {
    using P = MouseEvent::Phase;
    if (e.width > 0 && e.height > 0) width = e.width, height = e.height;
    // a slider's drag: the value follows the cursor along the track
    auto follow = [&] {
        const Slider& s = sliders_[std::size_t(active_)];
        const SliderRect r = slider_rect(sliders_, std::size_t(active_));
        const double v = s.value_at((e.x - r.track_lo.x) / double(r.track_hi.x - r.track_lo.x));
        if (s.get && s.get() == v) return;
        if (s.set) s.set(v);
        ++overlay_version_;
        if (s.live) pending_ = true, pending_reframe_ = pending_reframe_ || s.reframe;
    };
    if (e.phase == P::press) {
        active_ = -1, demo_drag_ = false;
        if (!e.secondary)
            for (std::size_t i = 0; i < sliders_.size(); ++i) {
                if (!slider_rect(sliders_, i).grabs(e.x, e.y)) continue;
                active_ = int(i);
                ++overlay_version_;
                follow();
                return true;
            }
        if (!e.secondary && window_.drag && window_.drag(drag_event(P::press, e.x, e.y))) {
            demo_drag_ = true;
            pending_ = true;
            return true;
        }
        return false;
    }
    if (active_ >= 0) {
        follow();
        if (e.phase == P::release) {
            const bool reframe = sliders_[std::size_t(active_)].reframe;
            active_ = -1;
            refresh(reframe || pending_reframe_);
            report();
        }
        return true;
    }
    if (demo_drag_) {
        const bool reframe = window_.drag(drag_event(e.phase, e.x, e.y));
        pending_ = true, pending_reframe_ = pending_reframe_ || reframe;
        if (e.phase == P::release) {
            demo_drag_ = false;
            refresh(pending_reframe_);
            report();
        }
        return true;
    }
    return false;
}

void DemoSession::set_slider(const std::string& label, double value) {
    flush();
    std::size_t i = 0;
    while (i < sliders_.size() && sliders_[i].label != label && ascii_text(sliders_[i].label) != label) ++i;
    if (i == sliders_.size()) {
        std::string names;
        for (const Slider& s : sliders_) names += (names.empty() ? "" : ", ") + ascii_text(s.label);
        throw std::invalid_argument(
            "no slider '" + label + "' here" +
            (names.empty() ? std::string(" (this view has none)") : " (sliders: " + names + ")"));
    }
    const Slider& s = sliders_[i];
    const SliderRect r = slider_rect(sliders_, i);
    const double x = r.track_lo.x + s.fraction(s.snap(value)) * double(r.track_hi.x - r.track_lo.x);
    const double y = 0.5 * double(r.track_lo.y + r.track_hi.y);
    mouse({MouseEvent::Phase::press, x, y, width, height, false});
    mouse({MouseEvent::Phase::release, x, y, width, height, false});
}

void DemoSession::drag(glm::dvec2 a, glm::dvec2 b, int steps) {
    flush();
    using P = MouseEvent::Phase;
    const bool captured = mouse({P::press, a.x, a.y, width, height, false});
    glm::dvec2 last = a;
    for (int k = 1; k <= std::max(1, steps); ++k) {
        const glm::dvec2 p = a + (b - a) * (double(k) / std::max(1, steps));
        if (captured)
            mouse({P::move, p.x, p.y, width, height, false});
        else
            camera.orbit(p.x - last.x, p.y - last.y);
        last = p;
    }
    if (captured) {
        mouse({P::release, b.x, b.y, width, height, false});
    } else {
        ++camera_version_;
        if (log) *log << "orbit: yaw " << fmt(camera.yaw_deg) << ", pitch " << fmt(camera.pitch_deg) << std::endl;
    }
}

glm::dvec2 DemoSession::pixel_of(const std::vector<double>& point) const {
    if (point.size() == 2) return {point[0] * width, point[1] * height};
    const dvec3 p = camera.pixel(dvec3(point[0], point[1], point[2]), width, height);
    if (!(p.z > 0.0))
        throw std::invalid_argument("--keys: the point " + fmt(dvec3(point[0], point[1], point[2])) +
                                    " is behind the camera");
    return {p.x, p.y};
}

void DemoSession::run(const ScriptStep& step) {
    using K = ScriptStep::Kind;
    switch (step.kind) {
        case K::key:
            key(step.key);
            break;
        case K::slider:
            set_slider(step.label, step.value);
            break;
        case K::drag:
            drag(pixel_of(step.from), pixel_of(step.to));
            break;
        case K::click: {
            const glm::dvec2 p = pixel_of(step.from);
            flush();
            if (!mouse({MouseEvent::Phase::press, p.x, p.y, width, height, false}))
                click(p.x, p.y);
            else
                mouse({MouseEvent::Phase::release, p.x, p.y, width, height, false});
            break;
        }
        case K::screenshot:
            break;  // the caller's (a window or a headless picture)
    }
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
    app_.add_flag("--widgets", widgets_,
                  "With --png: draw the sliders and the status line into it, as the window does");
    app_.add_option("--figures", figures_, "Render the handout's figures into this folder and exit (headless)");
    app_.add_option("--size", width_, "PNG width (height = 3/4 of it)")
        ->capture_default_str()
        ->check(CLI::Range(8, 8192));
    app_.add_option("--memory-mb", memory_mb_, "Address-space cap for your code, MiB (0: none; default: the grader's)")
        ->capture_default_str();
    app_.add_option("--frames", frames_, "(testing) draw N frames in the window, then exit")->group("");
    app_.add_option("--screenshot", screenshot_, "(testing) with --frames: save the window to this PNG")->group("");
    app_.add_option("--keys", keys_, "(testing) scripted input: keys, {LABEL=VALUE}, {drag A B}, {click A}")->group("");
    app_.footer(keys_help_);
}

std::optional<int> DemoProgram::parse(int argc, char** argv) {
    try {
        app_.parse(argc, argv);
        parse_script(keys_);  // a bad script is a usage error, before anything runs
    } catch (const CLI::ParseError& e) {
        return app_.exit(e);
    } catch (const std::invalid_argument& e) {
        std::cerr << program_ << ": " << e.what() << "\n";
        return 2;
    }
    if (!limit_demo_memory(memory_mb_)) std::cerr << program_ << ": could not cap the memory; running without\n";
    return std::nullopt;
}

int DemoProgram::run(const std::function<int()>& body) {
    try {
        if (!figures_.empty()) check_figure_dir(figures_);
        memory_reports_at_start_ = memory_limit_reports();
        const int status = body();
        if (status == 0 && memory_limit_reports() != memory_reports_at_start_) {
            std::cerr << program_ << ": a step ran out of memory (see above): exit status 1\n";
            return 1;
        }
        return status;
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
    if (memory_limit_reports() != memory_reports_at_start_) {
        // the renderer (OSMesa) allocates hundreds of MiB of its own and does not survive a failed allocation: a
        // process at its cap says so instead of drawing
        std::cout << status << "\n";
        std::cerr << program_ << ": not drawn: a step ran out of memory (see above)\n";
        return 1;
    }
    render_png(scene, camera, png_, width(), height());
    std::cout << status << "\nwrote " << png_ << "\n";
    return 0;
}

namespace {
// The scene with the rectangles added to its overlay.
Scene with_overlay(Scene scene, const std::vector<Scene::Rect>& rects) {
    for (const Scene::Rect& r : rects) scene.add_rect(r.lo, r.hi, r.color);
    return scene;
}
}  // namespace

int DemoProgram::write_headless(const Window& window) const {
    DemoSession session(window, width(), height());
    for (const ScriptStep& step : parse_script(keys_)) {
        if (step.kind != ScriptStep::Kind::screenshot) {
            session.log = &std::cout;
            session.run(step);
            continue;
        }
        // S: what the window's S key saves, rendered headless
        const auto dir = screenshot_dir();
        std::filesystem::create_directories(dir);
        std::filesystem::path file;
        int n = 0;
        do file = dir / ("geolab_screenshot_" + std::to_string(++n) + ".png");
        while (std::filesystem::exists(file));
        render_png(with_overlay(session.frame().scene, session.overlay()), session.camera, file, width(), height());
        std::cout << "wrote " << file.string() << "\n";
    }
    session.flush();
    const Scene scene = widgets_ ? with_overlay(session.frame().scene, session.overlay()) : session.frame().scene;
    return write_png(scene, session.camera, session.frame().status);
}

int DemoProgram::show(const Window& window) const {
    if (!png_.empty()) return write_headless(window);
    Viewer viewer(window.title, 960, 720);
    int w = 0, h = 0, fw = 0, fh = 0;
    viewer.size(w, h, fw, fh);
    DemoSession session(window, w, h);
    session.log = &std::cout;
    std::cout << keys_help_ << std::endl;
    // what changed in the session goes to the viewer
    int frame_v = -1, overlay_v = -1, camera_v = -1;
    auto sync = [&] {
        if (session.camera_version() != camera_v) viewer.set_camera(session.camera);
        if (session.frame_version() != frame_v) {
            viewer.set_scene(session.take_scene(), false);  // (the first scene sets Home's framing)
            viewer.set_status(session.status());
        }
        if (session.overlay_version() != overlay_v || session.frame_version() != frame_v)
            viewer.set_overlay(session.overlay());
        frame_v = session.frame_version(), overlay_v = session.overlay_version(), camera_v = session.camera_version();
    };
    std::cout << session.frame().status << std::endl;
    sync();
    // every input starts from the window's camera and size (the mouse orbits and zooms it; it may be resized)
    auto enter = [&] {
        session.camera = viewer.camera();
        int fbw = 0, fbh = 0;
        viewer.size(session.width, session.height, fbw, fbh);
    };
    viewer.on_mouse([&](const MouseEvent& e) {
        enter();
        const bool taken = session.mouse(e);
        sync();
        return taken;
    });
    viewer.on_pick([&](const Ray& ray) {
        enter();
        session.pick(ray);
        sync();
    });
    viewer.on_before_draw([&] {
        session.flush();
        int ww = 0, wh = 0, fbw = 0, fbh = 0;
        viewer.size(ww, wh, fbw, fbh);
        if (ww != session.width || wh != session.height) {  // resized: the status line wraps anew
            session.width = ww, session.height = wh;
            overlay_v = -1;
        }
        sync();
    });
    if (window.animate)
        viewer.on_frame([&](double seconds) {
            const bool changed = window.animate(seconds);
            if (changed) {
                enter();
                session.refresh(false);
                sync();
            }
            return changed;
        });
    return loop(
        viewer,
        [&](int key) {
            enter();
            session.key(key);
            sync();
        },
        [&](const ScriptStep& step) {
            enter();
            session.run(step);
            session.flush();
            sync();
        });
}

int DemoProgram::run_window(Viewer& viewer, const std::function<void(int key)>& press) const {
    std::cout << keys_help_ << std::endl;
    return loop(viewer, press, [&](const ScriptStep&) {
        throw std::invalid_argument("--keys: {...} commands need a demo shown through DemoProgram::show");
    });
}

int DemoProgram::loop(Viewer& viewer, const std::function<void(int key)>& press,
                      const std::function<void(const ScriptStep&)>& step) const {
    viewer.on_key(press);
    if (frames_ <= 0) {
        viewer.run();
        return 0;
    }
    for (const ScriptStep& s : parse_script(keys_)) {  // scripted: input, a few frames, a screenshot
        if (s.kind == ScriptStep::Kind::screenshot) {  // as the window's S key
            viewer.run_frames(1);
            std::cout << "wrote " << viewer.save_screenshot().string() << "\n";
        } else if (s.kind == ScriptStep::Kind::key) {
            press(s.key);
        } else {
            step(s);
        }
    }
    viewer.run_frames(frames_);
    if (!screenshot_.empty()) {
        viewer.screenshot(screenshot_);
        std::cout << "wrote " << screenshot_ << "\n";
    }
    return 0;
}

}  // namespace geolab::render
