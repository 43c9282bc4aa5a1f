#include "geolab/grading/submission.hpp"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include <cxxabi.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cstring>

#include <nlohmann/json.hpp>

#include "geolab/grading/release.hpp"
#include "geolab/models.hpp"
#include "course_build.hpp"
#include "text_file.hpp"

namespace geolab::grading {
namespace fs = std::filesystem;
namespace detail {

CommandResult run_plain(const std::vector<std::string>& argv, double timeout_s, std::size_t memory_mb,
                        std::size_t output_cap) {
    RunOptions o;
    o.memory_mb = memory_mb;
    o.output_cap = output_cap;
    o.file_size_mb = 1024;
    o.sandbox.no_network = false;
    return run_command(argv, timeout_s, o);
}

std::vector<std::string> compile_command(const fs::path& build, const fs::path& source) {
    const fs::path db = build / "compile_commands.json";
    auto j = nlohmann::json::parse(read_text(db), nullptr, false);
    if (j.is_discarded()) throw std::runtime_error(db.string() + ": cannot be read");
    for (const auto& e : j) {
        if (fs::path(e.value("file", "")) != source) continue;
        if (e.contains("arguments")) return e["arguments"].get<std::vector<std::string>>();
        return split_command(e.value("command", ""));
    }
    throw std::runtime_error(db.string() + " has no compile command for " + source.string() +
                             " (re-run cmake on the course build)");
}

std::vector<std::string> link_command(const fs::path& build, const std::string& target) {
    const std::string ninja = find_program("ninja");
    if (ninja.empty()) throw std::runtime_error("ninja not found: the grader needs the course's Ninja build");
    CommandResult r = run_plain({ninja, "-C", build.string(), "-t", "commands", target}, 60);
    if (r.exit_code != 0) throw std::runtime_error("cannot read the link command of " + target + ": " + r.output);
    std::istringstream lines(r.output);
    std::string line, last;
    while (std::getline(lines, line))
        if (!line.empty()) last = line;
    std::vector<std::string> args;
    for (auto& a : split_command(last))
        if (a != ":" && a != "&&") args.push_back(a);
    return args;
}

}  // namespace detail

namespace {

using Clock = std::chrono::steady_clock;

using detail::read_text;
using detail::write_text;
using detail::split_command;
using detail::find_program;
using detail::run_plain;
using detail::compile_command;
using detail::link_command;

// A folder only root may enter, or that others may only traverse (0711).
void make_dir(const fs::path& p, unsigned mode) {
    fs::create_directories(p);
    ::chmod(p.c_str(), mode);
}

std::string hex_hash(const std::string& text) {
    // FNV-1a, 64 bits, twice with different seeds: a cache key, not a security boundary.
    auto fnv = [&](std::uint64_t h) {
        for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
        return h;
    };
    char buf[40];
    std::snprintf(buf, sizeof buf, "%016llx%016llx", static_cast<unsigned long long>(fnv(1469598103934665603ull)),
                  static_cast<unsigned long long>(fnv(0x9e3779b97f4a7c15ull)));
    return buf;
}

// The lab's files: basename -> the stub text (generated from solutions/ when it exists); given files too (their
// text is the course's, whatever is submitted).
std::map<std::string, std::string> lab_files(const fs::path& root, const std::string& lab) {
    std::map<std::string, std::string> files;
    const fs::path sol = root / "solutions" / lab / "src", stu = root / "labs" / lab / "src";
    if (fs::is_directory(sol)) {
        for (const auto& e : fs::directory_iterator(sol))
            if (e.is_regular_file() && e.path().extension() == ".cpp")
                files[e.path().filename().string()] =
                    strip_solutions(read_text(e.path()), fs::relative(e.path(), root).string());
    } else if (fs::is_directory(stu)) {
        for (const auto& e : fs::directory_iterator(stu))
            if (e.is_regular_file() && e.path().extension() == ".cpp")
                files[e.path().filename().string()] = read_text(e.path());
    }
    return files;
}

// The submitted files: every regular file under `dir` (symlinks and special files are ignored).
struct Picked {
    std::map<std::string, fs::path> used;  // basename -> file
    std::vector<std::string> ignored;
};

Picked pick_files(const fs::path& dir, const std::map<std::string, std::string>& wanted,
                  const std::set<std::string>& given) {
    Picked p;
    std::vector<fs::path> all;
    for (auto it = fs::recursive_directory_iterator(dir, fs::directory_options::skip_permission_denied);
         it != fs::recursive_directory_iterator(); ++it) {
        const auto st = it->symlink_status();
        const fs::path rel = fs::relative(it->path(), dir);
        if (fs::is_symlink(st)) {
            p.ignored.push_back(rel.string() + " (a symbolic link: only regular files are graded)");
            continue;
        }
        if (fs::is_directory(st)) {
            if (rel.filename() == "__MACOSX" || rel.filename() == ".git") it.disable_recursion_pending();
            continue;
        }
        if (!fs::is_regular_file(st)) continue;
        all.push_back(it->path());
    }
    // Shallowest first, then by path: the choice among duplicates is deterministic.
    std::sort(all.begin(), all.end(), [&](const fs::path& a, const fs::path& b) {
        auto da = std::distance(a.begin(), a.end()), db = std::distance(b.begin(), b.end());
        return da != db ? da < db : a < b;
    });
    for (const auto& f : all) {
        const std::string base = f.filename().string(), rel = fs::relative(f, dir).string();
        if (!wanted.count(base)) {
            p.ignored.push_back(rel + " (not a file of this lab's src/)");
        } else if (given.count(base)) {
            const bool same = fs::file_size(f) < (1u << 20) && read_text(f) == wanted.at(base);
            p.ignored.push_back(rel + (same ? " (given code: the course's copy is graded; yours is identical)"
                                            : " (given code: the course's copy is graded; YOUR CHANGES TO IT ARE IGNORED)"));
        } else if (p.used.count(base)) {
            p.ignored.push_back(rel + " (another " + base + " was used: " +
                                fs::relative(p.used[base], dir).string() + ")");
        } else if (fs::file_size(f) > (1u << 20)) {
            p.ignored.push_back(rel + " (larger than 1 MiB)");
        } else {
            p.used[base] = f;
        }
    }
    return p;
}

// The folders a compile command reads headers from (-I, -isystem, -iquote, -idirafter; joined or separate):
// what the compiler is shown, read-only, besides the system's own folders.
std::vector<fs::path> include_dirs(const std::vector<std::string>& cmd) {
    std::vector<fs::path> dirs;
    for (std::size_t i = 0; i < cmd.size(); ++i)
        for (const char* flag : {"-I", "-isystem", "-iquote", "-idirafter"}) {
            const std::string f = flag;
            if (cmd[i] == f && i + 1 < cmd.size()) dirs.push_back(cmd[i + 1]);
            else if (cmd[i].size() > f.size() && cmd[i].compare(0, f.size(), f) == 0) dirs.push_back(cmd[i].substr(f.size()));
        }
    return dirs;
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
    if (from.empty()) return s;
    for (std::size_t pos = 0; (pos = s.find(from, pos)) != std::string::npos; pos += to.size())
        s.replace(pos, from.size(), to);
    return s;
}

std::string clip(const std::string& s, std::size_t n) {
    return s.size() > n ? s.substr(0, n) + "\n...(cut: " + std::to_string(s.size() - n) + " more bytes)" : s;
}

// A folder's files (path, size, mtime) as one string: a cheap fingerprint of headers for the object cache.
std::string tree_stamp(const fs::path& dir) {
    std::string s;
    if (!fs::is_directory(dir)) return s;
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        if (!e.is_regular_file()) continue;
        s += e.path().string() + ":" + std::to_string(e.file_size()) + ":" +
             std::to_string(e.last_write_time().time_since_epoch().count()) + ";";
    }
    return s;
}


// ---- checks of the student's compiled code (defence in depth) ---------------------------------------------

std::string demangle(const std::string& name) {
    if (name.size() > 4096 || name.rfind("_Z", 0) != 0) return name;
    int status = 0;
    char* d = abi::__cxa_demangle(name.c_str(), nullptr, nullptr, &status);
    std::string out = (status == 0 && d) ? d : name;
    std::free(d);
    return out;
}

// `nm -P` of `args`: (name, type letter) pairs; archive member headers are skipped.
std::vector<std::pair<std::string, char>> nm_symbols(std::vector<std::string> args) {
    const std::string nm = find_program("nm");
    if (nm.empty()) throw std::runtime_error("nm not found (apt-get install binutils)");
    args.insert(args.begin(), {nm, "-P", "--no-sort"});
    CommandResult r = run_plain(args, 120, 0, 64 << 20);
    std::vector<std::pair<std::string, char>> out;
    std::istringstream in(r.output);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream ls(line);
        std::string name, type;
        if (!(ls >> name >> type) || type.size() != 1 || name.back() == ':') continue;
        out.push_back({name, type[0]});
    }
    return out;
}

