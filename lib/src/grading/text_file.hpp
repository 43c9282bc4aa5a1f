#pragma once
// Whole-file text I/O for the grader's sources (internal to lib/src/grading).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

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

//! Split a command line as a POSIX shell would for the simple quoting CMake and Ninja write (compile_commands.json,
//! `ninja -t commands`).
inline std::vector<std::string> split_command(const std::string& cmd) {
    std::vector<std::string> out;
    std::string cur;
    bool in_token = false;
    char quote = 0;
    for (std::size_t i = 0; i < cmd.size(); ++i) {
        char c = cmd[i];
        if (quote) {
            if (c == quote) quote = 0;
            else if (c == '\\' && quote == '"' && i + 1 < cmd.size()) cur += cmd[++i];
            else cur += c;
        } else if (c == '\'' || c == '"') {
            quote = c;
            in_token = true;
        } else if (c == '\\' && i + 1 < cmd.size()) {
            cur += cmd[++i];
            in_token = true;
        } else if (c == ' ' || c == '\t' || c == '\n') {
            if (in_token) out.push_back(cur);
            cur.clear();
            in_token = false;
        } else {
            cur += c;
            in_token = true;
        }
    }
    if (in_token) out.push_back(cur);
    return out;
}

//! The absolute path of a system program (/usr/bin, /bin, /usr/local/bin), or "" when none is executable.
inline std::string find_program(const std::string& name) {
    for (const char* dir : {"/usr/bin", "/bin", "/usr/local/bin"}) {
        const std::filesystem::path p = std::filesystem::path(dir) / name;
        if (::access(p.c_str(), X_OK) == 0) return p.string();
    }
    return "";
}

}  // namespace geolab::grading::detail
