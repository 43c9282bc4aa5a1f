#pragma once
//! \file io.hpp
//! Mesh I/O: OBJ, OFF, PLY (ascii, binary little and big endian) and STL (ascii and binary), read and write.
//! Every reader validates as it goes and throws geolab::IoError naming the file, the line (text formats) or
//! element (binary formats) and the reason: truncated data, an index out of range, a NaN or inf coordinate,
//! wrong counts, an unknown format, an empty file. A reader never returns a partial or garbage soup.
//! Text errors carry the 1-based line; binary errors have line 0 and a reason starting "element NAME N: "
//! (PLY, e.g. "element face 12: ...") or "element N: " (STL triangle N). Header counts are checked against the
//! file size before anything is reserved, so a lying header fails at once: every allocation is bounded by what
//! the bytes left in the file can hold. A PLY header may declare each element once, and its face index lists
//! must have an integer type.
//! Text, the same way in every reader: a UTF-8 byte order mark at the start is skipped; a line ends with LF,
//! CRLF or a lone CR (old Mac files), each counted as one line; keywords (OFF, `v`/`f`, PLY's header words,
//! STL's `solid`/`facet`/...) are matched in any case (`SOLID`, `Facet`); names (PLY property and element
//! names) are case-sensitive.
#include <cstdint>
#include <filesystem>
#include <string>

#include "geolab/errors.hpp"
#include "geolab/soup.hpp"

namespace geolab {

enum class MeshFormat { obj, off, ply_ascii, ply_binary_le, ply_binary_be, stl_ascii, stl_binary };

//! The format implied by a file's extension (.obj .off .ply .stl; PLY/STL writes default to binary
//! little endian). \throw IoError for an unknown extension.
MeshFormat format_from_extension(const std::filesystem::path& path);

//! The size limit of read_mesh when ReadOptions does not set one: 1024 MiB, or GEOLAB_MAX_FILE_MB MiB when that
//! environment variable is set. \throw IoError when GEOLAB_MAX_FILE_MB is not a positive integer.
std::uint64_t default_max_file_bytes();

//! Options of read_mesh.
struct ReadOptions {
    //! Larger files are refused with an IoError naming the size, the limit and how to raise it;
    //! 0 means default_max_file_bytes().
    std::uint64_t max_file_bytes = 0;
};

//! Read a polygon soup from `path`; the format comes from the extension and, for PLY/STL, the header.
//! Only regular files are read (a FIFO, a device or a symlink to one is refused without reading from it),
//! up to options.max_file_bytes.
//! STL stores unshared triangle corners: identical positions (bit for bit, -0 = +0) are welded into one vertex,
//! numbered in order of first use; welding sorts the corners (O(n log n) whatever the coordinates).
//! OBJ: only `v` and `f` are used (f entries may be `i`, `i/t`, `i//n`, `i/t/n`, negative = relative).
//! \throw IoError (file, line or element, reason).
PolygonSoup read_mesh(const std::filesystem::path& path, const ReadOptions& options = {});

//! The bytes of a regular file, with read_mesh's checks and size limit (for the other readers of lib, e.g. the
//! volume mesh formats of volume_io.hpp). \throw IoError naming the file and the reason.
std::string read_text_file(const std::filesystem::path& path, const ReadOptions& options = {});

//! Parse mesh text already in memory; `name` is used in error messages only. Any failure, running out of
//! memory included, is an IoError naming `name`.
PolygonSoup read_mesh_from_string(const std::string& data, MeshFormat format, const std::string& name = "<memory>");

//! Write `soup` to `path` in the format of its extension (or the one given). STL triangulates polygons
//! as fans. Text formats write the shortest decimals that read back exactly; PLY writes doubles; STL floats.
//! \throw IoError when the file cannot be written or the extension is unknown; std::invalid_argument when a
//! face index is out of range (the soup is checked before anything is written).
void write_mesh(const std::filesystem::path& path, const PolygonSoup& soup);
void write_mesh(const std::filesystem::path& path, const PolygonSoup& soup, MeshFormat format);

}  // namespace geolab