bool is_weak(char t) { return t == 'W' || t == 'w' || t == 'V' || t == 'v' || t == 'u'; }
bool is_code(char t) { return t == 'T' || t == 'W' || t == 'i' || t == 'w'; }

// What the course's side of the link defines: the test objects, the other archives, the shared libraries the
// test program loads (the C and C++ runtime among them), and the lab's API (the stub archive's strong symbols).
struct CourseSymbols {
    std::set<std::string> tests, others, shared, api;
};

CourseSymbols course_symbols(const std::vector<std::string>& link_args, const fs::path& build,
                             const fs::path& course_program, const std::string& lab_archive) {
    CourseSymbols c;
    std::vector<std::string> objects, archives;
    for (const auto& a : link_args) {
        if (a.empty() || a[0] == '-') continue;
        fs::path p = fs::path(a).is_relative() ? build / a : fs::path(a);
        if (!fs::is_regular_file(p)) continue;
        const std::string ext = p.extension().string();
        if (ext == ".o") objects.push_back(p.string());
        else if (ext == ".a" && p.filename() != lab_archive) archives.push_back(p.string());
    }
    std::vector<std::string> defined{"-g", "--defined-only"};
    auto add = [&](std::vector<std::string> files, std::set<std::string>& into, bool dynamic) {
        if (files.empty()) return;
        std::vector<std::string> a = defined;
        if (dynamic) a.push_back("-D");
        a.insert(a.end(), files.begin(), files.end());
        for (const auto& [n, t] : nm_symbols(a)) into.insert(n);
    };
    add(objects, c.tests, false);
    add(archives, c.others, false);
    std::vector<std::string> libs;
    CommandResult l = run_plain({find_program("ldd"), course_program.string()}, 60);
    std::istringstream in(l.output);
    for (std::string line; std::getline(in, line);) {
        auto slash = line.find('/');
        if (slash == std::string::npos) continue;
        std::string path = line.substr(slash, line.find(' ', slash) - slash);
        if (fs::is_regular_file(path)) libs.push_back(path);
    }
    for (const auto& lib : libs) add({lib}, c.shared, true);
    for (const auto& [n, t] : nm_symbols({"-g", "--defined-only", (build / lab_archive).string()}))
        if (!is_weak(t)) c.api.insert(n);
    return c;
}

// course_symbols, kept in the job cache (`dir`) under a key made of every input's path, size and time: the course
// build and its shared libraries change rarely, and reading them (nm of each library) costs seconds a submission.
CourseSymbols cached_course_symbols(const std::vector<std::string>& link_args, const fs::path& build,
                                    const fs::path& course_program, const std::string& lab_archive,
                                    const fs::path& dir) {
    std::string key = "course symbols v1\n";
    auto stamp_of = [&](const fs::path& p) {
        std::error_code ec;
        const auto size = fs::file_size(p, ec);
        const auto time = fs::last_write_time(p, ec).time_since_epoch().count();
        key += p.string() + " " + std::to_string(ec ? 0 : size) + " " + std::to_string(ec ? 0 : time) + "\n";
    };
    stamp_of(course_program);
    stamp_of(build / lab_archive);
    for (const auto& a : link_args)
        if (!a.empty() && a[0] != '-') stamp_of(fs::path(a).is_relative() ? build / a : fs::path(a));
    for (const char* lib : {"/usr/lib/x86_64-linux-gnu/libc.so.6", "/usr/lib/x86_64-linux-gnu/libstdc++.so.6"})
        stamp_of(lib);  // a system upgrade
    const fs::path file = dir / (hex_hash(key) + ".symbols");
    CourseSymbols c;
    std::set<std::string>* sets[] = {&c.tests, &c.others, &c.shared, &c.api};
    if (fs::exists(file)) {
        std::istringstream in(read_text(file));
        for (std::string line; std::getline(in, line);)
            if (line.size() > 2 && line[0] >= '0' && line[0] <= '3') sets[line[0] - '0']->insert(line.substr(2));
        return c;
    }
    c = course_symbols(link_args, build, course_program, lab_archive);
    std::string text;
    for (int k = 0; k < 4; ++k)
        for (const auto& n : *sets[k]) text += std::to_string(k) + " " + n + "\n";
    const fs::path tmp = file.string() + ".tmp" + std::to_string(::getpid());
    write_text(tmp, text, fs::perms(0600));
    fs::rename(tmp, file);  // atomic: parallel jobs share the cache
    return c;
}

