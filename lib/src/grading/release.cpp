#include "geolab/grading/release.hpp"
#include "text_file.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

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

using detail::read_text;
using detail::write_text;

// The lab folders that have solutions: solutions/NN_name with a src/ folder.
std::vector<fs::path> solution_labs(const fs::path& root) {
    std::vector<fs::path> labs;
    if (!fs::is_directory(root / "solutions")) return labs;
    for (const auto& e : fs::directory_iterator(root / "solutions"))
        if (fs::is_directory(e.path() / "src")) labs.push_back(e.path());
    std::sort(labs.begin(), labs.end());
    return labs;
}

// The meaningful lines of a text, trimmed (no blank lines, no lone braces): what the leak scan compares.
std::vector<std::pair<std::string, int>> meaningful_lines(const std::string& text) {
    std::vector<std::pair<std::string, int>> out;
    std::istringstream in(text);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        const std::string t = trim(line);
        if (t.size() >= 4) out.push_back({t, n});
    }
    return out;
}

// Three consecutive meaningful lines as one key.
std::string shingle(const std::vector<std::pair<std::string, int>>& l, std::size_t i) {
    return l[i].first + "\n" + l[i + 1].first + "\n" + l[i + 2].first;
}

// Every run of three consecutive meaningful lines inside a solution block: the leak scan's needles. A single
// line (a loop header) is too common to prove a leak; three in a row are an answer.
std::set<std::string> solution_shingles(const fs::path& root) {
    std::set<std::string> needles;
    for (const auto& sol : solution_labs(root))
        for (const auto& e : fs::recursive_directory_iterator(sol)) {
            if (!e.is_regular_file()) continue;
            std::istringstream in(read_text(e.path()));
            std::string line, block;
            bool open = false;
            while (std::getline(in, line)) {
                const std::string t = trim(line);
                if (t.rfind(begin_marker, 0) == 0) {
                    open = true;
                    block.clear();
                } else if (t.rfind(end_marker, 0) == 0) {
                    open = false;
                    auto l = meaningful_lines(block);
                    for (std::size_t i = 0; i + 2 < l.size(); ++i) needles.insert(shingle(l, i));
                } else if (open && t.rfind(stub_prefix, 0) != 0) {
                    block += line + "\n";
                }
            }
        }
    // What the generated stubs keep (given code) is public: never a leak.
    for (const auto& sol : solution_labs(root))
        for (const auto& e : fs::recursive_directory_iterator(sol)) {
            if (!e.is_regular_file()) continue;
            auto l = meaningful_lines(strip_solutions(read_text(e.path()), e.path().string()));
            for (std::size_t i = 0; i + 2 < l.size(); ++i) needles.erase(shingle(l, i));
        }
    return needles;
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

std::set<std::string> given_files(const fs::path& lab_dir) {
    std::set<std::string> given;
    const fs::path list = lab_dir / "given.txt";
    if (!fs::exists(list)) return given;
    std::istringstream in(read_text(list));
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        const std::string t = trim(line);
        if (t.empty() || t[0] == '#') continue;
        if (t.find('/') != std::string::npos || fs::path(t).extension() != ".cpp")
            throw std::runtime_error(list.string() + ":" + std::to_string(n) + ": '" + t +
                                     "' is not the name of a src/*.cpp file (one basename per line)");
        given.insert(t);
    }
    return given;
}

