// Mesh I/O. Each reader takes the whole file as one string_view and parses it in place (std::from_chars, no
// streams per token), validating every count, index and coordinate as it goes. Errors name the file, the line
// (text) or the element (binary) and the reason.
#include "geolab/io.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <glm/geometric.hpp>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

namespace geolab {
namespace {

using Index = std::uint32_t;
constexpr std::uint64_t max_index = std::numeric_limits<Index>::max();

// ================================================================================================================
// Small text helpers
// ================================================================================================================

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v' || c == '\n'; }

// Keywords are matched in any case, in every reader ("SOLID", "Facet", "off", "PLY").
bool iequals(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

std::string lowercase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// A token for an error message: quoted, at most 32 characters, unprintable bytes shown as '?'.
std::string quote(std::string_view token) {
    std::string q = "'";
    for (char c : token.substr(0, 32)) q += (c >= 32 && c < 127) ? c : '?';
    return q + (token.size() > 32 ? "...'" : "'");
}

// The whole token as a double (a leading '+' is allowed), or nullopt. "nan" and "inf" parse: callers check.
std::optional<double> to_double(std::string_view s) {
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    double v = 0;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size() || s.empty()) return std::nullopt;
    return v;
}

// The whole token as an integer (a leading '+' is allowed), or nullopt.
std::optional<std::int64_t> to_int(std::string_view s) {
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    std::int64_t v = 0;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size() || s.empty()) return std::nullopt;
    return v;
}

// Fails unless a header's count of `items`, each at least `min_bytes` long, fits in the `available` bytes left.
// Run before reserving, so that "OFF 999999999999 1 0" fails at once instead of allocating.
void check_fits(const std::string& name, std::size_t line, std::uint64_t count, std::uint64_t min_bytes,
                std::uint64_t& available, const std::string& items) {
    if (min_bytes > 0 && count > available / min_bytes)
        throw IoError(name, line,
                      "header declares " + std::to_string(count) + " " + items + " but only " +
                          std::to_string(available) + " bytes follow: the file is truncated or the count is wrong");
    available -= count * min_bytes;
}

// ================================================================================================================
// TextParser: lines (1-based numbers) and whitespace-separated tokens of text in memory
// ================================================================================================================

class TextParser {
public:
    //! Parses `text` from byte `start`, whose line is `first_line`; `comment` starts a comment ('\0': none).
    TextParser(std::string_view text, const std::string& name, char comment, std::size_t start = 0,
               std::size_t first_line = 1)
        : text_(text),
          name_(name),
          next_(start),
          lf_(std::min(text.find('\n', start), text.size())),
          cr_(find_cr()),
          line_(first_line - 1),
          comment_(comment) {}

    //! Moves to the next line holding a token; false at the end of the text. A line ends with LF, CRLF or a
    //! lone CR; the positions of the next LF and CR are cached, so the scan is linear whichever is used.
    bool next_line() {
        while (next_ < text_.size()) {
            if (lf_ < next_) lf_ = std::min(text_.find('\n', next_), text_.size());
            if (cr_ < next_) cr_ = find_cr();
            const std::size_t end = std::min(lf_, cr_);
            rest_ = text_.substr(next_, end - next_);
            next_ = end + (end == cr_ && end + 1 == lf_ ? 2 : 1);  // CRLF is one line end
            ++line_;
            if (comment_ != '\0') rest_ = rest_.substr(0, rest_.find(comment_));
            skip_spaces();
            if (!rest_.empty()) return true;
        }
        rest_ = {};
        return false;
    }
    //! The next token on the current line, or empty when the line is used up.
    std::string_view token() {
        skip_spaces();
        std::size_t n = 0;
        while (n < rest_.size() && !is_space(rest_[n])) ++n;
        std::string_view t = rest_.substr(0, n);
        rest_.remove_prefix(n);
        return t;
    }
    //! The next token, moving on to the following lines as needed; empty at the end of the text.
    std::string_view token_any_line() {
        std::string_view t = token();
        while (t.empty() && next_line()) t = token();
        return t;
    }
    //! The next token on the current line without consuming it.
    std::string_view peek() {
        skip_spaces();
        std::size_t n = 0;
        while (n < rest_.size() && !is_space(rest_[n])) ++n;
        return rest_.substr(0, n);
    }
    bool at_line_end() {
        skip_spaces();
        return rest_.empty();
    }
    //! The remaining text of the current line (then consumed).
    std::string_view rest_of_line() { return std::exchange(rest_, {}); }
    std::size_t line() const { return line_; }
    //! The byte offset just past the current line.
    std::size_t offset() const { return std::min(next_, text_.size()); }
    const std::string& name() const { return name_; }

    [[noreturn]] void fail(const std::string& reason) const { throw IoError(name_, line_, reason); }

    //! The next token on this line as a finite double; `what` names it in errors (built only on failure).
    double real(std::string_view what) { return check_real(token(), what); }
    //! The next token on this line as an integer.
    std::int64_t integer(std::string_view what) { return check_int(token(), what); }
    //! The next token on this line as a non-negative count.
    std::uint64_t count(std::string_view what) {
        std::string_view t = token();
        std::int64_t n = check_int(t, what);
        if (n < 0) fail(std::string(what) + " is negative (" + quote(t) + ")");
        return static_cast<std::uint64_t>(n);
    }
    //! Consumes the rest of the line, failing unless every token is a number (colours, normals, ...).
    void skip_numbers(std::string_view what) {
        for (std::string_view t = token(); !t.empty(); t = token())
            if (!to_double(t)) fail("unexpected " + quote(t) + " after " + std::string(what));
    }

    double check_real(std::string_view t, std::string_view what) const {
        if (t.empty()) fail("missing " + std::string(what) + " (line ends early)");
        std::optional<double> v = to_double(t);
        if (!v) fail("expected " + std::string(what) + ", found " + quote(t));
        if (!std::isfinite(*v)) fail(std::string(what) + " is not finite (" + quote(t) + ")");
        return *v;
    }
    std::int64_t check_int(std::string_view t, std::string_view what) const {
        if (t.empty()) fail("missing " + std::string(what) + " (line ends early)");
        std::optional<std::int64_t> v = to_int(t);
        if (!v) fail("expected " + std::string(what) + " (an integer), found " + quote(t));
        return *v;
    }

private:
    // The first '\r' in [next_, lf_), or lf_ if there is none (never searches past the next LF: a binary PLY
    // body after the header is not scanned).
    std::size_t find_cr() const {
        const std::size_t r = text_.substr(next_, lf_ - next_).find('\r');
        return r == std::string_view::npos ? lf_ : next_ + r;
    }
    void skip_spaces() {
        std::size_t n = 0;
        while (n < rest_.size() && is_space(rest_[n])) ++n;
        rest_.remove_prefix(n);
    }

