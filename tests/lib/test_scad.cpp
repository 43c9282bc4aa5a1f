// lib's OpenSCAD subset reader (geolab/scad.hpp): what it builds, and its errors (line, column, construct).
#include <cmath>
#include <string>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include "geolab/errors.hpp"
#include "geolab/scad.hpp"

using namespace geolab::scad;

namespace {
glm::dvec3 apply(const glm::dmat4& M, glm::dvec3 p) { return glm::dvec3(M * glm::dvec4(p, 1.0)); }
bool near(glm::dvec3 a, glm::dvec3 b) { return glm::length(a - b) < 1e-12; }
std::string error_of(const std::string& text) {
    try {
        parse(text, "t.scad");
    } catch (const ParseError& e) {
        return e.what();
    }
    return "no error";
}
}  // namespace

TEST_CASE("scad: solids, parameters and defaults") {
    const Scene s = parse("cube([1, 2, 3]); sphere(d = 4); cylinder(h = 5, r1 = 1, r2 = 0.5, center = true);\n"
                          "cylinder(3, 2, 1); cube(2, center = true);");
    REQUIRE(s.nodes.size() == 6);  // five solids and the top-level union
    CHECK(s.nodes[0].kind == Kind::cube);
    CHECK(near(s.nodes[0].size, {1, 2, 3}));
    CHECK(!s.nodes[0].center);
    CHECK(s.nodes[1].r == 2);
    CHECK(s.nodes[2].h == 5);
    CHECK(s.nodes[2].r1 == 1);
    CHECK(s.nodes[2].r2 == 0.5);
    CHECK(s.nodes[2].center);
    CHECK(s.nodes[3].h == 3);  // positional: h, r1, r2
    CHECK(s.nodes[3].r1 == 2);
    CHECK(s.nodes[3].r2 == 1);
    CHECK(s.nodes[4].center);
    CHECK(s.nodes[5].kind == Kind::unite);
    CHECK(s.nodes[5].children.size() == 5);
    CHECK(s.root == 5);
}

TEST_CASE("scad: transforms compose outside-in, as OpenSCAD applies them") {
    // translate(t) rotate(90 about z) scale(2): a local point p goes to t + R(2p)
    const Scene s = parse("translate([1, 2, 3]) rotate(90) scale(2) cube(1);");
    REQUIRE(s.nodes.size() == 1);
    CHECK(near(apply(s.nodes[0].M, {1, 0, 0}), {1, 4, 3}));
    const Scene r = parse("rotate([90, 0, 90]) sphere(1);");  // about x by 90, then about z by 90
    CHECK(near(apply(r.nodes[0].M, {0, 1, 0}), {0, 0, 1}));   // y → z (x rotation), z stays under the z rotation
    CHECK(near(apply(r.nodes[0].M, {1, 0, 0}), {0, 1, 0}));
    const Scene m = parse("mirror([1, 0, 0]) translate([2, 0, 0]) sphere(1);");
    CHECK(near(apply(m.nodes[0].M, {0, 0, 0}), {-2, 0, 0}));
    const Scene a = parse("rotate(a = 180, v = [1, 1, 0]) sphere(1);");
    CHECK(near(apply(a.nodes[0].M, {1, 0, 0}), {0, 1, 0}));
    const Scene mm = parse("multmatrix([[1, 0, 0, 5], [0, 1, 0, 6], [0, 0, 1, 7]]) sphere(1);");
    CHECK(near(apply(mm.nodes[0].M, {0, 0, 0}), {5, 6, 7}));
}

TEST_CASE("scad: booleans, blocks, variables and arithmetic") {
    const Scene s = parse("w = 2 * (3 + 1) - 2; v = [1, 2, 3] * 2 + [0, 0, w];\n"
                          "difference() { cube(v); { sphere(w / 4); } cylinder(h = w, r = PI); }");
    REQUIRE(s.nodes.size() == 4);
    CHECK(near(s.nodes[0].size, {2, 4, 12}));
    CHECK(s.nodes[1].r == 1.5);
    CHECK(std::abs(s.nodes[2].r1 - 3.141592653589793) < 1e-15);
    CHECK(s.nodes[3].kind == Kind::difference);
    CHECK(s.nodes[3].children == std::vector<int>{0, 1, 2});
    CHECK(parse("union() cube(1);").nodes.size() == 1);  // one child: no boolean node
    CHECK(parse("/* a */ cube(1); // b\n$fn = 12; sphere(1, $fn = 30);").nodes.size() == 3);
}

TEST_CASE("scad: errors name the file, line, column and construct") {
    CHECK(error_of("cube(1);\n  for (i = [0:2]) cube(i);") == "t.scad:2:3: 'for' is not in the supported subset");
    CHECK(error_of("cube(1);\nsquare(2);") == "t.scad:2:1: module 'square' is not in the supported subset");
    CHECK(error_of("sphere(1, rr = 2);") == "t.scad:1:11: argument 'rr' of 'sphere' is not in the supported subset");
    CHECK(error_of("cube(1)") == "t.scad:1:8: expected ';' after cube(...), found the end of the file");
    CHECK(error_of("x = 1 == 1; cube(x);") == "t.scad:1:7: operator '==' is not in the supported subset");
    CHECK(error_of("sphere(1e400);").find("not finite") != std::string::npos);
    CHECK(error_of(std::string(1000, '{') + "cube(1);" + std::string(1000, '}')).find("nested deeper") !=
          std::string::npos);
    CHECK_THROWS_AS(read("/nonexistent/scene.scad"), geolab::IoError);
}
