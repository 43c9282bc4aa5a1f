// Volume mesh files: Medit .mesh (ASCII), TetGen .node/.ele/.face, legacy VTK (write). See volume_io.hpp.
#include "geolab/volume_io.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "geolab/errors.hpp"

namespace geolab {

void VolumeMesh::add_cell(VolumeCell type, std::span<const std::uint32_t> v, std::int32_t label) {
    if (v.size() != std::size_t(type))
        throw std::invalid_argument("VolumeMesh::add_cell: " + std::to_string(v.size()) + " corners for a cell of " +
                                    std::to_string(int(type)));
    for (std::uint32_t x : v) corners.push_back(x);
    offsets.push_back(std::uint32_t(corners.size()));
    types.push_back(type);
    labels.push_back(label);
}

void check_volume_mesh(const VolumeMesh& m) {
    if (m.offsets.size() != m.types.size() + 1 || m.labels.size() != m.types.size() || m.offsets.front() != 0 ||
        m.offsets.back() != m.corners.size() || m.triangle_labels.size() != m.triangles.size())
        throw std::invalid_argument("volume mesh: the array sizes do not match");
    for (std::size_t v = 0; v < m.n_vertices(); ++v) {
        const auto& p = m.positions[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw std::invalid_argument("volume mesh: vertex " + std::to_string(v) + " is not finite");
    }
    for (std::size_t c = 0; c < m.n_cells(); ++c) {
        if (m.offsets[c + 1] < m.offsets[c] || m.offsets[c + 1] - m.offsets[c] != std::uint32_t(m.types[c]))
            throw std::invalid_argument("volume mesh: cell " + std::to_string(c) + " has the wrong number of corners");
        const auto cs = m.cell(c);
        for (std::size_t i = 0; i < cs.size(); ++i) {
            if (cs[i] >= m.n_vertices())
                throw std::invalid_argument("volume mesh: cell " + std::to_string(c) + ": vertex " + std::to_string(cs[i]) +
                                            " out of range (" + std::to_string(m.n_vertices()) + " vertices)");
            for (std::size_t j = 0; j < i; ++j)
                if (cs[i] == cs[j])
                    throw std::invalid_argument("volume mesh: cell " + std::to_string(c) + " repeats vertex " +
                                                std::to_string(cs[i]));
        }
    }
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
        for (std::uint32_t x : m.triangles[t])
            if (x >= m.n_vertices())
                throw std::invalid_argument("volume mesh: triangle " + std::to_string(t) + ": vertex " + std::to_string(x) +
                                            " out of range");
}

namespace {

// A word for an error message: quoted, at most 40 bytes, unprintable bytes shown as '?'.
std::string quoted(std::string_view w) {
    std::string q = "'";
    for (char c : w.substr(0, 40)) q += (c >= 32 && c < 127) ? c : '?';
    return q + (w.size() > 40 ? "...'" : "'");
}

// Whitespace-separated words with line numbers; '#' comments to the end of the line; LF, CRLF or CR line ends.
class Words {
public:
    Words(const std::string& text, std::string name) : s_(text), name_(std::move(name)) {
        if (s_.size() >= 3 && s_.compare(0, 3, "\xEF\xBB\xBF") == 0) pos_ = 3;
    }
    [[noreturn]] void fail(const std::string& reason) const { throw IoError(name_, line_, reason); }
    std::size_t line() const { return line_; }
    bool at_end() {
        skip();
        return pos_ >= s_.size();
    }
    //! Bytes not read yet.
    std::size_t left() const { return s_.size() - pos_; }
    std::string_view word(const char* what) {
        skip();
        if (pos_ >= s_.size()) fail(std::string("unexpected end of file: expected ") + what);
        const std::size_t b = pos_;
        while (pos_ < s_.size() && !space(s_[pos_]) && s_[pos_] != '#') ++pos_;
        return std::string_view(s_).substr(b, pos_ - b);
    }
    std::int64_t integer(const char* what) {
        const std::string_view w = word(what);
        std::int64_t v = 0;
        const auto r = std::from_chars(w.data(), w.data() + w.size(), v);
        if (r.ec != std::errc() || r.ptr != w.data() + w.size())
            fail(std::string("expected an integer (") + what + "), got " + quoted(w));
        return v;
    }
    double real(const char* what) {
        const std::string_view w = word(what);
        double v = 0;
        const auto r = std::from_chars(w.data(), w.data() + w.size(), v);
        if (r.ec == std::errc::result_out_of_range) fail(std::string(what) + " is out of the range of a double");
        if (r.ec != std::errc() || r.ptr != w.data() + w.size())
            fail(std::string("expected a number (") + what + "), got " + quoted(w));
        if (!std::isfinite(v)) fail(std::string(what) + " is not finite");
        return v;
    }
    //! A count of entries of `numbers` numbers each: never more than the bytes left can hold (2 bytes a number).
    std::size_t count(const char* what, std::size_t numbers) {
        const std::int64_t n = integer(what);
        if (n < 0) fail(std::string(what) + " is negative (" + std::to_string(n) + ")");
        if (numbers > 0 && std::uint64_t(n) > left() / (2 * numbers))
            fail(std::string(what) + " is " + std::to_string(n) + ", more than the rest of the file can hold");
        return std::size_t(n);
    }
    //! An integer label (Medit reference, TetGen marker) that must fit in 32 bits.
    std::int32_t label(const char* what) {
        const std::int64_t v = integer(what);
        if (v < std::numeric_limits<std::int32_t>::min() || v > std::numeric_limits<std::int32_t>::max())
            fail(std::string(what) + " " + std::to_string(v) + " does not fit in 32 bits");
        return std::int32_t(v);
    }
    //! A 0-based index from a number with the given base, in [0, n).
    std::uint32_t index(const char* what, std::int64_t base, std::size_t n) {
        const std::int64_t v = integer(what);
        if (v < base || v - base >= std::int64_t(n))
            fail(std::string(what) + " " + std::to_string(v) + " out of range (" + std::to_string(n) + " vertices, numbered from " +
                 std::to_string(base) + ")");
        return std::uint32_t(v - base);
    }

private:
    static bool space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
    void skip() {
        while (pos_ < s_.size()) {
            const char c = s_[pos_];
            if (c == '\n') {
                ++line_, ++pos_;
            } else if (c == '\r') {
                ++line_, ++pos_;
                if (pos_ < s_.size() && s_[pos_] == '\n') ++pos_;
            } else if (space(c)) {
                ++pos_;
            } else if (c == '#') {
                while (pos_ < s_.size() && s_[pos_] != '\n' && s_[pos_] != '\r') ++pos_;
            } else {
                break;
            }
        }
    }
    const std::string& s_;
    std::string name_;
    std::size_t pos_ = 0, line_ = 1;
};

bool iequals(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
    return true;
}

std::string number(double v) {
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

std::ofstream open_out(const std::filesystem::path& path) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw IoError(path.string(), 0, "cannot open for writing");
    return out;
}
void close_out(std::ofstream& out, const std::filesystem::path& path) {
    out.flush();
    if (!out) throw IoError(path.string(), 0, "write failed");
}

}  // namespace

VolumeMesh read_medit_from_string(const std::string& data, const std::string& name) {
    Words in(data, name);
    if (in.at_end()) in.fail("empty file");
    VolumeMesh m;
    bool have_vertices = false, have_dimension = false, have_end = false;
    std::map<std::string, std::size_t> seen;  // section (lower case) -> the line of its keyword
    while (!in.at_end()) {
        const std::string_view kw = in.word("a keyword");
        const std::string key(kw);
        // Each keyword once: a second Tetrahedra section would otherwise be appended silently (libMeshb keeps one).
        std::string lower = key;
        std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        if (const auto [it, first] = seen.emplace(lower, in.line()); !first)
            in.fail("a second " + quoted(kw) + " section (the first is at line " + std::to_string(it->second) + ")");
        if (iequals(kw, "End")) {
            have_end = true;
            break;
        }
        if (iequals(kw, "MeshVersionFormatted")) {
            const auto v = in.integer("the version");
            if (v < 1 || v > 4) in.fail("MeshVersionFormatted " + std::to_string(v) + " is not a known version");
        } else if (iequals(kw, "Dimension")) {
            const auto d = in.integer("the dimension");
            if (d != 3) in.fail("Dimension " + std::to_string(d) + ": only 3D meshes are read");
            have_dimension = true;
        } else if (iequals(kw, "Vertices")) {
            const std::size_t n = in.count("the number of vertices", 4);
            if (n > std::numeric_limits<std::uint32_t>::max() - 1) in.fail("too many vertices");
            m.positions.reserve(n);
            for (std::size_t i = 0; i < n; ++i) {
                glm::dvec3 p;
                p.x = in.real("vertex x"), p.y = in.real("vertex y"), p.z = in.real("vertex z");
                (void)in.integer("the vertex reference");
                m.positions.push_back(p);
            }
            have_vertices = true;
        } else if (iequals(kw, "Tetrahedra") || iequals(kw, "Hexahedra") || iequals(kw, "Prisms") ||
                   iequals(kw, "Pyramids")) {
            const VolumeCell type = iequals(kw, "Tetrahedra") ? VolumeCell::tetrahedron
                                    : iequals(kw, "Hexahedra") ? VolumeCell::hexahedron
                                    : iequals(kw, "Prisms")    ? VolumeCell::prism
                                                               : VolumeCell::pyramid;
            if (!have_vertices) in.fail(key + " before Vertices (the vertices must come first)");
            const std::size_t k = std::size_t(type);
            const std::size_t n = in.count(("the number of " + key).c_str(), k + 1);
            if (n > (std::numeric_limits<std::uint32_t>::max() - m.corners.size()) / k) in.fail("too many cells");
            std::uint32_t v[8];
            for (std::size_t i = 0; i < n; ++i) {
                for (std::size_t j = 0; j < k; ++j) v[j] = in.index("a corner index", 1, m.n_vertices());
                for (std::size_t a = 0; a < k; ++a)
                    for (std::size_t b = 0; b < a; ++b)
                        if (v[a] == v[b]) in.fail(key + " entry " + std::to_string(i + 1) + " repeats vertex " + std::to_string(v[a] + 1));
                m.add_cell(type, std::span<const std::uint32_t>(v, k), in.label("the element reference"));
            }
        } else if (iequals(kw, "Triangles")) {
            if (!have_vertices) in.fail("Triangles before Vertices (the vertices must come first)");
            const std::size_t n = in.count("the number of triangles", 4);
            for (std::size_t i = 0; i < n; ++i) {
                std::array<std::uint32_t, 3> t{};
                for (auto& x : t) x = in.index("a corner index", 1, m.n_vertices());
                if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
                    in.fail("Triangles entry " + std::to_string(i + 1) + " repeats a vertex (" + std::to_string(t[0] + 1) +
                            " " + std::to_string(t[1] + 1) + " " + std::to_string(t[2] + 1) + ")");
                m.triangles.push_back(t);
                m.triangle_labels.push_back(in.label("the triangle reference"));
            }
        } else {
            // sections read and ignored: their entries' sizes
            struct Skip {
                const char* name;
                int ints, reals;
            };
            static const Skip skips[] = {{"Edges", 3, 0},         {"Quadrilaterals", 5, 0},  {"Corners", 1, 0},
                                         {"Ridges", 1, 0},        {"RequiredVertices", 1, 0}, {"RequiredEdges", 1, 0},
                                         {"Normals", 0, 3},       {"NormalAtVertices", 2, 0}, {"Tangents", 0, 3},
                                         {"TangentAtEdges", 3, 0}};
            const Skip* s = nullptr;
            for (const Skip& x : skips)
                if (iequals(kw, x.name)) s = &x;
            if (!s) in.fail("unknown keyword " + quoted(kw));
            const std::size_t n = in.count("the number of entries", std::size_t(s->ints + s->reals));
            for (std::size_t i = 0; i < n; ++i) {
                for (int j = 0; j < s->ints; ++j) (void)in.integer(s->name);
                for (int j = 0; j < s->reals; ++j) (void)in.real(s->name);
            }
        }
    }
    if (!have_dimension && !have_vertices) in.fail("not a Medit mesh (no Dimension and no Vertices)");
    if (!have_vertices) in.fail("no Vertices section");
    // Without End a file cut after a whole section would read as a smaller, valid mesh.
    if (!have_end) in.fail("the file ends without 'End' (truncated?)");
    if (!in.at_end()) in.fail("data after 'End': " + quoted(in.word("")));
    return m;
}

VolumeMesh read_medit(const std::filesystem::path& path, const ReadOptions& options) {
    return read_medit_from_string(read_text_file(path, options), path.string());
}

VolumeMesh read_tetgen_from_strings(const std::string& node, const std::string& ele, const std::string& face,
                                    const std::string& base) {
    VolumeMesh m;
    std::int64_t first = 0;
    {
        Words in(node, base + ".node");
        if (in.at_end()) in.fail("empty file");
        const std::size_t n = in.count("the number of nodes", 4);
        const auto dim = in.integer("the dimension");
        if (dim != 3) in.fail("dimension " + std::to_string(dim) + ": only 3D meshes are read");
        const std::size_t attrs = in.count("the number of attributes", 1);
        const auto marks = in.integer("the number of boundary markers");
        if (marks != 0 && marks != 1) in.fail("the number of boundary markers must be 0 or 1, got " + std::to_string(marks));
        if (n > 0 && in.left() / (2 * (4 + attrs + std::size_t(marks))) < n) in.fail("more nodes than the file can hold");
        if (n > std::numeric_limits<std::uint32_t>::max() - 1) in.fail("too many nodes");
        m.positions.reserve(n);
        for (std::size_t i = 0; i < n; ++i) {
            const auto idx = in.integer("the node index");
            if (i == 0) {
                if (idx != 0 && idx != 1) in.fail("the first node's index must be 0 or 1, got " + std::to_string(idx));
                first = idx;
            } else if (idx != first + std::int64_t(i)) {
                in.fail("node " + std::to_string(idx) + " where node " + std::to_string(first + std::int64_t(i)) +
                        " was expected (nodes must be numbered consecutively)");
            }
            glm::dvec3 p;
            p.x = in.real("node x"), p.y = in.real("node y"), p.z = in.real("node z");
            for (std::size_t a = 0; a < attrs; ++a) (void)in.real("a node attribute");
            if (marks) (void)in.integer("the node's boundary marker");
            m.positions.push_back(p);
        }
        if (!in.at_end()) in.fail("more data after the last node");
    }
    {
        Words in(ele, base + ".ele");
        if (in.at_end()) in.fail("empty file");
        const std::size_t n = in.count("the number of tetrahedra", 5);
        const auto k = in.integer("the nodes per tetrahedron");
        if (k != 4 && k != 10) in.fail("nodes per tetrahedron must be 4 or 10, got " + std::to_string(k));
        const std::size_t attrs = in.count("the number of attributes", 1);
        if (n > 0 && in.left() / (2 * (1 + std::size_t(k) + attrs)) < n) in.fail("more tetrahedra than the file can hold");
        for (std::size_t i = 0; i < n; ++i) {
            const auto idx = in.integer("the tetrahedron index");
            if (idx != first + std::int64_t(i))
                in.fail("tetrahedron " + std::to_string(idx) + " where " + std::to_string(first + std::int64_t(i)) +
                        " was expected (numbered like the nodes, consecutively)");
            std::uint32_t v[10];
            for (int j = 0; j < k; ++j) v[j] = in.index("a corner index", first, m.n_vertices());
            for (int a = 0; a < 4; ++a)
                for (int b = 0; b < a; ++b)
                    if (v[a] == v[b]) in.fail("tetrahedron " + std::to_string(idx) + " repeats node " + std::to_string(v[a] + first));
            std::int32_t label = 0;
            for (std::size_t a = 0; a < attrs; ++a) {
                const double x = in.real("a tetrahedron attribute");
                if (a == 0) {
                    if (x != std::floor(x) || std::abs(x) > 2e9) in.fail("the region attribute must be an integer");
                    label = std::int32_t(x);
                }
            }
            m.add_cell(VolumeCell::tetrahedron, std::span<const std::uint32_t>(v, 4), label);
        }
        if (!in.at_end()) in.fail("more data after the last tetrahedron");
    }
    if (!face.empty()) {
        Words in(face, base + ".face");
        if (in.at_end()) in.fail("empty file");
        const std::size_t n = in.count("the number of faces", 4);
        const auto marks = in.integer("the number of boundary markers");
        if (marks != 0 && marks != 1) in.fail("the number of boundary markers must be 0 or 1, got " + std::to_string(marks));
        for (std::size_t i = 0; i < n; ++i) {
            const auto idx = in.integer("the face index");
            if (idx != first + std::int64_t(i))
                in.fail("face " + std::to_string(idx) + " where " + std::to_string(first + std::int64_t(i)) + " was expected");
            std::array<std::uint32_t, 3> t{};
            for (auto& x : t) x = in.index("a corner index", first, m.n_vertices());
            if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
                in.fail("face " + std::to_string(idx) + " repeats a node (" + std::to_string(t[0] + first) + " " +
                        std::to_string(t[1] + first) + " " + std::to_string(t[2] + first) + ")");
            m.triangles.push_back(t);
            m.triangle_labels.push_back(marks ? in.label("the face's boundary marker") : 0);
        }
        if (!in.at_end()) in.fail("more data after the last face");
    }
    return m;
}

VolumeMesh read_tetgen(const std::filesystem::path& path, const ReadOptions& options) {
    std::filesystem::path base = path;
    const std::string ext = path.extension().string();
    if (ext == ".node" || ext == ".ele" || ext == ".face") base.replace_extension();
    auto with = [&](const char* e) { return std::filesystem::path(base.string() + e); };
    const std::string node = read_text_file(with(".node"), options);
    const std::string ele = read_text_file(with(".ele"), options);
    std::string face;
    std::error_code ec;
    if (std::filesystem::exists(with(".face"), ec)) face = read_text_file(with(".face"), options);
    return read_tetgen_from_strings(node, ele, face, base.string());
}

void write_medit(const std::filesystem::path& path, const VolumeMesh& m) {
    check_volume_mesh(m);
    std::ofstream out = open_out(path);
    out << "MeshVersionFormatted 2\n\nDimension 3\n\nVertices\n" << m.n_vertices() << "\n";
    for (const auto& p : m.positions) out << number(p.x) << ' ' << number(p.y) << ' ' << number(p.z) << " 0\n";
    const std::pair<VolumeCell, const char*> kinds[] = {{VolumeCell::tetrahedron, "Tetrahedra"},
                                                        {VolumeCell::hexahedron, "Hexahedra"},
                                                        {VolumeCell::prism, "Prisms"},
                                                        {VolumeCell::pyramid, "Pyramids"}};
    for (const auto& [type, name] : kinds) {
        std::size_t n = 0;
        for (VolumeCell t : m.types) n += t == type;
        if (n == 0) continue;
        out << "\n" << name << "\n" << n << "\n";
        for (std::size_t c = 0; c < m.n_cells(); ++c) {
            if (m.types[c] != type) continue;
            for (std::uint32_t v : m.cell(c)) out << v + 1 << ' ';
            out << m.labels[c] << "\n";
        }
    }
    if (!m.triangles.empty()) {
        out << "\nTriangles\n" << m.triangles.size() << "\n";
        for (std::size_t t = 0; t < m.triangles.size(); ++t)
            out << m.triangles[t][0] + 1 << ' ' << m.triangles[t][1] + 1 << ' ' << m.triangles[t][2] + 1 << ' '
                << m.triangle_labels[t] << "\n";
    }
    out << "\nEnd\n";
    close_out(out, path);
}

void write_tetgen(const std::filesystem::path& base, const VolumeMesh& m) {
    check_volume_mesh(m);
    for (VolumeCell t : m.types)
        if (t != VolumeCell::tetrahedron) throw std::invalid_argument("write_tetgen: TetGen files hold tetrahedra only");
    const std::filesystem::path node = base.string() + ".node", ele = base.string() + ".ele", face = base.string() + ".face";
    {
        std::ofstream out = open_out(node);
        out << m.n_vertices() << " 3 0 0\n";
        for (std::size_t v = 0; v < m.n_vertices(); ++v)
            out << v << ' ' << number(m.positions[v].x) << ' ' << number(m.positions[v].y) << ' ' << number(m.positions[v].z) << "\n";
        out << "# written by geolab\n";
        close_out(out, node);
    }
    {
        std::ofstream out = open_out(ele);
        out << m.n_cells() << " 4 1\n";
        for (std::size_t c = 0; c < m.n_cells(); ++c) {
            out << c;
            for (std::uint32_t v : m.cell(c)) out << ' ' << v;
            out << ' ' << m.labels[c] << "\n";
        }
        out << "# written by geolab\n";
        close_out(out, ele);
    }
    if (!m.triangles.empty()) {
        std::ofstream out = open_out(face);
        out << m.triangles.size() << " 1\n";
        for (std::size_t t = 0; t < m.triangles.size(); ++t)
            out << t << ' ' << m.triangles[t][0] << ' ' << m.triangles[t][1] << ' ' << m.triangles[t][2] << ' '
                << m.triangle_labels[t] << "\n";
        out << "# written by geolab\n";
        close_out(out, face);
    }
}

void write_vtk(const std::filesystem::path& path, const VolumeMesh& m, const std::vector<double>& scalars,
               const std::string& scalar_name) {
    check_volume_mesh(m);
    if (!scalars.empty() && scalars.size() != m.n_cells())
        throw std::invalid_argument("write_vtk: " + std::to_string(scalars.size()) + " cell scalars for " +
                                    std::to_string(m.n_cells()) + " cells");
    for (char c : scalar_name)
        if (std::isspace(static_cast<unsigned char>(c))) throw std::invalid_argument("write_vtk: the scalar name has a space");
    std::ofstream out = open_out(path);
    out << "# vtk DataFile Version 3.0\ngeolab volume mesh\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS " << m.n_vertices()
        << " double\n";
    for (const auto& p : m.positions) out << number(p.x) << ' ' << number(p.y) << ' ' << number(p.z) << "\n";
    out << "CELLS " << m.n_cells() << ' ' << m.n_cells() + m.corners.size() << "\n";
    for (std::size_t c = 0; c < m.n_cells(); ++c) {
        const auto v = m.cell(c);
        out << v.size();
        if (m.types[c] == VolumeCell::prism) {
            // VTK's wedge: the first triangle's normal points AWAY from the second; ours points toward it
            const std::uint32_t w[6] = {v[0], v[2], v[1], v[3], v[5], v[4]};
            for (std::uint32_t x : w) out << ' ' << x;
        } else {
            for (std::uint32_t x : v) out << ' ' << x;
        }
        out << "\n";
    }
    out << "CELL_TYPES " << m.n_cells() << "\n";
    for (VolumeCell t : m.types)
        out << (t == VolumeCell::tetrahedron ? 10 : t == VolumeCell::hexahedron ? 12 : t == VolumeCell::prism ? 13 : 14) << "\n";
    out << "CELL_DATA " << m.n_cells() << "\nSCALARS label int 1\nLOOKUP_TABLE default\n";
    for (std::int32_t l : m.labels) out << l << "\n";
    if (!scalars.empty()) {
        out << "SCALARS " << scalar_name << " double 1\nLOOKUP_TABLE default\n";
        for (double s : scalars) out << number(s) << "\n";
    }
    close_out(out, path);
}

}  // namespace geolab
