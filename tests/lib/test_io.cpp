// Tests of geolab's mesh I/O: round trips of every fixture through every format, hand-written files in each
// format's variants, and every kind of bad input (which must throw IoError naming file, line/element, reason).
#include <doctest/doctest.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <iterator>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "geolab/fixtures.hpp"
#include "geolab/io.hpp"
#include "geolab/models.hpp"

namespace {

namespace fs = std::filesystem;
namespace fx = geolab::fixtures;
using geolab::IoError;
using geolab::MeshFormat;
using geolab::PolygonSoup;
using geolab::read_mesh_from_string;

// A fresh folder for this process's files, removed at exit.
struct ScratchDir {
    fs::path dir = fs::temp_directory_path() / ("geolab_test_io_" + std::to_string(::getpid()));
    ScratchDir() { fs::create_directories(dir); }
    ~ScratchDir() {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
    fs::path operator/(const std::string& name) const { return dir / name; }
};

const ScratchDir& scratch() {
    static ScratchDir d;
    return d;
}

void write_bytes(const fs::path& path, const std::string& data) { std::ofstream(path, std::ios::binary) << data; }

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// what() of the IoError that reading `data` throws, or a note saying what happened instead.
std::string io_error_message(const std::string& data, MeshFormat format, const std::string& name) {
    try {
        read_mesh_from_string(data, format, name);
    } catch (const IoError& e) {
        return e.what();
    } catch (const std::exception& e) {
        return std::string("wrong exception type: ") + e.what();
    }
    return "no exception";
}

// Reading `data` throws IoError whose message names `where` ("file:line:" or "element ...") and has `reason`.
#define CHECK_IO_ERROR(data, format, name, where, reason)                    \
    do {                                                                     \
        CHECK_THROWS_AS(read_mesh_from_string(data, format, name), IoError); \
        const std::string msg_ = io_error_message(data, format, name);       \
        CHECK_MESSAGE(contains(msg_, name), msg_);                           \
        CHECK_MESSAGE(contains(msg_, where), msg_);                          \
        CHECK_MESSAGE(contains(msg_, reason), msg_);                         \
    } while (0)

std::vector<std::pair<std::string, PolygonSoup>> all_fixtures() {
    return {{"tetrahedron", fx::tetrahedron()},
            {"cube", fx::cube()},
            {"cube_triangulated", fx::cube(true)},
            {"icosphere2", fx::icosphere(2)},
            {"torus_quads", fx::torus(8, 6, 1.0, 0.35, false)},
            {"torus", fx::torus()},
            {"grid", fx::grid(3, 5)},
            {"two_components", fx::two_components()},
            {"bowtie", fx::bowtie()},
            {"fan", fx::fan()},
            {"mobius", fx::mobius()},
            {"mobius_quads", fx::mobius(7, false)}};
}

std::vector<std::uint32_t> face_of(const PolygonSoup& s, std::size_t f) { return {s.face(f).begin(), s.face(f).end()}; }

// Exact formats: same positions bit for bit, same faces.
void check_same_soup(const PolygonSoup& got, const PolygonSoup& want) {
    REQUIRE(got.n_vertices() == want.n_vertices());
    REQUIRE(got.n_faces() == want.n_faces());
    for (std::size_t v = 0; v < want.n_vertices(); ++v) {
        CAPTURE(v);
        CHECK(got.positions[v] == want.positions[v]);
    }
    CHECK(got.offsets == want.offsets);
    CHECK(got.indices == want.indices);
}

// STL: triangles of the fans over each face, in order, positions equal up to float rounding; welding restores
// one vertex per distinct position.
void check_same_triangles(const PolygonSoup& got, const PolygonSoup& want) {
    std::vector<glm::dvec3> corners;
    for (std::size_t f = 0; f < want.n_faces(); ++f)
        for (std::size_t k = 1; k + 1 < want.face(f).size(); ++k)
            for (std::size_t c : {std::size_t(0), k, k + 1}) corners.push_back(want.positions[want.face(f)[c]]);
    REQUIRE(got.is_triangle_soup());
    REQUIRE(got.n_faces() * 3 == corners.size());
    CHECK(got.n_vertices() == want.n_vertices());  // every fixture vertex is used and distinct
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const glm::dvec3 p = got.positions[got.indices[i]];
        CAPTURE(i);
        CHECK(glm::length(p - corners[i]) <= 1e-6 * (1 + glm::length(corners[i])));
    }
}

// A binary PLY value in the given byte order.
template <class T>
void put(std::string& out, T v, bool big_endian) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if (big_endian == (std::endian::native == std::endian::little)) std::reverse(b, b + sizeof(T));
    out.append(b, sizeof(T));
}