    std::string_view text_;
    const std::string& name_;
    std::size_t next_;  // start of the next line
    std::size_t lf_;    // the next '\n' at or after next_ (text_.size() when none)
    std::size_t cr_;    // the next '\r' at or after next_ if before lf_, else lf_
    std::string_view rest_;
    std::size_t line_;
    char comment_;
};

// ================================================================================================================
// OFF
// ================================================================================================================

// Reads the optional header keyword ([ST][C][N][4][n]OFF; "OFF" and the S, T, C prefixes in any case, "n" is
// the dimension prefix). Returns false when the file starts with the counts.
bool read_off_keyword(TextParser& in) {
    std::string_view key = in.peek();
    if (key.size() < 3 || !iequals(key.substr(key.size() - 3), "OFF")) return false;
    in.token();
    std::string_view prefix = key.substr(0, key.size() - 3);
    if (prefix.find('4') != std::string_view::npos || prefix.find('n') != std::string_view::npos)
        in.fail("unsupported OFF variant " + quote(key) + " (only 3D vertices are read)");
    if (prefix.find_first_not_of("STCNstc") != std::string_view::npos) in.fail("unknown OFF header " + quote(key));
    if (iequals(in.peek(), "BINARY")) in.fail("binary OFF is not supported");
    return true;
}

void read_off_vertices(TextParser& in, std::uint64_t nv, PolygonSoup& soup) {
    for (std::uint64_t v = 0; v < nv; ++v) {
        if (!in.next_line())
            in.fail("unexpected end of file: header declares " + std::to_string(nv) + " vertices, found " +
                    std::to_string(v));
        double x = in.real("vertex x"), y = in.real("vertex y"), z = in.real("vertex z");
        in.skip_numbers("the vertex coordinates");  // normals, colours, texture coordinates
        soup.positions.emplace_back(x, y, z);
    }
}

void read_off_faces(TextParser& in, std::uint64_t nv, std::uint64_t nf, PolygonSoup& soup) {
    for (std::uint64_t f = 0; f < nf; ++f) {
        if (!in.next_line())
            in.fail("unexpected end of file: header declares " + std::to_string(nf) + " faces, found " +
                    std::to_string(f));
        std::uint64_t n = in.count("face vertex count");
        if (n < 3) in.fail("face " + std::to_string(f) + " has " + std::to_string(n) + " vertices (at least 3 needed)");
        for (std::uint64_t k = 0; k < n; ++k) {
            std::int64_t i = in.integer("vertex index");
            if (i < 0 || static_cast<std::uint64_t>(i) >= nv)
                in.fail("face " + std::to_string(f) + ": vertex index " + std::to_string(i) + " out of range [0, " +
                        std::to_string(nv) + ")");
            soup.indices.push_back(static_cast<Index>(i));
        }
        in.skip_numbers("the face's vertex indices");  // a colour
        soup.offsets.push_back(static_cast<Index>(soup.indices.size()));
    }
}

PolygonSoup read_off(std::string_view text, const std::string& name) {
    TextParser in(text, name, '#');
    if (!in.next_line()) in.fail("empty file (no OFF header)");
    if (read_off_keyword(in) && in.at_line_end() && !in.next_line())
        in.fail("unexpected end of file: missing the vertex and face counts");
    std::uint64_t nv = in.count("vertex count"), nf = in.count("face count");
    if (!in.at_line_end()) in.count("edge count");
    if (!in.at_line_end()) in.fail("unexpected " + quote(in.token()) + " after the counts");
    // every vertex needs at least "0 0 0\n", every face "3 0 1 2\n"
    std::uint64_t available = text.size() - in.offset() + 1;
    check_fits(name, in.line(), nv, 6, available, "vertices");
    check_fits(name, in.line(), nf, 8, available, "faces (after the vertices)");
    if (nv > max_index) in.fail("too many vertices (" + std::to_string(nv) + ")");

    PolygonSoup soup;
    soup.positions.reserve(nv);
    soup.offsets.reserve(nf + 1);
    soup.indices.reserve(3 * nf);
    read_off_vertices(in, nv, soup);
    read_off_faces(in, nv, nf, soup);
    if (in.next_line()) in.fail("unexpected data after the last face (" + quote(in.token()) + ")");
    return soup;
}

// ================================================================================================================
// OBJ
// ================================================================================================================

// The OBJ statements that are read past without use (everything but `v` and `f`).
bool is_ignored_obj_statement(std::string_view key) {
    static constexpr std::array<std::string_view, 33> known = {
        "vt",     "vn",  "vp",   "l",     "p",        "g",        "o",    "s",          "mg",        "usemtl", "mtllib",
        "cstype", "deg", "bmat", "step",  "curv",     "curv2",    "surf", "parm",       "trim",      "hole",   "scrv",
        "sp",     "end", "con",  "bevel", "c_interp", "d_interp", "lod",  "shadow_obj", "trace_obj", "ctech",  "stech"};
    return std::any_of(known.begin(), known.end(), [&](std::string_view k) { return iequals(k, key); });
}

// One corner of an `f` statement: `i`, `i/t`, `i//n` or `i/t/n`; negative i counts back from the last vertex.
Index read_obj_corner(TextParser& in, std::string_view token, std::size_t n_vertices) {
    std::string_view head = token.substr(0, token.find('/'));
    for (std::string_view rest = token.substr(head.size()); !rest.empty();) {  // t and n: empty or integers
        rest.remove_prefix(1);
        std::string_view part = rest.substr(0, rest.find('/'));
        if (!part.empty() && !to_int(part)) in.fail("malformed face corner " + quote(token));
        rest.remove_prefix(part.size());
    }
    std::int64_t i = in.check_int(head, "vertex index");
    if (i == 0) in.fail("vertex index 0 in " + quote(token) + " (OBJ indices start at 1)");
    std::int64_t resolved = i > 0 ? i - 1 : static_cast<std::int64_t>(n_vertices) + i;
    if (resolved < 0 || static_cast<std::uint64_t>(resolved) >= n_vertices)
        in.fail("vertex index " + std::to_string(i) + " out of range (" + std::to_string(n_vertices) +
                " vertices so far)");
    return static_cast<Index>(resolved);
}

void read_obj_face(TextParser& in, PolygonSoup& soup) {
    std::size_t corners = 0;
    for (std::string_view t = in.token(); !t.empty(); t = in.token(), ++corners)
        soup.indices.push_back(read_obj_corner(in, t, soup.positions.size()));
    if (corners < 3) in.fail("face has " + std::to_string(corners) + " vertices (at least 3 needed)");
    if (soup.indices.size() > max_index) in.fail("too many face indices");
    soup.offsets.push_back(static_cast<Index>(soup.indices.size()));
}

PolygonSoup read_obj(std::string_view text, const std::string& name) {
    TextParser in(text, name, '#');
    PolygonSoup soup;
    while (in.next_line()) {
        std::string_view key = in.token();
        if (iequals(key, "v")) {
            double x = in.real("vertex x"), y = in.real("vertex y"), z = in.real("vertex z");
            in.skip_numbers("the vertex coordinates");  // w or a colour
            if (soup.positions.size() == max_index) in.fail("too many vertices");
            soup.positions.emplace_back(x, y, z);
        } else if (iequals(key, "f")) {
            read_obj_face(in, soup);
        } else if (!is_ignored_obj_statement(key)) {
            in.fail("unknown OBJ statement " + quote(key));
        }
    }
    if (soup.positions.empty()) throw IoError(name, 0, "empty file: no vertices found");
    return soup;
}

// ================================================================================================================
// PLY
// ================================================================================================================

enum class PlyType { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

std::optional<PlyType> ply_type(std::string_view s) {
    static constexpr std::array<std::pair<std::string_view, PlyType>, 16> names = {{{"char", PlyType::int8},
                                                                                    {"int8", PlyType::int8},
                                                                                    {"uchar", PlyType::uint8},
                                                                                    {"uint8", PlyType::uint8},
                                                                                    {"short", PlyType::int16},
                                                                                    {"int16", PlyType::int16},
                                                                                    {"ushort", PlyType::uint16},
                                                                                    {"uint16", PlyType::uint16},
                                                                                    {"int", PlyType::int32},
                                                                                    {"int32", PlyType::int32},
                                                                                    {"uint", PlyType::uint32},
                                                                                    {"uint32", PlyType::uint32},
                                                                                    {"float", PlyType::float32},
                                                                                    {"float32", PlyType::float32},
                                                                                    {"double", PlyType::float64},
                                                                                    {"float64", PlyType::float64}}};
    for (auto [name, type] : names)
        if (iequals(s, name)) return type;
    return std::nullopt;
}

std::string_view type_name(PlyType t) {
    static constexpr std::array<std::string_view, 8> names = {"int8",  "uint8",  "int16",   "uint16",
                                                              "int32", "uint32", "float32", "float64"};
    return names[static_cast<std::size_t>(t)];
}

std::size_t size_of(PlyType t) {
    switch (t) {
        case PlyType::int8:
        case PlyType::uint8:
            return 1;
        case PlyType::int16:
        case PlyType::uint16:
            return 2;
        case PlyType::int32:
        case PlyType::uint32:
        case PlyType::float32:
            return 4;
        case PlyType::float64:
            return 8;
    }
    return 0;
}

bool is_integer(PlyType t) { return t != PlyType::float32 && t != PlyType::float64; }

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::float32;  // the item type for lists
    bool is_list = false;
    PlyType count_type = PlyType::uint8;
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
    std::size_t line = 0;  // where the header declares it
};

struct PlyHeader {
    MeshFormat format = MeshFormat::ply_ascii;
    std::vector<PlyElement> elements;
    std::size_t body_offset = 0;  // first byte after "end_header\n"
    std::size_t body_line = 0;    // line number of that byte
};

bool is_face_list(const PlyProperty& p) {
    return p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index");
}

void read_ply_property(TextParser& in, PlyHeader& h) {
    if (h.elements.empty()) in.fail("property before any element");
    PlyProperty p;
    std::string_view type = in.token();
    if (iequals(type, "list")) {
        p.is_list = true;
        std::string_view count_type = in.token();
        auto ct = ply_type(count_type);
        if (!ct || !is_integer(*ct))
            in.fail("bad list count type " + quote(count_type) + " (an integer type is needed)");
        p.count_type = *ct;
        type = in.token();
    }
    auto t = ply_type(type);
    if (!t) in.fail("unknown property type " + quote(type));
    p.type = *t;
    p.name = std::string(in.token());
    if (p.name.empty()) in.fail("property without a name");
    PlyElement& e = h.elements.back();
    for (const PlyProperty& q : e.properties)
        if (q.name == p.name) in.fail("element '" + e.name + "' declares property '" + p.name + "' twice");
    if (e.name == "face" && is_face_list(p) && !is_integer(p.type))
        in.fail("face vertex indices must have an integer type, not " + std::string(type_name(p.type)));
    e.properties.push_back(std::move(p));
}

void read_ply_header_line(TextParser& in, PlyHeader& h) {
    std::string_view key = in.token();
    if (iequals(key, "comment") || iequals(key, "obj_info")) {
        in.rest_of_line();
    } else if (iequals(key, "format")) {
        std::string_view f = in.token();
        if (iequals(f, "ascii"))
            h.format = MeshFormat::ply_ascii;
        else if (iequals(f, "binary_little_endian"))
            h.format = MeshFormat::ply_binary_le;
        else if (iequals(f, "binary_big_endian"))
            h.format = MeshFormat::ply_binary_be;
        else
            in.fail("unknown PLY format " + quote(f));
        in.rest_of_line();  // version
    } else if (iequals(key, "element")) {
        PlyElement e;
        e.name = std::string(in.token());
        if (e.name.empty()) in.fail("element without a name");
        for (const PlyElement& seen : h.elements)
            if (seen.name == e.name)
                in.fail("element '" + e.name + "' declared twice (first on line " + std::to_string(seen.line) +
                        "): each element may be declared once");
        e.count = in.count("element count of '" + e.name + "'");
        e.line = in.line();
        h.elements.push_back(std::move(e));
    } else if (iequals(key, "property")) {
        read_ply_property(in, h);
    } else {
        in.fail("unknown PLY header line starting with " + quote(key));
    }
}

// The smallest number of bytes one instance of `e` can take (its face list holding at least 3 indices).
std::uint64_t min_element_size(const PlyElement& e, bool binary) {
    std::uint64_t bytes = 0;
    for (const PlyProperty& p : e.properties) {
        std::uint64_t items = is_face_list(p) ? 3 : 0;
        if (binary)
            bytes += p.is_list ? size_of(p.count_type) + items * size_of(p.type) : size_of(p.type);
        else
            bytes += 2 + 2 * items;  // "0 " per number
    }
    return bytes;
}

const PlyElement* find_element(const PlyHeader& h, std::string_view name) {
    for (const PlyElement& e : h.elements)
        if (e.name == name) return &e;
    return nullptr;
}

void check_ply_header(const TextParser& in, const PlyHeader& h, std::size_t file_size) {
    const PlyElement* vertex = find_element(h, "vertex");
    if (!vertex) in.fail("no 'vertex' element in the header");
    for (const char* axis : {"x", "y", "z"}) {
        auto it = std::find_if(vertex->properties.begin(), vertex->properties.end(),
                               [&](const PlyProperty& p) { return p.name == axis && !p.is_list; });
        if (it == vertex->properties.end()) in.fail(std::string("vertex element has no scalar property ") + axis);
    }
    if (const PlyElement* face = find_element(h, "face")) {
        auto list = std::find_if(face->properties.begin(), face->properties.end(), is_face_list);
        if (list == face->properties.end())
            in.fail("face element has no list property 'vertex_indices' or 'vertex_index'");
        if (!is_integer(list->type)) in.fail("face vertex indices must have an integer type");
    }
    bool binary = h.format != MeshFormat::ply_ascii;
    std::uint64_t available = file_size - h.body_offset + (binary ? 0 : 1);
    for (const PlyElement& e : h.elements)
        check_fits(in.name(), e.line, e.count, min_element_size(e, binary), available, "'" + e.name + "' elements");
    if (vertex->count > max_index)
        throw IoError(in.name(), vertex->line, "too many vertices (" + std::to_string(vertex->count) + ")");
}

PlyHeader read_ply_header(std::string_view text, const std::string& name) {
    TextParser in(text, name, '\0');
    if (!in.next_line() || !iequals(in.token(), "ply") || !in.at_line_end())
        in.fail("not a PLY file (no 'ply' magic line)");
    PlyHeader h;
    bool has_format = false;
    while (true) {
        if (!in.next_line()) in.fail("unexpected end of file in the header (no end_header)");
        if (iequals(in.peek(), "end_header")) break;
        has_format = has_format || iequals(in.peek(), "format");
        read_ply_header_line(in, h);
        if (!in.at_line_end()) in.fail("unexpected " + quote(in.token()) + " in the header");
    }
    if (!has_format) in.fail("no 'format' line in the header");
    h.body_offset = in.offset();
    h.body_line = in.line() + 1;
    check_ply_header(in, h, text.size());
    return h;
}

// Reads the body of an ascii PLY; same interface as PlyBinaryReader, so the element loop is shared.
class PlyAsciiReader {
public:
    PlyAsciiReader(std::string_view text, const std::string& name, const PlyHeader& h)
        : in_(text, name, '\0', h.body_offset, h.body_line) {}
    //! Names the element being read, for errors at the end of the file.
    void begin(const PlyElement& element, std::uint64_t index) {
        element_ = &element;
        index_ = index;
    }
    double real(PlyType) { return in_.check_real(next("a number"), "coordinate"); }
    std::int64_t integer(PlyType, std::string_view what) { return in_.check_int(next(what), what); }
    void skip(const PlyProperty& p) {
        std::uint64_t n = p.is_list ? count(p.count_type, "list count") : 1;
        for (std::uint64_t i = 0; i < n; ++i)
            if (std::string_view t = next("a property value"); !to_double(t))
                fail("expected a number for '" + p.name + "', found " + quote(t));
    }
    std::uint64_t count(PlyType t, std::string_view what) {
        std::int64_t n = integer(t, what);
        if (n < 0) fail(std::string(what) + " is negative");
        return static_cast<std::uint64_t>(n);
    }
    void finish() {
        if (std::string_view t = in_.token_any_line(); !t.empty()) fail("unexpected data after the last element");
    }
    [[noreturn]] void fail(const std::string& reason) const { in_.fail(reason); }

private:
    std::string_view next(std::string_view what) {
        std::string_view t = in_.token_any_line();
        if (t.empty())
            in_.fail("unexpected end of file: expected " + std::string(what) + " of element " + element_->name + " " +
                     std::to_string(index_) + " (the header declares " + std::to_string(element_->count) +
                     ", the file is truncated)");
        return t;
    }
    TextParser in_;
    const PlyElement* element_ = nullptr;
    std::uint64_t index_ = 0;
};

// Reads the body of a binary PLY, swapping bytes when the file's endianness differs from the machine's.
class PlyBinaryReader {
public:
    PlyBinaryReader(std::string_view data, const std::string& name, const PlyHeader& h)
        : data_(data),
          name_(name),
          pos_(h.body_offset),
          swap_((h.format == MeshFormat::ply_binary_le) != (std::endian::native == std::endian::little)) {}
    //! Names the element being read, for errors.
    void begin(const PlyElement& element, std::uint64_t index) {
        element_ = &element;
        index_ = index;
    }
    double real(PlyType t) {
        double v = load(t);
        if (!std::isfinite(v)) fail("coordinate is not finite");
        return v;
    }
    std::int64_t integer(PlyType t, std::string_view what) {
        if (!is_integer(t)) fail(std::string(what) + " has the non-integer type " + std::string(type_name(t)));
        return static_cast<std::int64_t>(load(t));  // exact: every integer PLY type fits
    }
    std::uint64_t count(PlyType t, std::string_view what) {
        std::int64_t n = integer(t, what);
        if (n < 0) fail(std::string(what) + " is negative");
        return static_cast<std::uint64_t>(n);
    }
    void skip(const PlyProperty& p) {
        std::uint64_t n = p.is_list ? count(p.count_type, "list count") : 1;
        if (n > (data_.size() - pos_) / size_of(p.type))
            fail("unexpected end of data: property '" + p.name + "' needs " + std::to_string(n * size_of(p.type)) +
                 " bytes at byte " + std::to_string(pos_) + ", the file has " + std::to_string(data_.size()) +
                 " bytes (truncated file)");
        pos_ += n * size_of(p.type);
    }
    void finish() {
        if (pos_ != data_.size())
            throw IoError(name_, 0,
                          std::to_string(data_.size() - pos_) + " bytes of unexpected data after the last element");
    }
    [[noreturn]] void fail(const std::string& reason) const {
        throw IoError(
            name_, 0,
            "element " + (element_ ? element_->name : std::string("?")) + " " + std::to_string(index_) + ": " + reason);
    }

private:
    // One value of type t, byte-swapped as needed, widened to double (exact for every PLY type).
    double load(PlyType t) {
        std::size_t n = size_of(t);
        if (data_.size() - pos_ < n)
            fail("unexpected end of data: expected a value of type " + std::string(type_name(t)) + " at byte " +
                 std::to_string(pos_) + ", the file has " + std::to_string(data_.size()) + " bytes (truncated file)");
        std::array<unsigned char, 8> b{};
        std::memcpy(b.data(), data_.data() + pos_, n);
        pos_ += n;
        if (swap_) std::reverse(b.begin(), b.begin() + n);
        switch (t) {
            case PlyType::int8:
                return std::bit_cast<std::int8_t>(b[0]);
            case PlyType::uint8:
                return b[0];
            case PlyType::int16:
                return as<std::int16_t>(b);
            case PlyType::uint16:
                return as<std::uint16_t>(b);
            case PlyType::int32:
                return as<std::int32_t>(b);
            case PlyType::uint32:
                return as<std::uint32_t>(b);
            case PlyType::float32:
                return as<float>(b);
            case PlyType::float64:
                return as<double>(b);
        }
        return 0;
    }
    template <class T>
    static T as(const std::array<unsigned char, 8>& b) {
        T v;
        std::memcpy(&v, b.data(), sizeof(T));
        return v;
    }

