// geolab grade: run the labs' graded tests, each case in its own process, and report.
#include <unistd.h>

#include <iostream>
#include <thread>

#include "commands.hpp"
#include "geolab/config.hpp"
#include "geolab/grading/independence.hpp"
#include "geolab/grading/report.hpp"
#include "geolab/grading/runner.hpp"
#include "geolab/grading/submission.hpp"

namespace geolab::cli {
namespace {

struct GradeArgs {
    std::vector<std::string> labs;
    bool solutions = false;
    std::string json, junit, expect;
    int jobs = 0;
    double timeout = 20;
    std::size_t memory_mb = 4096;
    bool student_view = false;
    bool quiet = false, verbose = false;
    std::string test;
    std::string submission, lab, work_dir, forbidden, figures;
    bool asan = false, no_course_build = false, allow_unisolated = false;
    bool independence = false;
    int job = 0;
    double max_seconds = 1200;
};

// CI's honesty checks: the reference scores 100%; untouched stubs score 0 and every graded test fails cleanly.
bool check_expectation(const std::vector<grading::LabReport>& reports, const std::string& expect) {
    bool ok = true;
    for (const auto& lab : reports) {
        if (!lab.error.empty()) {
            std::cerr << "expect " << expect << ": lab " << lab.lab << " could not be run\n";
            ok = false;
            continue;
        }
        if (lab.results.empty()) {
            std::cerr << "expect " << expect << ": lab " << lab.lab << " has no tests\n";
            ok = false;
        }
        for (const auto& r : lab.results) {
            if (r.info.points <= 0) continue;
            if (expect == "full" && r.status != grading::Status::passed) {
                std::cerr << "expect full: " << lab.lab << ": '" << r.info.name << "' " << to_string(r.status) << ": "
                          << grading::first_message(r) << "\n";
                ok = false;
            }
            const bool clean = r.status == grading::Status::failed || r.status == grading::Status::not_implemented;
            if (expect == "zero" && !clean) {
                std::cerr << "expect zero: " << lab.lab << ": '" << r.info.name << "' " << to_string(r.status)
                          << (r.status == grading::Status::passed ? " on the stub: the test asserts nothing a stub can't satisfy"
                                                                  : ": a stub must fail cleanly")
                          << "\n";
                ok = false;
            }
        }
    }
    return ok;
}

// geolab grade --submission DIR|ZIP --lab NN: one student's files against the full course (hidden tests too).
int run_submission(const GradeArgs& a) {
    if (a.lab.empty()) throw std::runtime_error("--submission needs --lab NN (the lab the submission is for)");
    grading::SubmissionOptions opt = submission_options(resolve_lab(a.lab), a.work_dir, a.job);
    opt.asan = a.asan;
    opt.build_course = !a.no_course_build;
    opt.forbidden = a.forbidden;
    opt.max_seconds = a.max_seconds;
    opt.allow_unisolated = a.allow_unisolated;
    if (!a.figures.empty()) opt.run.figure_dir = std::filesystem::absolute(a.figures);
    opt.run.timeout_s = a.timeout;
    opt.run.memory_mb = a.memory_mb;
    opt.run.only_test = a.test;
    opt.run.jobs = a.jobs > 0 ? a.jobs : std::max(1u, std::thread::hardware_concurrency());
    if (!a.quiet) std::cerr << "grading " << a.submission << " (lab " << opt.lab << ") ...\n";
    const auto rep = grading::grade_submission(a.submission, opt);
    std::cout << rep.summary();
    // A submission that could not be graded says so in its one status line: no table of tests that never ran.
    using S = grading::SubmissionStatus;
    if (rep.status == S::ok || rep.status == S::compile_error)
        grading::print_console(std::cout, {rep.lab},
                               a.student_view ? grading::HiddenPolicy::name_points : grading::HiddenPolicy::show,
                               ::isatty(1), a.verbose);
    else if (rep.status != S::grader_error)
        std::cout << "score: 0 / " << rep.lab.max_score() << "\n";
    write_submission_reports(rep, a.json, a.junit);
    if (!a.json.empty()) std::cout << "results.json written to " << a.json << "\n";
    if (!a.junit.empty()) std::cout << "JUnit XML written to " << a.junit << "\n";
    if (rep.status == grading::SubmissionStatus::grader_error) return 2;
    return rep.status == grading::SubmissionStatus::not_found ? 1 : 0;
}

// geolab grade NN --independence: DESIGN.md rule 6 on the reference, one task file stubbed at a time.
int run_independence(const GradeArgs& a) {
    if (!config::has_solutions) throw std::runtime_error("--independence needs the reference (solutions/)");
    std::vector<std::string> labs;
    for (const auto& l : a.labs) labs.push_back(resolve_lab(l));
    if (labs.empty()) labs = known_labs();
    bool ok = true;
    for (const auto& lab : labs) {
        grading::IndependenceOptions opt;
        opt.course_root = source_dir();
        opt.build_dir = bin_dir().parent_path();
        opt.work_dir = opt.build_dir / "independence" / lab.substr(0, 2);
        opt.lab = lab;
        opt.jobs = a.jobs > 0 ? a.jobs : std::max(1u, std::thread::hardware_concurrency());
        opt.timeout_s = a.timeout;
        if (!a.quiet) opt.progress = [](const std::string& line) { std::cerr << "  " << line << "\n"; };
        const auto rep = grading::check_independence(opt);
        std::cout << rep.text();
        ok = ok && rep.ok();
    }
    return ok ? 0 : 1;
}

int run_grade(const GradeArgs& a) {
    if (a.independence) return run_independence(a);
    if (!a.submission.empty()) return run_submission(a);
    if (!a.lab.empty()) throw std::runtime_error("--lab is for --submission; to grade this tree say: geolab grade " + a.lab);
    std::vector<std::string> labs;
    for (const auto& l : a.labs) labs.push_back(resolve_lab(l));
    if (labs.empty()) labs = known_labs();
    if (a.solutions && !config::has_solutions)
        throw std::runtime_error("--solutions: this tree has no solutions/ (the student release grades your own code)");

    if (!a.test.empty() && labs.size() != 1)
        throw std::runtime_error("--test runs one test of one lab: name the lab too (geolab grade 01 --test NAME)");
    grading::RunOptions opt;
    opt.only_test = a.test;
    opt.timeout_s = a.timeout;
    opt.memory_mb = a.memory_mb;
    opt.jobs = a.jobs > 0 ? a.jobs : std::max(1u, std::thread::hardware_concurrency());
    const bool tty = ::isatty(2);
    opt.on_result = [&](const grading::TestResult& r, std::size_t done, std::size_t total) {
        if (a.quiet) return;
        if (tty)
            std::cerr << "\r  [" << done << "/" << total << "] " << std::string(60, ' ') << "\r  [" << done << "/"
                      << total << "] " << r.info.name.substr(0, 60) << std::flush;
        else if (done == total || done % 10 == 0)
            std::cerr << "  " << done << "/" << total << " tests run\n";
    };

    std::vector<grading::LabReport> reports;
    const std::string variant = a.solutions ? "solution" : "student";
    for (const auto& lab : labs) {
        const auto program = bin_dir() / ("test_" + lab + (a.solutions ? "_solution" : ""));
        if (!a.quiet) std::cerr << "grading " << lab << " (" << variant << ") ...\n";
        grading::RunOptions lab_opt = opt;
        // Record and replay: the lab's judge lists the tests and decides every verdict (docs/architecture.md).
        if (const auto judge = bin_dir() / ("judge_" + lab); std::filesystem::exists(judge)) lab_opt.judge = judge;
        else std::cerr << "warning: " << lab << " has no judge (no GEOLAB_BOUNDARY list): its verdicts are decided by "
                       << "the program that runs the tested code (verdict not isolated)\n";
        reports.push_back(grading::grade_program(lab, variant, program, lab_opt));
        if (tty && !a.quiet) std::cerr << "\n";
    }
    grading::print_console(std::cout, reports,
                           a.student_view ? grading::HiddenPolicy::name_points : grading::HiddenPolicy::show,
                           ::isatty(1), a.verbose);
    if (!a.json.empty()) {
        grading::write_gradescope_json(a.json, reports);
        std::cout << "results.json written to " << a.json << "\n";
    }
    if (!a.junit.empty()) {
        grading::write_junit(a.junit, reports);
        std::cout << "JUnit XML written to " << a.junit << "\n";
    }
    if (!a.expect.empty()) {
        const bool ok = check_expectation(reports, a.expect);
        std::cout << "expect " << a.expect << ": " << (ok ? "OK" : "FAILED") << "\n";
        return ok ? 0 : 1;
    }
    for (const auto& r : reports)
        if (!r.error.empty()) return 2;
    return 0;
}

}  // namespace

grading::SubmissionOptions submission_options(const std::string& lab, const std::string& work_dir, int job) {
    grading::SubmissionOptions opt;
    opt.lab = lab;
    opt.course_root = source_dir();
    opt.build_dir = bin_dir().parent_path();
    const std::filesystem::path base = work_dir.empty() ? opt.build_dir / "grading" : std::filesystem::path(work_dir);
    opt.work_dir = base / lab.substr(0, 2) / ("job" + std::to_string(job));
    return opt;
}

void write_submission_reports(const grading::SubmissionReport& rep, const std::string& json, const std::string& junit) {
    if (!json.empty()) {
        std::string preamble = rep.summary();
        if (!preamble.empty()) preamble += "\n";
        grading::write_gradescope_json(json, {rep.lab}, preamble);
    }
    if (!junit.empty()) grading::write_junit(junit, {rep.lab});
}

void add_grade(CLI::App& app, int& status) {
    auto a = std::make_shared<GradeArgs>();
    auto* cmd = app.add_subcommand("grade", "Run the graded tests of labs (all by default), one process per test");
    cmd->add_option("labs", a->labs, "Labs to grade: 01, 1 or 01_halfedge (default: all)");
    cmd->add_flag("--solutions", a->solutions, "Grade the reference solutions instead of labs/ (instructors)");
    cmd->add_option("--json", a->json, "Write Gradescope results.json here");
    cmd->add_option("--junit", a->junit, "Write JUnit XML here");
    cmd->add_option("--jobs,-j", a->jobs, "Tests run at once (default: the number of cores)");
    cmd->add_option("--timeout", a->timeout, "Default wall-clock limit per test, seconds")->capture_default_str();
    cmd->add_option("--memory-mb", a->memory_mb, "Address-space limit per test, MiB")->capture_default_str();
    cmd->add_flag("--student-view", a->student_view, "Withhold the messages of hidden tests, as students see it");
    cmd->add_flag("--quiet,-q", a->quiet, "No progress lines");
    cmd->add_flag("--verbose,-v", a->verbose, "Every message of a failed test, uncut, and what the test printed");
    cmd->add_option("--test,-t", a->test,
                    "Run one test of the lab: its name as the report prints it, or a part only it contains");
    cmd->add_option("--submission", a->submission,
                    "Grade a student's submission (a folder or a .zip) against the full course, hidden tests included");
    cmd->add_option("--lab", a->lab, "With --submission: the lab it is for (01, 1 or 01_halfedge)");
    cmd->add_flag("--asan", a->asan, "With --submission: also run with AddressSanitizer + UBSan (an ungraded item)");
    cmd->add_option("--work-dir", a->work_dir, "With --submission: the grading work folder (default: BUILD/grading)");
    cmd->add_option("--job", a->job, "With --submission: the job folder to use (jobN): gradings of one lab that run at "
                                     "once need different ones; they share the compiled-object cache")
        ->check(CLI::Range(0, 63));
    cmd->add_option("--forbidden", a->forbidden, "With --submission: the forbidden-calls list (default labs/NN/forbidden.txt)");
    cmd->add_option("--figures", a->figures, "With --submission: write the tests' pictures (attach_mesh_figure) here");
    cmd->add_option("--max-seconds", a->max_seconds,
                    "With --submission: wall-clock cap of the whole submission, seconds (0: none)")
        ->capture_default_str();
    cmd->add_flag("--allow-unisolated", a->allow_unisolated,
                  "With --submission, as root: grade even when the sandbox cannot be set up (the report says NOT ISOLATED)");
    cmd->add_flag("--no-course-build", a->no_course_build,
                  "With --submission: do not bring the course's test program up to date first");
    cmd->add_flag("--independence", a->independence,
                  "CI check of DESIGN.md rule 6 on the reference: each task file stubbed in turn must cost the points of "
                  "its own tasks only");
    cmd->add_option("--expect", a->expect, "CI check: 'full' (every graded test passes) or 'zero' (every graded test "
                                           "fails cleanly: failed or not implemented, never crashed or timed out)")
        ->check(CLI::IsMember({"full", "zero"}));
    cmd->callback([a, &status] { status = run_grade(*a); });
}

}  // namespace geolab::cli