// The problems of one student object: symbols defined outside the lab's API, early-running sections, raw
// system-call instructions, uses of what only the tests define. Each a sentence a student can act on.
std::vector<std::string> object_problems(const std::string& file, const fs::path& obj, const CourseSymbols& c) {
    std::vector<std::string> problems;
    std::set<std::string> own;
    for (const auto& [n, t] : nm_symbols({obj.string()})) {
        const std::string d = demangle(n);
        if (t == 'i') {
            problems.push_back(file + " defines the indirect function (ifunc) '" + d +
                               "', whose resolver would run before any test code");
            continue;
        }
        if (t == 'U' || t == 'w' || t == 'v' || (std::islower(static_cast<unsigned char>(t)) && t != 'u')) continue;
        own.insert(n);
        if (c.api.count(n) || n.rfind("DW.ref.", 0) == 0) continue;
        const bool mangled = n.rfind("_Z", 0) == 0;
        const bool theirs = c.shared.count(n) || c.others.count(n) || c.tests.count(n);
        if (!mangled && is_code(t))
            problems.push_back(file + " defines the C-linkage function '" + n +
                               "' (extern \"C\", or a C library name): only the lab's API may be defined; make helpers "
                               "static or put them in an anonymous namespace");
        else if (!mangled && (theirs || n[0] == '_'))
            problems.push_back(file + " defines the global '" + n + "', which the C library or the course's code uses");
        else if (mangled && !is_weak(t) && theirs)
            problems.push_back(file + " redefines '" + d + "', which the C++ runtime or the course's code defines");
        else if (mangled && (n.rfind("_Znw", 0) == 0 || n.rfind("_Zna", 0) == 0 || n.rfind("_Zdl", 0) == 0 ||
                             n.rfind("_Zda", 0) == 0) &&
                 // the placement forms are <new>'s own inline functions (not replaceable), emitted weak at -O0
                 !(is_weak(t) && (n == "_ZnwmPv" || n == "_ZnamPv" || n == "_ZdlPvS_" || n == "_ZdaPvS_")))
            problems.push_back(file + " replaces '" + d + "': replacing the global allocation functions is not allowed");
    }
    for (const auto& [n, t] : nm_symbols({"-u", obj.string()}))
        if (c.tests.count(n) && !c.others.count(n) && !c.shared.count(n) && !c.api.count(n))
            problems.push_back(file + " uses '" + demangle(n) +
                               "', which only the test code defines (the tests' helpers are not part of the lab's API)");
    const std::string objdump = find_program("objdump");
    if (objdump.empty()) throw std::runtime_error("objdump not found (apt-get install binutils)");
    {
        std::istringstream in(run_plain({objdump, "-h", "-w", obj.string()}, 60).output);
        for (std::string line; std::getline(in, line);) {
            std::istringstream ls(line);
            std::string idx, name;
            if (!(ls >> idx >> name) || !std::isdigit(static_cast<unsigned char>(idx[0]))) continue;
            auto starts = [&](const char* p) { return name.rfind(p, 0) == 0; };
            if (starts(".preinit_array") || starts(".init_array.") || starts(".ctors") || starts(".dtors") ||
                starts(".fini_array.") || name == ".init" || name == ".fini")
                problems.push_back(file + " has a section '" + name +
                                   "': code that runs before (or around) the program's own start-up is not allowed "
                                   "(constructor priorities, .preinit_array, .ctors)");
        }
    }
    {
        std::istringstream in(run_plain({objdump, "-d", "--no-show-raw-insn", obj.string()}, 120, 0, 64 << 20).output);
        std::string function;
        for (std::string line; std::getline(in, line);) {
            if (!line.empty() && line.back() == ':' && line.find(" <") != std::string::npos)
                function = demangle(line.substr(line.find(" <") + 2, line.size() - line.find(" <") - 4));
            auto tab = line.rfind('\t');
            if (tab == std::string::npos) continue;
            const std::string insn = line.substr(tab + 1);
            if (insn.rfind("syscall", 0) == 0 || insn.rfind("sysenter", 0) == 0 ||
                (insn.rfind("int", 0) == 0 && insn.find("$0x80") != std::string::npos)) {
                problems.push_back(file + ": " + function + " executes a raw system call instruction ('" + insn +
                                   "'): talk to the system through the C++ library only");
                break;
            }
        }
    }
    return problems;
}

// ---- forbidden calls over the student's whole code --------------------------------------------------------
// A call graph of all the student's objects together: nodes are their functions (locals qualified by file) and
// one node per file for references from data (tables of function pointers, .init_array); edges come from the
// disassembly's direct calls and from every relocation. Aliases (symbols at one address) are one function.
struct CallGraph {
    std::map<std::string, std::set<std::string>> edges;
    std::map<std::string, std::string> file_of;     // node -> student file
    std::map<std::string, bool> strong;             // node -> a strong (non-weak) definition
    std::map<std::string, std::set<std::string>> alias;  // node -> the other names at its address
};

// A node as a student reads it: the demangled name without its parameter list.
std::string pretty(const std::string& node) {
    const auto hash = node.find('#');
    std::string d = demangle(hash == std::string::npos ? node : node.substr(hash + 1));
    if (const auto paren = d.find('('); paren != std::string::npos && paren > 0) d = d.substr(0, paren);
    return d;
}

void add_object(CallGraph& g, const std::string& file, const fs::path& obj) {
    const std::string objdump = find_program("objdump");
    // The symbol table: functions by section and offset; locals get the file's name in front.
    struct Fn {
        std::string section, node;
        unsigned long long start, size;
    };
    std::vector<Fn> fns;
    std::set<std::string> locals;
    {
        std::istringstream in(run_plain({objdump, "-t", "-w", obj.string()}, 60, 0, 64 << 20).output);
        for (std::string line; std::getline(in, line);) {
            // "0000000000000000 g     F .text	0000000000000123 name"
            if (line.size() < 26 || line[16] != ' ') continue;
            const std::string flags = line.substr(17, 7);
            const auto tab = line.find('\t', 25);
            if (tab == std::string::npos) continue;
            const std::string section = line.substr(25, tab - 25);
            std::istringstream rest(line.substr(tab + 1));
            std::string size, name;
            if (!(rest >> size >> name)) continue;
            const bool local = flags[0] == 'l';
            if (flags[6] != 'F' && flags[6] != 'i' && flags.find('F') == std::string::npos) continue;
            const std::string node = local ? file + "#" + name : name;
            if (local) locals.insert(name);
            fns.push_back({section, node, std::stoull(line.substr(0, 16), nullptr, 16), std::stoull(size, nullptr, 16)});
            g.file_of[node] = file;
            g.strong[node] = g.strong[node] || flags[1] != 'w';
            g.edges[node];
        }
    }
    for (const auto& a : fns)
        for (const auto& b : fns)
            if (&a != &b && a.section == b.section && a.start == b.start) g.alias[a.node].insert(b.node);
    auto node_of = [&](const std::string& name) { return locals.count(name) ? file + "#" + name : name; };
    auto at = [&](const std::string& section, unsigned long long off) -> std::string {
        for (const auto& f : fns)
            if (f.section == section && off >= f.start && off < f.start + std::max(1ull, f.size)) return f.node;
        return "";
    };
    // A relocation's target: "name", "name+0x10", ".text+0x1a0" (a local function by its section and offset).
    auto target = [&](const std::string& type, std::string expr) -> std::string {
        long long addend = 0;
        auto sign = expr.find_last_of("+-");
        if (sign != std::string::npos && sign > 0 && expr.compare(sign + 1, 2, "0x") == 0) {
            addend = std::stoll(expr.substr(sign + 3), nullptr, 16) * (expr[sign] == '-' ? -1 : 1);
            expr = expr.substr(0, sign);
        }
        if (!expr.empty() && expr[0] == '.') {
            if (type.find("PC32") != std::string::npos || type.find("PLT32") != std::string::npos) addend += 4;
            return addend >= 0 ? at(expr, static_cast<unsigned long long>(addend)) : "";
        }
        return node_of(expr);
    };
    // Code: "Disassembly of section S:", "<fn>:" headers, calls and jumps to "<name>", relocation lines.
    {
        std::istringstream in(run_plain({objdump, "-dr", "-w", "--no-show-raw-insn", obj.string()}, 120, 0, 256 << 20).output);
        std::string current;
        for (std::string line; std::getline(in, line);) {
            if (line.rfind("Disassembly of section ", 0) == 0) {
                current.clear();
                continue;
            }
            if (!line.empty() && line.back() == ':' && line.find(" <") != std::string::npos && line[0] != ' ') {
                const auto a = line.find(" <") + 2;
                current = node_of(line.substr(a, line.size() - a - 2));
                continue;
            }
            if (current.empty()) continue;
            const auto r = line.find("R_X86_64_");
            if (r != std::string::npos) {
                std::istringstream ls(line.substr(r));
                std::string type, expr;
                if (ls >> type >> expr) {
                    const std::string t = target(type, expr);
                    if (!t.empty() && t != current) g.edges[current].insert(t);
                }
                continue;
            }
            const auto lt = line.rfind('<'), gt = line.rfind('>');
            if ((line.find("call") != std::string::npos || line.find("jmp") != std::string::npos) && lt != std::string::npos &&
                gt != std::string::npos && gt > lt) {
                std::string name = line.substr(lt + 1, gt - lt - 1);
                if (auto plus = name.find('+'); plus != std::string::npos) name = name.substr(0, plus);
                const std::string t = node_of(name);
                if (t != current) g.edges[current].insert(t);
            }
        }
    }
    // Data: every relocation outside code and unwind/debug sections, as one node per file.
    {
        std::istringstream in(run_plain({objdump, "-r", "-w", obj.string()}, 60, 0, 64 << 20).output);
        std::string section;
        const std::string data_node = file + "#(data)";
        for (std::string line; std::getline(in, line);) {
            if (line.rfind("RELOCATION RECORDS FOR [", 0) == 0) {
                section = line.substr(24, line.find(']') - 24);
                continue;
            }
            if (section.empty() || section.rfind(".text", 0) == 0 || section.rfind(".eh_frame", 0) == 0 ||
                section.rfind(".debug", 0) == 0 || section.rfind(".note", 0) == 0 || section == ".gcc_except_table")
                continue;
            std::istringstream ls(line);
            std::string off, type, expr;
            if (!(ls >> off >> type >> expr) || type.rfind("R_", 0) != 0) continue;
            const std::string t = target(type, expr);
            if (t.empty()) continue;
            g.edges[data_node].insert(t);
            g.file_of[data_node] = file;
        }
    }
}

