#pragma once
// Whole-file text I/O for the grader's sources (internal to lib/src/grading).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace geolab::grading::detail {

//! The whole file. \throw std::runtime_error "PATH: cannot read".
inline std::string read_text(const std::filesystem::path& p) {
    std::ifstream f(p, std::ios::binary);
    if (!f) throw std::runtime_error(p.string() + ": cannot read");
    std::ostringstream os;
    os << f.rdbuf();
    return os.str();
}

//! Replace the file with `text` (creating its folder) and set its permissions.
//! \throw std::runtime_error "PATH: cannot write".
inline void write_text(const std::filesystem::path& p, const std::string& text,
                       std::filesystem::perms perms = std::filesystem::perms(0644)) {
    std::filesystem::create_directories(p.parent_path());
    std::ofstream f(p, std::ios::binary | std::ios::trunc);
    f << text;
    f.close();
    if (!f) throw std::runtime_error(p.string() + ": cannot write");
    std::filesystem::permissions(p, perms);
}

}  // namespace geolab::grading::detail
