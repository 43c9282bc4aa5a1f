// geolab grade-all SUBMISSIONS --lab NN --csv grades.csv --jobs N: grade a whole class. One submission per
// sub-folder or zip; per student a folder of results (results.json, junit.xml, log.txt, done.json); resumable:
// a student whose done.json exists and whose submission has the same content (a hash of its files) is not graded
// again; a submission that changed since is; one bad submission never stops the batch.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <atomic>
#include <chrono>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "geolab/grading/report.hpp"

namespace geolab::cli {
namespace fs = std::filesystem;
namespace {

struct Student {
    std::string name;
    fs::path submission;
};

struct Outcome {  // what done.json holds
    std::string status;
    std::string content;  // submission_hash() of what was graded
    double score = 0, max_score = 0;
    std::vector<std::pair<std::string, std::pair<double, double>>> tasks;  // task -> (score, max)
};

std::vector<Student> find_students(const fs::path& dir) {
    std::vector<Student> students;
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string n = e.path().filename().string();
        if (n.empty() || n[0] == '.') continue;
        if (e.is_directory()) students.push_back({n, e.path()});
        else if (e.is_regular_file() && e.path().extension() == ".zip") students.push_back({e.path().stem().string(), e.path()});
    }
    std::sort(students.begin(), students.end(), [](const Student& a, const Student& b) { return a.name < b.name; });
    return students;
}

nlohmann::json to_json(const Outcome& o) {
    nlohmann::json tasks = nlohmann::json::array();
    for (const auto& [t, s] : o.tasks) tasks.push_back({{"task", t}, {"score", s.first}, {"max_score", s.second}});
    return {{"status", o.status}, {"score", o.score}, {"max_score", o.max_score}, {"tasks", tasks},
            {"submission_hash", o.content}};
}

// The content of a submission, as a hash: a zip's bytes; a folder's files (relative path, kind and bytes of every
// entry, in path order; a symbolic link by its target). Any change a grading could see changes it.
std::string submission_hash(const fs::path& p) {
    std::uint64_t a = 1469598103934665603ull, b = 0x9e3779b97f4a7c15ull;
    auto add = [&](const std::string& bytes) {
        for (unsigned char c : bytes) {
            a = (a ^ c) * 1099511628211ull;
            b = (b ^ c) * 1099511628211ull;
        }
        const std::string len = "|" + std::to_string(bytes.size()) + "|";  // keeps boundaries unambiguous
        for (unsigned char c : len) a = (a ^ c) * 1099511628211ull, b = (b ^ c) * 1099511628211ull;
    };
    auto add_file = [&](const fs::path& f) {
        std::ifstream in(f, std::ios::binary);
        std::ostringstream data;
        data << in.rdbuf();
        add(data.str());
    };
    if (fs::is_directory(p)) {
        std::vector<fs::path> entries;
        for (auto it = fs::recursive_directory_iterator(p, fs::directory_options::skip_permission_denied);
             it != fs::recursive_directory_iterator(); ++it)
            entries.push_back(it->path());
        std::sort(entries.begin(), entries.end());
        for (const auto& e : entries) {
            const auto st = fs::symlink_status(e);
            add(fs::relative(e, p).string());
            if (fs::is_symlink(st)) add("link:" + fs::read_symlink(e).string());
            else if (fs::is_regular_file(st)) add_file(e);
            else add(fs::is_directory(st) ? "dir" : "other");
        }
    } else {
        add_file(p);
    }
    char buf[40];
    std::snprintf(buf, sizeof buf, "%016llx%016llx", static_cast<unsigned long long>(a), static_cast<unsigned long long>(b));
    return buf;
}

bool read_done(const fs::path& file, Outcome& o) {
    std::ifstream f(file);
    if (!f) return false;
    auto j = nlohmann::json::parse(f, nullptr, false);
    if (j.is_discarded() || !j.contains("status") || !j.contains("score") || !j.contains("tasks")) return false;
    o.status = j["status"];
    o.content = j.value("submission_hash", "");
    o.score = j["score"];
    o.max_score = j.value("max_score", 0.0);
    for (const auto& t : j["tasks"]) o.tasks.push_back({t["task"], {t["score"], t["max_score"]}});
    return true;
}

Outcome outcome_of(const grading::SubmissionReport& rep) {
    Outcome o;
    o.status = to_string(rep.status);
    o.score = rep.lab.score();
    o.max_score = rep.lab.max_score();
    for (const auto& r : rep.lab.results) {
        if (r.info.suite == "Checks") continue;
        auto it = std::find_if(o.tasks.begin(), o.tasks.end(), [&](const auto& t) { return t.first == r.info.suite; });
        if (it == o.tasks.end()) it = o.tasks.insert(o.tasks.end(), {r.info.suite, {0.0, 0.0}});
        it->second.first += r.score;
        it->second.second += r.info.points;
    }
    return o;
}

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string o = "\"";
    for (char c : s) o += c == '"' ? std::string("\"\"") : std::string(1, c);
    return o + "\"";
}