// The forbidden entry matches a symbol: as a substring of its mangled or its demangled name.
bool entry_matches(const ForbiddenCall& f, const std::string& node) {
    const std::string name = node.substr(node.find('#') == std::string::npos ? 0 : node.find('#') + 1);
    return name.find(f.symbol) != std::string::npos || demangle(name).find(f.symbol) != std::string::npos;
}

// The forbidden entry's symbols in the graph (aliases included), and the files that hold a strong definition of
// one of them: there the student writes that function's own task, so those files are exempt.
std::set<std::string> forbidden_nodes(const CallGraph& g, const ForbiddenCall& f) {
    std::set<std::string> bad;
    for (const auto& [n, e] : g.edges) {
        if (entry_matches(f, n)) bad.insert(n);
        for (const auto& t : e)
            if (entry_matches(f, t)) bad.insert(t);
    }
    for (const auto& b : std::set<std::string>(bad))
        if (g.alias.count(b)) bad.insert(g.alias.at(b).begin(), g.alias.at(b).end());
    return bad;
}
std::set<std::string> exempt_files(const CallGraph& g, const std::set<std::string>& bad) {
    std::set<std::string> files;
    for (const auto& b : bad)
        if (g.file_of.count(b) && g.strong.count(b) && g.strong.at(b)) files.insert(g.file_of.at(b));
    return files;
}

// Every student function (or data node) that reaches a forbidden symbol, through any of the student's own
// functions in any file. The file holding the student's own (strong) definition of the forbidden function is
// exempt (that is where its task is written); so is the forbidden function itself.
std::vector<ForbiddenCall> forbidden_in_graph(const CallGraph& g, const std::vector<ForbiddenCall>& list,
                                              const std::string& lab) {
    std::vector<ForbiddenCall> hits;
    for (const auto& f : list) {
        const std::set<std::string> bad = forbidden_nodes(g, f);
        if (bad.empty()) continue;
        const std::set<std::string> exempt = exempt_files(g, bad);
        std::set<std::string> reported;
        for (const auto& [start, unused] : g.edges) {
            if (bad.count(start) || !g.file_of.count(start)) continue;
            const std::string file = g.file_of.at(start);
            if (exempt.count(file) || reported.count(file)) continue;
            // Breadth-first through the student's functions; remember the way for the message.
            std::map<std::string, std::string> from{{start, ""}};
            std::vector<std::string> queue{start};
            std::string found;
            for (std::size_t qi = 0; qi < queue.size() && found.empty(); ++qi) {
                const auto it = g.edges.find(queue[qi]);
                if (it == g.edges.end()) continue;
                for (const auto& t : it->second) {
                    if (from.count(t)) continue;
                    from[t] = queue[qi];
                    if (bad.count(t)) {
                        found = t;
                        break;
                    }
                    if (g.edges.count(t)) queue.push_back(t);
                }
            }
            if (found.empty()) continue;
            std::vector<std::string> way;
            for (std::string n = from[found]; !n.empty() && n != start; n = from[n]) way.push_back(pretty(n));
            std::reverse(way.begin(), way.end());
            ForbiddenCall hit = f;
            hit.file = "labs/" + lab + "/src/" + file;
            hit.where = (start.find("#(data)") != std::string::npos ? std::string("a table of function pointers")
                                                                     : pretty(start));
            for (const auto& w : way) hit.where += " -> " + w;
            hit.where += " -> " + pretty(found);
            hits.push_back(hit);
            reported.insert(file);
        }
    }
    return hits;
}

// A regular expression that matches exactly `text` (llvm::Regex, POSIX extended).
std::string regex_escape(const std::string& text) {
    std::string o;
    for (char c : text) {
        if (std::strchr(".^$|()[]{}*+?\\", c)) o += '\\';
        o += c;
    }
    return o;
}

// The clang-query matcher of one forbidden entry: a call to, or a reference of, a function whose qualified name
// ends with the entry, written in the student's file (templates and inline functions included).
std::string ast_matcher(const ForbiddenCall& f) {
    const std::string re = "(^|::)" + regex_escape(f.symbol) + "$";
    return "match expr(anyOf(callExpr(callee(functionDecl(matchesName(\"" + re +
           "\")))), declRefExpr(to(functionDecl(matchesName(\"" + re + "\"))))), isExpansionInMainFile())";
}

// A TestResult for a check of the grader (0 points unless it zeroes a task).
TestResult check_result(const std::string& name, bool passed, std::vector<std::string> messages,
                        std::string output = "") {
    TestResult r;
    r.info.name = name;
    r.info.suite = "Checks";
    r.info.points = 0;
    r.status = passed ? Status::passed : Status::failed;
    r.messages = std::move(messages);
    r.output = std::move(output);
    return r;
}

}  // namespace

const char* to_string(SubmissionStatus s) {
    switch (s) {
        case SubmissionStatus::ok: return "ok";
        case SubmissionStatus::compile_error: return "compile error";
        case SubmissionStatus::grader_error: return "grader error";
        case SubmissionStatus::empty: return "empty submission";
        case SubmissionStatus::unreadable: return "unreadable submission";
        case SubmissionStatus::not_found: return "not found";
    }
    return "?";
}

std::vector<ForbiddenCall> read_forbidden_list(const fs::path& file) {
    std::vector<ForbiddenCall> list;
    if (!fs::exists(file)) return list;
    std::istringstream in(read_text(file));
    std::string line;
    auto trim = [](std::string s) {
        auto a = s.find_first_not_of(" \t\r");
        if (a == std::string::npos) return std::string();
        return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
    };
    while (std::getline(in, line)) {
        line = trim(line);
        if (line.empty() || line[0] == '#') continue;
        ForbiddenCall f;
        std::vector<std::string> parts;
        std::size_t a = 0;
        for (std::size_t b; (b = line.find('|', a)) != std::string::npos; a = b + 1) parts.push_back(trim(line.substr(a, b - a)));
        parts.push_back(trim(line.substr(a)));
        f.symbol = parts[0];
        if (parts.size() > 1) f.reason = parts[1];
        if (parts.size() > 2) f.task = parts[2];
        if (!f.symbol.empty()) list.push_back(f);
    }
    return list;
}

