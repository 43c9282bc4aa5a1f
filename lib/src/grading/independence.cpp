// DESIGN.md rule 6, measured (geolab/grading/independence.hpp): the reference graded once per task file with
// that file replaced by its stub, each variant relinked from the course build's own objects.
#include "geolab/grading/independence.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <nlohmann/json.hpp>

#include "course_build.hpp"
#include "geolab/grading/release.hpp"
#include "text_file.hpp"

namespace geolab::grading {
namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;
using detail::find_program;
using detail::read_text;
using detail::run_plain;
using detail::write_text;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The object file the course build compiles `source` into (the "-o" of its compile command).
fs::path object_of(const fs::path& build, const fs::path& source) {
    const auto cmd = detail::compile_command(build, source);
    for (std::size_t i = 0; i + 1 < cmd.size(); ++i)
        if (cmd[i] == "-o") {
            const fs::path o = cmd[i + 1];
            return o.is_relative() ? build / o : o;
        }
    throw std::runtime_error("the compile command of " + source.string() + " names no object (-o)");
}

// How to link the reference's performer with other objects in place of its lab archive.
struct LinkRecipe {
    std::vector<std::string> before, after;  // around the archive
    fs::path redefine_syms;                  // the boundary renaming the archive's objects had (empty: none)

    std::vector<std::string> command(const std::vector<fs::path>& objects, const fs::path& out) const {
        std::vector<std::string> a = before;
        for (const auto& o : objects) a.push_back(o.string());
        a.insert(a.end(), after.begin(), after.end());
        a.push_back("-o");
        a.push_back(out.string());
        return a;
    }
};

LinkRecipe read_link_recipe(const fs::path& build, const std::string& lab) {
    const std::string target = "test_" + lab + "_solution";
    const std::vector<std::string> cmd = detail::link_command(build, target);
    const std::string archive = "liblab_" + lab.substr(0, 2) + "_sol.a";
    const std::string performer = "liblab_" + lab.substr(0, 2) + "_sol_performer.a";
    LinkRecipe r;
    bool seen = false;
    for (std::size_t i = 0; i < cmd.size(); ++i) {
        std::string a = cmd[i];
        if (a == "-o" && i + 1 < cmd.size()) {
            ++i;
            continue;
        }
        const std::string name = fs::path(a).filename().string();
        if (name == archive || name == performer) {
            if (name == performer) r.redefine_syms = build / "boundary" / lab / "student.syms";
            seen = true;
            continue;
        }
        if (i > 0 && !a.empty() && a[0] != '-' && fs::path(a).is_relative() && fs::exists(build / a))
            a = (build / a).string();
        (seen ? r.after : r.before).push_back(a);
    }
    if (!seen) throw std::runtime_error("the link command of " + target + " does not use " + archive);
    if (!r.before.empty() && fs::path(r.before[0]).is_relative()) {
        const std::string p = find_program(r.before[0]);
        if (!p.empty()) r.before[0] = p;
    }
    return r;
}

// One test's outcome in a run of several tests in one process.
struct SeqResult {
    bool passed = false;
    std::string status;     // "passed", "failed", "not implemented", "crashed or timed out"
    std::string message;    // the first one
    std::string last_call;  // the last function of the lab the test called (where it failed)
};

// Runs `tests` of `program` in as few processes as it can (--geolab-run-all: every test in order, one verdict line
// each); a test that ends its process (a crash, its time limit) is recorded as such and the next process starts
// after it.
std::map<std::string, SeqResult> run_all(const fs::path& program, const std::vector<TestInfo>& tests,
                                         double default_timeout, const fs::path& dir) {
    std::map<std::string, SeqResult> results;
    fs::create_directories(dir);
    RunOptions o;
    o.memory_mb = 4096;
    o.output_cap = 16 << 20;
    o.file_size_mb = 1024;
    o.sandbox.no_network = false;
    o.sandbox.workdir = dir / "tmp";  // a fresh working folder (and TMPDIR, HOME) per process
    for (std::size_t from = 0; from < tests.size();) {
        const fs::path list = dir / "tests.txt", out = dir / "verdicts.jsonl";
        std::string text;
        double total = 10;
        for (std::size_t i = from; i < tests.size(); ++i) {
            const double limit = tests[i].timeout_s > 0 ? tests[i].timeout_s : default_timeout;
            text += std::to_string(limit) + "\t" + tests[i].name + "\n";
            total += limit;
        }
        write_text(list, text);
        fs::remove(out);
        const CommandResult c = run_command({program.string(), "--geolab-run-all", list.string(), out.string()}, total, o);
        std::size_t answered = 0;
        if (fs::exists(out)) {
            std::istringstream in(read_text(out));
            for (std::string line; std::getline(in, line);) {
                const auto j = nlohmann::json::parse(line, nullptr, false);
                if (j.is_discarded() || !j.contains("ran") || from + answered >= tests.size()) break;
                const std::string& name = tests[from + answered].name;
                SeqResult r;
                r.passed = j.value("status", "") == "passed";
                r.status = r.passed ? "passed" : j.value("not_implemented", false) ? "not implemented" : "failed";
                const auto messages = j.value("messages", std::vector<std::string>{});
                if (!messages.empty()) r.message = messages.front().substr(0, messages.front().find('\n'));
                r.last_call = j.value("last_call", "");
                results[name] = r;
                ++answered;
            }
        }
        from += answered;
        if (from < tests.size()) {  // the process ended in this test
            SeqResult r;
            r.status = "crashed or timed out";
            r.message = c.timed_out ? "killed after its time limit" : "the process ended: " + c.output.substr(
                                                                              c.output.size() > 300 ? c.output.size() - 300 : 0);
            results[tests[from].name] = r;
            ++from;
        }
    }
    return results;
}

// How a test failed with a file stubbed, and whether the test itself called the stub ("calls f itself") or a
// function of its own task reached it ("f, called by g": the reference's g calls another task's f).
std::string failure_text(const SeqResult& r) {
    std::string why = r.status + (r.message.empty() ? "" : ": " + r.message);
    const std::string ni = "not implemented: ";
    auto pos = r.message.rfind(ni);
    if (pos == std::string::npos || r.last_call.empty()) return why;
    const std::string stub = r.message.substr(pos + ni.size(), r.message.find(' ', pos + ni.size()) - pos - ni.size());
    std::string called = r.last_call;
    if (const auto colons = called.rfind("::"); colons != std::string::npos) called = called.substr(colons + 2);
    return called == stub ? "the test calls " + stub + " itself"
                          : stub + " (a stub), reached through the test's call of " + r.last_call;
}

// The number N of a task "Task N: ..." (0 if none).
int task_number(const std::string& suite) {
    if (suite.rfind("Task ", 0) != 0) return 0;
    return std::atoi(suite.c_str() + 5);
}

// The task table of a lab's headers: "//! | N | file.cpp | ..." rows (continuation rows leave N empty).
std::map<int, std::string> task_table(const fs::path& include_dir) {
    std::map<int, std::string> table;
    if (!fs::is_directory(include_dir)) return table;
    const std::regex row(R"(^//!\s*\|\s*([0-9]+)\s*\|\s*([A-Za-z0-9_]+\.cpp)\s*\|)");
    for (const auto& e : fs::recursive_directory_iterator(include_dir)) {
        if (!e.is_regular_file() || e.path().extension() != ".hpp") continue;
        std::istringstream in(read_text(e.path()));
        std::smatch m;
        for (std::string line; std::getline(in, line);)
            if (std::regex_search(line, m, row)) table[std::stoi(m[1])] = m[2];
    }
    return table;
}

// A declared whole-chain test (grading/chain.hpp).
bool whole_chain(const TestInfo& t) { return t.builds_on == "*"; }

// Whether test t declares it builds on `task` (a suite name "Task N: ..."): its list names "Task N".
bool declares(const TestInfo& t, const std::string& task) {
    std::istringstream in(t.builds_on);
    for (std::string item; std::getline(in, item, ',');) {
        const auto a = item.find_first_not_of(' '), b = item.find_last_not_of(' ');
        if (a == std::string::npos) continue;
        item = item.substr(a, b - a + 1);
        if (task == item || task.rfind(item + ":", 0) == 0) return true;
    }
    return false;
}

std::string points_text(double p) {
    std::ostringstream os;
    os << p;
    return os.str();
}

}  // namespace

