#pragma once
//! \file io.hpp
//! Mesh I/O: OBJ, OFF, PLY (ascii, binary little and big endian) and STL (ascii and binary), read and write.
//! Every reader validates as it goes and throws geolab::IoError naming the file, the line (text formats) or
//! element (binary formats) and the reason: truncated data, an index out of range, a NaN or inf coordinate,
//! wrong counts, an unknown format, an empty file. A reader never returns a partial or garbage soup.
//! Text errors carry the 1-based line; binary errors have line 0 and a reason starting "element NAME N: "
//! (PLY, e.g. "element face 12: ...") or "element N: " (STL triangle N). Header counts are checked against the
//! file size before anything is reserved, so a lying header fails at once.
#include <filesystem>
#include <string>

#include "geolab/errors.hpp"
#include "geolab/soup.hpp"

namespace geolab {

enum class MeshFormat { obj, off, ply_ascii, ply_binary_le, ply_binary_be, stl_ascii, stl_binary };

//! The format implied by a file's extension (.obj .off .ply .stl; PLY/STL writes default to binary
//! little endian). \throw IoError for an unknown extension.
MeshFormat format_from_extension(const std::filesystem::path& path);

//! Read a polygon soup from `path`; the format comes from the extension and, for PLY/STL, the header.
//! STL stores unshared triangle corners: identical positions are welded into one vertex.
//! OBJ: only `v` and `f` are used (f entries may be `i`, `i/t`, `i//n`, `i/t/n`, negative = relative).
//! \throw IoError (file, line or element, reason).
PolygonSoup read_mesh(const std::filesystem::path& path);

//! Parse mesh text already in memory; `name` is used in error messages only.
PolygonSoup read_mesh_from_string(const std::string& data, MeshFormat format, const std::string& name = "<memory>");

//! Write `soup` to `path` in the format of its extension (or the one given). STL triangulates polygons
//! as fans. Text formats write the shortest decimals that read back exactly; PLY writes doubles; STL floats.
//! \throw IoError when the file cannot be written or the extension is unknown; std::invalid_argument when a
//! face index is out of range (the soup is checked before anything is written).
void write_mesh(const std::filesystem::path& path, const PolygonSoup& soup);
void write_mesh(const std::filesystem::path& path, const PolygonSoup& soup, MeshFormat format);

}  // namespace geolab