std::string num(double v) {
    std::ostringstream os;
    os << std::setprecision(6) << v;
    return os.str();
}

std::string duration(double s) {
    const int t = static_cast<int>(s + 0.5);
    std::ostringstream os;
    if (t >= 3600) os << t / 3600 << " h " << (t % 3600) / 60 << " min";
    else if (t >= 60) os << t / 60 << " min " << t % 60 << " s";
    else os << t << " s";
    return os.str();
}

}  // namespace

void add_grade_all(CLI::App& app, int& status) {
    struct Args {
        std::string dir, lab, csv, results, work_dir;
        int jobs = 1;
        double timeout = 20;
        std::size_t memory_mb = 4096;
        bool asan = false, no_course_build = false, regrade = false, allow_unisolated = false;
        double max_seconds = 1200;
    };
    auto a = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("grade-all", "Grade a folder of submissions (one sub-folder or zip per student) into a CSV");
    cmd->add_option("submissions", a->dir, "The folder of submissions")->required();
    cmd->add_option("--lab", a->lab, "The lab: 01, 1 or 01_halfedge")->required();
    cmd->add_option("--csv", a->csv, "The grades table to write")->required();
    cmd->add_option("--jobs,-j", a->jobs, "Submissions graded at once (each gets its own work folder)")->capture_default_str();
    cmd->add_option("--results", a->results, "Per-student results (default: RESULTS next to the CSV, 'grades-NN/')");
    cmd->add_option("--work-dir", a->work_dir, "The grading work folder (default: BUILD/grading)");
    cmd->add_option("--timeout", a->timeout, "Default wall-clock limit per test, seconds")->capture_default_str();
    cmd->add_option("--memory-mb", a->memory_mb, "Address-space limit per test, MiB")->capture_default_str();
    cmd->add_flag("--asan", a->asan, "Also run each submission with AddressSanitizer + UBSan (ungraded)");
    cmd->add_flag("--no-course-build", a->no_course_build, "Do not bring the course's test program up to date first");
    cmd->add_option("--max-seconds", a->max_seconds, "Wall-clock cap per submission, seconds (0: none)")
        ->capture_default_str();
    cmd->add_flag("--allow-unisolated", a->allow_unisolated,
                  "As root: grade even when the sandbox cannot be set up (each report says NOT ISOLATED)");
    cmd->add_flag("--regrade", a->regrade, "Grade every student again, even those with complete results");
    cmd->callback([a, &status] {
        const std::string lab = resolve_lab(a->lab);
        if (!fs::is_directory(a->dir)) throw std::runtime_error(a->dir + ": no such folder of submissions");
        const fs::path results = a->results.empty()
                                     ? fs::absolute(a->csv).parent_path() / ("grades-" + lab.substr(0, 2))
                                     : fs::path(a->results);
        fs::create_directories(results);
        const auto students = find_students(a->dir);
        if (students.empty()) throw std::runtime_error(a->dir + " holds no sub-folders or zip files to grade");
        const int jobs = std::max(1, a->jobs);
        const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
        const int test_jobs = std::max(1, static_cast<int>(cores) / jobs);

        // Bring the course build up to date once, not once per student.
        if (!a->no_course_build) {
            grading::SubmissionOptions probe = submission_options(lab, a->work_dir, 0);
            const std::string command = "cmake --build '" + probe.build_dir.string() + "' --target test_" + lab + " >/dev/null";
            if (std::system(command.c_str()) != 0)
                throw std::runtime_error("the course build of test_" + lab + " failed: run " + command);
        }

        std::vector<Outcome> outcomes(students.size());
        std::vector<char> have(students.size(), 0);
        std::vector<std::size_t> todo;
        // Resume by content: a student is graded again when the submission changed since its done.json.
        std::vector<std::string> content(students.size());
        std::size_t changed = 0;
        for (std::size_t i = 0; i < students.size(); ++i) {
            content[i] = submission_hash(students[i].submission);
            const bool done_before = !a->regrade && read_done(results / students[i].name / "done.json", outcomes[i]);
            // A grader error is the grader's, not the student's: the next run tries again.
            if (done_before && outcomes[i].content == content[i] && outcomes[i].status != "grader error") {
                have[i] = 1;
                continue;
            }
            if (done_before && outcomes[i].status != "grader error") ++changed;
            outcomes[i] = Outcome{};
            todo.push_back(i);
        }
        std::cerr << "grade-all: " << students.size() << " submissions, " << students.size() - todo.size()
                  << " already graded, " << todo.size() << " to grade";
        if (changed) std::cerr << " (" << changed << " changed since the last run)";
        std::cerr << " with " << jobs << " job(s)\n";

        std::atomic<std::size_t> next{0};
        std::mutex m;
        std::size_t done = 0;
        double busy_seconds = 0;
        const bool tty = ::isatty(2);
        const auto t0 = std::chrono::steady_clock::now();
        auto progress = [&](const std::string& who, const Outcome& o) {
            // Remaining time: the mean time per submission so far, spread over the jobs.
            const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            const double per = done ? elapsed / static_cast<double>(done) : 0;
            const double left = per * static_cast<double>(todo.size() - done);
            const int width = 30, filled = static_cast<int>(width * done / std::max<std::size_t>(1, todo.size()));
            std::ostringstream line;
            line << "[" << std::string(filled, '#') << std::string(width - filled, '.') << "] " << done << "/"
                 << todo.size() << "  " << duration(left) << " left  (" << who << ": " << num(o.score) << "/"
                 << num(o.max_score) << ", " << o.status << ")";
            if (tty) std::cerr << "\r" << std::left << std::setw(110) << line.str() << std::flush;
            else std::cerr << line.str() << "\n";
        };
        auto worker = [&](int job) {
            for (std::size_t k; (k = next++) < todo.size();) {
                const std::size_t i = todo[k];
                const Student& s = students[i];
                const fs::path dir = results / s.name;
                Outcome o;
                const auto s0 = std::chrono::steady_clock::now();
                try {
                    fs::create_directories(dir);
                    fs::remove(dir / "done.json");
                    grading::SubmissionOptions opt = submission_options(lab, a->work_dir, job);
                    opt.build_course = false;
                    opt.asan = a->asan;
                    opt.run.timeout_s = a->timeout;
                    opt.run.memory_mb = a->memory_mb;
                    opt.run.jobs = test_jobs;
                    opt.max_seconds = a->max_seconds;
                    opt.allow_unisolated = a->allow_unisolated;
                    const auto rep = grading::grade_submission(s.submission, opt);
                    write_submission_reports(rep, (dir / "results.json").string(), (dir / "junit.xml").string());
                    std::ofstream log(dir / "log.txt");
                    log << "student: " << s.name << "\nsubmission: " << s.submission.string() << "\n" << rep.summary();
                    grading::print_console(log, {rep.lab}, grading::HiddenPolicy::show, false, true);
                    o = outcome_of(rep);
                } catch (const std::exception& e) {
                    o = Outcome{};
                    o.status = "grader error";
                    std::ofstream(dir / "log.txt", std::ios::app) << "grader error: " << e.what() << "\n";
                }
                o.content = content[i];
                // done.json last, atomically: its presence means the student's results are complete.
                {
                    std::ofstream f(dir / "done.json.tmp");
                    f << to_json(o).dump(2) << "\n";
                }
                std::error_code ec;
                fs::rename(dir / "done.json.tmp", dir / "done.json", ec);
                std::lock_guard lock(m);
                outcomes[i] = o;
                have[i] = 1;
                ++done;
                busy_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - s0).count();
                progress(s.name, o);
            }
        };
        std::vector<std::thread> pool;
        for (int j = 0; j < jobs; ++j) pool.emplace_back(worker, j);
        for (auto& t : pool) t.join();
        if (tty && !todo.empty()) std::cerr << "\n";

        // The CSV: one row per student, per-task columns in the order the tasks first appear.
        std::vector<std::string> tasks;
        for (std::size_t i = 0; i < students.size(); ++i)
            for (const auto& [t, s] : outcomes[i].tasks)
                if (std::find(tasks.begin(), tasks.end(), t) == tasks.end()) tasks.push_back(t);
        std::ofstream csv(a->csv);
        csv << "student,score,max_score";
        for (const auto& t : tasks) csv << "," << csv_field(t);
        csv << ",status\n";
        std::map<std::string, int> counts;
        for (std::size_t i = 0; i < students.size(); ++i) {
            const Outcome& o = outcomes[i];
            csv << csv_field(students[i].name) << "," << num(o.score) << "," << num(o.max_score);
            for (const auto& t : tasks) {
                auto it = std::find_if(o.tasks.begin(), o.tasks.end(), [&](const auto& x) { return x.first == t; });
                csv << "," << (it == o.tasks.end() ? "0" : num(it->second.first));
            }
            csv << "," << csv_field(o.status) << "\n";
            ++counts[o.status];
        }
        csv.close();
        if (!csv) throw std::runtime_error(a->csv + ": cannot write");
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::cout << "grades of " << students.size() << " students written to " << a->csv << " (";
        bool first = true;
        for (const auto& [s, n] : counts) std::cout << (first ? "" : ", ") << n << " " << s, first = false;
        std::cout << "); per-student results in " << results.string() << "; graded " << todo.size() << " in "
                  << duration(wall);
        if (!todo.empty()) std::cout << " (" << num(busy_seconds / static_cast<double>(todo.size())) << " s per submission)";
        std::cout << "\n";
        if (counts.count("grader error"))
            std::cout << counts["grader error"] << " grader error(s): not the students' fault; run the same command again "
                      << "to grade them again (see their log.txt)\n";
        status = counts.count("grader error") ? 3 : 0;
    });
}

}  // namespace geolab::cli
