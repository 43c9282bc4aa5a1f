// The readers added after issue 13 against hostile files: Medit .mesh and TetGen (lab 02), .bpt and TrueType
// glyphs (lab 05), the OpenSCAD subset (lab 07). Every one reads through lib's read_text_file (a FIFO, a device or
// a directory is refused at once), treats a byte order mark and CR line ends as the surface readers do, refuses
// duplicate sections and silent truncation, and names the file, the line (or element) and the reason. The inputs
// here failed before this file was written (each case says what happened then).
#include <doctest/doctest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "geolab/bezier_data.hpp"
#include "geolab/errors.hpp"
#include "geolab/io.hpp"
#include "geolab/scad.hpp"
#include "geolab/volume_io.hpp"

namespace {

namespace fs = std::filesystem;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The message of the exception `read` throws ("no exception" when it returns).
std::string error_of(const std::function<void()>& read) {
    try {
        read();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "no exception";
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// A scratch folder removed at the end.
struct Scratch {
    fs::path dir = fs::temp_directory_path() / ("geolab_readers_hostile_" + std::to_string(::getpid()));
    Scratch() { fs::create_directories(dir); }
    ~Scratch() {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
};

const std::string tet_vertices = "Vertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n";
const std::string tet_node = "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n";

std::string medit_error(const std::string& text) {
    return error_of([&] { geolab::read_medit_from_string(text, "h.mesh"); });
}
std::string tetgen_error(const std::string& ele, const std::string& face) {
    return error_of([&] { geolab::read_tetgen_from_strings(tet_node, ele, face, "h"); });
}
std::string scad_error(const std::string& text) {
    return error_of([&] { geolab::scad::parse(text, "h.scad"); });
}
std::string bpt_error(const std::string& text) {
    return error_of([&] { geolab::read_bpt_from_string(text, "h.bpt"); });
}

}  // namespace

TEST_SUITE("readers hostile") {
    TEST_CASE("every file reader refuses a FIFO, /dev/zero and a directory at once, naming the file") {
        // Before: scad::read, read_bpt and read_glyph blocked forever on a FIFO; scad::read and read_bpt grew
        // without bound on /dev/zero (1 GB in 3 s); a directory read as an empty file ("the scene has no solid").
        Scratch scratch;
        const fs::path fifo = scratch.dir / "pipe", zero = scratch.dir / "zero", dir = scratch.dir / "folder";
        REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
        fs::create_symlink("/dev/zero", zero);
        fs::create_directory(dir);
        const std::pair<const char*, std::function<void(const fs::path&)>> readers[] = {
            {"read_medit", [](const fs::path& p) { geolab::read_medit(p); }},
            {"read_tetgen", [](const fs::path& p) { geolab::read_tetgen(p); }},
            {"read_bpt", [](const fs::path& p) { geolab::read_bpt(p.string()); }},
            {"read_glyph", [](const fs::path& p) { geolab::read_glyph(p.string(), U'A'); }},
            {"scad::read", [](const fs::path& p) { geolab::scad::read(p.string()); }},
        };
        for (const auto& [name, read] : readers) {
            for (const auto& [file, expect] : {std::pair{fifo, "FIFO"}, {zero, "character device"}, {dir, "directory"}}) {
                // TetGen reads base.node: give it files named so
                fs::path p = file;
                if (std::string(name) == "read_tetgen") {
                    p = scratch.dir / (file.filename().string() + "_t.node");
                    if (!fs::exists(fs::symlink_status(p))) {
                        if (file == fifo) REQUIRE(::mkfifo(p.c_str(), 0600) == 0);
                        else if (file == zero) fs::create_symlink("/dev/zero", p);
                        else fs::create_directory(p);
                    }
                }
                const auto t0 = std::chrono::steady_clock::now();
                bool io_error = false;
                std::string msg;
                try {
                    read(p);
                } catch (const geolab::IoError& e) {
                    io_error = true;
                    msg = e.what();
                } catch (const std::exception& e) {
                    msg = std::string("not an IoError: ") + e.what();
                }
                INFO(name << " on " << p.string() << ": " << msg);
                CHECK(io_error);
                CHECK(contains(msg, p.string() + ":0:"));
                CHECK(contains(msg, expect));
                CHECK(seconds_since(t0) < 5.0);
            }
        }
    }

    TEST_CASE("Medit: each section once, End required and last, triangles checked, labels in 32 bits") {
        // Before: each of these read without an error (a second section was appended, a label clamped, a file cut
        // after a whole section read as a smaller mesh, anything after End ignored).
        const std::string head = "MeshVersionFormatted 2\nDimension 3\n" + tet_vertices;
        CHECK(contains(medit_error(head + "Tetrahedra\n1\n1 2 3 4 5\nTetrahedra\n1\n1 2 3 4 6\nEnd\n"),
                       "h.mesh:12: a second 'Tetrahedra' section (the first is at line 9)"));
        CHECK(contains(medit_error("Dimension 3\n" + head + "End\n"), "h.mesh:3: a second 'Dimension' section"));
        CHECK(contains(medit_error(head + "vertices\n1\n0 0 0 0\nEnd\n"), "a second 'vertices' section"));
        CHECK(contains(medit_error(head + "Tetrahedra\n1\n1 2 3 4 5\n"), "h.mesh:12: the file ends without 'End'"));
        CHECK(contains(medit_error(head + "End\nTetrahedra\n1\n1 2 3 4 5\n"), "h.mesh:10: data after 'End': 'Tetrahedra'"));
        CHECK(contains(medit_error(head + "Triangles\n1\n1 1 2 0\nEnd\n"), "h.mesh:11: Triangles entry 1 repeats a vertex"));
        CHECK(contains(medit_error(head + "Triangles\n1\n1 2 3 99999999999\nEnd\n"),
                       "h.mesh:11: the triangle reference 99999999999 does not fit in 32 bits"));
        CHECK(contains(medit_error(head + "Tetrahedra\n1\n1 2 3 4 -2147483649\nEnd\n"), "does not fit in 32 bits"));
        // unprintable bytes and long words are quoted, at most 40 bytes
        CHECK(contains(medit_error(head + std::string("Bad\0word", 8) + "\nEnd\n"), "unknown keyword 'Bad?word'"));
        const std::string msg = medit_error(head + std::string(1 << 20, 'K') + "\nEnd\n");
        CHECK(msg.size() < 200);
        CHECK(contains(msg, "KKKK...'"));
        // still read: a byte order mark, CR-only line ends, keywords in any case, comments after End
        const geolab::VolumeMesh m = geolab::read_medit_from_string(
            "\xEF\xBB\xBFmeshversionformatted 2\rDIMENSION 3\r" + std::string("VERTICES\r4\r0 0 0 0\r1 0 0 0\r0 1 0 0\r") +
                "0 0 1 0\rtetrahedra\r1\r1 2 3 4 5\rend\r# written by hand\r",
            "ok.mesh");
        CHECK(m.n_cells() == 1);
    }

    TEST_CASE("TetGen: face corners distinct, boundary markers in 32 bits") {
        // Before: both read (the marker clamped to 2^31 - 1).
        CHECK(contains(tetgen_error("1 4 0\n0 0 1 2 3\n", "1 1\n0 0 0 2 -1\n"), "h.face:2: face 0 repeats a node (0 0 2)"));
        CHECK(contains(tetgen_error("1 4 0\n0 0 1 2 3\n", "1 1\n0 0 1 2 99999999999\n"),
                       "h.face:2: the face's boundary marker 99999999999 does not fit in 32 bits"));
        CHECK(geolab::read_tetgen_from_strings(tet_node, "1 4 0\n0 0 1 2 3\n", "1 1\n0 0 1 2 -7\n", "h").triangle_labels[0] ==
              -7);
    }

    TEST_CASE(".bpt: byte order mark, CR-only line ends, tokens quoted in messages") {
        const std::string patch = "1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n";
        // Before: rejected ("patch count '\xEF\xBB\xBF1' is not an integer", "expected one number" on line 1).
        CHECK(geolab::read_bpt_from_string("\xEF\xBB\xBF" + patch, "bom.bpt").size() == 1);
        std::string cr = patch;
        std::replace(cr.begin(), cr.end(), '\n', '\r');
        const auto t = geolab::read_bpt_from_string(cr, "cr.bpt");
        REQUIRE(t.size() == 1);
        CHECK(t[0].points[3] == glm::dvec3(1, 1, 0));
        CHECK(contains(bpt_error("1\r1 1\r0 0 0\r1 0 0\r0 1 0\r1 1 x\r"), "h.bpt:6: coordinate 'x' is not a number"));
        // Before: the whole 5 MB token, and a raw NUL byte, went into the message.
        const std::string msg = bpt_error("1\n1 1\n" + std::string(5 << 20, '9') + " 0 0\n");
        CHECK(msg.size() < 200);
        CHECK(contains(msg, "h.bpt:3: coordinate '9999"));
        CHECK(contains(bpt_error(std::string("1\n1 1\n0 0 \0\n", 13)), "h.bpt:3: coordinate '?' is not a number"));
    }

    TEST_CASE("glyphs: read from memory; a truncated or empty font is a clean error") {
        const std::string font = [] {
            std::ifstream in(geolab::default_font_path(), std::ios::binary);
            return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        }();
        REQUIRE(font.size() > 100000);
        CHECK(geolab::read_glyph_from_memory(font, U'B', "dejavu").contours.size() == 3);
        for (std::size_t cut : {std::size_t(0), std::size_t(12), std::size_t(1000), font.size() / 2}) {
            const std::string msg = error_of([&] { geolab::read_glyph_from_memory(font.substr(0, cut), U'B', "cut.ttf"); });
            INFO("font cut at " << cut << " bytes: " << msg);
            CHECK(contains(msg, "cut.ttf:0:"));
        }
    }

    TEST_CASE("scad: a byte order mark, CR-only line ends (// comments too), control characters named") {
        // Before: a BOM was "a non-ASCII character"; with CR-only line ends a // comment ran to the end of the file,
        // silently dropping every solid after it; a NUL byte went raw into the message.
        CHECK(geolab::scad::parse("\xEF\xBB\xBF" "cube();", "bom.scad").nodes.size() == 1);
        const geolab::scad::Scene s = geolab::scad::parse("cube();\r// a comment\rsphere(1);\r", "cr.scad");
        CHECK(s.nodes.size() == 3);  // two solids and their union
        CHECK(contains(scad_error("cube();\r\rbad();\r"), "h.scad:3:1: module 'bad'"));
        CHECK(contains(scad_error("cube();\r\n\r\nbad();\r\n"), "h.scad:3:1: module 'bad'"));
        CHECK(contains(scad_error(std::string("cube();\0", 8)), "h.scad:1:8: expected a statement, found control character 0x00"));
    }

    TEST_CASE("scad: variables are shared, arithmetic is budgeted: no blow-up from a few kilobytes") {
        std::string ones = "[1";
        for (int i = 1; i < 1000; ++i) ones += ",1";
        ones += "]";
        // Before: 6 KB of nested variables took 825 MB (and 20 more entries would take 800 GB).
        std::string nested = "a = " + ones + ";\nb = [a";
        for (int i = 1; i < 1000; ++i) nested += ",a";
        nested += "];\nc = [b";
        for (int i = 1; i < 1000; ++i) nested += ",b";
        nested += "];\ncube();\n";
        auto t0 = std::chrono::steady_clock::now();
        CHECK(geolab::scad::parse(nested, "nested.scad").nodes.size() == 1);
        CHECK(seconds_since(t0) < 2.0);  // measured 0.01 s
        // Before: 100,000 copies of a 1000-vector took 3.9 GB and 7.9 s.
        std::string copies = "a = " + ones + ";\n";
        for (int i = 0; i < 100000; ++i) copies += "x" + std::to_string(i) + " = a;";
        copies += "\ncube();\n";
        t0 = std::chrono::steady_clock::now();
        CHECK(geolab::scad::parse(copies, "copies.scad").nodes.size() == 1);
        CHECK(seconds_since(t0) < 5.0);  // measured 0.2 s
        // Before: a 1.2 MB sum of 1000-vectors took 9.7 s; now it stops at the budget.
        std::string sum = "a = " + ones + ";\nb = a";
        for (int i = 0; i < 200000; ++i) sum += "+a";
        sum += ";\ncube();\n";
        t0 = std::chrono::steady_clock::now();
        CHECK(contains(scad_error(sum), "h.scad:2:2006: the expressions compute more than 1000000 vector entries"));
        CHECK(seconds_since(t0) < 2.0);  // measured 0.03 s
        CHECK(contains(scad_error(nested + "d = c + c;"), "compute more than 1000000 vector entries"));
        CHECK(contains(scad_error(nested + "d = -c;"), "compute more than 1000000 vector entries"));
        // ordinary vector arithmetic is untouched
        const geolab::scad::Scene s = geolab::scad::parse("v = [1, 2, 3]; w = -(v + v) / 2 * 3; translate(w) cube();");
        CHECK(s.nodes[0].M[3][0] == -3);
        CHECK(s.nodes[0].M[3][2] == -9);
    }
}

TEST_SUITE("readers hostile") {
    // A file cut anywhere before its last token must not read as a smaller, valid file. (Inside the last token a
    // cut can leave a valid number — "12" cut to "1" — which no reader can tell, Medit's End aside.)
    TEST_CASE("truncated at every byte: Medit, TetGen and .bpt never read a cut file") {
        const std::string medit = "MeshVersionFormatted 2\nDimension 3\n" + tet_vertices +
                                  "Tetrahedra\n1\n1 2 3 4 5\nTriangles\n2\n1 2 3 7\n1 2 4 8\nEnd\n";
        REQUIRE(geolab::read_medit_from_string(medit).triangles.size() == 2);
        const std::size_t end = medit.rfind("End") + 3;
        int cut_errors = 0;
        for (std::size_t cut = 0; cut < end; ++cut) {
            const std::string msg = medit_error(medit.substr(0, cut));
            INFO("Medit cut at byte " << cut << ": " << msg);
            CHECK(contains(msg, "h.mesh:"));
            cut_errors += contains(msg, "h.mesh:");
        }
        CHECK(cut_errors == int(end));
        // TetGen: each of the three files cut before its last token (an empty .face means no .face file: skipped)
        const std::string ele = "1 4 1\n0 0 1 2 3 12\n", face = "1 1\n0 0 1 2 -1\n";
        REQUIRE(geolab::read_tetgen_from_strings(tet_node, ele, face, "h").triangles.size() == 1);
        auto last_token = [](const std::string& text) { return text.find_last_of(" \n", text.size() - 2) + 1; };
        for (int file = 0; file < 3; ++file) {
            const std::string& full = file == 0 ? tet_node : file == 1 ? ele : face;
            for (std::size_t cut = file == 2 ? 1 : 0; cut < last_token(full); ++cut) {
                const std::string part = full.substr(0, cut);
                const std::string msg = error_of([&] {
                    geolab::read_tetgen_from_strings(file == 0 ? part : tet_node, file == 1 ? part : ele,
                                                     file == 2 ? part : face, "h");
                });
                INFO("TetGen file " << file << " cut at byte " << cut << ": " << msg);
                CHECK(contains(msg, "h."));
            }
        }
        // .bpt
        const std::string bpt = "1\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 0.5\n";
        REQUIRE(geolab::read_bpt_from_string(bpt).size() == 1);
        for (std::size_t cut = 0; cut < last_token(bpt); ++cut) {
            const std::string msg = bpt_error(bpt.substr(0, cut));
            INFO(".bpt cut at byte " << cut << ": " << msg);
            CHECK(contains(msg, "h.bpt:"));
        }
    }
}