const std::string tetra_off =
    "OFF\n"
    "4 4 6\n"
    "0.0 0.0 0.0\n"
    "1.0 0.0 0.0\n"
    "0.0 1.0 0.0\n"
    "0.0 0.0 1.0\n"
    "3 0 2 1\n"
    "3 0 1 3\n"
    "3 0 3 2\n"
    "3 1 2 3\n";

}  // namespace

TEST_SUITE("io") {
    // ---- formats and round trips -----------------------------------------------------------------------------------

    TEST_CASE("format_from_extension: known extensions in any case, unknown ones throw") {
        CHECK(geolab::format_from_extension("a.obj") == MeshFormat::obj);
        CHECK(geolab::format_from_extension("dir/a.OFF") == MeshFormat::off);
        CHECK(geolab::format_from_extension("a.ply") == MeshFormat::ply_binary_le);
        CHECK(geolab::format_from_extension("a.Stl") == MeshFormat::stl_binary);
        CHECK_THROWS_AS(geolab::format_from_extension("mesh.xyz"), IoError);
        CHECK_THROWS_AS(geolab::format_from_extension("mesh"), IoError);
        try {
            geolab::format_from_extension("mesh.xyz");
        } catch (const IoError& e) {
            CHECK(contains(e.what(), "mesh.xyz"));
            CHECK(contains(e.what(), "unknown"));
        }
    }

    TEST_CASE("round trip: every fixture through every format") {
        const std::vector<std::pair<MeshFormat, std::string>> formats = {
            {MeshFormat::obj, ".obj"},           {MeshFormat::off, ".off"},           {MeshFormat::ply_ascii, ".ply"},
            {MeshFormat::ply_binary_le, ".ply"}, {MeshFormat::ply_binary_be, ".ply"}, {MeshFormat::stl_ascii, ".stl"},
            {MeshFormat::stl_binary, ".stl"}};
        for (const auto& [name, soup] : all_fixtures()) {
            for (std::size_t i = 0; i < formats.size(); ++i) {
                const auto& [format, ext] = formats[i];
                const fs::path path = scratch() / (name + "_" + std::to_string(i) + ext);
                CAPTURE(path.string());
                geolab::write_mesh(path, soup, format);
                PolygonSoup back = geolab::read_mesh(path);
                if (format == MeshFormat::stl_ascii || format == MeshFormat::stl_binary)
                    check_same_triangles(back, soup);
                else
                    check_same_soup(back, soup);
            }
        }
    }

    TEST_CASE("write_mesh picks the format from the extension; PLY/STL default to binary") {
        const PolygonSoup cube = fx::cube(true);
        geolab::write_mesh(scratch() / "ext.ply", cube);
        geolab::write_mesh(scratch() / "ext.stl", cube);
        std::ifstream ply(scratch() / "ext.ply", std::ios::binary);
        std::string header((std::istreambuf_iterator<char>(ply)), {});
        CHECK(contains(header, "format binary_little_endian"));
        CHECK(fs::file_size(scratch() / "ext.stl") == 84 + 50 * 12);
        CHECK_THROWS_AS(geolab::write_mesh(scratch() / "ext.xyz", cube), IoError);
        CHECK_THROWS_AS(geolab::write_mesh("/nonexistent-folder-geolab/x.off", cube), IoError);
    }

    TEST_CASE("read_mesh: a missing file or a folder throws IoError naming it") {
        CHECK_THROWS_AS(geolab::read_mesh(scratch() / "missing.off"), IoError);
        try {
            geolab::read_mesh(scratch() / "missing.off");
        } catch (const IoError& e) {
            CHECK(contains(e.what(), "missing.off"));
        }
        fs::create_directories(scratch() / "folder.off");
        CHECK_THROWS_AS(geolab::read_mesh(scratch() / "folder.off"), IoError);
        CHECK_THROWS_AS(geolab::read_mesh(scratch() / "file.unknown"), IoError);
    }

    // ---- OFF
    // ---------------------------------------------------------------------------------------------------------

    TEST_CASE("OFF: comments, header variants, counts on the header line, colours") {
        PolygonSoup t = read_mesh_from_string(tetra_off, MeshFormat::off);
        CHECK(t.n_vertices() == 4);
        CHECK(t.n_faces() == 4);
        CHECK(face_of(t, 0) == std::vector<std::uint32_t>{0, 2, 1});

        const std::string commented =
            "# a comment\nOFF # trailing comment\n\n# another\n3 1 0\n0 0 0 # v0\n1 0 0\n\n0 1 0\n# faces\n3 0 1 2\n";
        CHECK(read_mesh_from_string(commented, MeshFormat::off).n_faces() == 1);

        const std::string same_line = "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
        CHECK(read_mesh_from_string(same_line, MeshFormat::off).n_vertices() == 3);

        const std::string no_keyword = "3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
        CHECK(read_mesh_from_string(no_keyword, MeshFormat::off).n_faces() == 1);

        const std::string coff =
            "COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2 0.5 0.5 0.5\n";
        PolygonSoup c = read_mesh_from_string(coff, MeshFormat::off);
        CHECK(c.n_vertices() == 3);
        CHECK(face_of(c, 0) == std::vector<std::uint32_t>{0, 1, 2});
        CHECK(c.positions[1] == glm::dvec3(1, 0, 0));

        const std::string noff = "NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n";
        CHECK(read_mesh_from_string(noff, MeshFormat::off).n_vertices() == 3);

        const std::string crlf = "OFF\r\n3 1 0\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n";
        CHECK(read_mesh_from_string(crlf, MeshFormat::off).n_faces() == 1);

        const std::string quad_and_tri = "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n4 0 1 2 3\n3 1 4 2\n";
        PolygonSoup q = read_mesh_from_string(quad_and_tri, MeshFormat::off);
        CHECK(q.face(0).size() == 4);
        CHECK(q.face(1).size() == 3);
    }

    TEST_CASE("OFF: bad input throws IoError naming file, line and reason") {
        const MeshFormat off = MeshFormat::off;
        CHECK_IO_ERROR("", off, "empty.off", "empty.off:0:", "empty");
        CHECK_IO_ERROR("\n\n  \n", off, "blank.off", "blank.off:", "empty");
        CHECK_IO_ERROR("# only a comment\n", off, "comment.off", "comment.off:", "empty");
        CHECK_IO_ERROR("OFF\n", off, "nocounts.off", "nocounts.off:1:", "counts");
        // fewer vertices than the header says (long lines, so the size guard does not fire first)
        CHECK_IO_ERROR(
            "OFF\n4 1 0\n0.000000 0.000000 0.000000\n1.000000 0.000000 0.000000\n0.000000 1.00000 0.0000000\n", off,
            "fewverts.off", "fewverts.off:5:", "end of file");
        // fewer faces than the header says
        CHECK_IO_ERROR("OFF\n3 2 0\n0.0000 0.0000 0.0000\n1.0000 0.0000 0.0000\n0.0000 1.0000 0.0000\n3 0 1 2\n", off,
                       "fewfaces.off", "fewfaces.off:6:", "2 faces");
        CHECK_IO_ERROR("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", off, "range.off", "range.off:6:", "out of range");
        CHECK_IO_ERROR("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", off, "negidx.off",
                       "negidx.off:6:", "out of range");
        CHECK_IO_ERROR("OFF\n-3 1 0\n0 0 0\n", off, "negcount.off", "negcount.off:2:", "negative");
        CHECK_IO_ERROR("OFF\n3 -1 0\n0 0 0\n", off, "negfaces.off", "negfaces.off:2:", "negative");
        CHECK_IO_ERROR("OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", off, "nan.off", "nan.off:4:", "not finite");
        CHECK_IO_ERROR("OFF\n3 1 0\n0 0 0\n1 0 0\n0 inf 0\n3 0 1 2\n", off, "inf.off", "inf.off:5:", "not finite");
        CHECK_IO_ERROR("OFF\n3 1 0\n0.0 0 0\n1 0 0\n0 1 0\n2 0 1\n", off, "two.off", "two.off:6:", "at least 3");
        CHECK_IO_ERROR("OFF\n3 1 0\n0 0 0\n1 abc 0\n0 1 0\n3 0 1 2\n", off, "garbage.off", "garbage.off:4:", "'abc'");
        CHECK_IO_ERROR("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 x 2\n", off, "garbage2.off", "garbage2.off:6:", "'x'");
        CHECK_IO_ERROR("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 red\n", off, "colour.off", "colour.off:6:", "'red'");
        CHECK_IO_ERROR("OFF\n3 1 0\n0.0 0.0\n1 0 0\n0 1 0\n3 0 1 2\n", off, "short.off", "short.off:3:", "missing");
        CHECK_IO_ERROR("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n", off, "extra.off",
                       "extra.off:7:", "after the last face");
        CHECK_IO_ERROR("OFF\nthree 1 0\n", off, "word.off", "word.off:2:", "'three'");
        CHECK_IO_ERROR("4OFF\n3 1 0\n", off, "4d.off", "4d.off:1:", "unsupported");
        CHECK_IO_ERROR("OFF BINARY\n", off, "bin.off", "bin.off:1:", "binary");
        std::string binary_junk = "OFF\n3 1 0\n";
        for (int i = 0; i < 64; ++i) binary_junk += char(i * 37 % 256);
        CHECK_IO_ERROR(binary_junk, off, "junk.off", "junk.off:", "expected");
    }

    TEST_CASE("OFF: a huge header count fails fast, before allocating") {
        const std::string tiny = "OFF 999999999999 1 0";  // 20 bytes
        const auto start = std::chrono::steady_clock::now();
        CHECK_IO_ERROR(tiny, MeshFormat::off, "huge.off", "huge.off:1:", "truncated");
        CHECK_IO_ERROR("OFF\n1 99999999999999\n0 0 0\n", MeshFormat::off, "hugef.off", "hugef.off:2:", "faces");
        CHECK_IO_ERROR("OFF\n99999999999999999999999 1 0\n", MeshFormat::off, "overflow.off",
                       "overflow.off:2:", "integer");
        CHECK(std::chrono::steady_clock::now() - start < std::chrono::milliseconds(500));
    }

    // ---- OBJ
    // ---------------------------------------------------------------------------------------------------------

    TEST_CASE("OBJ: v and f only; f corners as i, i/t, i//n, i/t/n and negative (relative) indices") {
        const std::string obj =
            "# comment\nmtllib x.mtl\no thing\n"
            "v 0 0 0\nv 1 0 0\nv 1 1 0 1.0\nv 0 1 0 0.5 0.5 0.5\n"
            "vt 0 0\nvt 1 0\nvn 0 0 1\n"
            "g group\nusemtl m\ns off\n"
            "f 1/1/1 2/2/1 3//1\n"
            "f 1 3/2 4\n"
            "f -4 -2 -1\n"
            "l 1 2\n";
        PolygonSoup s = read_mesh_from_string(obj, MeshFormat::obj, "forms.obj");
        CHECK(s.n_vertices() == 4);
        REQUIRE(s.n_faces() == 3);
        CHECK(face_of(s, 0) == std::vector<std::uint32_t>{0, 1, 2});
        CHECK(face_of(s, 1) == std::vector<std::uint32_t>{0, 2, 3});
        CHECK(face_of(s, 2) == std::vector<std::uint32_t>{0, 2, 3});
        CHECK(s.positions[2] == glm::dvec3(1, 1, 0));

        // negative indices count back from the vertices defined so far
        const std::string relative = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 5 5 5\nf -4 -3 -1\n";
        PolygonSoup r = read_mesh_from_string(relative, MeshFormat::obj);
        CHECK(face_of(r, 0) == std::vector<std::uint32_t>{0, 1, 2});
        CHECK(face_of(r, 1) == std::vector<std::uint32_t>{0, 1, 3});

        const std::string quad = "v 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nv 0 1 0\r\nf 1 2 3 4\r\n";
        CHECK(read_mesh_from_string(quad, MeshFormat::obj).face(0).size() == 4);
    }

    TEST_CASE("OBJ: bad input throws IoError naming file, line and reason") {
        const MeshFormat obj = MeshFormat::obj;
        CHECK_IO_ERROR("", obj, "empty.obj", "empty.obj:0:", "empty");
        CHECK_IO_ERROR("# nothing\n", obj, "nothing.obj", "nothing.obj:", "empty");
        CHECK_IO_ERROR("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", obj, "range.obj", "range.obj:4:", "out of range");
        CHECK_IO_ERROR("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", obj, "neg.obj", "neg.obj:4:", "out of range");
        CHECK_IO_ERROR("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", obj, "zero.obj", "zero.obj:4:", "start at 1");
        CHECK_IO_ERROR("v 0 0 0\nv 1 0 0\nf 1 2\n", obj, "two.obj", "two.obj:3:", "at least 3");
        CHECK_IO_ERROR("v 0 0 0\nv 1 0 nan\n", obj, "nan.obj", "nan.obj:2:", "not finite");
        CHECK_IO_ERROR("v 0 0 0\nv 1 -inf 0\n", obj, "inf.obj", "inf.obj:2:", "not finite");
        CHECK_IO_ERROR("v 0 0 0\nv 1 x 0\n", obj, "garbage.obj", "garbage.obj:2:", "'x'");
        CHECK_IO_ERROR("v 0 0\n", obj, "short.obj", "short.obj:1:", "missing");
        CHECK_IO_ERROR("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3a\n", obj, "tok.obj", "tok.obj:4:", "'3a'");
        CHECK_IO_ERROR("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2/x 3\n", obj, "slash.obj", "slash.obj:4:", "malformed");
        CHECK_IO_ERROR("v 0 0 0\nhello world\n", obj, "stmt.obj", "stmt.obj:2:", "unknown");
    }

    // ---- PLY
    // ---------------------------------------------------------------------------------------------------------

    TEST_CASE("PLY ascii: extra vertex properties, vertex_index with int counts, other elements skipped") {
        const std::string ply =
            "ply\nformat ascii 1.0\ncomment made by hand\nobj_info nothing\n"
            "element vertex 4\n"
            "property float x\nproperty float y\nproperty float z\n"
            "property float nx\nproperty uchar red\nproperty list uchar float extra\n"
            "element edge 1\nproperty int vertex1\nproperty int vertex2\n"
            "element face 2\n"
            "property uchar flags\nproperty list int int vertex_index\nproperty float quality\n"
            "end_header\n"
            "0 0 0 0.5 255 2 1.5 2.5\n1 0 0 0.5 255 0\n1 1 0 0.5 255 1 7\n0 1 0 0.5 255 0\n"
            "0 1\n"
            "7 3 0 1 2 0.5\n"
            "0 4 0 1 2 3 0.25\n";
        PolygonSoup s = read_mesh_from_string(ply, MeshFormat::ply_ascii, "hand.ply");
        CHECK(s.n_vertices() == 4);
        REQUIRE(s.n_faces() == 2);
        CHECK(face_of(s, 0) == std::vector<std::uint32_t>{0, 1, 2});
        CHECK(face_of(s, 1) == std::vector<std::uint32_t>{0, 1, 2, 3});
        CHECK(s.positions[2] == glm::dvec3(1, 1, 0));
    }

    TEST_CASE("PLY binary big endian: float positions, skipped properties, uchar/int lists") {
        std::string ply =
            "ply\nformat binary_big_endian 1.0\n"
            "element vertex 3\nproperty float x\nproperty float y\nproperty float z\nproperty short s\n"
            "property list uchar int extra\n"
            "element face 1\nproperty list uchar int vertex_indices\nproperty double d\n"
            "element other 2\nproperty list int uint stuff\n"
            "end_header\n";
        const float xyz[3][3] = {{0.5f, -1.25f, 2}, {1, 0, 0}, {0, 1, 1e-3f}};
        for (int v = 0; v < 3; ++v) {
            for (float c : xyz[v]) put(ply, c, true);
            put(ply, std::int16_t(-7), true);
            put(ply, std::uint8_t(v), true);  // a list of v ints
            for (int k = 0; k < v; ++k) put(ply, std::int32_t(k), true);
        }
        put(ply, std::uint8_t(3), true);
        for (std::int32_t i : {2, 0, 1}) put(ply, i, true);
        put(ply, 3.5, true);
        for (int k = 0; k < 2; ++k) {
            put(ply, std::int32_t(2), true);
            put(ply, std::uint32_t(9), true);
            put(ply, std::uint32_t(9), true);
        }
        PolygonSoup s = read_mesh_from_string(ply, MeshFormat::ply_binary_be, "be.ply");
        REQUIRE(s.n_vertices() == 3);
        REQUIRE(s.n_faces() == 1);
        for (int v = 0; v < 3; ++v)
            CHECK(s.positions[v] == glm::dvec3(double(xyz[v][0]), double(xyz[v][1]), double(xyz[v][2])));
        CHECK(face_of(s, 0) == std::vector<std::uint32_t>{2, 0, 1});

        // the same file cut short anywhere in the body fails with an element named
        const std::size_t body = ply.find("end_header\n") + 11;
        for (std::size_t cut = body; cut < ply.size(); cut += 5) {
            CAPTURE(cut);
            CHECK_IO_ERROR(ply.substr(0, cut), MeshFormat::ply_binary_be, "cut.ply", "element", "truncated");
        }
    }

    TEST_CASE("PLY binary little endian: double positions, uint count and index types") {
        std::string ply =
            "ply\r\nformat binary_little_endian 1.0\r\nelement vertex 3\r\nproperty double x\r\nproperty double y\r\n"
            "property double z\r\nelement face 1\r\nproperty list uint uint vertex_indices\r\nend_header\n";
        for (double c : {0.1, 0.2, 0.3, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0}) put(ply, c, false);
        put(ply, std::uint32_t(3), false);
        for (std::uint32_t i : {0u, 1u, 2u}) put(ply, i, false);
        PolygonSoup s = read_mesh_from_string(ply, MeshFormat::ply_binary_le, "le.ply");
        CHECK(s.positions[0] == glm::dvec3(0.1, 0.2, 0.3));
        CHECK(face_of(s, 0) == std::vector<std::uint32_t>{0, 1, 2});
    }

    TEST_CASE("PLY: bad input throws IoError naming file, line or element, and reason") {
        const MeshFormat ply = MeshFormat::ply_ascii;
        const std::string head =
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
        const std::string verts = "0 0 0\n1 0 0\n0 1 0\n";
        CHECK_IO_ERROR("", ply, "empty.ply", "empty.ply:0:", "empty");
        CHECK_IO_ERROR("plx\n", ply, "magic.ply", "magic.ply:1:", "not a PLY");
        CHECK_IO_ERROR("ply\nformat ascii 1.0\nelement vertex 3\n", ply, "noend.ply", "noend.ply:3:", "end_header");
        CHECK_IO_ERROR("ply\nformat text 1.0\nend_header\n", ply, "fmt.ply", "fmt.ply:2:", "unknown PLY format");
        CHECK_IO_ERROR("ply\nformat ascii 1.0\nelement vertex -3\nend_header\n", ply, "neg.ply",
                       "neg.ply:3:", "negative");
        CHECK_IO_ERROR(
            "ply\nformat ascii 1.0\nelement vertex 999999999999\nproperty float x\nproperty float y\n"
            "property float z\nend_header\n0 0 0\n",
            ply, "huge.ply", "huge.ply:3:", "truncated");
        CHECK_IO_ERROR("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n",
                       ply, "noz.ply", "noz.ply:", "property z");
        CHECK_IO_ERROR("ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n", ply, "type.ply",
                       "type.ply:4:", "unknown property type");
        CHECK_IO_ERROR(head + verts + "3 0 1 5\n", ply, "range.ply", "range.ply:13:", "out of range");
        CHECK_IO_ERROR(head + verts + "2 0 1     \n", ply, "two.ply", "two.ply:13:", "at least 3");
        CHECK_IO_ERROR(head + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", ply, "nan.ply", "nan.ply:11:", "not finite");
        CHECK_IO_ERROR(head + "0.000000 0.000000 0.000000\n1.000000 0.000000 0.000000\n", ply, "trunc.ply",
                       "trunc.ply:11:", "end of file");
        CHECK_IO_ERROR(head + "0 0 0\n1 0 0\n", ply, "short.ply",
                       "short.ply:3:", "truncated");  // caught by the size check
        CHECK_IO_ERROR(head + verts + "3 0 1 2\n7\n", ply, "extra.ply", "extra.ply:14:", "after the last element");
        CHECK_IO_ERROR(head + verts + "3 0 q 2\n", ply, "garbage.ply", "garbage.ply:13:", "'q'");

        // binary: errors name the element
        std::string bin =
            "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n";
        for (int k = 0; k < 9; ++k) put(bin, float(k == 4 ? 1 : 0), false);
        std::string good_face, bad_face;
        put(good_face, std::uint8_t(3), false);
        put(bad_face, std::uint8_t(3), false);
        for (std::int32_t i : {0, 1, 2}) put(good_face, i, false);
        for (std::int32_t i : {0, 1, 3}) put(bad_face, i, false);
        CHECK_NOTHROW(read_mesh_from_string(bin + good_face + good_face, ply, "ok.ply"));
        CHECK_IO_ERROR(bin + good_face + bad_face, ply, "brange.ply", "element face 1", "out of range");
        CHECK_IO_ERROR(bin + good_face, ply, "bsize.ply", "bsize.ply:7:", "truncated");  // caught by the size check
        std::string long_face;  // a quad whose last index is missing: passes the size check, fails while reading
        put(long_face, std::uint8_t(4), false);
        for (std::int32_t i : {0, 1, 2}) put(long_face, i, false);
        CHECK_IO_ERROR(bin + good_face + long_face, ply, "bshort.ply", "element face 1", "truncated");
        CHECK_IO_ERROR(bin + good_face + good_face + "xx", ply, "bextra.ply", "bextra.ply:0:", "unexpected data");
        std::string nan_vertex = bin;
        const std::size_t first_vertex = bin.find("end_header\n") + 11;
        const float nan = NAN;
        std::memcpy(&nan_vertex[first_vertex + 12], &nan, 4);  // vertex 1, x
        CHECK_IO_ERROR(nan_vertex + good_face + good_face, ply, "bnan.ply", "element vertex 1", "not finite");
        std::string huge =
            "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nelement face 4000000000\nproperty list uchar int vertex_indices\nend_header\n";
        CHECK_IO_ERROR(huge + std::string(36, '\0'), ply, "bhuge.ply", "bhuge.ply:7:", "4000000000");
    }

    // ---- STL
    // ---------------------------------------------------------------------------------------------------------

    TEST_CASE("STL: identical corner positions are welded (the cube has 8 vertices)") {
        for (MeshFormat format : {MeshFormat::stl_binary, MeshFormat::stl_ascii}) {
            CAPTURE(int(format));
            const fs::path path = scratch() / (format == MeshFormat::stl_ascii ? "cube_ascii.stl" : "cube_bin.stl");
            geolab::write_mesh(path, fx::cube(), format);  // quads are split into 12 triangles
            PolygonSoup s = geolab::read_mesh(path);
            CHECK(s.n_vertices() == 8);
            CHECK(s.n_faces() == 12);
            CHECK(s.is_triangle_soup());
        }
        const std::string ascii =
            "solid two\n"
            "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n endloop\nendfacet\n"
            "facet normal 0 0 1\n outer loop\n  vertex 1 0 0\n  vertex 1 1 0\n  vertex 0 1 0\n endloop\nendfacet\n"
            "endsolid two\n";
        PolygonSoup s = read_mesh_from_string(ascii, MeshFormat::stl_ascii, "two.stl");
        CHECK(s.n_vertices() == 4);
        CHECK(face_of(s, 1) == std::vector<std::uint32_t>{1, 3, 2});
    }

    TEST_CASE("STL: bad input throws IoError naming file, line or element, and reason") {
        const MeshFormat stl = MeshFormat::stl_binary;
        CHECK_IO_ERROR("", stl, "empty.stl", "empty.stl:0:", "empty");
        CHECK_IO_ERROR("solid x\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n", stl, "cut.stl",
                       "cut.stl:5:", "end of file");
        CHECK_IO_ERROR(
            "solid x\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 nan 0\n  vertex 0 1 0\n"
            " endloop\nendfacet\nendsolid\n",
            stl, "nan.stl", "nan.stl:5:", "not finite");
        CHECK_IO_ERROR(
            "solid x\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n"
            " endloop\nendfacet\nfacet wobble\n",
            stl, "word.stl", "word.stl:9:", "'wobble'");
        CHECK_IO_ERROR(
            "solid x\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n"
            " endloop\nendfacet\nnonsense\n",
            stl, "garbage.stl", "garbage.stl:9:", "'nonsense'");

        // binary: 84-byte header, then 50 bytes per triangle
        std::string bin(80, 'h');
        put(bin, std::uint32_t(2), false);
        for (int t = 0; t < 2; ++t) {
            for (int k = 0; k < 12; ++k) put(bin, float(k == 3 + t || k == 7 ? 1 : 0), false);  // normal + 3 corners
            put(bin, std::uint16_t(0), false);
        }
        CHECK(read_mesh_from_string(bin, stl, "ok.stl").n_faces() == 2);
        CHECK_IO_ERROR(bin.substr(0, 40), stl, "hdr.stl", "hdr.stl:0:", "truncated");
        CHECK_IO_ERROR(bin.substr(0, 84 + 70), stl, "short.stl", "element 1", "truncated");
        std::string huge = bin.substr(0, 80);
        put(huge, std::uint32_t(4000000000u), false);
        CHECK_IO_ERROR(huge, stl, "huge.stl", "element 0", "4000000000");
        std::string nan_corner = bin;
        const float nan = NAN;
        std::memcpy(&nan_corner[84 + 50 + 12 + 4], &nan, 4);  // triangle 1, corner 0, y
        CHECK_IO_ERROR(nan_corner, stl, "bnan.stl", "element 1", "non-finite");
    }

    // ---- the CGAL models
    // -----------------------------------------------------------------------------------------------

    TEST_CASE("models: every OFF from libcgal-demo reads or throws IoError; bunny00 has its header's counts") {
        std::optional<fs::path> bunny = geolab::model_path("bunny00");
        if (!bunny) {
            MESSAGE("models not found in " << geolab::models_dir().string()
                                           << ": skipped (run tools/fetch_models.sh to fetch them)");
            return;
        }
        PolygonSoup b = geolab::read_mesh(*bunny);
        CHECK(b.n_vertices() == 37706);
        CHECK(b.n_faces() == 75408);
        CHECK(b.is_triangle_soup());

        std::size_t read = 0, rejected = 0;
        for (const auto& entry : fs::directory_iterator(geolab::models_dir())) {
            if (entry.path().extension() != ".off") continue;
            CAPTURE(entry.path().string());
            try {
                PolygonSoup s = geolab::read_mesh(entry.path());
                CHECK(s.offsets.back() == s.indices.size());
                CHECK(std::all_of(s.indices.begin(), s.indices.end(), [&](auto v) { return v < s.n_vertices(); }));
                ++read;
            } catch (const IoError& e) {
                MESSAGE("rejected: " << std::string(e.what()));
                ++rejected;
            }
        }
        MESSAGE(read << " models read, " << rejected << " rejected with IoError");
        CHECK(read > 0);
    }

}  // TEST_SUITE
