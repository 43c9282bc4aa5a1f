#include "geolab/grading/submission.hpp"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include <sys/stat.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "geolab/grading/release.hpp"
#include "text_file.hpp"

namespace geolab::grading {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;

using detail::read_text;
using detail::write_text;

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

// Split a command line the way a POSIX shell would for the simple quoting CMake writes.
std::vector<std::string> split_command(const std::string& cmd) {
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

// The lab's student files: basename -> the stub text (generated from solutions/ when it exists).
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

// Run a trusted command (unzip, nm, ninja, the linker) with plain limits, no sandbox.
CommandResult run_plain(const std::vector<std::string>& argv, double timeout_s, std::size_t memory_mb = 0) {
    RunOptions o;
    o.memory_mb = memory_mb;
    o.output_cap = 4 << 20;
    o.file_size_mb = 1024;
    o.sandbox.no_network = false;
    return run_command(argv, timeout_s, o);
}

std::string find_program(const std::string& name) {
    for (const char* dir : {"/usr/bin", "/bin", "/usr/local/bin"}) {
        fs::path p = fs::path(dir) / name;
        if (::access(p.c_str(), X_OK) == 0) return p.string();
    }
    return "";
}

// The submitted files: every regular file under `dir` (symlinks and special files are ignored).
struct Picked {
    std::map<std::string, fs::path> used;  // basename -> file
    std::vector<std::string> ignored;
};

Picked pick_files(const fs::path& dir, const std::map<std::string, std::string>& wanted) {
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

// The course's compile command of one lab file, from compile_commands.json.
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

// The course's link command of test_<lab> (the last command ninja would run for it).
std::vector<std::string> link_command(const fs::path& build, const std::string& lab) {
    const std::string ninja = find_program("ninja");
    if (ninja.empty()) throw std::runtime_error("ninja not found: the grader needs the course's Ninja build");
    CommandResult r = run_plain({ninja, "-C", build.string(), "-t", "commands", "test_" + lab}, 60);
    if (r.exit_code != 0) throw std::runtime_error("cannot read the link command of test_" + lab + ": " + r.output);
    std::istringstream lines(r.output);
    std::string line, last;
    while (std::getline(lines, line))
        if (!line.empty()) last = line;
    std::vector<std::string> args;
    for (auto& a : split_command(last))
        if (a != ":" && a != "&&") args.push_back(a);
    return args;
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
    os << "status: " << to_string(status) << "\n";
    if (!error.empty()) os << "grader error: " << error << "\n";
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
    if (!ignored.empty()) {
        os << "ignored (only the lab's src/*.cpp files are graded):\n";
        for (const auto& i : ignored) os << "  " << i << "\n";
    }
    for (const auto& f : forbidden)
        os << "forbidden call: " << f.file << " calls " << f.symbol << (f.reason.empty() ? "" : " (" + f.reason + ")")
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

        // 1. The submission: a folder, or a zip unpacked into a fresh folder.
        fs::path sub_dir = submission;
        if (fs::is_regular_file(submission)) {
            sub_dir = work / "unpacked";
            fs::remove_all(sub_dir);
            make_dir(sub_dir, 0700);
            const std::string unzip = find_program("unzip");
            if (unzip.empty()) throw std::runtime_error("unzip not found (apt-get install unzip)");
            CommandResult u = run_plain({unzip, "-qq", "-o", fs::absolute(submission).string(), "-d", sub_dir.string()}, 120);
            if (u.exit_code != 0 && u.exit_code != 1)  // 1: warnings (e.g. skipped ../ entries)
                throw std::runtime_error(submission.string() + ": cannot unzip: " + clip(u.output, 1000));
        } else if (!fs::is_directory(submission)) {
            throw std::runtime_error(submission.string() + ": no such folder or zip file");
        }
        Picked picked = pick_files(sub_dir, files);
        rep.ignored = picked.ignored;

        // 2. The lab's sources: submitted files, stubs for the rest.
        fs::remove_all(work / "src");
        make_dir(work / "src", 0700);
        for (const auto& [name, stub] : files) {
            if (picked.used.count(name)) {
                fs::copy_file(picked.used[name], work / "src" / name, fs::copy_options::overwrite_existing);
                fs::permissions(work / "src" / name, fs::perms(0644));
                rep.used.push_back(name + " <- " + fs::relative(picked.used[name], sub_dir).string());
            } else {
                write_text(work / "src" / name, stub);
                rep.stubbed.push_back(name);
            }
        }

        // The sandbox of everything untrusted: its own uid, no network, the answers out of sight.
        RunOptions sandboxed = opt.run;
        if (fs::exists(boundary_syms)) {
            if (!fs::exists(judge))
                throw std::runtime_error(judge.string() + " not found: build the course first (cmake --build " +
                                         build.string() + ")");
            sandboxed.judge = judge;
        }
        sandboxed.sandbox.drop_privileges = true;
        sandboxed.sandbox.no_network = true;
        sandboxed.sandbox.workdir = work / "tmp";
        sandboxed.sandbox.hide = {root / "solutions", root / "tests", build / "CMakeFiles", build / "bin",
                                  build / "tests", work / "src", cache};

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
            std::vector<std::string> cmd = link_command(build, opt.lab), args;
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

        // 5. Forbidden calls: the undefined symbols of each student object against labs/NN/forbidden.txt.
        const auto forbidden =
            read_forbidden_list(opt.forbidden.empty() ? root / "labs" / opt.lab / "forbidden.txt" : opt.forbidden);
        std::vector<TestResult> checks;
        if (!forbidden.empty()) {
            const std::string nm = find_program("nm");
            std::vector<std::string> found_msgs;
            std::size_t k = 0;
            for (const auto& [name, stub] : files) {
                const fs::path obj = objects[k++];
                std::string syms;
                for (bool demangle : {false, true}) {
                    std::vector<std::string> a{nm, "-u"};
                    if (demangle) a.push_back("-C");
                    a.push_back(obj.string());
                    syms += run_plain(a, 60).output + "\n";
                }
                for (const auto& f : forbidden) {
                    if (syms.find(f.symbol) == std::string::npos) continue;
                    ForbiddenCall hit = f;
                    hit.file = "labs/" + opt.lab + "/src/" + name;
                    rep.forbidden.push_back(hit);
                    found_msgs.push_back(hit.file + " calls " + f.symbol + (f.reason.empty() ? "" : ": " + f.reason) +
                                         (f.task.empty() ? "" : " (task '" + f.task + "' scores 0)"));
                }
            }
            checks.push_back(check_result("no forbidden calls", found_msgs.empty(), found_msgs));
        }

        // 6. Run every test (hidden included) as the sandbox user.
        rep.lab = grade_program(opt.lab, "submission", program, sandboxed);
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
