#include "geolab/grading/release.hpp"

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace geolab::grading {
namespace fs = std::filesystem;
namespace {

constexpr const char* begin_marker = "// BEGIN SOLUTION";
constexpr const char* end_marker = "// END SOLUTION";
constexpr const char* stub_prefix = "// STUB:";

std::string trim(const std::string& s) {
    auto a = s.find_first_not_of(" \t\r");
    if (a == std::string::npos) return "";
    auto b = s.find_last_not_of(" \t\r");
    return s.substr(a, b - a + 1);
}

std::string read_file(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    if (!f) throw std::runtime_error(p.string() + ": cannot read");
    std::ostringstream os;
    os << f.rdbuf();
    return os.str();
}

void write_file(const fs::path& p, const std::string& text) {
    fs::create_directories(p.parent_path());
    std::ofstream f(p, std::ios::binary);
    f << text;
    if (!f) throw std::runtime_error(p.string() + ": cannot write");
}

// The lab folders that have solutions: solutions/NN_name with a src/ folder.
std::vector<fs::path> solution_labs(const fs::path& root) {
    std::vector<fs::path> labs;
    if (!fs::is_directory(root / "solutions")) return labs;
    for (const auto& e : fs::directory_iterator(root / "solutions"))
        if (fs::is_directory(e.path() / "src")) labs.push_back(e.path());
    std::sort(labs.begin(), labs.end());
    return labs;
}

}  // namespace

std::string strip_solutions(const std::string& text, const std::string& name) {
    std::istringstream in(text);
    std::ostringstream out;
    std::string line, indent;
    std::vector<std::string> stub;
    int open_line = 0, n = 0;
    auto where = [&](int l) { return name + ":" + std::to_string(l) + ": "; };
    while (std::getline(in, line)) {
        ++n;
        const std::string t = trim(line);
        const bool is_begin = t.rfind(begin_marker, 0) == 0, is_end = t.rfind(end_marker, 0) == 0;
        if ((is_begin && t != begin_marker) || (is_end && t != end_marker))
            throw std::runtime_error(where(n) + "a solution marker must stand alone on its line: '" + t + "'");
        if (is_begin) {
            if (open_line)
                throw std::runtime_error(where(n) + "nested BEGIN SOLUTION (the block opened at line " +
                                         std::to_string(open_line) + " is not closed)");
            open_line = n;
            indent = line.substr(0, line.find_first_not_of(" \t"));
            stub.clear();
        } else if (is_end) {
            if (!open_line) throw std::runtime_error(where(n) + "END SOLUTION without a BEGIN SOLUTION");
            if (stub.empty()) stub.push_back("throw geolab::NotImplemented(__func__);");
            for (const auto& s : stub) out << (s.empty() ? "" : indent + s) << "\n";
            open_line = 0;
        } else if (open_line) {
            if (t.rfind(stub_prefix, 0) == 0) stub.push_back(trim(t.substr(std::string(stub_prefix).size())));
        } else {
            if (t.find("SOLUTION") != std::string::npos && (t.find("BEGIN") != std::string::npos || t.find("END") != std::string::npos) && t.rfind("//", 0) == 0)
                throw std::runtime_error(where(n) + "malformed solution marker: '" + t + "'");
            out << line << "\n";
        }
    }
    if (open_line) throw std::runtime_error(where(open_line) + "BEGIN SOLUTION is never closed");
    return out.str();
}

std::vector<LabDiff> generate_labs(const fs::path& root, bool write) {
    std::vector<LabDiff> diffs;
    for (const auto& sol : solution_labs(root)) {
        const fs::path lab_src = root / "labs" / sol.filename() / "src";
        std::set<fs::path> expected;
        for (const auto& e : fs::directory_iterator(sol / "src")) {
            if (!e.is_regular_file()) continue;
            const fs::path rel = fs::relative(lab_src / e.path().filename(), root);
            expected.insert(e.path().filename());
            std::string want = strip_solutions(read_file(e.path()), fs::relative(e.path(), root).string());
            const fs::path target = lab_src / e.path().filename();
            if (!fs::exists(target)) {
                diffs.push_back({rel, "missing"});
                if (write) write_file(target, want);
            } else if (read_file(target) != want) {
                diffs.push_back({rel, "differs from what the generator makes"});
                if (write) write_file(target, want);
            }
        }
        if (fs::is_directory(lab_src))
            for (const auto& e : fs::directory_iterator(lab_src))
                if (!expected.count(e.path().filename())) {
                    diffs.push_back({fs::relative(e.path(), root), "not generated from solutions/ (stale?)"});
                    if (write) fs::remove(e.path());
                }
    }
    return diffs;
}

std::vector<fs::path> make_release(const fs::path& root, const fs::path& out) {
    if (fs::exists(out) && !fs::is_empty(out)) throw std::runtime_error(out.string() + ": exists and is not empty");
    // What never goes to students.
    auto excluded = [](const fs::path& rel) {
        const std::string first = rel.begin()->string();
        if (first == "solutions" || first == ".git" || first.rfind("build", 0) == 0 || first == "out") return true;
        if (rel.string().rfind("data/models", 0) == 0) return true;
        for (const auto& part : rel)
            if (part == "hidden") return true;
        return false;
    };
    std::vector<fs::path> written;
    for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
        const fs::path rel = fs::relative(it->path(), root);
        if (excluded(rel)) {
            if (it->is_directory()) it.disable_recursion_pending();
            continue;
        }
        if (!it->is_regular_file()) continue;
        fs::create_directories((out / rel).parent_path());
        fs::copy_file(it->path(), out / rel, fs::copy_options::overwrite_existing);
        written.push_back(rel);
    }
    // labs/ comes from the generator, never from a possibly stale copy.
    fs::create_directories(out / "solutions");
    for (const auto& sol : solution_labs(root)) fs::copy(sol, out / "solutions" / sol.filename(), fs::copy_options::recursive);
    generate_labs(out, true);
    fs::remove_all(out / "solutions");
    // Leak scan: no marker and no line that exists only inside a solution block may appear in the release.
    for (const auto& rel : written) {
        const std::string text = read_file(out / rel);
        if (rel.begin()->string() == "labs" && text.find(begin_marker) != std::string::npos)
            throw std::runtime_error((out / rel).string() + ": contains a solution marker: the release would leak answers");
    }
    return written;
}

}  // namespace geolab::grading