    std::string_view data_;
    const std::string& name_;
    std::size_t pos_;
    bool swap_;
    const PlyElement* element_ = nullptr;
    std::uint64_t index_ = 0;
};

template <class Reader>
void read_ply_vertices(Reader& in, const PlyElement& e, PolygonSoup& soup) {
    std::vector<int> axis(e.properties.size(), -1);  // 0, 1, 2 for x, y, z
    for (std::size_t k = 0; k < e.properties.size(); ++k)
        if (!e.properties[k].is_list && e.properties[k].name.size() == 1 && std::strchr("xyz", e.properties[k].name[0]))
            axis[k] = e.properties[k].name[0] - 'x';
    soup.positions.reserve(e.count);
    for (std::uint64_t v = 0; v < e.count; ++v) {
        in.begin(e, v);
        glm::dvec3 p{0.0};
        for (std::size_t k = 0; k < e.properties.size(); ++k) {
            if (axis[k] >= 0)
                p[axis[k]] = in.real(e.properties[k].type);
            else
                in.skip(e.properties[k]);
        }
        soup.positions.push_back(p);
    }
}

template <class Reader>
void read_ply_face(Reader& in, const PlyProperty& p, std::uint64_t f, std::uint64_t nv, PolygonSoup& soup) {
    std::uint64_t n = in.count(p.count_type, "face vertex count");
    if (n < 3) in.fail("face " + std::to_string(f) + " has " + std::to_string(n) + " vertices (at least 3 needed)");
    for (std::uint64_t k = 0; k < n; ++k) {
        std::int64_t i = in.integer(p.type, "vertex index");
        if (i < 0 || static_cast<std::uint64_t>(i) >= nv)
            in.fail("face " + std::to_string(f) + ": vertex index " + std::to_string(i) + " out of range [0, " +
                    std::to_string(nv) + ")");
        soup.indices.push_back(static_cast<Index>(i));
    }
    if (soup.indices.size() > max_index) in.fail("too many face indices");
    soup.offsets.push_back(static_cast<Index>(soup.indices.size()));
}

template <class Reader>
void read_ply_faces(Reader& in, const PlyElement& e, std::uint64_t nv, PolygonSoup& soup) {
    soup.offsets.reserve(e.count + 1);
    soup.indices.reserve(3 * e.count);
    bool seen = false;  // only the first index list is the face; any other list is skipped
    for (std::uint64_t f = 0; f < e.count; ++f) {
        in.begin(e, f);
        seen = false;
        for (const PlyProperty& p : e.properties) {
            if (is_face_list(p) && !seen) {
                read_ply_face(in, p, f, nv, soup);
                seen = true;
            } else {
                in.skip(p);
            }
        }
    }
}

template <class Reader>
PolygonSoup read_ply_body(Reader in, const PlyHeader& h) {
    PolygonSoup soup;
    std::uint64_t nv = find_element(h, "vertex")->count;
    for (const PlyElement& e : h.elements) {
        if (e.name == "vertex") {
            read_ply_vertices(in, e, soup);
        } else if (e.name == "face") {
            read_ply_faces(in, e, nv, soup);
        } else if (!e.properties.empty()) {  // skip other elements (with no properties there is nothing to skip)
            for (std::uint64_t i = 0; i < e.count; ++i) {
                in.begin(e, i);
                for (const PlyProperty& p : e.properties) in.skip(p);
            }
        }
    }
    in.finish();
    return soup;
}

PolygonSoup read_ply(std::string_view data, const std::string& name) {
    PlyHeader h = read_ply_header(data, name);
    if (h.format == MeshFormat::ply_ascii) return read_ply_body(PlyAsciiReader(data, name, h), h);
    return read_ply_body(PlyBinaryReader(data, name, h), h);
}

// ================================================================================================================
// STL
// ================================================================================================================

// Welds identical corner positions into one vertex (STL stores every triangle corner separately). Sort-based:
// the corners are sorted by (position bits, corner), so equal positions form runs and the first corner of a run
// names the vertex. O(n log n) for any input: unlike a hash table, no choice of coordinates can make it slow.
class Welder {
public:
    //! Records the next corner (its index is the number of corners added before it).
    void add(glm::vec3 p) {
        p += glm::vec3(0.0f);  // -0 becomes +0, so the two weld
        corners_.push_back({std::bit_cast<std::uint32_t>(p.x), std::bit_cast<std::uint32_t>(p.y),
                            std::bit_cast<std::uint32_t>(p.z), static_cast<Index>(corners_.size())});
    }
    void reserve(std::size_t corners) { corners_.reserve(corners); }
    std::size_t size() const { return corners_.size(); }
    //! Appends one position per distinct corner position to soup.positions, numbered in order of first use, and
    //! the vertex of every corner, in order, to soup.indices.
    void finish(PolygonSoup& soup) {
        const std::size_t n = corners_.size(), base = soup.indices.size();
        std::sort(corners_.begin(), corners_.end());
        soup.indices.resize(base + n);
        Index* first = soup.indices.data() + base;  // first[c]: the first corner with c's position
        for (std::size_t i = 0; i < n; ++i)
            first[corners_[i].corner] = i > 0 && corners_[i].same_position(corners_[i - 1])
                                            ? first[corners_[i - 1].corner]
                                            : corners_[i].corner;
        std::vector<Corner> by_corner(n);  // positions again, by corner, to number the vertices in corner order
        for (const Corner& c : corners_) by_corner[c.corner] = c;
        corners_ = {};
        for (std::size_t c = 0; c < n; ++c) {
            if (first[c] == c) {  // first use of this position: a new vertex
                const Corner& k = by_corner[c];
                soup.positions.emplace_back(std::bit_cast<float>(k.x), std::bit_cast<float>(k.y),
                                            std::bit_cast<float>(k.z));
                first[c] = static_cast<Index>(soup.positions.size() - 1);
            } else {
                first[c] = first[first[c]];  // first[c] < c is already a vertex number
            }
        }
    }

private:
    struct Corner {
        std::uint32_t x, y, z;  // the float bits
        Index corner;
        bool same_position(const Corner& o) const { return x == o.x && y == o.y && z == o.z; }
        bool operator<(const Corner& o) const { return std::tie(x, y, z, corner) < std::tie(o.x, o.y, o.z, o.corner); }
    };
    std::vector<Corner> corners_;
};

void expect_keyword(TextParser& in, std::string_view word) {
    std::string_view t = in.token_any_line();
    if (t.empty()) in.fail("unexpected end of file: expected '" + std::string(word) + "' (truncated file)");
    if (!iequals(t, word)) in.fail("expected '" + std::string(word) + "', found " + quote(t));
}

float stl_coordinate(TextParser& in) {
    double v = in.check_real(in.token_any_line(), "vertex coordinate");
    if (std::abs(v) > std::numeric_limits<float>::max()) in.fail("vertex coordinate does not fit in a float");
    return static_cast<float>(v);
}

void read_stl_facet(TextParser& in, std::size_t facet, Welder& weld, PolygonSoup& soup) {
    if (weld.size() + 3 > max_index) in.fail("too many triangles");
    expect_keyword(in, "normal");
    for (int k = 0; k < 3; ++k)  // the normal is recomputed by whoever needs it
        if (!to_double(in.token_any_line())) in.fail("malformed normal of facet " + std::to_string(facet));
    expect_keyword(in, "outer");
    expect_keyword(in, "loop");
    for (int c = 0; c < 3; ++c) {
        expect_keyword(in, "vertex");
        glm::vec3 p;
        for (int k = 0; k < 3; ++k) p[k] = stl_coordinate(in);
        weld.add(p);
    }
    expect_keyword(in, "endloop");
    expect_keyword(in, "endfacet");
    soup.offsets.push_back(static_cast<Index>(weld.size()));
}

PolygonSoup read_stl_ascii(std::string_view text, const std::string& name) {
    TextParser in(text, name, '\0');
    if (!in.next_line() || !iequals(in.token(), "solid")) in.fail("not an ascii STL file (no 'solid' line)");
    in.rest_of_line();  // the solid's name
    PolygonSoup soup;
    Welder weld;
    for (std::size_t facet = 0;; ++facet) {
        std::string_view t = in.token_any_line();
        if (iequals(t, "endsolid")) break;
        if (t.empty()) in.fail("unexpected end of file: expected 'facet' or 'endsolid' (truncated file)");
        if (!iequals(t, "facet")) in.fail("expected 'facet' or 'endsolid', found " + quote(t));
        read_stl_facet(in, facet, weld, soup);
    }
    in.rest_of_line();
    if (in.next_line()) in.fail("unexpected data after 'endsolid'");
    weld.finish(soup);
    return soup;
}

constexpr std::size_t stl_header_bytes = 84, stl_triangle_bytes = 50;

std::uint32_t load_u32_le(const char* p) {
    std::array<unsigned char, 4> b;
    std::memcpy(b.data(), p, 4);
    return b[0] | (b[1] << 8) | (b[2] << 16) | (std::uint32_t(b[3]) << 24);
}

float load_f32_le(const char* p) { return std::bit_cast<float>(load_u32_le(p)); }

// Binary when the size matches the triangle count; otherwise ascii if the text (after a BOM and spaces) starts
// with "solid" in any case.
bool is_binary_stl(std::string_view data, std::string_view text) {
    if (data.size() >= stl_header_bytes &&
        stl_header_bytes + stl_triangle_bytes * std::uint64_t(load_u32_le(data.data() + 80)) == data.size())
        return true;
    std::size_t start = 0;
    while (start < text.size() && is_space(text[start])) ++start;
    return !iequals(text.substr(start, 5), "solid");
}

PolygonSoup read_stl_binary(std::string_view data, const std::string& name) {
    if (data.size() < stl_header_bytes)
        throw IoError(name, 0,
                      "truncated binary STL: " + std::to_string(data.size()) + " bytes, the header alone is 84");
    std::uint64_t n = load_u32_le(data.data() + 80);
    std::uint64_t expected = stl_header_bytes + stl_triangle_bytes * n;
    if (expected != data.size()) {
        std::uint64_t whole = (data.size() - stl_header_bytes) / stl_triangle_bytes;
        throw IoError(name, 0,
                      "element " + std::to_string(std::min(whole, n)) + ": header declares " + std::to_string(n) +
                          " triangles (" + std::to_string(expected) + " bytes) but the file has " +
                          std::to_string(data.size()) + " bytes (" +
                          (expected > data.size() ? "truncated" : "extra data") + ")");
    }
    if (3 * n > max_index) throw IoError(name, 0, "too many triangles (" + std::to_string(n) + ")");
    PolygonSoup soup;
    Welder weld;
    weld.reserve(3 * n);
    soup.offsets.reserve(n + 1);
    for (std::uint64_t t = 0; t < n; ++t) {
        const char* corner = data.data() + stl_header_bytes + t * stl_triangle_bytes + 12;  // past the normal
        for (int c = 0; c < 3; ++c, corner += 12) {
            glm::vec3 p(load_f32_le(corner), load_f32_le(corner + 4), load_f32_le(corner + 8));
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                throw IoError(name, 0, "element " + std::to_string(t) + ": triangle has a non-finite coordinate");
            weld.add(p);
        }
        soup.offsets.push_back(static_cast<Index>(weld.size()));
    }
    weld.finish(soup);
    return soup;
}

// ================================================================================================================
// Writers: the whole file is built in memory, then written at once
// ================================================================================================================

class TextWriter {
public:
    TextWriter& operator<<(std::string_view s) {
        out_ += s;
        return *this;
    }
    TextWriter& operator<<(double v) { return put(v); }
    TextWriter& operator<<(float v) { return put(v); }
    TextWriter& operator<<(std::uint64_t v) { return put(v); }
    TextWriter& operator<<(std::uint32_t v) { return put(v); }
    std::string& str() { return out_; }

private:
    template <class T>
    TextWriter& put(T v) {  // shortest text that reads back to exactly v
        char buf[32];
        auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
        out_.append(buf, end);
        return *this;
    }
    std::string out_;
};

// "x y z\n" with the shortest decimals that read back to exactly p.
void write_position(TextWriter& out, const glm::dvec3& p) { out << p.x << " " << p.y << " " << p.z << "\n"; }

std::string off_text(const PolygonSoup& soup) {
    TextWriter out;
    out << "OFF\n" << std::uint64_t(soup.n_vertices()) << " " << std::uint64_t(soup.n_faces()) << " 0\n";
    for (const auto& p : soup.positions) write_position(out, p);
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        auto vs = soup.face(f);
        out << std::uint64_t(vs.size());
        for (Index v : vs) out << " " << v;
        out << "\n";
    }
    return std::move(out.str());
}

