#pragma once
//! \file bezier_data.hpp
//! Real Bézier data for lab 05: Newell's teapot patches (the .bpt text format) and TrueType glyph outlines read
//! through FreeType, both as control points. Reading only: no evaluation here (that is the lab's work).
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "geolab/boundary.hpp"

namespace geolab {

//! A tensor-product Bézier patch of degree (degree_u, degree_v): control point P_ij (i = 0..degree_u along u,
//! j = 0..degree_v along v) is points[i * (degree_v + 1) + j]. The surface is
//!     S(u, v) = Σ_i Σ_j B_i^{degree_u}(u) B_j^{degree_v}(v) P_ij,   (u, v) ∈ [0, 1]².
struct BezierPatch {
    int degree_u = 0, degree_v = 0;
    std::vector<glm::dvec3> points;
    GEOLAB_FIELDS(degree_u, degree_v, points)
};

//! Reads a .bpt file: the patch count, then per patch a line "du dv" and (du + 1)(dv + 1) lines "x y z", the
//! inner index running fastest (the file's k-th point of a patch is P_ij with i = k / (dv + 1), j = k % (dv + 1)).
//! For data/teapot.bpt (Newell's 32 patches) S_u × S_v points INTO the teapot's body.
//! Text as in every reader of lib: a UTF-8 byte order mark is skipped; a line ends with LF, CRLF or a lone CR.
//! The file is read with read_text_file (io.hpp: regular files only, GEOLAB_MAX_FILE_MB).
//! \throw IoError "FILE:LINE: reason" on a missing file, a bad count (1..100000) or degree (1..30), a point line
//!        without exactly three finite numbers, a missing point or trailing data.
std::vector<BezierPatch> read_bpt(const std::string& path);
//! The same from text in memory; `path` names it in errors.
std::vector<BezierPatch> read_bpt_from_string(std::string_view text, const std::string& path = "<memory>");

//! The project's copy of Newell's teapot (data/teapot.bpt in the course tree).
std::string teapot_path();

//! One quadratic Bézier segment: on-curve start, off-curve control, on-curve end.
using QuadSegment = std::array<glm::dvec2, 3>;

//! A glyph's outline in font units (y up), as TrueType stores it: closed contours of quadratic segments, each
//! segment's end the next one's start and the last segment's end the first one's start. FreeType's decomposition
//! expands the on/off points: two consecutive off-curve points imply the on-curve point midway, and a straight
//! edge (two on-curve points) becomes the segment (a, (a + b)/2, b) — the same line as a quadratic.
//! TrueType orients outer contours clockwise and holes counter-clockwise (y up).
struct GlyphOutline {
    std::vector<std::vector<QuadSegment>> contours;
    double advance = 0;       //!< horizontal advance, font units
    double units_per_em = 0;  //!< the font's em size in font units (2048 for DejaVu)
    GEOLAB_FIELDS(contours, advance, units_per_em)
};

//! The outline of the glyph of `codepoint` in the TrueType font file `font_path`, unscaled (font units).
//! The file is read with read_text_file (io.hpp: regular files only, GEOLAB_MAX_FILE_MB), then parsed by FreeType.
//! \throw IoError naming the file when it cannot be read, FreeType cannot open it, the font has no glyph for the
//!        code point, or the outline has cubic segments (not a TrueType quadratic outline).
GlyphOutline read_glyph(const std::string& font_path, char32_t codepoint);
//! The same from the font file's bytes in memory; `font_path` names it in errors.
GlyphOutline read_glyph_from_memory(const std::string& font, char32_t codepoint,
                                    const std::string& font_path = "<memory>");

//! DejaVu Sans from Debian's fonts-dejavu-core (/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf).
std::string default_font_path();

}  // namespace geolab