IndependenceReport check_independence(const IndependenceOptions& opt) {
    const auto t0 = Clock::now();
    IndependenceReport rep;
    rep.lab = opt.lab;
    const fs::path root = fs::absolute(opt.course_root), build = fs::absolute(opt.build_dir),
                   work = fs::absolute(opt.work_dir);
    const fs::path sol_dir = root / "solutions" / opt.lab / "src", lab_dir = root / "labs" / opt.lab;
    if (!fs::is_directory(sol_dir)) throw std::runtime_error(sol_dir.string() + " not found: the check needs the reference");
    const fs::path reference = build / "bin" / ("test_" + opt.lab + "_solution");
    const fs::path judge = build / "bin" / ("judge_" + opt.lab);
    if (!fs::exists(reference)) throw std::runtime_error(reference.string() + " not found: build the course first");
    auto say = [&](const std::string& s) {
        if (opt.progress) opt.progress(s);
    };

    // The tests (the judge's listing where there is one), graded only.
    RunOptions list_opt;
    list_opt.sandbox.no_network = false;
    for (auto& t : list_tests(fs::exists(judge) ? judge : reference, list_opt))
        if (t.points > 0) rep.tests.push_back(t);

    // The files: every solution file; the task files are those that are not given.
    const std::set<std::string> given = given_files(lab_dir);
    std::vector<std::string> all_files, task_files;
    for (const auto& e : fs::directory_iterator(sol_dir))
        if (e.is_regular_file() && e.path().extension() == ".cpp") all_files.push_back(e.path().filename().string());
    std::sort(all_files.begin(), all_files.end());
    for (const auto& f : all_files)
        if (!given.count(f)) task_files.push_back(f);

    // Each file's reference and stub objects, with the boundary renaming the performer's archive has.
    const LinkRecipe recipe = read_link_recipe(build, opt.lab);
    fs::remove_all(work);
    fs::create_directories(work / "ref");
    fs::create_directories(work / "stub");
    auto renamed = [&](const fs::path& source, const fs::path& out) {
        const fs::path obj = object_of(build, source);
        if (recipe.redefine_syms.empty()) {
            fs::copy_file(obj, out, fs::copy_options::overwrite_existing);
            return;
        }
        const std::string objcopy = find_program("objcopy");
        if (objcopy.empty()) throw std::runtime_error("objcopy not found (apt-get install binutils)");
        const CommandResult c = run_plain({objcopy, "--redefine-syms=" + recipe.redefine_syms.string(), obj.string(), out.string()}, 120);
        if (c.exit_code != 0) throw std::runtime_error("objcopy failed on " + obj.string() + ": " + c.output);
    };
    for (const auto& f : all_files) renamed(sol_dir / f, work / "ref" / (f + ".o"));
    for (const auto& f : task_files) renamed(lab_dir / "src" / f, work / "stub" / (f + ".o"));

    // The variants, `jobs` at a time: index 0 is the reference itself (the course's program), then one per file.
    std::vector<std::map<std::string, SeqResult>> runs(task_files.size() + 1);
    rep.stubbed.resize(task_files.size());
    std::atomic<std::size_t> next{0};
    std::mutex say_mutex;
    auto worker = [&] {
        for (std::size_t k; (k = next++) <= task_files.size();) {
            const auto tk = Clock::now();
            fs::path program = reference;
            const fs::path dir = work / (k == 0 ? std::string("reference") : task_files[k - 1]);
            if (k > 0) {
                StubbedFile& s = rep.stubbed[k - 1];
                s.file = task_files[k - 1];
                std::vector<fs::path> objects;
                for (const auto& f : all_files) objects.push_back(work / (f == s.file ? "stub" : "ref") / (f + ".o"));
                program = dir / ("test_" + opt.lab + "_without_" + fs::path(s.file).stem().string());
                fs::create_directories(dir);
                const CommandResult l = run_plain(recipe.command(objects, program), 600);
                if (l.exit_code != 0) {
                    s.error = "the reference does not link with " + s.file + " a stub (another file uses what only the " +
                              "solution of " + s.file + " defines?):\n" + l.output.substr(0, 2000);
                    s.seconds = since(tk);
                    continue;
                }
            }
            runs[k] = run_all(program, rep.tests, opt.timeout_s, dir);
            if (k > 0) {
                StubbedFile& s = rep.stubbed[k - 1];
                for (const auto& [name, r] : runs[k])
                    if (!r.passed) s.failed[name] = failure_text(r);
                s.seconds = since(tk);
                std::lock_guard lock(say_mutex);
                say(s.file + " a stub: " + std::to_string(s.failed.size()) + " of " + std::to_string(rep.tests.size()) +
                    " graded tests fail (" + points_text(std::round(s.seconds * 10) / 10) + " s)");
            }
        }
    };
    std::vector<std::thread> pool;
    for (int j = 0; j < std::max(1, opt.jobs); ++j) pool.emplace_back(worker);
    for (auto& t : pool) t.join();

    // The reference itself must pass every graded test when they share one process.
    for (const auto& t : rep.tests)
        if (!runs[0].count(t.name) || !runs[0][t.name].passed)
            throw std::runtime_error("the reference fails '" + t.name + "' when the lab's tests run in one process (" +
                                     (runs[0].count(t.name) ? runs[0][t.name].status + ": " + runs[0][t.name].message
                                                            : std::string("no verdict")) +
                                     "): the check cannot tell what a stub costs");

    // What each stub costs, per task.
    std::map<std::string, double> task_points;
    for (const auto& t : rep.tests)
        if (!whole_chain(t)) task_points[t.suite] += t.points;
    std::map<std::string, std::map<std::string, double>> lost;  // file -> task -> points
    for (const auto& s : rep.stubbed)
        for (const auto& t : rep.tests)
            if (!whole_chain(t) && s.failed.count(t.name)) lost[s.file][t.suite] += t.points;
    // The owner of each task: the file the lab's header names for it (its "| task | file |" table), else the file
    // whose stub fails every test of the task and costs the fewest points in all (the most specific one).
    const std::map<int, std::string> table = task_table(lab_dir / "include");
    std::map<std::string, double> total_lost;
    for (const auto& s : rep.stubbed)
        for (const auto& t : rep.tests)
            if (s.failed.count(t.name)) total_lost[s.file] += t.points;
    for (const auto& [task, total] : task_points) {
        if (const auto it = table.find(task_number(task)); it != table.end()) {
            rep.owner[task] = it->second;
            continue;
        }
        std::vector<std::string> candidates;
        for (const auto& s : rep.stubbed) {
            bool all = true;
            for (const auto& t : rep.tests)
                if (t.suite == task && !whole_chain(t) && !s.failed.count(t.name)) all = false;
            if (all && s.error.empty()) candidates.push_back(s.file);
        }
        std::sort(candidates.begin(), candidates.end(),
                  [&](const std::string& a, const std::string& b) { return total_lost[a] < total_lost[b]; });
        if (candidates.empty())
            rep.problems.push_back(task + ": no single task file's stub fails all its tests, and the lab's header names "
                                          "no file for it");
        else if (candidates.size() > 1 && total_lost[candidates[0]] == total_lost[candidates[1]])
            rep.problems.push_back(task + ": " + candidates[0] + " and " + candidates[1] + " both fail all its tests and "
                                          "cost as much: name the task's file in the lab header's task table");
        else
            rep.owner[task] = candidates[0];
    }
    // May test t fail when `file` is a stub? Its own task's file; the files of the tasks it is declared to build on.
    auto allowed = [&](const TestInfo& t, const std::string& file) {
        if (rep.owner.count(t.suite) && rep.owner.at(t.suite) == file) return true;
        if (whole_chain(t)) return true;
        for (const auto& [task, owner] : rep.owner)
            if (owner == file && declares(t, task)) return true;
        return false;
    };
    for (const auto& s : rep.stubbed) {
        if (!s.error.empty()) {
            rep.problems.push_back(s.error);
            continue;
        }
        if (lost[s.file].empty())
            rep.problems.push_back(s.file + ": its stub costs no point (are its functions tested? is it a given file "
                                            "missing from given.txt?)");
        std::map<std::string, std::string> bad;  // task -> the tests, listed
        std::map<std::string, double> bad_points;
        for (const auto& t : rep.tests) {
            if (!s.failed.count(t.name) || allowed(t, s.file)) continue;
            bad[t.suite] += "\n    '" + t.name + "' (" + points_text(t.points) + " points): " + s.failed.at(t.name);
            bad_points[t.suite] += t.points;
        }
        for (const auto& [task, tests] : bad)
            rep.problems.push_back(task + " loses " + points_text(bad_points[task]) + " of its " +
                                   points_text(task_points[task]) + " points when " + s.file + " is a stub (" + task +
                                   " is " + (rep.owner.count(task) ? rep.owner.at(task) : std::string("no file")) +
                                   "'s): rule 6, a test of one task must not depend on another task's answer "
                                   "(or declare it: grading/chain.hpp):" + tests);
    }
    // The declarations, with what each test was seen to depend on; one that depends on nothing declared is stale.
    for (const auto& t : rep.tests) {
        if (t.builds_on.empty()) continue;
        std::string files;
        bool other = false;
        for (const auto& s : rep.stubbed)
            if (s.failed.count(t.name)) {
                files += (files.empty() ? "" : ", ") + s.file;
                other = other || !rep.owner.count(t.suite) || rep.owner.at(t.suite) != s.file;
            }
        const std::string what = whole_chain(t) ? "whole-chain test" : "builds on " + t.builds_on + ":";
        rep.notes.push_back("'" + t.name + "' (" + t.suite + ", " + points_text(t.points) + " points), " + what +
                            " fails when these are stubs: " + (files.empty() ? std::string("none") : files));
        if (!other)
            rep.problems.push_back("'" + t.name + "' is declared (" + (whole_chain(t) ? "whole_chain" : "builds_on " + t.builds_on) +
                                   ") but no other task's stub fails it: drop the declaration");
    }
    rep.seconds = since(t0);
    return rep;
}