std::vector<LabDiff> generate_labs(const fs::path& root, bool write) {
    std::vector<LabDiff> diffs;
    for (const auto& sol : solution_labs(root)) {
        const fs::path lab_src = root / "labs" / sol.filename() / "src";
        const auto given = given_files(root / "labs" / sol.filename());
        for (const auto& g : given)
            if (!fs::is_regular_file(sol / "src" / g))
                diffs.push_back({fs::relative(root / "labs" / sol.filename() / "given.txt", root),
                                 "lists " + g + ", which solutions/" + sol.filename().string() + "/src does not have"});
        std::set<fs::path> expected;
        for (const auto& e : fs::directory_iterator(sol / "src")) {
            if (!e.is_regular_file()) continue;
            const fs::path rel = fs::relative(lab_src / e.path().filename(), root);
            expected.insert(e.path().filename());
            const std::string text = read_text(e.path());
            // Given or not is said once, in given.txt; a file without a solution block is given code.
            const bool has_block = text.find(begin_marker) != std::string::npos;
            const std::string base = e.path().filename().string();
            if (given.count(base) && has_block)
                diffs.push_back({rel, "listed in given.txt but has a solution block (given code is never a task)"});
            if (!given.count(base) && !has_block && e.path().extension() == ".cpp")
                diffs.push_back({rel, "has no solution block but is not listed in labs/" + sol.filename().string() +
                                          "/given.txt (given code must be marked so that the grader takes the course's copy)"});
            std::string want = strip_solutions(text, fs::relative(e.path(), root).string());
            const fs::path target = lab_src / e.path().filename();
            if (!fs::exists(target)) {
                diffs.push_back({rel, "missing"});
                if (write) write_text(target, want);
            } else if (read_text(target) != want) {
                diffs.push_back({rel, "differs from what the generator makes"});
                if (write) write_text(target, want);
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

std::vector<fs::path> tracked_files(const fs::path& root) {
    if (std::system("git --version >/dev/null 2>&1") != 0)
        throw std::runtime_error("git is not installed: the release copies only the files git tracks in " +
                                 root.string());
    // git ls-files -z: every path in the index, NUL-separated (names with spaces or newlines survive).
    const fs::path list = fs::temp_directory_path() / ("geolab-ls-files-" + std::to_string(::getpid()));
    const std::string cmd = "git -C '" + root.string() + "' ls-files -z --cached >'" + list.string() + "' 2>/dev/null";
    const int rc = std::system(cmd.c_str());
    const std::string text = fs::exists(list) ? read_text(list) : std::string();
    fs::remove(list);
    if (rc != 0)
        throw std::runtime_error(root.string() + " is not a git work tree: the release copies only the files git "
                                 "tracks (run 'git init && git add' first)");
    std::vector<fs::path> files;
    for (std::size_t a = 0; a < text.size();) {
        const std::size_t b = std::min(text.find('\0', a), text.size());
        if (b > a) files.emplace_back(text.substr(a, b - a));
        a = b + 1;
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<fs::path> make_release(const fs::path& root, const fs::path& out, bool git_init) {
    if (fs::exists(out) && !fs::is_empty(out)) throw std::runtime_error(out.string() + ": exists and is not empty");
    // What never goes to students.
    auto excluded = [](const fs::path& rel) {
        const std::string first = rel.begin()->string();
        if (first == "solutions" || first == ".git" || first.rfind("build", 0) == 0 || first == "out") return true;
        if (rel.string().rfind("data/models", 0) == 0) return true;
        // The grader's adversarial suite is the reference with twists: answers, so instructors only.
        if (rel.string().rfind("tests/grading/adversarial", 0) == 0) return true;
        // geolab mutate's fixture lab has a solution of its own; mutate needs solutions/, so instructors only.
        if (rel.string().rfind("tests/grading/mutate", 0) == 0) return true;
        if (rel == release_readme_template) return true;  // it becomes README.md
        for (const auto& part : rel)
            if (part == "hidden") return true;
        return false;
    };
    // Only what git tracks: a screenshot, notes or a scratch file lying in the instructor's tree never ships.
    const std::vector<fs::path> tracked = tracked_files(root);
    std::vector<fs::path> written;
    for (const fs::path& rel : tracked) {
        const fs::path from = root / rel;
        if (excluded(rel) || !fs::is_regular_file(fs::symlink_status(from))) continue;  // (deleted, symlinks)
        fs::create_directories((out / rel).parent_path());
        fs::copy_file(from, out / rel, fs::copy_options::overwrite_existing);
        fs::permissions(out / rel, fs::status(from).permissions());
        written.push_back(rel);
    }
    // The student's README replaces the instructor's: a student's two commands, where the handouts are.
    const fs::path student_readme = root / release_readme_template;
    if (!fs::is_regular_file(student_readme))
        throw std::runtime_error(student_readme.string() + ": the student README template is missing");
    // @HANDOUTS@ becomes a link to every released handout (docs/labs/NN_name.md of a lab labs/NN_name).
    std::string handouts;
    for (const auto& rel : written) {
        const std::string r = rel.generic_string(), stem = rel.stem().string();
        if (rel.parent_path() == "docs/labs" && rel.extension() == ".md" && fs::is_directory(out / "labs" / stem))
            handouts += (handouts.empty() ? "" : ", ") + ("[" + r + "](" + r + ")");
    }
    std::string readme = read_text(student_readme);
    if (const auto at = readme.find("@HANDOUTS@"); at != std::string::npos)
        readme.replace(at, std::string("@HANDOUTS@").size(), handouts.empty() ? "docs/labs/" : handouts);
    write_text(out / "README.md", readme);
    if (std::find(written.begin(), written.end(), fs::path("README.md")) == written.end())
        written.push_back("README.md");
    // labs/ comes from the generator, never from a possibly stale copy.
    // (From the tracked solution files only: an untracked scratch file in solutions/ makes no stub.)
    for (const fs::path& rel : tracked)
        if (rel.begin()->string() == "solutions" && fs::is_regular_file(fs::symlink_status(root / rel))) {
            fs::create_directories((out / rel).parent_path());
            fs::copy_file(root / rel, out / rel);
        }
    generate_labs(out, true);
    fs::remove_all(out / "solutions");
    // Leak scan: no marker and no line that exists only inside a solution block may appear in the release.
    const auto answers = solution_shingles(root);
    for (const auto& rel : written) {
        const std::string text = read_text(out / rel);
        if (rel.begin()->string() == "labs" && text.find(begin_marker) != std::string::npos)
            throw std::runtime_error((out / rel).string() + ": contains a solution marker: the release would leak answers");
        // Binary files are skipped; so are the released tests, whose brute-force checks may share a few lines
        // with a solution on purpose (the instructor published them).
        if (text.find('\0') != std::string::npos || rel.begin()->string() == "tests") continue;
        const auto l = meaningful_lines(text);
        for (std::size_t i = 0; i + 2 < l.size(); ++i)
            if (answers.count(shingle(l, i)))
                throw std::runtime_error((out / rel).string() + ":" + std::to_string(l[i].second) +
                                         ": holds three lines of a reference solution ('" + l[i].first +
                                         "' ...): the release would leak answers");
    }
    if (git_init) {
        // A fresh repository with one commit: the students' history starts here, with no trace of answers.
        const std::string q = "'" + out.string() + "'";
        if (std::system("git --version >/dev/null 2>&1") == 0) {
            const std::string cmd = "cd " + q + " && git init -q && git add -A && git -c user.name=geolab -c "
                                    "user.email=geolab@localhost commit -q -m 'Student release' >/dev/null 2>&1";
            if (std::system(cmd.c_str()) != 0) throw std::runtime_error(out.string() + ": git init/commit failed");
        }
    }
    return written;
}

}  // namespace geolab::grading
