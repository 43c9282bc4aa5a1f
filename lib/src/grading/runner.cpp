#include "geolab/grading/runner.hpp"

#include <atomic>
#include <chrono>
#include <cerrno>
#include <cstdlib>
#include <csignal>
#include <cstring>
#include <fstream>
#include <functional>
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
#include <grp.h>
#include <pwd.h>
#include <sched.h>
#include <sys/file.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <dirent.h>

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

// ---- the sandbox ---------------------------------------------------------------------------------------------
// Every command runs under a supervisor: the grader forks S, S becomes a child subreaper and forks the test T.
// When T ends (or the grader asks through the control pipe: time limit, output cap), S kills T's process group,
// every process of T's leased uid, and every orphan that was reparented to S (double forks, setsid()), reaps them
// all, and only then reports T's wait status through the status pipe. The grader never has stray children.
// S and T run between fork and exec / _exit: only async-signal-safe system calls there.

// A uid no account uses, leased for the lifetime of one test through an flock'ed file.
struct UidLease {
    int fd = -1;
    unsigned uid = 0;
    UidLease() = default;
    UidLease(const UidLease&) = delete;
    UidLease& operator=(const UidLease&) = delete;
    ~UidLease() {
        if (fd >= 0) ::close(fd);
    }
};

bool lease_uid(const Sandbox& sb, UidLease& lease) {
    const char* dir = "/tmp/geolab-sandbox-uids";
    ::mkdir(dir, 0755);
    struct stat st {};
    if (::lstat(dir, &st) != 0 || !S_ISDIR(st.st_mode) || st.st_uid != 0 || (st.st_mode & 022)) return false;
    static std::atomic<unsigned> start{0};
    const unsigned first = start++ % std::max(1u, sb.uid_pool_size);
    for (unsigned k = 0; k < sb.uid_pool_size; ++k) {
        const unsigned uid = sb.uid_pool_first + (first + k) % sb.uid_pool_size;
        if (::getpwuid(uid) != nullptr) continue;  // a real account: never borrow it
        const std::string path = std::string(dir) + "/" + std::to_string(uid);
        int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0600);
        if (fd < 0) continue;
        if (::flock(fd, LOCK_EX | LOCK_NB) == 0) {
            lease.fd = fd;
            lease.uid = uid;
            return true;
        }
        ::close(fd);
    }
    return false;
}

// Async-signal-safe: the parent pid of /proc/<pid>/stat, or -1.
pid_t parent_of(const char* pid_name) {
    char path[64] = "/proc/";
    std::size_t n = 6;
    for (const char* p = pid_name; *p && n < 50; ++p) path[n++] = *p;
    const char* tail = "/stat";
    for (const char* p = tail; *p; ++p) path[n++] = *p;
    path[n] = 0;
    int fd = ::open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0) return -1;
    char buf[512];
    ssize_t len = ::read(fd, buf, sizeof buf - 1);
    ::close(fd);
    if (len <= 0) return -1;
    buf[len] = 0;
    // "pid (comm) state ppid ...": comm may contain anything, so look for the last ')'.
    ssize_t close_paren = -1;
    for (ssize_t i = 0; i < len; ++i)
        if (buf[i] == ')') close_paren = i;
    if (close_paren < 0 || close_paren + 4 >= len) return -1;
    const char* p = buf + close_paren + 4;  // ") S " then ppid
    pid_t ppid = 0;
    while (*p >= '0' && *p <= '9') ppid = ppid * 10 + (*p++ - '0');
    return ppid;
}

// Async-signal-safe: SIGKILL every child of this process; returns how many were found.
int kill_my_children(pid_t self) {
    int found = 0;
    int dfd = ::open("/proc", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dfd < 0) return 0;
    alignas(8) char buf[8192];
    for (;;) {
        long n = ::syscall(SYS_getdents64, dfd, buf, sizeof buf);
        if (n <= 0) break;
        for (long off = 0; off < n;) {
            struct linux_dirent64 {
                ino64_t d_ino;
                off64_t d_off;
                unsigned short d_reclen;
                unsigned char d_type;
                char d_name[];
            };
            auto* d = reinterpret_cast<linux_dirent64*>(buf + off);
            off += d->d_reclen;
            if (d->d_name[0] < '1' || d->d_name[0] > '9') continue;
            if (parent_of(d->d_name) == self) {
                pid_t pid = 0;
                for (const char* p = d->d_name; *p; ++p) pid = pid * 10 + (*p - '0');
                ::kill(pid, SIGKILL);
                ++found;
            }
        }
    }
    ::close(dfd);
    return found;
}