std::string obj_text(const PolygonSoup& soup) {
    TextWriter out;
    out << "# written by geolab\n";
    for (const auto& p : soup.positions) {
        out << "v ";
        write_position(out, p);
    }
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        out << "f";
        for (Index v : soup.face(f)) out << " " << std::uint64_t(v) + 1;
        out << "\n";
    }
    return std::move(out.str());
}

// Appends the bytes of v in the requested byte order.
template <class T>
void put_bytes(std::string& out, T v, bool little_endian) {
    std::array<char, sizeof(T)> b;
    std::memcpy(b.data(), &v, sizeof(T));
    if (little_endian != (std::endian::native == std::endian::little)) std::reverse(b.begin(), b.end());
    out.append(b.data(), b.size());
}

std::size_t max_face_size(const PolygonSoup& soup) {
    std::size_t m = 0;
    for (std::size_t f = 0; f < soup.n_faces(); ++f)
        m = std::max<std::size_t>(m, soup.offsets[f + 1] - soup.offsets[f]);
    return m;
}

std::string ply_data(const PolygonSoup& soup, MeshFormat format) {
    const bool ascii = format == MeshFormat::ply_ascii, le = format == MeshFormat::ply_binary_le;
    const bool wide_count = max_face_size(soup) > 255;
    TextWriter out;
    out << "ply\nformat " << (ascii ? "ascii" : le ? "binary_little_endian" : "binary_big_endian") << " 1.0\n";
    out << "comment written by geolab\n";
    out << "element vertex " << std::uint64_t(soup.n_vertices()) << "\n";
    out << "property double x\nproperty double y\nproperty double z\n";
    out << "element face " << std::uint64_t(soup.n_faces()) << "\n";
    out << "property list " << (wide_count ? "uint" : "uchar") << " uint vertex_indices\nend_header\n";
    if (ascii) {
        for (const auto& p : soup.positions) write_position(out, p);
        for (std::size_t f = 0; f < soup.n_faces(); ++f) {
            out << std::uint64_t(soup.face(f).size());
            for (Index v : soup.face(f)) out << " " << v;
            out << "\n";
        }
        return std::move(out.str());
    }
    std::string& bytes = out.str();
    bytes.reserve(bytes.size() + 24 * soup.n_vertices() + 13 * soup.n_faces());
    for (const auto& p : soup.positions)
        for (int k = 0; k < 3; ++k) put_bytes(bytes, p[k], le);
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        auto vs = soup.face(f);
        if (wide_count)
            put_bytes(bytes, static_cast<std::uint32_t>(vs.size()), le);
        else
            put_bytes(bytes, static_cast<std::uint8_t>(vs.size()), le);
        for (Index v : vs) put_bytes(bytes, v, le);
    }
    return std::move(bytes);
}