std::string SubmissionReport::summary() const {
    std::ostringstream os;
    // One status line: the word, and for a submission that could not be graded, why (and what to do).
    os << "status: " << to_string(status);
    if (!error.empty()) os << ": " << error;
    if (status == SubmissionStatus::grader_error)
        os << "\nthis is a problem of the grader, not of the submission: grade it again (the same command); if it "
              "fails again, tell the instructor this message";
    os << "\n";
    if (!isolation.empty()) {
        if (isolation.rfind("NOT ISOLATED", 0) == 0)
            os << "!!!!!!!! " << isolation << "\n!!!!!!!! the student's code ran with the grader's rights and could see "
                  "the course tree: do not trust this grade for a submission you do not trust\n";
        else
            os << "sandbox: " << isolation << "\n";
    }
    if (capped) os << "the wall-clock cap of the whole submission was reached: what had not finished scores 0\n";
    if (!used.empty()) {
        os << "files graded:";
        for (const auto& u : used) os << " " << u;
        os << "\n";
    }
    if (!stubbed.empty()) {
        os << "not submitted (the untouched stub was used):";
        for (const auto& s : stubbed) os << " " << s;
        os << "\n";
    }
    if (!given.empty()) {
        os << "given files (always the course's copy):";
        for (const auto& g : given) os << " " << g;
        os << "\n";
    }
    for (const auto& r : rejected) os << "rejected: " << r << "\n";
    if (!ignored.empty()) {
        os << "ignored (only the lab's own src/*.cpp files are graded, given files excepted):\n";
        for (const auto& i : ignored) os << "  " << i << "\n";
    }
    for (const auto& f : forbidden)
        os << "forbidden call: " << f.file << " calls " << f.symbol << (f.where.empty() ? "" : " [" + f.where + "]")
           << (f.reason.empty() ? "" : " (" + f.reason + ")")
           << (f.task.empty() ? "" : "; task '" + f.task + "' scores 0") << "\n";
    if (status == SubmissionStatus::ok && !lab.isolated)
        os << "verdict not isolated: this lab has no GEOLAB_BOUNDARY list, so its test program (with your code in "
              "it) decided its own verdicts\n";
    if (status == SubmissionStatus::compile_error) os << "\nYour code did not compile; every test scores 0.\n";
    if (!compiler_output.empty()) os << "\n--- compiler messages ---\n" << compiler_output << "\n";
    return os.str();
}