// Async-signal-safe: kill and reap every descendant of the supervisor (it is a child subreaper).
void kill_everything(pid_t test_pid, unsigned uid) {
    ::kill(-test_pid, SIGKILL);
    if (uid != 0) {
        // Every process of the leased uid, wherever it went (setsid, double fork): kill(-1) as that uid.
        pid_t k = ::fork();
        if (k == 0) {
            if (::setgroups(0, nullptr) != 0 || ::setgid(uid) != 0 || ::setuid(uid) != 0) ::_exit(1);
            for (int i = 0; i < 100 && ::kill(-1, SIGKILL) == 0; ++i) {
            }
            ::_exit(0);
        }
    }
    const pid_t self = ::getpid();
    for (int round = 0; round < 2000; ++round) {
        int st;
        while (::waitpid(-1, &st, WNOHANG) > 0) {
        }
        const int found = kill_my_children(self);
        if (::waitpid(-1, &st, WNOHANG) < 0 && errno == ECHILD && found == 0) return;
        timespec ts{0, 1000000};
        ::nanosleep(&ts, nullptr);
    }
}

// Run argv under a supervisor with the limits of `opt`. `extra_fds` become the child's fds 3, 4, ... (record
// and replay pipes); the verdict pipe's write end follows them and is passed as GEOLAB_RESULT_FD together with
// GEOLAB_TOKEN=token (when token is non-empty). `forked` is called in the grader once the supervisor exists.
ChildOutcome run_child(const std::vector<std::string>& argv, const std::string& token, double timeout_s,
                       const RunOptions& opt, rlim_t memory_mb, const std::vector<int>& extra_fds = {},
                       const std::function<void()>& forked = {}) {
    ChildOutcome out;
    const Sandbox& sb = opt.sandbox;
    const bool root = ::geteuid() == 0;
    UidLease lease;
    const bool drop = sb.drop_privileges && root && lease_uid(sb, lease);
    // The test's own working folder (owned by the test's uid), removed afterwards.
    std::string workdir;
    if (!sb.workdir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(sb.workdir, ec);
        std::string tmpl = (sb.workdir / "run-XXXXXX").string();
        if (::mkdtemp(tmpl.data())) {
            workdir = tmpl;
            if (drop) (void)!::chown(workdir.c_str(), lease.uid, lease.uid);
            if (sb.prepare) sb.prepare(workdir, drop ? lease.uid : 0);
        }
    }
    int out_pipe[2], verdict_pipe[2], status_pipe[2], ctrl_pipe[2];
    if (::pipe2(out_pipe, O_CLOEXEC) != 0) throw std::runtime_error("grader: pipe failed");
    if (::pipe2(verdict_pipe, O_CLOEXEC) != 0 || ::pipe2(status_pipe, O_CLOEXEC) != 0 ||
        ::pipe2(ctrl_pipe, O_CLOEXEC) != 0)
        throw std::runtime_error("grader: pipe failed");
    // Everything the children need is prepared before fork: after fork only async-signal-safe calls.
    std::vector<std::string> env_strings;
    for (char** e = environ; *e; ++e) {
        if (std::strncmp(*e, "GEOLAB_TOKEN=", 13) == 0 || std::strncmp(*e, "GEOLAB_RESULT_FD=", 17) == 0) continue;
        if (!workdir.empty() && (std::strncmp(*e, "TMPDIR=", 7) == 0 || std::strncmp(*e, "HOME=", 5) == 0)) continue;
        env_strings.emplace_back(*e);
    }
    const int n_extra = static_cast<int>(std::min<std::size_t>(extra_fds.size(), 4));
    int extra[4] = {-1, -1, -1, -1};
    for (int i = 0; i < n_extra; ++i) extra[i] = extra_fds[static_cast<std::size_t>(i)];
    const int verdict_target = 3 + n_extra;
    if (!token.empty()) {
        env_strings.push_back("GEOLAB_TOKEN=" + token);
        env_strings.push_back("GEOLAB_RESULT_FD=" + std::to_string(verdict_target));
    }
    if (!workdir.empty()) {
        env_strings.push_back("TMPDIR=" + workdir);
        env_strings.push_back("HOME=" + workdir);
    }
    for (const auto& e : opt.env) env_strings.push_back(e);
    if (!opt.figure_dir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(opt.figure_dir, ec);
        env_strings.push_back("GEOLAB_FIGURE_DIR=" + (workdir.empty() ? opt.figure_dir.string() : workdir));
    }
    std::vector<char*> envp, args;
    for (auto& s : env_strings) envp.push_back(s.data());
    envp.push_back(nullptr);
    std::vector<std::string> argv_copy = argv;
    for (auto& s : argv_copy) args.push_back(s.data());
    args.push_back(nullptr);
    std::vector<std::string> hide;
    if (root)
        for (const auto& h : sb.hide)
            if (std::filesystem::is_directory(h)) hide.push_back(h.string());
    const rlim_t mem = memory_mb << 20;
    const rlim_t fsize = static_cast<rlim_t>(opt.file_size_mb) << 20;
    const rlim_t cpu = static_cast<rlim_t>(timeout_s) + 2;
    const rlim_t nproc = static_cast<rlim_t>(sb.max_processes);
    const unsigned uid = drop ? lease.uid : 0;
    const bool no_network = sb.no_network && root;
    const char* cwd = workdir.empty() ? nullptr : workdir.c_str();
    int devnull = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
    const pid_t grader = ::getpid();

    auto t0 = Clock::now();
    pid_t sup = ::fork();
    if (sup < 0) throw std::runtime_error("grader: fork failed");
    if (sup == 0) {
        // ---- the supervisor ----
        // Other grader threads fork too: close every descriptor that is not ours (pipes of other tests, their
        // uid leases) so that their EOFs and locks do not wait for this test.
        int keep[9] = {devnull, out_pipe[1], verdict_pipe[1], status_pipe[1], ctrl_pipe[0], extra[0], extra[1],
                       extra[2], extra[3]};
        for (int i = 1; i < 9; ++i)
            for (int j = i; j > 0 && keep[j] < keep[j - 1]; --j) std::swap(keep[j], keep[j - 1]);
        unsigned from = 3;
        for (int fd : keep) {
            if (fd < 0 || static_cast<unsigned>(fd) < from) continue;
            if (static_cast<unsigned>(fd) > from) ::close_range(from, static_cast<unsigned>(fd) - 1, 0);
            from = static_cast<unsigned>(fd) + 1;
        }
        ::close_range(from, ~0u, 0);
        ::setpgid(0, 0);
        ::prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (::getppid() != grader) ::_exit(1);
        ::prctl(PR_SET_CHILD_SUBREAPER, 1);
        pid_t test = ::fork();
        if (test == 0) {
            // ---- the test ----
            ::setpgid(0, 0);
            if (no_network) (void)::unshare(CLONE_NEWNET);
            if (!hide.empty() && ::unshare(CLONE_NEWNS) == 0) {
                ::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr);
                for (const auto& h : hide)
                    ::mount("tmpfs", h.c_str(), "tmpfs", MS_RDONLY | MS_NOSUID | MS_NODEV | MS_NOEXEC, "size=4k,mode=0555");
            }
            if (mem) set_limit(RLIMIT_AS, mem);
            set_limit(RLIMIT_FSIZE, fsize);
            set_limit(RLIMIT_CPU, cpu);
            set_limit(RLIMIT_CORE, 0);
            if (uid) set_limit(RLIMIT_NPROC, nproc);
            if (cwd && ::chdir(cwd) != 0) ::_exit(126);
            // Move our fds out of the way first (the parent may run with 0-2 closed), then into place.
            int in_fd = ::fcntl(devnull, F_DUPFD_CLOEXEC, 10);
            int out_fd = ::fcntl(out_pipe[1], F_DUPFD_CLOEXEC, 10);
            int verdict_fd = ::fcntl(verdict_pipe[1], F_DUPFD_CLOEXEC, 10);
            int moved[4] = {-1, -1, -1, -1};
            for (int i = 0; i < n_extra; ++i) moved[i] = ::fcntl(extra[i], F_DUPFD_CLOEXEC, 10);
            ::dup2(in_fd, 0);  // dup2 clears O_CLOEXEC on the copies
            ::dup2(out_fd, 1);
            ::dup2(out_fd, 2);
            for (int i = 0; i < n_extra; ++i) ::dup2(moved[i], 3 + i);
            if (!token.empty()) ::dup2(verdict_fd, verdict_target);
            if (uid && (::setgroups(0, nullptr) != 0 || ::setgid(uid) != 0 || ::setuid(uid) != 0)) {
                const char msg[] = "grader: cannot drop privileges\n";
                (void)!::write(2, msg, sizeof msg - 1);
                ::_exit(126);
            }
            ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // after setuid, which clears it
            ::execve(args[0], args.data(), envp.data());
            const char msg[] = "grader: cannot execute the test program\n";
            (void)!::write(2, msg, sizeof msg - 1);
            ::_exit(127);
        }
        // The supervisor keeps no end of the output and verdict pipes: EOF there means every writer is gone.
        ::close(out_pipe[1]);
        ::close(verdict_pipe[1]);
        ::close(devnull);
        for (int i = 0; i < n_extra; ++i) ::close(extra[i]);  // the record pipes' ends belong to the test alone
        int wstatus = 0;
        int killed = 0;
        if (test > 0) {
            for (;;) {
                pid_t w = ::waitpid(test, &wstatus, WNOHANG);
                if (w == test) break;
                pollfd p{ctrl_pipe[0], POLLIN, 0};
                if (::poll(&p, 1, 10) > 0) {  // the grader asks to stop (or died)
                    killed = 1;
                    ::kill(-test, SIGKILL);
                    ::kill(test, SIGKILL);
                    ::waitpid(test, &wstatus, 0);
                    break;
                }
            }
            kill_everything(test, uid);
        } else {
            wstatus = 127 << 8;
        }
        int msg[2] = {wstatus, killed};
        (void)!::write(status_pipe[1], msg, sizeof msg);
        ::_exit(0);
    }
    ::setpgid(sup, sup);
    if (forked) forked();
    ::close(devnull);
    ::close(out_pipe[1]);
    ::close(verdict_pipe[1]);
    ::close(status_pipe[1]);
    ::close(ctrl_pipe[0]);

    const auto deadline = t0 + std::chrono::duration<double>(timeout_s);
    const auto hard_deadline = deadline + std::chrono::seconds(15);
    bool out_open = true, verdict_open = true, status_open = true, asked = false;
    std::string status_bytes;
    auto ask_stop = [&] {
        if (!asked) (void)!::write(ctrl_pipe[1], "k", 1);
        asked = true;
    };
    while (out_open || verdict_open || status_open) {
        auto now = Clock::now();
        if (!asked && now >= deadline) {
            out.timed_out = true;
            ask_stop();
        }
        if (now >= hard_deadline) {  // the supervisor itself is stuck: kill it (its test dies with it)
            out.timed_out = true;
            ::kill(-sup, SIGKILL);
            break;
        }
        pollfd fds[3];
        int n = 0;
        if (out_open) fds[n++] = {out_pipe[0], POLLIN, 0};
        if (verdict_open) fds[n++] = {verdict_pipe[0], POLLIN, 0};
        if (status_open) fds[n++] = {status_pipe[0], POLLIN, 0};
        ::poll(fds, static_cast<nfds_t>(n), 20);
        for (int i = 0; i < n; ++i) {
            if (!(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            bool over = false;
            if (fds[i].fd == out_pipe[0]) {
                out_open = drain(out_pipe[0], out.output, opt.output_cap, over);
                if (over && !out.flooded) {
                    out.flooded = true;
                    ask_stop();
                }
            } else if (fds[i].fd == verdict_pipe[0]) {
                verdict_open = drain(verdict_pipe[0], out.verdict, 1 << 20, over);
            } else {
                status_open = drain(status_pipe[0], status_bytes, 64, over);
            }
        }
    }
    int sup_status = 0;
    ::waitpid(sup, &sup_status, 0);
    ::close(out_pipe[0]);
    ::close(verdict_pipe[0]);
    ::close(status_pipe[0]);
    ::close(ctrl_pipe[1]);
    if (!workdir.empty()) {
        if (sb.collect) sb.collect(workdir);
        // The pictures the test drew in its folder: regular PNG files only, moved to the figure folder.
        if (!opt.figure_dir.empty()) {
            std::error_code ec;
            for (const auto& e : std::filesystem::directory_iterator(workdir, ec)) {
                if (e.path().extension() != ".png" || !e.is_regular_file(ec) || e.is_symlink(ec)) continue;
                if (e.file_size(ec) > (16u << 20)) continue;
                std::filesystem::copy_file(e.path(), opt.figure_dir / e.path().filename(),
                                           std::filesystem::copy_options::overwrite_existing, ec);
            }
        }
        std::error_code ec;
        std::filesystem::remove_all(workdir, ec);
    }
    out.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    int wstatus = SIGKILL;  // no report from the supervisor: treat as killed
    if (status_bytes.size() >= 2 * sizeof(int)) std::memcpy(&wstatus, status_bytes.data(), sizeof(int));
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
    for (const auto& f : j.value("figures", std::vector<std::string>{}))
        if (!opt.figure_dir.empty()) {
            const auto moved = opt.figure_dir / std::filesystem::path(f).filename();
            if (std::filesystem::exists(moved)) r.figures.push_back(moved.string());
        }
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
    ChildOutcome c = run_child({program.string(), "--geolab-list"}, random_token(), 60, opt, opt.memory_mb);
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
        // By task ("Task 2" before "Task 10"), visible before hidden, then in file order.
        auto task_number = [](const std::string& suite) {
            auto d = suite.find_first_of("0123456789");
            return d == std::string::npos ? 0 : std::atoi(suite.c_str() + d);
        };
        const int ta = task_number(a.suite), tb = task_number(b.suite);
        return std::tie(ta, a.suite, a.hidden, a.file, a.line) < std::tie(tb, b.suite, b.hidden, b.file, b.line);
    });
    return tests;
}