// Calls emit(a, b, c) for each triangle of a fan over every face (STL only stores triangles).
template <class Emit>
void for_each_fan_triangle(const PolygonSoup& soup, Emit emit) {
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        auto vs = soup.face(f);
        for (std::size_t k = 1; k + 1 < vs.size(); ++k)
            emit(glm::vec3(soup.positions[vs[0]]), glm::vec3(soup.positions[vs[k]]),
                 glm::vec3(soup.positions[vs[k + 1]]));
    }
}

glm::vec3 unit_normal(glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    glm::vec3 n = glm::cross(b - a, c - a);
    float len = glm::length(n);
    return len > 0 ? n / len : glm::vec3(0.0f);
}

std::string stl_ascii_text(const PolygonSoup& soup) {
    TextWriter out;
    out << "solid geolab\n";
    auto vertex = [&](glm::vec3 p) { out << "      vertex " << p.x << " " << p.y << " " << p.z << "\n"; };
    for_each_fan_triangle(soup, [&](glm::vec3 a, glm::vec3 b, glm::vec3 c) {
        glm::vec3 n = unit_normal(a, b, c);
        out << "  facet normal " << n.x << " " << n.y << " " << n.z << "\n    outer loop\n";
        vertex(a), vertex(b), vertex(c);
        out << "    endloop\n  endfacet\n";
    });
    out << "endsolid geolab\n";
    return std::move(out.str());
}

