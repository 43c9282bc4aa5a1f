// Lab 05's data readers: Newell's .bpt patches and TrueType glyph outlines (FreeType's own decomposition).
#include "geolab/bezier_data.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>
#include <sstream>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include "geolab/config.hpp"
#include "geolab/errors.hpp"
#include "geolab/io.hpp"

namespace geolab {

namespace {

// A token for an error message: quoted, at most 40 bytes, unprintable bytes shown as '?'.
std::string quoted(std::string_view t) {
    std::string q = "'";
    for (char c : t.substr(0, 40)) q += (c >= 32 && c < 127) ? c : '?';
    return q + (t.size() > 40 ? "...'" : "'");
}

// Whitespace-separated tokens of one line.
std::vector<std::string_view> tokens_of(std::string_view line) {
    std::vector<std::string_view> out;
    constexpr std::string_view blanks = " \t\f\v";
    for (std::size_t b = line.find_first_not_of(blanks); b != std::string_view::npos;) {
        const std::size_t e = std::min(line.find_first_of(blanks, b), line.size());
        out.push_back(line.substr(b, e - b));
        b = line.find_first_not_of(blanks, e);
    }
    return out;
}

long parse_int(const std::string& file, std::size_t line, std::string_view tok, const char* what) {
    long v = 0;
    const auto [p, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
    if (ec != std::errc() || p != tok.data() + tok.size())
        throw IoError(file, line, std::string(what) + " " + quoted(tok) + " is not an integer");
    return v;
}

double parse_double(const std::string& file, std::size_t line, std::string_view tok) {
    double v = 0;
    const auto [p, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
    if (ec == std::errc::result_out_of_range && p == tok.data() + tok.size())
        throw IoError(file, line, "coordinate " + quoted(tok) + " is out of the range of a double");
    if (ec != std::errc() || p != tok.data() + tok.size())
        throw IoError(file, line, "coordinate " + quoted(tok) + " is not a number");
    if (!std::isfinite(v)) throw IoError(file, line, "coordinate " + quoted(tok) + " is not finite");
    return v;
}

}  // namespace

std::vector<BezierPatch> read_bpt(const std::string& path) { return read_bpt_from_string(read_text_file(path), path); }

std::vector<BezierPatch> read_bpt_from_string(std::string_view text, const std::string& path) {
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // a UTF-8 byte order mark
    std::size_t pos = 0, line_no = 0;
    // The tokens of the next line holding one (blank lines are skipped); false at the end of the text. A line ends
    // with LF, CRLF or a lone CR.
    auto next = [&](std::vector<std::string_view>& toks) {
        while (pos < text.size()) {
            std::size_t e = pos;
            while (e < text.size() && text[e] != '\n' && text[e] != '\r') ++e;
            const std::string_view line = text.substr(pos, e - pos);
            pos = e + (e + 1 < text.size() && text[e] == '\r' && text[e + 1] == '\n' ? 2 : 1);
            ++line_no;
            toks = tokens_of(line);
            if (!toks.empty()) return true;
        }
        return false;
    };
    std::vector<std::string_view> t;
    if (!next(t)) throw IoError(path, line_no, "empty file: expected the patch count");
    if (t.size() != 1) throw IoError(path, line_no, "expected one number, the patch count");
    const long count = parse_int(path, line_no, t[0], "patch count");
    if (count < 1 || count > 100000)
        throw IoError(path, line_no, "patch count " + std::to_string(count) + " is out of range (1..100000)");
    std::vector<BezierPatch> patches;
    patches.reserve(std::size_t(count));
    for (long k = 0; k < count; ++k) {
        if (!next(t))
            throw IoError(path, line_no, "file ends after " + std::to_string(k) + " of " + std::to_string(count) +
                                             " patches: expected the degrees 'du dv' of patch " + std::to_string(k));
        if (t.size() != 2) throw IoError(path, line_no, "expected two degrees 'du dv' for patch " + std::to_string(k));
        BezierPatch p;
        const long du = parse_int(path, line_no, t[0], "degree"), dv = parse_int(path, line_no, t[1], "degree");
        if (du < 1 || du > 30 || dv < 1 || dv > 30)
            throw IoError(path, line_no, "patch " + std::to_string(k) + ": degrees " + std::to_string(du) + " " +
                                             std::to_string(dv) + " out of range (1..30)");
        p.degree_u = int(du);
        p.degree_v = int(dv);
        const std::size_t n = std::size_t(du + 1) * std::size_t(dv + 1);
        p.points.reserve(n);
        for (std::size_t i = 0; i < n; ++i) {
            if (!next(t))
                throw IoError(path, line_no, "file ends inside patch " + std::to_string(k) + ": " +
                                                 std::to_string(i) + " of " + std::to_string(n) + " points");
            if (t.size() != 3)
                throw IoError(path, line_no, "patch " + std::to_string(k) + " point " + std::to_string(i) +
                                                 ": expected 'x y z', got " + std::to_string(t.size()) + " values");
            p.points.emplace_back(parse_double(path, line_no, t[0]), parse_double(path, line_no, t[1]),
                                  parse_double(path, line_no, t[2]));
        }
        patches.push_back(std::move(p));
    }
    if (next(t)) throw IoError(path, line_no, "trailing data after the last patch: " + quoted(t[0]));
    return patches;
}

std::string teapot_path() { return std::string(config::source_dir) + "/data/teapot.bpt"; }

std::string default_font_path() { return "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"; }

namespace {

struct Decomposer {
    GlyphOutline* out;
    glm::dvec2 pen{0.0};
    bool cubic = false;
};

glm::dvec2 to_vec(const FT_Vector* v) { return {double(v->x), double(v->y)}; }

int move_to(const FT_Vector* to, void* user) {
    auto* d = static_cast<Decomposer*>(user);
    d->out->contours.emplace_back();
    d->pen = to_vec(to);
    return 0;
}
int line_to(const FT_Vector* to, void* user) {
    auto* d = static_cast<Decomposer*>(user);
    const glm::dvec2 b = to_vec(to);
    d->out->contours.back().push_back({d->pen, 0.5 * (d->pen + b), b});
    d->pen = b;
    return 0;
}
int conic_to(const FT_Vector* control, const FT_Vector* to, void* user) {
    auto* d = static_cast<Decomposer*>(user);
    const glm::dvec2 b = to_vec(to);
    d->out->contours.back().push_back({d->pen, to_vec(control), b});
    d->pen = b;
    return 0;
}
int cubic_to(const FT_Vector*, const FT_Vector*, const FT_Vector*, void* user) {
    static_cast<Decomposer*>(user)->cubic = true;
    return 1;  // stop: not a quadratic outline
}

// Owns the FreeType library and face handles.
struct FtHandles {
    FT_Library lib = nullptr;
    FT_Face face = nullptr;
    ~FtHandles() {
        if (face) FT_Done_Face(face);
        if (lib) FT_Done_FreeType(lib);
    }
};

std::string hex(char32_t c) {
    std::ostringstream s;
    s << "U+" << std::hex << std::uppercase << std::uint32_t(c);
    return s.str();
}

}  // namespace

GlyphOutline read_glyph(const std::string& font_path, char32_t codepoint) {
    // Read through lib's read_text_file (regular files only, with the size limit), never by FreeType's own open:
    // a FIFO would block it and /dev/zero has no end.
    return read_glyph_from_memory(read_text_file(font_path), codepoint, font_path);
}

GlyphOutline read_glyph_from_memory(const std::string& font, char32_t codepoint, const std::string& font_path) {
    FtHandles ft;
    if (FT_Init_FreeType(&ft.lib)) throw IoError(font_path, 0, "FreeType could not be initialised");
    if (FT_New_Memory_Face(ft.lib, reinterpret_cast<const FT_Byte*>(font.data()), FT_Long(font.size()), 0, &ft.face))
        throw IoError(font_path, 0, "FreeType cannot open this file as a font");
    const FT_UInt index = FT_Get_Char_Index(ft.face, FT_ULong(codepoint));
    if (index == 0) throw IoError(font_path, 0, "the font has no glyph for " + hex(codepoint));
    if (FT_Load_Glyph(ft.face, index, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP))
        throw IoError(font_path, 0, "FreeType cannot load the glyph of " + hex(codepoint));
    if (ft.face->glyph->format != FT_GLYPH_FORMAT_OUTLINE)
        throw IoError(font_path, 0, "the glyph of " + hex(codepoint) + " is not an outline");
    GlyphOutline g;
    g.advance = double(ft.face->glyph->advance.x);
    g.units_per_em = double(ft.face->units_per_EM);
    Decomposer d{&g};
    FT_Outline_Funcs funcs{};
    funcs.move_to = move_to;
    funcs.line_to = line_to;
    funcs.conic_to = conic_to;
    funcs.cubic_to = cubic_to;
    funcs.shift = 0;
    funcs.delta = 0;
    const FT_Error err = FT_Outline_Decompose(&ft.face->glyph->outline, &funcs, &d);
    if (d.cubic)
        throw IoError(font_path, 0, "the glyph of " + hex(codepoint) +
                                        " has cubic segments: not a TrueType (quadratic) outline");
    if (err) throw IoError(font_path, 0, "FreeType cannot decompose the outline of " + hex(codepoint));
    // FreeType closes each contour with a line back to its start; a zero-length closing line is dropped.
    for (auto& c : g.contours)
        if (!c.empty() && c.back()[0] == c.back()[2]) c.pop_back();
    std::erase_if(g.contours, [](const auto& c) { return c.empty(); });
    return g;
}

}  // namespace geolab