SubmissionReport grade_submission(const fs::path& submission, const SubmissionOptions& opt) {
    SubmissionReport rep;
    rep.lab.lab = opt.lab;
    rep.lab.variant = "submission";
    const auto t0 = Clock::now();
    auto finish = [&]() -> SubmissionReport& {
        rep.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
        rep.lab.seconds = rep.seconds;
        return rep;
    };
    try {
        const fs::path root = fs::absolute(opt.course_root), build = fs::absolute(opt.build_dir),
                       work = fs::absolute(opt.work_dir);
        const auto files = lab_files(root, opt.lab);
        if (files.empty()) throw std::runtime_error("lab " + opt.lab + " has no src/*.cpp files in " + root.string());
        const fs::path course_program = build / "bin" / ("test_" + opt.lab);
        // The judge (record and replay): the course's own program, never relinked; it lists and judges.
        const fs::path judge = build / "bin" / ("judge_" + opt.lab);
        const fs::path boundary_syms = build / "boundary" / opt.lab / "student.syms";
        if (opt.build_course) {
            const std::string cmake = find_program("cmake");
            std::vector<std::string> cmd{cmake, "--build", build.string(), "--target", "test_" + opt.lab};
            if (fs::exists(boundary_syms)) cmd.push_back("judge_" + opt.lab);
            CommandResult b = run_plain(cmd, 3600);
            if (b.exit_code != 0)
                throw std::runtime_error("the course build of test_" + opt.lab + " failed:\n" + clip(b.output, 4000));
        }
        if (!fs::exists(course_program))
            throw std::runtime_error(course_program.string() + " not found: build the course first (cmake --build " +
                                     build.string() + ")");

        // Tests run as their own uid: every folder above the work folder must let others through (x).
        if (can_drop_privileges())
            for (fs::path p = work.parent_path(); !p.empty() && p != p.root_path(); p = p.parent_path()) {
                struct stat st {};
                if (::stat(p.c_str(), &st) == 0 && !(st.st_mode & S_IXOTH))
                    throw std::runtime_error("the work folder " + work.string() + " is not reachable by the tests' uid: " +
                                             p.string() + " lacks o+x (chmod o+x it, or choose another --work-dir)");
            }
        // The job's folders: root-only except what the sandboxed processes must reach (the test program).
        make_dir(work, 0711);
        make_dir(work / "src", 0700);
        const fs::path cache = work.parent_path() / "cache";  // shared by the lab's jobs: objects by content
        make_dir(cache, 0700);
        make_dir(work / "bin", 0711);
        make_dir(work / "tmp", 0711);

        // A submission that cannot be graded scores 0 on every test, listed (from the course's own program) so
        // that max_score is right; `why` is the one status line.
        auto score_zero = [&](SubmissionStatus status, const std::string& why) -> SubmissionReport& {
            rep.status = status;
            rep.error = why;
            for (const auto& t : list_tests(fs::exists(judge) ? judge : course_program, opt.run)) {
                TestResult r;
                r.info = t;
                r.status = Status::failed;
                r.messages.push_back(std::string(to_string(status)) + ": no test ran");
                rep.lab.results.push_back(std::move(r));
            }
            return finish();
        };

        // 1. The submission: a folder, or a zip unpacked into a fresh folder.
        if (!fs::exists(submission))
            return score_zero(SubmissionStatus::not_found, submission.string() + ": no such folder or zip file");
        fs::path sub_dir = submission;
        if (fs::is_regular_file(submission)) {
            sub_dir = work / "unpacked";
            fs::remove_all(sub_dir);
            make_dir(sub_dir, 0700);
            const std::string unzip = find_program("unzip");
            if (unzip.empty()) throw std::runtime_error("unzip not found (apt-get install unzip)");
            CommandResult u = run_plain({unzip, "-qq", "-o", fs::absolute(submission).string(), "-d", sub_dir.string()}, 120);
            if (u.exit_code != 0 && u.exit_code != 1) {  // 1: warnings (e.g. skipped ../ entries)
                // unzip's message on one line, without its "[file]" line: the status is one line.
                std::string why, line;
                std::istringstream lines(u.output);
                while (std::getline(lines, line)) {
                    if (line.empty() || line[0] == '[') continue;
                    for (std::istringstream words(line); words >> line;) why += (why.empty() ? "" : " ") + line;
                }
                if (const auto dot = why.find(". "); dot != std::string::npos) why.resize(dot);  // its first sentence
                if (why.size() > 200) why.resize(200);
                return score_zero(SubmissionStatus::unreadable,
                                  submission.string() + " is not a zip file that can be unpacked (unzip: " + why +
                                      "): make the zip again and resubmit");
            }
        } else if (!fs::is_directory(submission)) {
            return score_zero(SubmissionStatus::unreadable, submission.string() + " is neither a folder nor a zip file");
        }
        const auto given = given_files(root / "labs" / opt.lab);
        Picked picked = pick_files(sub_dir, files, given);
        rep.ignored = picked.ignored;
        if (picked.used.empty()) {
            std::string names;
            for (const auto& [name, stub] : files)
                if (!given.count(name)) names += (names.empty() ? "" : ", ") + name;
            return score_zero(SubmissionStatus::empty, "none of the lab's files (" + names + ") is in " +
                                                           submission.filename().string() +
                                                           ": submit your labs/" + opt.lab + "/src/*.cpp");
        }

        // 2. The lab's sources: submitted files, stubs for the rest, the course's copy of given files.
        fs::remove_all(work / "src");
        make_dir(work / "src", 0700);
        for (const auto& [name, stub] : files) {
            if (given.count(name)) {
                write_text(work / "src" / name, stub);
                rep.given.push_back(name);
            } else if (picked.used.count(name)) {
                fs::copy_file(picked.used[name], work / "src" / name, fs::copy_options::overwrite_existing);
                fs::permissions(work / "src" / name, fs::perms(0644));
                rep.used.push_back(name + " <- " + fs::relative(picked.used[name], sub_dir).string());
            } else {
                write_text(work / "src" / name, stub);
                rep.stubbed.push_back(name);
            }
        }

        // The sandbox of everything untrusted: its own uid, no network, a file system built from an allow-list,
        // a clean environment, and a wall-clock cap on the whole submission. Fail closed: as root, a sandbox that
        // cannot be set up means no grading (unless the instructor says --allow-unisolated, and then loudly).
        RunOptions sandboxed = opt.run;
        if (fs::exists(boundary_syms)) {
            if (!fs::exists(judge))
                throw std::runtime_error(judge.string() + " not found: build the course first (cmake --build " +
                                         build.string() + ")");
            sandboxed.judge = judge;
        }
        Sandbox& sb = sandboxed.sandbox;
        sb.drop_privileges = true;
        sb.no_network = true;
        sb.workdir = work / "tmp";
        sb.allow_list = true;
        sb.clean_env = true;
        const std::string problem = isolation_problem(sb);
        if (problem.empty()) {
            sb.require_isolation = true;
            rep.isolation = "isolated (own uid, allow-list file system, private /tmp, no network, clean environment)";
        } else if (can_drop_privileges() && !opt.allow_unisolated) {
            throw SandboxError("refusing to grade: the sandbox cannot be set up: " + problem +
                               " (fix that, or grade with --allow-unisolated to run the student's code NOT ISOLATED)");
        } else {
            rep.isolation = "NOT ISOLATED: " + problem;
            sb.allow_list = false;  // what is left: the old hide-list, where root can make it
            sb.hide = {root / "solutions", root / "tests", build / "CMakeFiles", build / "bin", build / "tests",
                       work / "src", cache};
        }
        if (opt.max_seconds > 0) sandboxed.deadline = t0 + std::chrono::duration_cast<Clock::duration>(
                                                              std::chrono::duration<double>(opt.max_seconds));

        const std::string stamp = tree_stamp(root / "labs" / opt.lab / "include") + tree_stamp(root / "lib" / "include") +
                                  tree_stamp(build / "lib" / "include");

        // 3. Compile each file with the course's own command, as the sandbox user; objects are cached by content.
        auto compile_all = [&](bool asan, std::vector<fs::path>& objects, std::string& messages) {
            bool ok = true;
            for (const auto& [name, stub] : files) {
                const fs::path src = work / "src" / name;
                const std::string text = read_text(src);
                std::vector<std::string> cmd = compile_command(build, root / "labs" / opt.lab / "src" / name);
                std::vector<std::string> args;
                for (std::size_t i = 0; i < cmd.size(); ++i) {
                    const std::string& a = cmd[i];
                    if (a == "-o" && i + 1 < cmd.size()) {
                        ++i;
                        continue;
                    }
                    if (a == "-MD" || a == "-MMD") continue;
                    if ((a == "-MT" || a == "-MF") && i + 1 < cmd.size()) {
                        ++i;
                        continue;
                    }
                    if (a == "-c" && i + 1 < cmd.size()) {
                        ++i;
                        continue;
                    }
                    if (fs::path(a) == root / "labs" / opt.lab / "src" / name) continue;
                    args.push_back(a);
                }
                if (asan)
                    for (const char* f : {"-fsanitize=address,undefined", "-fno-omit-frame-pointer", "-g", "-O1"})
                        args.push_back(f);
                args.push_back("-fdiagnostics-color=never");
                args.push_back("-o");
                args.push_back("student.o");
                args.push_back("-c");
                args.push_back(name);
                std::string key_src;
                for (const auto& a : args) key_src += a + " ";
                const fs::path cached = cache / (hex_hash(key_src + "\n" + stamp + "\n" + text) + ".o");
                const fs::path cached_log = fs::path(cached).replace_extension(".log");
                if (fs::exists(cached)) {
                    objects.push_back(cached);
                    if (fs::exists(cached_log)) messages += read_text(cached_log);
                    continue;
                }
                RunOptions o = sandboxed;
                o.sandbox.visible = include_dirs(cmd);
                o.memory_mb = std::max<std::size_t>(opt.run.memory_mb, 4096);
                o.output_cap = 256 << 10;
                bool produced = false;
                o.sandbox.prepare = [&](const fs::path& dir, unsigned uid) {
                    write_text(dir / name, text);
                    if (uid) (void)!::chown((dir / name).c_str(), uid, uid);
                };
                o.sandbox.collect = [&](const fs::path& dir) {
                    struct stat st {};
                    const fs::path obj = dir / "student.o";
                    if (::lstat(obj.c_str(), &st) == 0 && S_ISREG(st.st_mode) && st.st_size < (512 << 20)) {
                        const fs::path tmp = cached.string() + ".tmp" + std::to_string(::getpid()) + name;
                        fs::copy_file(obj, tmp, fs::copy_options::overwrite_existing);
                        fs::rename(tmp, cached);  // atomic: parallel jobs share the cache
                        produced = true;
                    }
                };
                CommandResult r = run_command(args, opt.compile_timeout_s, o);
                std::string out = replace_all(r.output, name + ":", "labs/" + opt.lab + "/src/" + name + ":");
                out = replace_all(out, "In file included from " + name, "In file included from labs/" + opt.lab + "/src/" + name);
                if (r.exit_code != 0 || !produced) {
                    ok = false;
                    fs::remove(cached);
                    messages += out.empty() ? "labs/" + opt.lab + "/src/" + name + ": the compiler failed\n" : out;
                } else {
                    if (!out.empty()) write_text(cached_log, out, fs::perms(0600));
                    messages += out;
                    objects.push_back(cached);
                }
            }
            return ok;
        };

        // 4. Link the course's test objects with the student's objects, with the course's own link command.
        auto link = [&](const std::vector<fs::path>& objects, bool asan, const fs::path& out) {
            std::vector<std::string> cmd = link_command(build, "test_" + opt.lab), args;
            const std::string archive = "liblab_" + opt.lab.substr(0, 2) + ".a";
            // The performer (record and replay) links the lab with each boundary function renamed for the
            // recorder: the student's objects get the same renaming (definitions and their calls among them).
            const std::string performer_archive = "liblab_" + opt.lab.substr(0, 2) + "_performer.a";
            std::vector<fs::path> linked = objects;
            bool renamed = false;
            for (const auto& a : cmd) {
                if (fs::path(a).filename() != performer_archive || renamed) continue;
                renamed = true;
                const std::string objcopy = find_program("objcopy");
                if (objcopy.empty()) throw std::runtime_error("objcopy not found (apt-get install binutils)");
                make_dir(work / "obj", 0700);
                linked.clear();
                for (std::size_t k = 0; k < objects.size(); ++k) {
                    const fs::path o = work / "obj" / (std::to_string(k) + (asan ? "_asan" : "") + ".o");
                    CommandResult c = run_plain({objcopy, "--redefine-syms=" + boundary_syms.string(),
                                                 objects[k].string(), o.string()}, 120);
                    if (c.exit_code != 0) return "objcopy failed on a compiled file: " + c.output;
                    linked.push_back(o);
                }
            }
            bool replaced = false;
            for (std::size_t i = 0; i < cmd.size(); ++i) {
                const std::string& a = cmd[i];
                if (a == "-o" && i + 1 < cmd.size()) {
                    ++i;
                    continue;
                }
                if (fs::path(a).filename() == archive || fs::path(a).filename() == performer_archive) {
                    for (const auto& o : linked) args.push_back(o.string());
                    replaced = true;
                    continue;
                }
                if (!a.empty() && a[0] != '-' && i > 0 && fs::path(a).is_relative() && fs::exists(build / a))
                    args.push_back((build / a).string());
                else
                    args.push_back(a);
            }
            if (!replaced) throw std::runtime_error("the link command of test_" + opt.lab + " does not use " + archive);
            if (asan) args.push_back("-fsanitize=address,undefined");
            args.push_back("-o");
            args.push_back(out.string() + ".tmp");
            if (!args.empty() && fs::path(args[0]).is_relative()) {
                std::string p = find_program(args[0]);
                if (!p.empty()) args[0] = p;
            }
            CommandResult r = run_plain(args, 300);
            if (r.exit_code != 0) return r.output.empty() ? std::string("the linker failed") : r.output;
            fs::rename(out.string() + ".tmp", out);
            ::chmod(out.c_str(), 0711);  // the test may run it, never read it
            return std::string();
        };

        std::vector<fs::path> objects;
        std::string messages;
        const bool compiled = compile_all(false, objects, messages);
        rep.compiler_output = clip(messages, 20000);
        std::string link_error;
        const fs::path program = work / "bin" / ("test_" + opt.lab);
        if (compiled) {
            link_error = link(objects, false, program);
            // A link error caused by the student (a missing definition, a duplicate symbol) is a compile error.
            if (!link_error.empty()) rep.compiler_output += "\n" + clip(replace_all(link_error, work.string() + "/", ""), 20000);
        }
        if (!compiled || !link_error.empty()) {
            // Score 0, but with every test listed (from the course's own program) so max_score is right.
            rep.status = SubmissionStatus::compile_error;
            RunOptions list_opt = opt.run;
            for (const auto& t : list_tests(fs::exists(judge) ? judge : course_program, list_opt)) {
                TestResult r;
                r.info = t;
                r.status = Status::failed;
                r.messages.push_back("your code did not compile (or link): see the compiler's messages");
                rep.lab.results.push_back(std::move(r));
            }
            return finish();
        }

        // 5. Defence in depth on the student's objects (given files are the course's): only the lab's API may be
        //    defined, nothing may run before the program's start-up, no raw system calls, no test-only helpers.
        //    Any finding scores the whole submission 0.
        std::vector<TestResult> checks;
        std::vector<std::pair<std::string, fs::path>> student_objects;  // (basename, object), editable files only
        {
            std::size_t k = 0;
            for (const auto& [name, stub] : files) {
                const fs::path obj = objects[k++];
                if (!given.count(name)) student_objects.push_back({name, obj});
            }
        }
        const std::vector<std::string> link_args = link_command(build, "test_" + opt.lab);
        const CourseSymbols course = cached_course_symbols(link_args, build, course_program,
                                                           "liblab_" + opt.lab.substr(0, 2) + ".a", cache);
        for (const auto& [name, obj] : student_objects)
            for (auto& p : object_problems("labs/" + opt.lab + "/src/" + name, obj, course)) rep.rejected.push_back(p);
        checks.push_back(check_result("student code defines only the lab's API, runs nothing early, makes no raw system calls",
                                      rep.rejected.empty(),
                                      rep.rejected.empty() ? std::vector<std::string>{"nothing found"} : rep.rejected));

        // 6. Forbidden calls, over the student's whole code: the call graph of all their objects together (a wrapper
        //    in another file, an alias, a function pointer), and the source through clang's AST (templates and
        //    inline functions, which leave no call in the object).
        const auto forbidden =
            read_forbidden_list(opt.forbidden.empty() ? root / "labs" / opt.lab / "forbidden.txt" : opt.forbidden);
        if (!forbidden.empty()) {
            CallGraph graph;
            for (const auto& [name, obj] : student_objects) add_object(graph, name, obj);
            std::vector<ForbiddenCall> hits = forbidden_in_graph(graph, forbidden, opt.lab);
            std::vector<std::string> notes;
            const std::string clang_query = find_program("clang-query");
            if (clang_query.empty()) {
                notes.push_back("clang-query is not installed (apt-get install clang-tools): template and inline calls "
                                "were not checked");
            } else {
                for (const auto& [name, obj] : student_objects) {
                    const std::string text = read_text(work / "src" / name);
                    std::vector<std::string> cmd = compile_command(build, root / "labs" / opt.lab / "src" / name);
                    std::vector<std::string> args{clang_query};
                    std::string key = "ast\n" + text + "\n" + stamp;
                    for (const auto& f : forbidden) {
                        if (f.symbol.rfind("_Z", 0) == 0) continue;  // a mangled name: the object check's business
                        args.push_back("-c");
                        args.push_back(ast_matcher(f));
                        key += "\n" + f.symbol;
                    }
                    if (args.size() == 1) break;
                    args.push_back(name);
                    args.push_back("--");
                    for (std::size_t i = 1; i < cmd.size(); ++i) {
                        const std::string& a = cmd[i];
                        if ((a == "-o" || a == "-c" || a == "-MT" || a == "-MF") && i + 1 < cmd.size()) {
                            ++i;
                            continue;
                        }
                        if (a == "-MD" || a == "-MMD" || fs::path(a) == root / "labs" / opt.lab / "src" / name) continue;
                        args.push_back(a);
                    }
                    args.push_back("-Wno-unknown-warning-option");
                    const fs::path cached = cache / (hex_hash(key) + ".ast");
                    std::string out;
                    int rc = 0;
                    if (fs::exists(cached)) {
                        out = read_text(cached);
                    } else {
                        RunOptions o = sandboxed;
                        o.sandbox.visible = include_dirs(cmd);
                        o.memory_mb = std::max<std::size_t>(opt.run.memory_mb, 4096);
                        o.output_cap = 1 << 20;
                        o.sandbox.prepare = [&](const fs::path& dir, unsigned uid) {
                            write_text(dir / name, text);
                            if (uid) (void)!::chown((dir / name).c_str(), uid, uid);
                        };
                        o.sandbox.collect = nullptr;
                        CommandResult r = run_command(args, opt.compile_timeout_s, o);
                        out = r.output;
                        rc = r.exit_code;
                        if (rc == 0 && out.find(" error: ") == std::string::npos) write_text(cached, out, fs::perms(0600));
                    }
                    // clang-query answers each "match" with its matches and then "N match(es)."; a parse error
                    // means the file could not be checked: fail closed for the tasks the list names.
                    if (rc != 0 || out.find(" error: ") != std::string::npos) {
                        notes.push_back("labs/" + opt.lab + "/src/" + name +
                                        " could not be parsed by clang for the source-level check: it counts as "
                                        "calling every forbidden function\n" + clip(out, 1500));
                        for (const auto& f : forbidden) {
                            ForbiddenCall hit = f;
                            hit.file = "labs/" + opt.lab + "/src/" + name;
                            hit.where = "unverifiable source";
                            hits.push_back(hit);
                        }
                        continue;
                    }
                    std::istringstream in(out);
                    std::size_t entry = 0;
                    std::vector<const ForbiddenCall*> asked;
                    for (const auto& f : forbidden)
                        if (f.symbol.rfind("_Z", 0) != 0) asked.push_back(&f);
                    std::string first_line;
                    for (std::string line; std::getline(in, line) && entry < asked.size();) {
                        if (first_line.empty() && line.find(name + ":") == 0) first_line = line.substr(0, line.find(": note"));
                        const auto m = line.find(" match");
                        if (m == std::string::npos || line.find_first_not_of("0123456789") != m) continue;
                        if (std::stoi(line.substr(0, m)) > 0 &&
                            !exempt_files(graph, forbidden_nodes(graph, *asked[entry])).count(name)) {
                            ForbiddenCall hit = *asked[entry];
                            hit.file = "labs/" + opt.lab + "/src/" + name;
                            hit.where = "in the source" + (first_line.empty() ? std::string() : " (line " +
                                        first_line.substr(name.size() + 1, first_line.find(':', name.size() + 1) - name.size() - 1) + ")");
                            hits.push_back(hit);
                        }
                        first_line.clear();
                        ++entry;
                    }
                }
            }
            std::vector<std::string> found_msgs;
            std::set<std::pair<std::string, std::string>> seen;
            for (const auto& h : hits) {
                if (!seen.insert({h.symbol, h.file}).second) continue;
                rep.forbidden.push_back(h);
                found_msgs.push_back(h.file + " calls " + h.symbol + (h.where.empty() ? "" : " [" + h.where + "]") +
                                     (h.reason.empty() ? "" : ": " + h.reason) +
                                     (h.task.empty() ? "" : " (task '" + h.task + "' scores 0)"));
            }
            for (const auto& n : notes) found_msgs.push_back(n);
            checks.push_back(check_result("no forbidden calls", rep.forbidden.empty(), found_msgs));
        }

        // 7. Run every test (hidden included) in the sandbox: it sees the test program, the fixtures and models.
        RunOptions tests_opt = sandboxed;
        tests_opt.sandbox.visible = {program, root / "data", geolab::models_dir()};
        rep.lab = grade_program(opt.lab, "submission", program, tests_opt);
        rep.lab.variant = "submission";
        if (!rep.lab.error.empty()) throw std::runtime_error(rep.lab.error);
        for (const auto& f : rep.forbidden) {
            if (f.task.empty()) continue;
            for (auto& r : rep.lab.results)
                if (r.info.suite == f.task && r.score > 0) {
                    r.score = 0;
                    r.messages.push_back("scored 0: " + f.file + " calls " + f.symbol + ", which this lab forbids");
                }
        }
        if (!rep.rejected.empty())
            for (auto& r : rep.lab.results)
                if (r.score > 0) {
                    r.score = 0;
                    r.messages.push_back("scored 0: the submission was rejected (" + rep.rejected.front() + ")");
                }

        // 7. Sanitizers (ungraded): the same tests with the student's code built with ASan + UBSan.
        if (opt.asan) {
            std::vector<fs::path> asan_objects;
            std::string asan_messages;
            std::vector<std::string> findings;
            std::string details;
            bool clean = true;
            if (!compile_all(true, asan_objects, asan_messages)) {
                clean = false;
                findings.push_back("the sanitizer build did not compile");
                details = clip(asan_messages, 4000);
            } else if (std::string e = link(asan_objects, true, work / "bin" / ("test_" + opt.lab + "_asan")); !e.empty()) {
                clean = false;
                findings.push_back("the sanitizer build did not link");
                details = clip(e, 4000);
            } else {
                RunOptions a = sandboxed;
                a.sandbox.visible = {work / "bin" / ("test_" + opt.lab + "_asan"), root / "data", geolab::models_dir()};
                a.memory_mb = 0;  // ASan reserves terabytes of address space: no RLIMIT_AS
                a.timeout_s = opt.run.timeout_s * 3;
                a.env.push_back("ASAN_OPTIONS=detect_leaks=0:abort_on_error=0:halt_on_error=1");
                a.env.push_back("UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=0");
                LabReport ar = grade_program(opt.lab, "asan", work / "bin" / ("test_" + opt.lab + "_asan"), a);
                for (const auto& r : ar.results) {
                    for (const char* marker : {"ERROR: AddressSanitizer", "runtime error:"}) {
                        auto pos = r.output.find(marker);
                        if (pos == std::string::npos) continue;
                        clean = false;
                        const std::string excerpt = r.output.substr(r.output.rfind('\n', pos) == std::string::npos ? 0 : r.output.rfind('\n', pos) + 1, 600);
                        findings.push_back((r.info.hidden ? std::string("(a hidden test)") : "'" + r.info.name + "'") + ": " +
                                           (std::string(marker).find("Address") != std::string::npos ? "AddressSanitizer" : "UBSan"));
                        if (!r.info.hidden) details += "--- " + r.info.name + " ---\n" + excerpt + "\n";
                        break;
                    }
                }
            }
            if (findings.empty()) findings.push_back("no findings");
            checks.push_back(check_result("sanitizers: AddressSanitizer + UBSan (ungraded)", clean, findings, clip(details, 20000)));
        }
        for (auto& c : checks) rep.lab.results.push_back(std::move(c));
        rep.capped = sandboxed.deadline && Clock::now() >= *sandboxed.deadline;
        rep.status = SubmissionStatus::ok;
    } catch (const std::exception& e) {
        rep.status = SubmissionStatus::grader_error;
        rep.error = e.what();
        rep.lab.error = e.what();
    }
    return finish();
}

