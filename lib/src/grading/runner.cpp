#include "geolab/grading/runner.hpp"

#include <atomic>
#include <chrono>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <mutex>
#include <optional>
#include <sstream>
#include <algorithm>
#include <tuple>
#include <random>
#include <stdexcept>
#include <thread>

#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

extern char** environ;

namespace geolab::grading {

const char* to_string(Status s) {
    switch (s) {
        case Status::passed: return "passed";
        case Status::failed: return "failed";
        case Status::not_implemented: return "not implemented";
        case Status::crashed: return "crashed";
        case Status::timeout: return "timed out";
        case Status::error: return "error";
    }
    return "?";
}

double LabReport::score() const {
    double s = 0;
    for (const auto& r : results) s += r.score;
    return s;
}
double LabReport::max_score() const {
    double s = 0;
    for (const auto& r : results) s += r.info.points;
    return s;
}

namespace {

using Clock = std::chrono::steady_clock;

// What happened to one child process.
struct ChildOutcome {
    std::string output;   // stdout + stderr, up to the cap
    std::string verdict;  // everything written to the verdict pipe
    bool timed_out = false, flooded = false, exited = false, started = true;
    int exit_code = 0, signal = 0;
    double seconds = 0;
};

// A fresh random token for one run: 128 bits from the OS.
std::string random_token() {
    std::random_device rd;
    static const char* hex = "0123456789abcdef";
    std::string t;
    for (int i = 0; i < 32; ++i) t += hex[rd() & 15u];
    return t;
}

void set_limit(int resource, rlim_t value) {
    rlimit rl{value, value};
    ::setrlimit(resource, &rl);
}

// Read what is available on fd into out (up to `cap` bytes kept); returns false at EOF or error.
bool drain(int fd, std::string& out, std::size_t cap, bool& over) {
    char buf[65536];
    ssize_t n = ::read(fd, buf, sizeof buf);
    if (n > 0) {
        std::size_t keep = out.size() < cap ? std::min<std::size_t>(static_cast<std::size_t>(n), cap - out.size()) : 0;
        out.append(buf, keep);
        if (keep < static_cast<std::size_t>(n)) over = true;
        return true;
    }
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) return true;
    return false;
}

// Run argv as a child in its own process group with the limits of `opt`; the verdict pipe's write end is
// passed as GEOLAB_RESULT_FD together with GEOLAB_TOKEN=token.
ChildOutcome run_child(const std::vector<std::string>& argv, const std::string& token, double timeout_s,
                       const RunOptions& opt) {
    ChildOutcome out;
    int out_pipe[2], verdict_pipe[2];
    if (::pipe2(out_pipe, O_CLOEXEC) != 0) throw std::runtime_error("grader: pipe failed");
    if (::pipe2(verdict_pipe, O_CLOEXEC) != 0) {
        ::close(out_pipe[0]);
        ::close(out_pipe[1]);
        throw std::runtime_error("grader: pipe failed");
    }
    // Everything the child needs is prepared before fork: after fork only async-signal-safe calls.
    std::vector<std::string> env_strings;
    for (char** e = environ; *e; ++e) {
        if (std::strncmp(*e, "GEOLAB_TOKEN=", 13) == 0 || std::strncmp(*e, "GEOLAB_RESULT_FD=", 17) == 0) continue;
        env_strings.emplace_back(*e);
    }
    env_strings.push_back("GEOLAB_TOKEN=" + token);
    env_strings.push_back("GEOLAB_RESULT_FD=3");
    std::vector<char*> envp, args;
    for (auto& s : env_strings) envp.push_back(s.data());
    envp.push_back(nullptr);
    std::vector<std::string> argv_copy = argv;
    for (auto& s : argv_copy) args.push_back(s.data());
    args.push_back(nullptr);
    const rlim_t mem = static_cast<rlim_t>(opt.memory_mb) << 20;
    const rlim_t fsize = static_cast<rlim_t>(opt.file_size_mb) << 20;
    const rlim_t cpu = static_cast<rlim_t>(timeout_s) + 2;
    int devnull = ::open("/dev/null", O_RDONLY | O_CLOEXEC);

    auto t0 = Clock::now();
    pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("grader: fork failed");
    if (pid == 0) {
        ::setpgid(0, 0);
        set_limit(RLIMIT_AS, mem);
        set_limit(RLIMIT_FSIZE, fsize);
        set_limit(RLIMIT_CPU, cpu);
        set_limit(RLIMIT_CORE, 0);
        // Move our fds out of the way first (the parent may run with 0-2 closed), then into place.
        int in_fd = ::fcntl(devnull, F_DUPFD_CLOEXEC, 10);
        int out_fd = ::fcntl(out_pipe[1], F_DUPFD_CLOEXEC, 10);
        int verdict_fd = ::fcntl(verdict_pipe[1], F_DUPFD_CLOEXEC, 10);
        ::dup2(in_fd, 0);  // dup2 clears O_CLOEXEC on the copies
        ::dup2(out_fd, 1);
        ::dup2(out_fd, 2);
        ::dup2(verdict_fd, 3);
        ::execve(args[0], args.data(), envp.data());
        const char msg[] = "grader: cannot execute the test program\n";
        (void)!::write(2, msg, sizeof msg - 1);
        ::_exit(127);
    }
    ::setpgid(pid, pid);  // also from the parent, so the group exists before we might kill it
    ::close(devnull);
    ::close(out_pipe[1]);
    ::close(verdict_pipe[1]);

    const auto deadline = t0 + std::chrono::duration<double>(timeout_s);
    bool out_open = true, verdict_open = true, reaped = false;
    int wstatus = 0;
    auto kill_group = [&] { ::kill(-pid, SIGKILL); };
    std::optional<Clock::time_point> grace;  // after the child exits, leftovers get a short grace period
    while (out_open || verdict_open || !reaped) {
        if (!reaped) {
            pid_t w = ::waitpid(pid, &wstatus, WNOHANG);
            if (w == pid) {
                reaped = true;
                kill_group();  // children it left behind die with it
                grace = Clock::now() + std::chrono::milliseconds(500);
            }
        }
        auto now = Clock::now();
        if (!reaped && now >= deadline) {
            out.timed_out = true;
            kill_group();
            ::waitpid(pid, &wstatus, 0);
            reaped = true;
            break;
        }
        if (grace && now >= *grace) break;
        pollfd fds[2];
        int n = 0;
        if (out_open) fds[n++] = {out_pipe[0], POLLIN, 0};
        if (verdict_open) fds[n++] = {verdict_pipe[0], POLLIN, 0};
        if (n == 0) {
            if (!reaped) ::usleep(2000);
            continue;
        }
        ::poll(fds, static_cast<nfds_t>(n), 20);
        for (int i = 0; i < n; ++i) {
            if (!(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            bool over = false;
            if (fds[i].fd == out_pipe[0]) {
                out_open = drain(out_pipe[0], out.output, opt.output_cap, over);
                if (over && !out.flooded) {
                    out.flooded = true;
                    kill_group();
                }
            } else {
                verdict_open = drain(verdict_pipe[0], out.verdict, 1 << 20, over);
            }
        }
    }
    if (!reaped) {
        kill_group();
        ::waitpid(pid, &wstatus, 0);
    }
    ::close(out_pipe[0]);
    ::close(verdict_pipe[0]);
    out.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    if (WIFEXITED(wstatus)) {
        out.exited = true;
        out.exit_code = WEXITSTATUS(wstatus);
    } else if (WIFSIGNALED(wstatus)) {
        out.signal = WTERMSIG(wstatus);
    }
    return out;
}

std::string signal_name(int sig) {
    const char* abbrev = ::sigabbrev_np(sig);
    std::string s = abbrev ? std::string("SIG") + abbrev : "signal " + std::to_string(sig);
    if (const char* d = ::strsignal(sig)) s += std::string(" (") + d + ")";
    return s;
}

std::string tail(const std::string& s, std::size_t n) { return s.size() > n ? "..." + s.substr(s.size() - n) : s; }

// Decide the status of a finished child from what the parent saw.
void classify(const ChildOutcome& c, const std::string& token, TestResult& r, const RunOptions& opt) {
    r.seconds = c.seconds;
    r.output = c.output;
    auto fail = [&](Status s, std::string why) {
        r.status = s;
        r.messages.push_back(std::move(why));
    };
    if (c.timed_out) return fail(Status::timeout, "killed after the time limit: an infinite loop, or far too slow?");
    if (c.flooded)
        return fail(Status::error, "killed: printed more than " + std::to_string(opt.output_cap) + " bytes");
    if (c.signal) {
        std::string m = "crashed with " + signal_name(c.signal);
        if (c.signal == SIGXCPU) m += ": CPU time limit";
        if (c.signal == SIGXFSZ) m += ": wrote a file larger than the limit";
        return fail(Status::crashed, m);
    }
    // The verdict: exactly one line "<token> <json>".
    const std::string prefix = token + " ";
    auto pos = c.verdict.find(prefix);
    if (pos == std::string::npos) {
        std::string m = "the test program exited (status " + std::to_string(c.exit_code) +
                        ") before the test finished: does the code call exit(), or abort?";
        if (c.exit_code == 127 && c.output.find("cannot execute") != std::string::npos)
            m = "the test program could not be started";
        if (c.output.find("std::bad_alloc") != std::string::npos) m += " (ran out of memory)";
        return fail(Status::error, m);
    }
    nlohmann::json j = nlohmann::json::parse(c.verdict.substr(pos + prefix.size()), nullptr, false);
    if (j.is_discarded() || !j.contains("status") || !j.contains("ran"))
        return fail(Status::error, "the test's verdict could not be read");
    std::vector<std::string> ran = j["ran"].get<std::vector<std::string>>();
    if (ran.size() != 1 || ran[0] != r.info.name)
        return fail(Status::error, "the test program ran " + std::to_string(ran.size()) + " tests instead of this one");
    for (const auto& m : j.value("messages", std::vector<std::string>{})) r.messages.push_back(m);
    if (j["status"] == "passed") {
        r.status = Status::passed;
        r.score = r.info.points;
    } else {
        r.status = j.value("not_implemented", false) ? Status::not_implemented : Status::failed;
        if (r.messages.empty()) r.messages.push_back("failed");
    }
}

}  // namespace

std::vector<TestInfo> list_tests(const std::filesystem::path& program, const RunOptions& opt) {
    if (!std::filesystem::exists(program))
        throw std::runtime_error(program.string() + ": test program not found (build it first)");
    ChildOutcome c = run_child({program.string(), "--geolab-list"}, random_token(), 60, opt);
    if (c.timed_out || c.signal || c.flooded || !c.exited || c.exit_code != 0)
        throw std::runtime_error(program.string() + ": could not list the tests (" +
                                 (c.signal ? signal_name(c.signal)
                                           : c.timed_out ? "timed out" : "exit status " + std::to_string(c.exit_code)) +
                                 ")\n" + tail(c.output, 2000));
    std::vector<TestInfo> tests;
    std::istringstream lines(c.output);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.empty() || line[0] != '{') continue;
        auto j = nlohmann::json::parse(line, nullptr, false);
        if (j.is_discarded()) continue;
        TestInfo t;
        t.name = j.value("name", "");
        t.suite = j.value("suite", "");
        t.file = j.value("file", "");
        t.line = j.value("line", 0);
        t.points = j.value("points", 0.0);
        t.hidden = j.value("hidden", false);
        t.hint = j.value("hint", "");
        t.timeout_s = j.value("timeout", 0.0);
        if (!j.value("filter_safe", true))
            throw std::runtime_error(t.file + ":" + std::to_string(t.line) + ": test name '" + t.name +
                                     "' contains one of * ? , \\ [ ] which the grader cannot select exactly");
        tests.push_back(std::move(t));
    }
    std::stable_sort(tests.begin(), tests.end(), [](const TestInfo& a, const TestInfo& b) {
        return std::tie(a.file, a.line) < std::tie(b.file, b.line);
    });
    return tests;
}