std::string stl_binary_data(const PolygonSoup& soup) {
    std::string bytes(80, '\0');
    std::string_view title = "binary STL written by geolab";  // must not start with "solid"
    bytes.replace(0, title.size(), title);
    std::uint64_t n = 0;
    for_each_fan_triangle(soup, [&](glm::vec3, glm::vec3, glm::vec3) { ++n; });
    if (n > std::numeric_limits<std::uint32_t>::max())
        throw std::invalid_argument("write_mesh: too many triangles for STL");
    put_bytes(bytes, static_cast<std::uint32_t>(n), true);
    bytes.reserve(bytes.size() + stl_triangle_bytes * n);
    for_each_fan_triangle(soup, [&](glm::vec3 a, glm::vec3 b, glm::vec3 c) {
        for (glm::vec3 p : {unit_normal(a, b, c), a, b, c})
            for (int k = 0; k < 3; ++k) put_bytes(bytes, p[k], true);
        put_bytes(bytes, std::uint16_t{0}, true);  // attribute byte count
    });
    return bytes;
}

void write_file(const std::filesystem::path& path, const std::string& data) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "wb"), &std::fclose);
    if (!f) throw IoError(path.string(), 0, std::string("cannot open for writing: ") + std::strerror(errno));
    if (std::fwrite(data.data(), 1, data.size(), f.get()) != data.size() || std::fflush(f.get()) != 0)
        throw IoError(path.string(), 0, std::string("write failed: ") + std::strerror(errno));
}