namespace {

// The judge's options: the same limits, its own uid and no network, but nothing hidden (it is the course's own
// program, in the build's bin/, and holds no student code); only the judge attaches pictures.
RunOptions judge_options(const RunOptions& opt) {
    RunOptions j = opt;
    j.sandbox.hide.clear();
    j.sandbox.prepare = nullptr;
    j.sandbox.collect = nullptr;
    return j;
}

// Record and replay: the performer runs the test with the student's code and records into the judge, which
// replays it and decides. Two children at once, joined by two pipes: record (performer -> judge) and go
// (judge -> performer, for timed calls).
TestResult run_replayed(const std::filesystem::path& program, const TestInfo& test, const RunOptions& opt) {
    TestResult r;
    r.info = test;
    const std::string token = random_token();
    const double limit = test.timeout_s > 0 ? test.timeout_s : opt.timeout_s;
    int record[2], go[2];
    if (::pipe2(record, O_CLOEXEC) != 0) throw std::runtime_error("grader: pipe failed");
    if (::pipe2(go, O_CLOEXEC) != 0) {
        ::close(record[0]);
        ::close(record[1]);
        throw std::runtime_error("grader: pipe failed");
    }
    // The grader's copies close once both supervisors hold theirs: then EOF on either pipe means a side is gone.
    std::mutex m;
    int forked = 0;
    bool closed = false;
    auto close_ours = [&] {
        std::lock_guard lock(m);
        if (closed) return;
        closed = true;
        for (int fd : {record[0], record[1], go[0], go[1]}) ::close(fd);
    };
    auto one_forked = [&] {
        bool both;
        {
            std::lock_guard lock(m);
            both = ++forked == 2;
        }
        if (both) close_ours();
    };
    RunOptions perf_opt = opt;
    perf_opt.figure_dir.clear();  // pictures come from the judge
    const RunOptions judge_opt = judge_options(opt);
    ChildOutcome perf, judge;
    std::exception_ptr perf_error;
    std::thread performer_thread([&] {
        try {
            perf = run_child({program.string(), "--geolab-record", test.name}, "", limit, perf_opt, opt.memory_mb,
                             {record[1], go[0]}, one_forked);
        } catch (...) {
            perf_error = std::current_exception();
        }
    });
    try {
        // The judge waits for the performer; its own limit covers the performer's and some replay time.
        judge = run_child({opt.judge.string(), "--geolab-replay", test.name, "--geolab-record-fd", "3",
                           "--geolab-go-fd", "4"},
                          token, 2 * limit + 10, judge_opt, opt.memory_mb, {record[0], go[1]}, one_forked);
    } catch (...) {
        close_ours();
        performer_thread.join();
        throw;
    }
    performer_thread.join();
    close_ours();
    if (perf_error) std::rethrow_exception(perf_error);

    classify(judge, token, r, opt);
    r.output = perf.output;  // what the student's program printed
    r.seconds = perf.seconds;
    // Where the judge stopped, to name the call the student's program was in.
    std::string stopped, where;
    if (auto pos = judge.verdict.find(token + " "); pos != std::string::npos) {
        auto j = nlohmann::json::parse(judge.verdict.substr(pos + token.size() + 1), nullptr, false);
        if (!j.is_discarded() && j.is_object()) {
            stopped = j.value("stopped", "");
            const auto calls = j.value("calls", 0u);
            const std::string fn = j.value("last_function", "");
            where = calls == 0 ? std::string(" before its first call into your code")
                               : " in or after call " + std::to_string(calls) + " (" + fn + ")";
            if (!test.suite.empty()) where += ", in '" + test.suite + "'";
        }
    }
    auto override_with = [&](Status s, const std::string& why) {
        r.status = s;
        r.score = 0;
        r.messages.insert(r.messages.begin(), why);
    };
    if (perf.timed_out)
        override_with(Status::timeout, "killed after the time limit" + where + ": an infinite loop, or far too slow?");
    else if (perf.flooded)
        override_with(Status::error, "killed: printed more than " + std::to_string(opt.output_cap) + " bytes");
    else if (perf.signal && stopped == "eof") {
        std::string m = "crashed with " + signal_name(perf.signal) + where;
        if (perf.signal == SIGXCPU) m += ": CPU time limit";
        if (perf.signal == SIGXFSZ) m += ": wrote a file larger than the limit";
        override_with(Status::crashed, m);
    } else if (stopped == "eof") {
        std::string m = "the test program exited (status " + std::to_string(perf.exit_code) + ")" + where +
                        ", before the test finished: does the code call exit(), or abort?";
        if (perf.exit_code == 127 && perf.output.find("cannot execute") != std::string::npos)
            m = "the test program could not be started";
        if (perf.output.find("std::bad_alloc") != std::string::npos) m += " (ran out of memory)";
        override_with(Status::error, m);
    } else if (judge.signal || (judge.verdict.empty() && !judge.timed_out)) {
        // No verdict from the judge: it stopped on the answers it was given (an index out of range aborts it).
        override_with(Status::failed, "the test stopped on your code's answers" + where +
                                          " (the judge, which replays them, " +
                                          (judge.signal ? "was killed by " + signal_name(judge.signal) : std::string("exited")) +
                                          "): an index or size out of range?");
    }
    return r;
}

}  // namespace