std::string IndependenceReport::text() const {
    std::ostringstream os;
    double total = 0;
    for (const auto& t : tests) total += t.points;
    os << "independence of lab " << lab << ": the reference with one task file a stub (" << tests.size()
       << " graded tests, " << total << " points)\n";
    std::map<std::string, double> task_points;
    for (const auto& t : tests)
        if (!whole_chain(t)) task_points[t.suite] += t.points;
    for (const auto& s : stubbed) {
        os << "  " << s.file << ": ";
        if (!s.error.empty()) {
            os << "could not be checked\n";
            continue;
        }
        std::map<std::string, double> lost;
        double chain = 0;
        for (const auto& t : tests)
            if (s.failed.count(t.name)) (whole_chain(t) ? chain : lost[t.suite]) += t.points;
        if (lost.empty() && chain == 0) os << "costs nothing";
        bool first = true;
        for (const auto& [task, p] : lost) {
            os << (first ? "" : "; ") << task << " -" << p << " of " << task_points[task]
               << (owner.count(task) && owner.at(task) != s.file ? " (not its task)" : "");
            first = false;
        }
        if (chain > 0) os << (first ? "" : "; ") << "whole-chain tests -" << chain;
        os << "\n";
    }
    os << "  owners:";
    for (const auto& [task, file] : owner) os << " " << task.substr(0, task.find(':')) << " " << file << ";";
    os << "\n";
    for (const auto& n : notes) os << "  note: " << n << "\n";
    for (const auto& p : problems) os << "PROBLEM: " << p << "\n";
    os << "independence " << lab << ": " << (problems.empty() ? "OK" : "FAILED") << " in "
       << std::round(seconds * 10) / 10 << " s\n";
    return os.str();
}

}  // namespace geolab::grading