// What a file that is not a regular file is, for the error message.
std::string file_kind(mode_t mode) {
    if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

std::string mebibytes(std::uint64_t bytes) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f MiB", static_cast<double>(bytes) / (1 << 20));
    return buf;
}

[[noreturn]] void throw_too_large(const std::filesystem::path& path, std::string_view size, std::uint64_t max_bytes) {
    throw IoError(path.string(), 0,
                  "the file is " + std::string(size) + ", more than the limit of " + mebibytes(max_bytes) +
                      " (raise it with the environment variable GEOLAB_MAX_FILE_MB, or geolab info --max-file-mb)");
}

// The whole file. Opened without blocking (a FIFO with no writer), then refused unless it is a regular file
// (fstat on the open descriptor: a symlink to /dev/zero is a character device); never reads more than
// max_bytes + 1 bytes, even from a file that grows while it is read.
std::string read_file(const std::filesystem::path& path, std::uint64_t max_bytes) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) throw IoError(path.string(), 0, std::string("cannot open: ") + std::strerror(errno));
    const std::unique_ptr<const int, void (*)(const int*)> closer(&fd, [](const int* f) { ::close(*f); });
    struct stat st {};
    if (::fstat(fd, &st) != 0) throw IoError(path.string(), 0, std::string("cannot stat: ") + std::strerror(errno));
    if (S_ISDIR(st.st_mode)) throw IoError(path.string(), 0, "is a directory, not a file");
    if (!S_ISREG(st.st_mode))
        throw IoError(path.string(), 0, "is " + file_kind(st.st_mode) + ", not a regular file: only files are read");
    const auto size = static_cast<std::uint64_t>(st.st_size);
    if (size > max_bytes) throw_too_large(path, mebibytes(size), max_bytes);
    std::string data(size, '\0');
    std::size_t have = 0;
    while (true) {
        if (have == data.size()) {  // the file may have grown since fstat: read on, up to the limit
            if (have > max_bytes) throw_too_large(path, "larger than that (it grew while read)", max_bytes);
            data.resize(std::min<std::uint64_t>(max_bytes + 1, have + (1 << 16)));
        }
        const ssize_t n = ::read(fd, data.data() + have, data.size() - have);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throw IoError(path.string(), 0, std::string("read failed: ") + std::strerror(errno));
        if (n == 0) break;
        have += static_cast<std::size_t>(n);
    }
    if (have > max_bytes) throw_too_large(path, "larger than that (it grew while read)", max_bytes);
    data.resize(have);
    return data;
}

