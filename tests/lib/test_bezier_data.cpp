// Tests of lab 05's data readers: Newell's teapot (.bpt) with every kind of malformed file (IoError naming the file,
// the line and the reason), and FreeType glyph outlines (closed chains of quadratic segments; clear errors).
#include <doctest/doctest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "geolab/bezier_data.hpp"
#include "geolab/errors.hpp"

namespace {
std::string write_temp(const std::string& text) {
    static int k = 0;
    const auto p = std::filesystem::temp_directory_path() /
                   ("geolab_bpt_" + std::to_string(::getpid()) + "_" + std::to_string(k++) + ".bpt");
    std::ofstream(p) << text;
    return p.string();
}
// The IoError's message for a file's text (empty when it reads).
std::string error_of(const std::string& text) {
    const std::string p = write_temp(text);
    std::string msg;
    try {
        geolab::read_bpt(p);
    } catch (const geolab::IoError& e) {
        msg = e.what();
    }
    std::filesystem::remove(p);
    return msg;
}
std::string points(int n) {
    std::string s;
    for (int i = 0; i < n; ++i) s += std::to_string(i) + " 0.5 -1e2\n";
    return s;
}
}  // namespace

TEST_CASE("read_bpt: the teapot has 32 bicubic patches with finite points") {
    const auto t = geolab::read_bpt(geolab::teapot_path());
    REQUIRE(t.size() == 32);
    for (const auto& p : t) {
        CHECK(p.degree_u == 3);
        CHECK(p.degree_v == 3);
        CHECK(p.points.size() == 16);
    }
    CHECK(t[0].points[0] == glm::dvec3(1.4, 0, 2.4));
}

TEST_CASE("read_bpt: a valid small file, blank lines and CRLF allowed") {
    const std::string p = write_temp("1\r\n\n1 2\r\n" + points(6));
    const auto t = geolab::read_bpt(p);
    std::filesystem::remove(p);
    REQUIRE(t.size() == 1);
    CHECK(t[0].degree_u == 1);
    CHECK(t[0].degree_v == 2);
    CHECK(t[0].points[5] == glm::dvec3(5, 0.5, -100));
}

TEST_CASE("read_bpt: malformed files name the line and the reason") {
    struct Case {
        std::string text, expect;
    };
    const Case cases[] = {
        {"", ":0: empty file"},
        {"x\n", ":1: patch count 'x' is not an integer"},
        {"0\n", ":1: patch count 0 is out of range"},
        {"2 3\n", ":1: expected one number"},
        {"1\n3\n", ":2: expected two degrees"},
        {"1\n0 3\n", ":2: patch 0: degrees 0 3 out of range"},
        {"1\n3 99\n", ":2: patch 0: degrees 3 99 out of range"},
        {"1\n1 1\n0 0 0\n1 1\n", ":4: patch 0 point 1: expected 'x y z', got 2 values"},
        {"1\n1 1\n0 0 0\n1 1 nan\n", ":4: coordinate 'nan' is not finite"},
        {"1\n1 1\n0 0 0\n1 1 1e999\n", ":4: coordinate '1e999' is out of the range"},
        {"1\n1 1\n0 0 z\n", ":3: coordinate 'z' is not a number"},
        {"1\n1 1\n" + points(3), "file ends inside patch 0: 3 of 4 points"},
        {"2\n1 1\n" + points(4), "file ends after 1 of 2 patches"},
        {"1\n1 1\n" + points(4) + "7\n", ":7: trailing data"},
    };
    for (const auto& c : cases) {
        const std::string msg = error_of(c.text);
        INFO("file text: '" << c.text << "' gave: '" << msg << "', expected to contain '" << c.expect << "'");
        CHECK(msg.find(c.expect) != std::string::npos);
    }
    CHECK_THROWS_AS(geolab::read_bpt("/nonexistent/teapot.bpt"), geolab::IoError);
}

TEST_CASE("read_glyph: closed chains of quadratic segments; clear errors") {
    const auto g = geolab::read_glyph(geolab::default_font_path(), U'B');
    CHECK(g.units_per_em == 2048);
    CHECK(g.advance > 0);
    REQUIRE(g.contours.size() == 3);  // the outline and the two counters
    for (const auto& c : g.contours) {
        REQUIRE(!c.empty());
        for (std::size_t k = 0; k < c.size(); ++k) CHECK(c[k][2] == c[(k + 1) % c.size()][0]);
    }
    CHECK(geolab::read_glyph(geolab::default_font_path(), U' ').contours.empty());
    CHECK_THROWS_AS(geolab::read_glyph("/nonexistent.ttf", U'a'), geolab::IoError);
    CHECK_THROWS_AS(geolab::read_glyph(geolab::teapot_path(), U'a'), geolab::IoError);  // not a font
    CHECK_THROWS_AS(geolab::read_glyph(geolab::default_font_path(), char32_t(0x10FFFD)), geolab::IoError);
}