std::vector<std::string> check_gradescope_results(const std::string& text) {
    std::vector<std::string> problems;
    auto j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded()) return {"not valid JSON"};
    if (!j.is_object()) return {"the top level is not an object"};
    const std::set<std::string> visibilities = {"hidden", "after_due_date", "after_published", "visible"};
    const std::set<std::string> formats = {"text", "html", "simple_format", "md", "ansi"};
    auto check_common = [&](const nlohmann::json& o, const std::string& where) {
        for (const char* key : {"score", "max_score", "execution_time"})
            if (o.contains(key) && !o[key].is_number()) problems.push_back(where + key + " is not a number");
        for (const char* key : {"output", "name", "number", "name_format", "output_format"})
            if (o.contains(key) && !o[key].is_string()) problems.push_back(where + key + " is not a string");
        for (const char* key : {"visibility", "stdout_visibility"})
            if (o.contains(key) && (!o[key].is_string() || !visibilities.count(o[key].get<std::string>())))
                problems.push_back(where + key + " is not one of hidden, after_due_date, after_published, visible");
        for (const char* key : {"output_format", "name_format"})
            if (o.contains(key) && o[key].is_string() && !formats.count(o[key].get<std::string>()))
                problems.push_back(where + key + " is not one of text, html, simple_format, md, ansi");
        if (o.contains("extra_data") && !o["extra_data"].is_object()) problems.push_back(where + "extra_data is not an object");
    };
    check_common(j, "");
    const bool has_tests = j.contains("tests");
    if (has_tests && !j["tests"].is_array()) problems.push_back("tests is not an array");
    bool every_test_scored = has_tests && j["tests"].is_array() && !j["tests"].empty();
    if (has_tests && j["tests"].is_array()) {
        for (std::size_t i = 0; i < j["tests"].size(); ++i) {
            const auto& t = j["tests"][i];
            const std::string where = "tests[" + std::to_string(i) + "].";
            if (!t.is_object()) {
                problems.push_back(where + " is not an object");
                continue;
            }
            check_common(t, where);
            if (!t.contains("score")) every_test_scored = false;
            if (t.contains("status") && !(t["status"] == "passed" || t["status"] == "failed"))
                problems.push_back(where + "status is not passed or failed");
            if (t.contains("tags") && !t["tags"].is_array()) problems.push_back(where + "tags is not an array");
            if (t.contains("score") && t.contains("max_score") && t["score"].is_number() && t["max_score"].is_number() &&
                t["score"].get<double>() > t["max_score"].get<double>() + 1e-9)
                problems.push_back(where + "score is larger than max_score");
        }
    }
    if (!j.contains("score") && !every_test_scored)
        problems.push_back("score is missing (required unless every test has a score)");
    if (j.contains("leaderboard") && !j["leaderboard"].is_array()) problems.push_back("leaderboard is not an array");
    return problems;
}

}  // namespace geolab::grading