// Indices out of range would make the writers read out of bounds.
void check_indices(const PolygonSoup& soup) {
    if (soup.offsets.empty() || soup.offsets.back() != soup.indices.size())
        throw std::invalid_argument("write_mesh: soup offsets do not match its indices");
    for (Index v : soup.indices)
        if (v >= soup.n_vertices())
            throw std::invalid_argument("write_mesh: vertex index " + std::to_string(v) + " out of range (" +
                                        std::to_string(soup.n_vertices()) + " vertices)");
}

}  // namespace

MeshFormat format_from_extension(const std::filesystem::path& path) {
    const std::string ext = lowercase(path.extension().string());
    if (ext == ".obj") return MeshFormat::obj;
    if (ext == ".off") return MeshFormat::off;
    if (ext == ".ply") return MeshFormat::ply_binary_le;
    if (ext == ".stl") return MeshFormat::stl_binary;
    throw IoError(path.string(), 0,
                  "unknown mesh format " + (ext.empty() ? std::string("(no extension)") : quote(ext)) +
                      " (expected .obj, .off, .ply or .stl)");
}

namespace {
// The limit from GEOLAB_MAX_FILE_MB (default 1024 MiB); a bad value is an IoError naming `file`.
std::uint64_t max_file_bytes_from_env(const std::string& file) {
    constexpr std::uint64_t mib = 1 << 20, default_mib = 1024;
    const char* env = std::getenv("GEOLAB_MAX_FILE_MB");
    if (env == nullptr || *env == '\0') return default_mib * mib;
    std::optional<std::int64_t> v = to_int(env);
    if (!v || *v <= 0 || static_cast<std::uint64_t>(*v) > (std::uint64_t(1) << 40))
        throw IoError(file, 0,
                      "the environment variable GEOLAB_MAX_FILE_MB must be a positive whole number of MiB (at most "
                      "2^40), not " +
                          quote(env));
    return static_cast<std::uint64_t>(*v) * mib;
}
}  // namespace

std::uint64_t default_max_file_bytes() { return max_file_bytes_from_env("GEOLAB_MAX_FILE_MB"); }

std::string read_text_file(const std::filesystem::path& path, const ReadOptions& options) {
    const std::uint64_t max_bytes =
        options.max_file_bytes ? options.max_file_bytes : max_file_bytes_from_env(path.string());
    return read_file(path, max_bytes);
}

PolygonSoup read_mesh(const std::filesystem::path& path, const ReadOptions& options) {
    MeshFormat format = format_from_extension(path);
    const std::uint64_t max_bytes =
        options.max_file_bytes ? options.max_file_bytes : max_file_bytes_from_env(path.string());
    return read_mesh_from_string(read_file(path, max_bytes), format, path.string());
}

PolygonSoup read_mesh_from_string(const std::string& data, MeshFormat format, const std::string& name) {
    // Text starts after a UTF-8 byte order mark. A binary STL is tested on all its bytes (its 80-byte header is
    // free text that may start with anything).
    std::string_view text = data;
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
    if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw IoError(name, 0, "empty file");
    try {
        switch (format) {
            case MeshFormat::obj:
                return read_obj(text, name);
            case MeshFormat::off:
                return read_off(text, name);
            case MeshFormat::ply_ascii:
            case MeshFormat::ply_binary_le:
            case MeshFormat::ply_binary_be:
                return read_ply(text, name);  // the header names the encoding
            case MeshFormat::stl_ascii:
            case MeshFormat::stl_binary:
                return is_binary_stl(data, text) ? read_stl_binary(data, name) : read_stl_ascii(text, name);
        }
    } catch (const std::bad_alloc&) {  // the readers bound their allocations by the file's size; this is a backstop
        throw IoError(name, 0, "out of memory while reading a " + std::to_string(data.size()) + "-byte file");
    } catch (const std::length_error& e) {
        throw IoError(name, 0, std::string("too large to read: ") + e.what());
    }
    throw IoError(name, 0, "unknown mesh format");
}

void write_mesh(const std::filesystem::path& path, const PolygonSoup& soup) {
    write_mesh(path, soup, format_from_extension(path));
}

void write_mesh(const std::filesystem::path& path, const PolygonSoup& soup, MeshFormat format) {
    check_indices(soup);
    switch (format) {
        case MeshFormat::obj:
            return write_file(path, obj_text(soup));
        case MeshFormat::off:
            return write_file(path, off_text(soup));
        case MeshFormat::ply_ascii:
        case MeshFormat::ply_binary_le:
        case MeshFormat::ply_binary_be:
            return write_file(path, ply_data(soup, format));
        case MeshFormat::stl_ascii:
            return write_file(path, stl_ascii_text(soup));
        case MeshFormat::stl_binary:
            return write_file(path, stl_binary_data(soup));
    }
    throw IoError(path.string(), 0, "unknown mesh format");
}

}  // namespace geolab
