#pragma once
//! \file scad.hpp
//! A reader for a documented subset of OpenSCAD's language (lab 07's scenes). The subset:
//!
//! - solids: `cube(size, center)` (size a number or [x, y, z]), `sphere(r)` or `sphere(d = ...)`,
//!   `cylinder(h, r, center)`, `cylinder(h, r1, r2, center)`, also `d`, `d1`, `d2`;
//! - transforms of their child statement or block: `translate(v)`, `rotate(a)` (a number: about z),
//!   `rotate([ax, ay, az])` (about x, then y, then z, degrees), `rotate(a, v)` (a degrees about the axis v),
//!   `scale(s)` (number or vector), `mirror(v)` (the plane through the origin with normal v),
//!   `multmatrix(m)` (4×4 or 3×4 rows; the last row of a 4×4 must be 0 0 0 1);
//! - booleans over their children: `union()`, `difference()` (first child minus all others),
//!   `intersection()`; `{ ... }` groups; the top level is a union of its statements;
//! - `name = expression;` variables (each assigned once, before use), numbers, `true`, `false`, `PI`,
//!   vectors `[a, b, c]`, `+ - * /` with the usual precedence, unary minus, parentheses, vector ± vector,
//!   number × vector, vector / number;
//! - `//` and `/* */` comments; `$fn`, `$fa`, `$fs` accepted as arguments or assignments and IGNORED: the solids
//!   here are exact (a sphere is round), not the polyhedra OpenSCAD would make.
//!
//! Anything else (modules, functions, for, if, let, echo, import, 2-D shapes, extrusions, `!#%*` modifiers, an
//! unknown argument, ...) is a ParseError naming the file, line, column and the construct. Hostile input is
//! rejected cleanly: nesting deeper than 256, more than 1,000,000 solids, numbers that are not finite, vectors
//! longer than 1024 entries, arithmetic that computes more than 1,000,000 vector entries in all (a variable is
//! shared, not copied, where it is used). Parsing is linear in the file's length. Text as in every reader of lib: a
//! UTF-8 byte order mark is skipped, a line ends with LF, CRLF or a lone CR (a `//` comment too); keywords are
//! case-sensitive, as in OpenSCAD.
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace geolab::scad {

//! A reader error; what() is "NAME:LINE:COLUMN: message".
class ParseError : public std::runtime_error {
public:
    ParseError(const std::string& name, int line, int column, const std::string& message);
    int line, column;
};

enum class Kind : int { cube, sphere, cylinder, unite, difference, intersection };

//! One node of a parsed scene. Solids carry their parameters and the composed transform M of all the
//! transforms around them (their local coordinates → the scene's); booleans carry their children.
struct Node {
    Kind kind = Kind::unite;
    glm::dvec3 size{1.0};      //!< cube: the edge lengths
    bool center = false;       //!< cube, cylinder: centred at the origin (else cube in [0, size], cylinder z ∈ [0, h])
    double r = 1.0;            //!< sphere: the radius
    double h = 1.0, r1 = 1.0, r2 = 1.0;  //!< cylinder: height, radius at z = 0 (bottom) and at z = h (top)
    glm::dmat4 M{1.0};         //!< solids: local → scene
    std::vector<int> children; //!< booleans: indices into Scene::nodes (each smaller than this node's index)
    int line = 0, column = 0;  //!< where the statement starts (1-based)
};

//! A parsed scene: nodes in creation order (children before parents); `root` is a union of the top level.
struct Scene {
    std::vector<Node> nodes;
    int root = -1;
};

//! Parses OpenSCAD text (`name` is used in error messages). \throw ParseError on anything outside the subset,
//! and when the scene has no solid.
Scene parse(std::string_view text, const std::string& name = "<text>");

//! Reads (lib's read_text_file: regular files only, GEOLAB_MAX_FILE_MB) and parses a file.
//! \throw geolab::IoError when it cannot be read, ParseError as parse().
Scene read(const std::string& path);

}  // namespace geolab::scad