TestResult run_test(const std::filesystem::path& program, const TestInfo& test, const RunOptions& opt) {
    if (!opt.judge.empty()) return run_replayed(program, test, opt);
    TestResult r;
    r.info = test;
    const std::string token = random_token();
    const double limit = test.timeout_s > 0 ? test.timeout_s : opt.timeout_s;
    ChildOutcome c = run_child({program.string(), "--geolab-run", test.name}, token, limit, opt, opt.memory_mb);
    classify(c, token, r, opt);
    return r;
}

bool can_drop_privileges() { return ::geteuid() == 0; }

CommandResult run_command(const std::vector<std::string>& argv, double timeout_s, const RunOptions& opt) {
    ChildOutcome c = run_child(argv, "", timeout_s, opt, opt.memory_mb);
    CommandResult r;
    r.output = c.output;
    r.seconds = c.seconds;
    r.timed_out = c.timed_out;
    r.exit_code = c.exited && !c.timed_out && !c.flooded ? c.exit_code : -1;
    if (c.signal) r.output += "\n(killed by " + signal_name(c.signal) + ")";
    if (c.timed_out) r.output += "\n(killed after " + std::to_string(static_cast<int>(timeout_s)) + " s)";
    return r;
}

LabReport grade_program(const std::string& lab, const std::string& variant, const std::filesystem::path& program,
                        const RunOptions& opt) {
    LabReport report;
    report.lab = lab;
    report.variant = variant;
    auto t0 = Clock::now();
    std::vector<TestInfo> tests;
    report.isolated = !opt.judge.empty();
    try {
        tests = opt.judge.empty() ? list_tests(program, opt) : list_tests(opt.judge, judge_options(opt));
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
