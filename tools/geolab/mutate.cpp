// geolab mutate: how strong are a lab's tests? Seed one plausible bug at a time into the reference solution and
// count the mutants the tests kill (see grading/mutate.hpp and docs/instructor.md).
#include <unistd.h>

#include <csignal>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <thread>

#include "commands.hpp"
#include "geolab/config.hpp"
#include "geolab/grading/mutate.hpp"

namespace geolab::cli {
namespace {

namespace fs = std::filesystem;
namespace mut = grading::mutate;

struct MutateArgs {
    std::string lab, only, log, source, build, order = "killer";
    std::size_t max = 0;
    unsigned long long seed = 1;
    int jobs = 0;
    bool resume = false, rerun_survivors = false, full = false, array_bounds = false, json = false, quiet = false;
    double timeout_factor = 10;
};

// SIGINT/SIGTERM: the run never writes into solutions/, so there is nothing to restore; the handler's thread
// checks that solutions/NN_name is byte for byte what it was, says so, and exits 128 + signal (the test
// processes die with the grader: their supervisors have PR_SET_PDEATHSIG).
int signal_pipe[2] = {-1, -1};
extern "C" void on_signal(int sig) {
    const unsigned char s = static_cast<unsigned char>(sig);
    (void)!::write(signal_pipe[1], &s, 1);
}

std::map<std::string, std::string> read_folder(const fs::path& dir) {
    std::map<std::string, std::string> files;
    if (!fs::is_directory(dir)) return files;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) {
            std::ifstream f(e.path(), std::ios::binary);
            files[e.path().string()] = std::string(std::istreambuf_iterator<char>(f), {});
        }
    return files;
}

void install_signal_watch(const fs::path& lab_dir) {
    if (::pipe(signal_pipe) != 0) return;
    auto before = std::make_shared<std::map<std::string, std::string>>(read_folder(lab_dir));
    std::thread([lab_dir, before] {
        unsigned char sig = 0;
        while (::read(signal_pipe[0], &sig, 1) != 1) {
        }
        const bool same = read_folder(lab_dir) == *before;
        std::cerr << "\ngeolab mutate: interrupted (" << ::strsignal(sig) << "); " << lab_dir.string()
                  << (same ? " is unchanged (the run writes only into the build's mutate/ folder)\n"
                           : " CHANGED: restore it with git checkout\n");
        std::_Exit(same ? 128 + sig : 3);
    }).detach();
    struct sigaction sa {};
    sa.sa_handler = on_signal;
    ::sigemptyset(&sa.sa_mask);
    ::sigaction(SIGINT, &sa, nullptr);
    ::sigaction(SIGTERM, &sa, nullptr);
}

// The lab folder name in `source`: "1", "01" or "01_halfedge" -> "01_halfedge".
std::string find_lab(const fs::path& source, const std::string& arg) {
    const std::string nn = arg.size() == 1 ? "0" + arg : arg.substr(0, 2);
    std::vector<std::string> found;
    if (fs::is_directory(source / "solutions"))
        for (const auto& e : fs::directory_iterator(source / "solutions")) {
            const std::string name = e.path().filename().string();
            found.push_back(name);
            if (name == arg || name.substr(0, 2) == nn) return name;
        }
    std::string names;
    for (const auto& f : found) names += " " + f;
    throw CLI::ValidationError("lab", "no lab '" + arg + "' in " + (source / "solutions").string() +
                                          (names.empty() ? " (no solutions/ there)" : "; there are:" + names));
}

int run(const MutateArgs& a) {
    mut::MutateOptions opt;
    opt.source = a.source.empty() ? source_dir() : fs::absolute(a.source);
    opt.build = a.build.empty() ? bin_dir().parent_path() : fs::absolute(a.build);
    opt.lab = find_lab(opt.source, a.lab);
    opt.max = a.max;
    opt.seed = a.seed;
    opt.jobs = a.jobs > 0 ? a.jobs : std::max(1u, std::thread::hardware_concurrency());
    opt.only = a.only;
    opt.log = a.log;
    opt.resume = a.resume;
    if (a.resume && a.log.empty()) throw std::runtime_error("--resume needs --log FILE (the log of the run to resume)");
    if (a.rerun_survivors && !a.resume) throw std::runtime_error("--rerun-survivors goes with --resume --log FILE");
    opt.rerun_survivors = a.rerun_survivors;
    opt.full = a.full;
    opt.array_bounds = a.array_bounds;
    opt.order = a.order;
    opt.timeout_factor = a.timeout_factor;
    opt.quiet = a.quiet;
    const bool tty = ::isatty(2);
    opt.progress = [tty](const std::string& line) {
        if (tty && line.rfind("[", 0) == 0) std::cerr << "\r" << line << "   " << std::flush;
        else std::cerr << (tty ? "\n" : "") << line << "\n";
    };
    install_signal_watch(opt.source / "solutions" / opt.lab);
    const mut::MutateReport rep = mut::run_mutate(opt);
    if (tty && !a.quiet) std::cerr << "\n";
    if (a.json) std::cout << mut::report_json(rep) << "\n";
    else std::cout << mut::format_report(rep);
    return 0;
}

}  // namespace

void add_mutate(CLI::App& app, int& status) {
    auto a = std::make_shared<MutateArgs>();
    auto* cmd = app.add_subcommand("mutate", "How strong are a lab's tests? Seed one bug at a time into the reference "
                                             "solution and count the mutants the tests kill (instructors)");
    cmd->add_option("lab", a->lab, "The lab: 01, 1 or 01_halfedge")->required();
    cmd->add_option("--max", a->max, "Run a random sample of this many mutants (default: all)");
    cmd->add_option("--seed", a->seed, "Seed of the --max sample")->capture_default_str();
    cmd->add_option("--jobs,-j", a->jobs, "Mutants graded at once (default: the number of cores)");
    cmd->add_option("--only", a->only, "Only the mutants of this solution file (e.g. qef.cpp), or of one line of it "
                                       "(qef.cpp:58) or lines (qef.cpp:50-60); several, separated by commas (qef.cpp:58,origin.cpp)");
    cmd->add_option("--log", a->log, "Write one JSON line per mutant here");
    cmd->add_flag("--resume", a->resume, "Skip the mutants already in --log (after an interrupted run)");
    cmd->add_flag("--rerun-survivors", a->rerun_survivors,
                  "With --resume: grade the survivors in --log again (after adding tests); the rest stays as logged");
    cmd->add_flag("--full", a->full, "Run every test of each mutant (default: stop at its first failing test)");
    cmd->add_flag("--array-bounds", a->array_bounds,
                  "Also mutate the array bounds of declarations (double a[3] -> a[2], a[4]); each is rebuilt alone");
    cmd->add_flag("--json", a->json, "Print the summary as one JSON object");
    cmd->add_option("--order", a->order, "Test order: killer (the test that killed the file's last mutant, then the "
                                         "cheapest), cheap (cheapest first), listing")
        ->check(CLI::IsMember({"killer", "cheap", "listing"}))
        ->capture_default_str();
    cmd->add_option("--timeout-factor", a->timeout_factor,
                    "A mutant's test times out after this many times its baseline time + 2 s")
        ->capture_default_str();
    cmd->add_option("--source", a->source, "The course tree (default: the tree this program was built from)");
    cmd->add_option("--build", a->build, "Its Ninja build (default: the build this program belongs to)");
    cmd->add_flag("--quiet,-q", a->quiet, "No progress lines");
    cmd->callback([a, &status] { status = run(*a); });
}

}  // namespace geolab::cli