TestResult run_test(const std::filesystem::path& program, const TestInfo& test, const RunOptions& opt) {
    TestResult r;
    r.info = test;
    const std::string token = random_token();
    const double limit = test.timeout_s > 0 ? test.timeout_s : opt.timeout_s;
    ChildOutcome c = run_child({program.string(), "--geolab-run", test.name}, token, limit, opt);
    classify(c, token, r, opt);
    return r;
}

LabReport grade_program(const std::string& lab, const std::string& variant, const std::filesystem::path& program,
                        const RunOptions& opt) {
    LabReport report;
    report.lab = lab;
    report.variant = variant;
    auto t0 = Clock::now();
    std::vector<TestInfo> tests;
    try {
        tests = list_tests(program, opt);
    } catch (const std::exception& e) {
        report.error = e.what();
        return report;
    }
    report.results.resize(tests.size());
    std::atomic<std::size_t> next{0}, done{0};
    std::mutex progress_mutex;
    auto worker = [&] {
        for (std::size_t i; (i = next++) < tests.size();) {
            report.results[i] = run_test(program, tests[i], opt);
            std::lock_guard lock(progress_mutex);
            ++done;
            if (opt.on_result) opt.on_result(report.results[i], done, tests.size());
        }
    };
    std::vector<std::thread> pool;
    for (int j = 0; j < std::max(1, opt.jobs); ++j) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
    report.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return report;
}

}  // namespace geolab::grading
