#include "geolab/grading/runner.hpp"

#include <atomic>
#include <chrono>
#include <cerrno>
#include <cstdlib>
#include <csignal>
#include <signal.h>
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
    bool stopped = false;  // ended by the caller's stop flag (not by its own doing)
    std::string sandbox_error;  // the sandbox could not be set up in the child (then the program never ran)
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

// Lease a uid; returns why not (empty: leased). The lease folder must be root's and writable by root only: a
// folder another user made first could hold lock files that user controls (fail closed, never run as root).
std::string lease_uid(const Sandbox& sb, UidLease& lease) {
    const std::string dir = sb.uid_dir.string();
    ::mkdir(dir.c_str(), 0755);
    struct stat st {};
    if (::lstat(dir.c_str(), &st) != 0) return dir + " cannot be made (" + std::strerror(errno) + ")";
    if (!S_ISDIR(st.st_mode)) return dir + " is not a folder (a symbolic link or a file put there by someone?)";
    if (st.st_uid != 0)
        return dir + " is owned by uid " + std::to_string(st.st_uid) +
               ", not root: another user made it first; remove it (rm -rf " + dir + ") and grade again";
    if (st.st_mode & 022) return dir + " is writable by group or others; remove it (rm -rf " + dir + ") and grade again";
    static std::atomic<unsigned> start{0};
    const unsigned first = start++ % std::max(1u, sb.uid_pool_size);
    for (unsigned k = 0; k < sb.uid_pool_size; ++k) {
        const unsigned uid = sb.uid_pool_first + (first + k) % sb.uid_pool_size;
        if (::getpwuid(uid) != nullptr) continue;  // a real account: never borrow it
        const std::string path = dir + "/" + std::to_string(uid);
        int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0600);
        if (fd < 0) continue;
        struct stat fst {};
        if (::fstat(fd, &fst) != 0 || fst.st_uid != 0 || !S_ISREG(fst.st_mode)) {
            ::close(fd);
            continue;
        }
        if (::flock(fd, LOCK_EX | LOCK_NB) == 0) {
            lease.fd = fd;
            lease.uid = uid;
            return "";
        }
        ::close(fd);
    }
    return "every uid of " + std::to_string(sb.uid_pool_first) + "-" +
           std::to_string(sb.uid_pool_first + sb.uid_pool_size - 1) + " is in use";
}

// ---- the allow-list file system --------------------------------------------------------------------------
// Built before fork as a list of steps on absolute paths inside the new root; carried out in the child between
// fork and exec with plain system calls only (async-signal-safe). Every path keeps its host name inside.
struct MountStep {
    enum Kind { dir, file, link, bind_ro, bind_rw, bind_dev, tmpfs, proc } kind;
    std::string target;  // inside the new root (root + path)
    std::string source;  // host path (binds), link text (link), mount options (tmpfs)
};
struct MountPlan {
    std::string root;  // the new root's mount point on the host (an empty folder, root-only)
    std::vector<MountStep> steps;
    std::string cwd;   // the working folder (same name inside)
};

// The steps that make `path` (a host path) exist inside the plan: its missing parents as folders; a symbolic
// link as the same link, and its target too (so a link to the models folder keeps working).
void add_visible(MountPlan& plan, std::filesystem::path path, MountStep::Kind bind, int depth = 0) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (depth > 8 || path.empty() || !path.is_absolute()) return;
    path = path.lexically_normal();
    if (path.has_filename() == false && path != path.root_path()) path = path.parent_path();
    const fs::path parent = fs::weakly_canonical(path.parent_path(), ec);
    if (ec) return;
    path = parent / path.filename();
    const auto st = fs::symlink_status(path, ec);
    if (ec || !fs::exists(st)) return;
    for (fs::path p = parent; p != p.root_path(); p = p.parent_path())
        plan.steps.push_back({MountStep::dir, plan.root + p.string(), ""});
    if (fs::is_symlink(st)) {
        plan.steps.push_back({MountStep::link, plan.root + path.string(), fs::read_symlink(path, ec).string()});
        const fs::path target = fs::weakly_canonical(path, ec);
        if (!ec) add_visible(plan, target, bind, depth + 1);
        return;
    }
    plan.steps.push_back({fs::is_directory(st) ? MountStep::dir : MountStep::file, plan.root + path.string(), ""});
    plan.steps.push_back({bind, plan.root + path.string(), path.string()});
}

MountPlan make_plan(const std::string& root, const Sandbox& sb, const std::string& workdir) {
    MountPlan plan;
    plan.root = root;
    plan.cwd = workdir;
    // The system's own folders (merged /usr: /bin, /lib* are links into /usr) and the pieces of /etc that the
    // dynamic loader and the compiler driver read.
    for (const char* p : {"/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32", "/etc/alternatives",
                          "/etc/ld.so.cache", "/etc/ld.so.conf", "/etc/ld.so.conf.d", "/etc/localtime",
                          "/etc/passwd", "/etc/group", "/sys/devices/system/cpu"})
        add_visible(plan, p, MountStep::bind_ro);
    for (const char* p : {"/dev/null", "/dev/zero", "/dev/full", "/dev/random", "/dev/urandom"})
        add_visible(plan, p, MountStep::bind_dev);
    for (const auto& [name, to] : {std::pair{"/dev/fd", "/proc/self/fd"}, std::pair{"/dev/stdin", "/proc/self/fd/0"},
                                   std::pair{"/dev/stdout", "/proc/self/fd/1"}, std::pair{"/dev/stderr", "/proc/self/fd/2"}})
        plan.steps.push_back({MountStep::link, root + name, to});
    plan.steps.push_back({MountStep::dir, root + "/proc", ""});
    plan.steps.push_back({MountStep::proc, root + "/proc", ""});
    for (const char* p : {"/tmp", "/var", "/var/tmp", "/dev", "/dev/shm"}) plan.steps.push_back({MountStep::dir, root + p, ""});
    for (const char* p : {"/tmp", "/var/tmp", "/dev/shm"}) {
        plan.steps.push_back({MountStep::tmpfs, root + p, "size=256m,mode=1777"});
    }
    for (const auto& v : sb.visible) add_visible(plan, v, MountStep::bind_ro);
    if (!workdir.empty()) add_visible(plan, workdir, MountStep::bind_rw);
    // Parents before children; at one path: make it, then mount on it. Duplicates go.
    auto rank = [](MountStep::Kind k) { return k == MountStep::dir || k == MountStep::file || k == MountStep::link ? 0 : 1; };
    std::stable_sort(plan.steps.begin(), plan.steps.end(), [&](const MountStep& a, const MountStep& b) {
        const int ra = rank(a.kind), rb = rank(b.kind);
        return std::tie(a.target, ra) < std::tie(b.target, rb);
    });
    plan.steps.erase(std::unique(plan.steps.begin(), plan.steps.end(),
                                 [](const MountStep& a, const MountStep& b) {
                                     return a.target == b.target && a.kind == b.kind && a.source == b.source;
                                 }),
                     plan.steps.end());
    // What lies inside a folder already shown read-only is there already: no second mount, no mkdir.
    std::vector<MountStep> kept;
    std::vector<std::string> ro_roots;
    for (auto& st : plan.steps) {
        const bool under = std::any_of(ro_roots.begin(), ro_roots.end(), [&](const std::string& r) {
            return st.target.size() > r.size() && st.target.compare(0, r.size(), r) == 0 && st.target[r.size()] == '/';
        });
        if (under && st.kind != MountStep::bind_rw && st.kind != MountStep::tmpfs && st.kind != MountStep::proc) continue;
        if (st.kind == MountStep::bind_ro) ro_roots.push_back(st.target);
        kept.push_back(std::move(st));
    }
    plan.steps = std::move(kept);
    return plan;
}

// Async-signal-safe: carry out the plan in a fresh mount namespace and make its root ours. Returns 0, or the
// number of the step that failed (errno set).
int enter_plan(const MountPlan& plan) {
    if (::unshare(CLONE_NEWNS) != 0) return 1;
    if (::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0) return 2;
    if (::mount("tmpfs", plan.root.c_str(), "tmpfs", MS_NOSUID | MS_NODEV, "size=1m,mode=0755") != 0) return 3;
    const unsigned long ro = MS_REMOUNT | MS_BIND | MS_RDONLY | MS_NOSUID | MS_NODEV;
    for (const auto& s : plan.steps) {
        const char* t = s.target.c_str();
        switch (s.kind) {
            case MountStep::dir:
                if (::mkdir(t, 0755) != 0 && errno != EEXIST && errno != EROFS) return 10;
                break;
            case MountStep::file: {
                int fd = ::open(t, O_WRONLY | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
                if (fd < 0 && errno != EEXIST && errno != EROFS && errno != EACCES) return 11;
                if (fd >= 0) ::close(fd);
                break;
            }
            case MountStep::link:
                if (::symlink(s.source.c_str(), t) != 0 && errno != EEXIST) return 12;
                break;
            case MountStep::bind_ro:
            case MountStep::bind_rw:
            case MountStep::bind_dev:
                if (::mount(s.source.c_str(), t, nullptr, MS_BIND | MS_REC, nullptr) != 0) return 13;
                if (s.kind == MountStep::bind_ro && ::mount(nullptr, t, nullptr, ro, nullptr) != 0 &&
                    ::mount(nullptr, t, nullptr, MS_REMOUNT | MS_BIND | MS_RDONLY, nullptr) != 0)
                    return 14;
                if (s.kind == MountStep::bind_rw &&
                    ::mount(nullptr, t, nullptr, MS_REMOUNT | MS_BIND | MS_NOSUID | MS_NODEV, nullptr) != 0 &&
                    ::mount(nullptr, t, nullptr, MS_REMOUNT | MS_BIND, nullptr) != 0)
                    return 15;
                if (s.kind == MountStep::bind_dev &&
                    ::mount(nullptr, t, nullptr, MS_REMOUNT | MS_BIND | MS_NOSUID, nullptr) != 0 &&
                    ::mount(nullptr, t, nullptr, MS_REMOUNT | MS_BIND, nullptr) != 0)
                    return 16;
                break;
            case MountStep::tmpfs:
                if (::mount("tmpfs", t, "tmpfs", MS_NOSUID | MS_NODEV, s.source.c_str()) != 0) return 17;
                break;
            case MountStep::proc:
                // A proc of our own that hides other users' processes; where that is refused (a container
                // that masks parts of /proc), the host's, read-only (other uids' details stay unreadable).
                if (::mount("proc", t, "proc", MS_NOSUID | MS_NODEV | MS_NOEXEC, "hidepid=2") != 0 &&
                    (::mount("/proc", t, nullptr, MS_BIND | MS_REC, nullptr) != 0 ||
                     ::mount(nullptr, t, nullptr, ro | MS_NOEXEC, nullptr) != 0))
                    return 18;
                break;
        }
    }
    if (::chdir(plan.root.c_str()) != 0) return 20;
    if (::syscall(SYS_pivot_root, ".", ".") == 0) {
        if (::umount2(".", MNT_DETACH) != 0) return 21;
    } else if (::chroot(".") != 0) {
        return 22;
    }
    if (::chdir("/") != 0) return 23;
    if (::mount(nullptr, "/", nullptr, MS_REMOUNT | MS_RDONLY | MS_NOSUID | MS_NODEV, nullptr) != 0) return 24;
    if (!plan.cwd.empty() && ::chdir(plan.cwd.c_str()) != 0) return 25;
    return 0;
}

const char* plan_step_name(int step) {
    switch (step) {
        case 1: return "unshare(CLONE_NEWNS)";
        case 2: return "making / private";
        case 3: return "the new root's tmpfs";
        case 10: case 11: case 12: return "a mount point in the new root";
        case 13: return "a bind mount";
        case 14: case 15: case 16: return "remounting a bind mount";
        case 17: return "a private tmpfs (/tmp, /var/tmp, /dev/shm)";
        case 18: return "mounting /proc";
        case 20: case 23: case 25: return "chdir";
        case 21: case 22: return "pivot_root/chroot";
        case 24: return "making the new root read-only";
        case 30: return "unshare(CLONE_NEWNET)";
        case 31: return "dropping privileges";
    }
    return "setting up the sandbox";
}

// The child's environment when it is untrusted: only what a program needs to run, never the grader's own.
bool env_allowed(const char* e) {
    for (const char* name : {"LANG=", "LANGUAGE=", "TZ=", "TERM="})
        if (std::strncmp(e, name, std::strlen(name)) == 0) return true;
    return std::strncmp(e, "LC_", 3) == 0;
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

// write() to a pipe whose reader may be gone, without the grader dying of SIGPIPE: the signal is blocked in this
// thread for the write and a pending one is taken back (EPIPE is the answer then).
void write_without_sigpipe(int fd, const char* p, std::size_t n) {
    sigset_t pipe_set, old;
    sigemptyset(&pipe_set);
    sigaddset(&pipe_set, SIGPIPE);
    ::pthread_sigmask(SIG_BLOCK, &pipe_set, &old);
    const ssize_t w = ::write(fd, p, n);
    if (w < 0 && errno == EPIPE) {
        const timespec zero{0, 0};
        while (::sigtimedwait(&pipe_set, nullptr, &zero) > 0) {
        }
    }
    ::pthread_sigmask(SIG_SETMASK, &old, nullptr);
}

// Run argv under a supervisor with the limits of `opt`. `extra_fds` become the child's fds 3, 4, ... (record
// and replay pipes); the verdict pipe's write end follows them and is passed as GEOLAB_RESULT_FD together with
// GEOLAB_TOKEN=token (when token is non-empty). `forked` is called in the grader once the supervisor exists.
ChildOutcome run_child(const std::vector<std::string>& argv, const std::string& token, double timeout_s,
                       const RunOptions& opt, rlim_t memory_mb, const std::vector<int>& extra_fds = {},
                       const std::function<void()>& forked = {}, const std::atomic<bool>* stop = nullptr) {
    ChildOutcome out;
    const Sandbox& sb = opt.sandbox;
    const bool root = ::geteuid() == 0;
    // A whole run's wall-clock cap: nothing starts after it, nothing runs past it.
    if (opt.deadline) {
        const double left = std::chrono::duration<double>(*opt.deadline - Clock::now()).count();
        if (left <= 0) {
            out.timed_out = true;
            out.started = false;
            return out;
        }
        timeout_s = std::min(timeout_s, left);
    }
    // Fail closed: isolation that was asked for and cannot be had means nothing runs.
    UidLease lease;
    bool drop = false;
    if (sb.drop_privileges && root) {
        const std::string why = lease_uid(sb, lease);
        drop = why.empty();
        if (!drop && sb.require_isolation) throw SandboxError("no sandbox uid can be leased: " + why);
    }
    if (sb.require_isolation && !root)
        throw SandboxError("the grader does not run as root: it can give tests neither a uid nor a file system of their own");
    const bool use_plan = sb.allow_list && root;
    // The test's own working folder (owned by the test's uid), removed afterwards; next to it, the mount point
    // of its allow-list root.
    std::string workdir, newroot;
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
    if (use_plan) {
        std::string tmpl = ((sb.workdir.empty() ? std::filesystem::path("/tmp") : sb.workdir) / "root-XXXXXX").string();
        if (::mkdtemp(tmpl.data())) newroot = tmpl;
        else if (sb.require_isolation) throw SandboxError("cannot make the sandbox's root folder in " + sb.workdir.string());
    }
    MountPlan plan;
    if (!newroot.empty()) plan = make_plan(newroot, sb, workdir);
    int out_pipe[2], verdict_pipe[2], status_pipe[2], ctrl_pipe[2], setup_pipe[2];
    if (::pipe2(out_pipe, O_CLOEXEC) != 0) throw std::runtime_error("grader: pipe failed");
    if (::pipe2(verdict_pipe, O_CLOEXEC) != 0 || ::pipe2(status_pipe, O_CLOEXEC) != 0 ||
        ::pipe2(ctrl_pipe, O_CLOEXEC) != 0 || ::pipe2(setup_pipe, O_CLOEXEC) != 0)
        throw std::runtime_error("grader: pipe failed");
    // Everything the children need is prepared before fork: after fork only async-signal-safe calls.
    std::vector<std::string> env_strings;
    if (sb.clean_env) env_strings.emplace_back("PATH=/usr/local/bin:/usr/bin:/bin");
    for (char** e = environ; *e; ++e) {
        if (std::strncmp(*e, "GEOLAB_TOKEN=", 13) == 0 || std::strncmp(*e, "GEOLAB_RESULT_FD=", 17) == 0) continue;
        if (!workdir.empty() && (std::strncmp(*e, "TMPDIR=", 7) == 0 || std::strncmp(*e, "HOME=", 5) == 0)) continue;
        if (sb.clean_env && !env_allowed(*e)) continue;
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
    if (root && newroot.empty())
        for (const auto& h : sb.hide)
            if (std::filesystem::is_directory(h)) hide.push_back(h.string());
    const rlim_t mem = memory_mb << 20;
    const rlim_t fsize = static_cast<rlim_t>(opt.file_size_mb) << 20;
    const rlim_t cpu = static_cast<rlim_t>(timeout_s) + 2;
    const rlim_t nproc = static_cast<rlim_t>(sb.max_processes);
    const unsigned uid = drop ? lease.uid : 0;
    const bool no_network = sb.no_network && root;
    const bool strict = sb.require_isolation;
    const MountPlan* plan_ptr = newroot.empty() ? nullptr : &plan;
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
        int keep[11] = {devnull,  out_pipe[1], verdict_pipe[1], status_pipe[1], ctrl_pipe[0], setup_pipe[0],
                        setup_pipe[1], extra[0], extra[1], extra[2], extra[3]};
        for (int i = 1; i < 11; ++i)
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
            // A set-up step that fails is reported on the setup pipe (closed by exec: the program cannot write
            // there) and the program is never started.
            auto setup_failed = [&](int step) {
                int msg[2] = {step, errno};
                (void)!::write(setup_pipe[1], msg, sizeof msg);
                ::_exit(125);
            };
            ::setpgid(0, 0);
            if (no_network && ::unshare(CLONE_NEWNET) != 0 && strict) setup_failed(30);
            if (plan_ptr) {
                if (int step = enter_plan(*plan_ptr)) setup_failed(step);
            } else if (!hide.empty() && ::unshare(CLONE_NEWNS) == 0) {
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
            if (uid && (::setgroups(0, nullptr) != 0 || ::setgid(uid) != 0 || ::setuid(uid) != 0)) setup_failed(31);
            ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // after setuid, which clears it
            ::execve(args[0], args.data(), envp.data());
            const char msg[] = "grader: cannot execute the test program\n";
            (void)!::write(2, msg, sizeof msg - 1);
            ::_exit(127);
        }
        // The supervisor keeps no end of the output and verdict pipes: EOF there means every writer is gone.
        ::close(out_pipe[1]);
        ::close(verdict_pipe[1]);
        ::close(setup_pipe[1]);
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
        int msg[4] = {wstatus, killed, 0, 0};
        {
            int setup[2] = {0, 0};
            const int fl = ::fcntl(setup_pipe[0], F_GETFL);
            ::fcntl(setup_pipe[0], F_SETFL, fl | O_NONBLOCK);
            if (::read(setup_pipe[0], setup, sizeof setup) == static_cast<ssize_t>(sizeof setup)) {
                msg[2] = setup[0];
                msg[3] = setup[1];
            }
        }
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
    ::close(setup_pipe[0]);
    ::close(setup_pipe[1]);

    const auto deadline = t0 + std::chrono::duration<double>(timeout_s);
    const auto hard_deadline = deadline + std::chrono::seconds(15);
    bool out_open = true, verdict_open = true, status_open = true, asked = false;
    std::string status_bytes;
    auto ask_stop = [&] {
        if (!asked) write_without_sigpipe(ctrl_pipe[1], "k", 1);  // the supervisor may have ended already
        asked = true;
    };
    while (out_open || verdict_open || status_open) {
        auto now = Clock::now();
        if (!asked && now >= deadline) {
            out.timed_out = true;
            ask_stop();
        }
        if (!asked && stop && stop->load()) {
            out.stopped = true;  // the caller has what it needs (record and replay: the judge's verdict)
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
    if (!newroot.empty()) ::rmdir(newroot.c_str());  // only ever a mount point inside the child's namespace
    out.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    int wstatus = SIGKILL;  // no report from the supervisor: treat as killed
    if (status_bytes.size() >= 2 * sizeof(int)) std::memcpy(&wstatus, status_bytes.data(), sizeof(int));
    if (status_bytes.size() >= 4 * sizeof(int)) {
        int step = 0, err = 0;
        std::memcpy(&step, status_bytes.data() + 2 * sizeof(int), sizeof(int));
        std::memcpy(&err, status_bytes.data() + 3 * sizeof(int), sizeof(int));
        if (step) {
            out.sandbox_error = std::string("the sandbox could not be set up: ") + plan_step_name(step) + " failed (" +
                                std::strerror(err) + ")";
            if (strict) throw SandboxError(out.sandbox_error);
        }
    }
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

// A test's time limit, e.g. "20 s".
std::string seconds_text(const TestInfo& t, const RunOptions& opt) {
    std::ostringstream os;
    os << (t.timeout_s > 0 ? t.timeout_s : opt.timeout_s) << " s";
    return os.str();
}

// What an allocation that failed means under the grader's address-space cap.
std::string memory_message(const RunOptions& opt) {
    const std::string limit = opt.memory_mb ? "memory limit (" + std::to_string(opt.memory_mb) + " MiB) exceeded"
                                            : std::string("out of memory");
    return limit + " (std::bad_alloc)";
}
const char* memory_cause = ": a loop that never ends while it collects (an endless walk), or a far too large allocation?";

// The test's own report of a crash (test_main.cpp prints it when no judge watches): "input: ..." and "last check
// passed: ..." lines after "geolab: crashed with". Text only; the status comes from the signal the grader saw.
std::string crash_note(const std::string& output) {
    const auto pos = output.find("geolab: crashed with");
    if (pos == std::string::npos) return "";
    const auto body = output.find('\n', pos);
    if (body == std::string::npos) return "";
    std::string note = output.substr(body + 1, 2000);
    while (!note.empty() && note.back() == '\n') note.pop_back();
    return note.empty() ? "" : "\n" + note;
}

// The non-empty lines of `text`, joined by newlines.
std::string lines_of(const std::string& text) {
    std::string out;
    for (std::size_t a = 0, b; a < text.size(); a = b + 1) {
        b = text.find('\n', a);
        if (b == std::string::npos) b = text.size();
        if (b > a) out += (out.empty() ? "" : "\n") + text.substr(a, b - a);
    }
    return out;
}

// Replace the first message that reports a std::bad_alloc by what it means here; its contexts become "input:".
void name_memory_limit(TestResult& r, const RunOptions& opt, const std::string& where, const std::string& extra = "") {
    for (auto& m : r.messages)
        if (m.find("std::bad_alloc") != std::string::npos) {
            const auto nl = m.find('\n');
            const std::string input = nl == std::string::npos ? "" : lines_of(m.substr(nl + 1));
            m = memory_message(opt) + where + memory_cause + (input.empty() ? "" : "\ninput: " + input) + extra;
            return;
        }
    r.messages.insert(r.messages.begin(), memory_message(opt) + where + memory_cause + extra);
}

// Decide the status of a finished child from what the parent saw.
void classify(const ChildOutcome& c, const std::string& token, TestResult& r, const RunOptions& opt) {
    r.seconds = c.seconds;
    r.output = c.output;
    auto fail = [&](Status s, std::string why) {
        r.status = s;
        r.messages.push_back(std::move(why));
    };
    if (c.timed_out) return fail(Status::timeout, "killed after the time limit (" + seconds_text(r.info, opt) +
                                                     "): an endless loop (a walk that never gets back to its start?), or far too slow?");
    if (c.flooded)
        return fail(Status::error, "killed: printed more than " + std::to_string(opt.output_cap) + " bytes");
    if (c.signal) {
        std::string m = "crashed with " + signal_name(c.signal);
        if (c.signal == SIGXCPU) m += ": CPU time limit";
        if (c.signal == SIGXFSZ) m += ": wrote a file larger than the limit";
        if (c.signal == SIGABRT && c.output.find("std::bad_alloc") != std::string::npos) m += ": " + memory_message(opt);
        return fail(Status::crashed, m + crash_note(c.output));
    }
    // The verdict: exactly one line "<token> <json>".
    const std::string prefix = token + " ";
    auto pos = c.verdict.find(prefix);
    if (pos == std::string::npos) {
        std::string m = "the test program exited (status " + std::to_string(c.exit_code) +
                        ") before the test finished: does the code call exit(), or abort?";
        if (c.exit_code == 127 && c.output.find("cannot execute") != std::string::npos)
            m = "the test program could not be started";
        if (c.output.find("std::bad_alloc") != std::string::npos) m += " (" + memory_message(opt) + ")";
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
        if (j.value("out_of_memory", false) && r.status == Status::failed && opt.judge.empty())
            name_memory_limit(r, opt, "");
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
        t.builds_on = j.value("builds_on", "");
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
    if (j.sandbox.allow_list) j.sandbox.visible.push_back(opt.judge);  // its own program, read-only
    return j;
}

// True when the judge's verdict (the line with the run's token) says it did not stop at the end of the recording
// ("stopped" is not "eof"): then it decided from what the performer sent, and the performer's fate changes nothing.
bool verdict_without_eof(const std::string& verdict, const std::string& token) {
    const auto pos = verdict.find(token + " ");
    if (pos == std::string::npos) return false;
    const auto j = nlohmann::json::parse(verdict.substr(pos + token.size() + 1), nullptr, false);
    return !j.is_discarded() && j.is_object() && j.value("stopped", "") != "eof";
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
    // Once the judge has decided from a recording that did not end early (a wrong or malformed answer, or the end of
    // the test), the rest of the performer's run can change nothing: it is stopped instead of running the test on.
    std::atomic<bool> judge_decided{false};
    std::thread performer_thread([&] {
        try {
            perf = run_child({program.string(), "--geolab-record", test.name}, "", limit, perf_opt, opt.memory_mb,
                             {record[1], go[0]}, one_forked, &judge_decided);
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
        judge_decided = true;
        performer_thread.join();
        throw;
    }
    if (verdict_without_eof(judge.verdict, token)) judge_decided = true;
    performer_thread.join();
    close_ours();
    if (perf_error) std::rethrow_exception(perf_error);

    classify(judge, token, r, opt);
    r.output = perf.output;  // what the student's program printed
    r.seconds = perf.seconds;
    // Where the judge stopped, to name the call the student's program was in.
    std::string stopped, where, input, last_check;
    bool out_of_memory = false;
    if (auto pos = judge.verdict.find(token + " "); pos != std::string::npos) {
        auto j = nlohmann::json::parse(judge.verdict.substr(pos + token.size() + 1), nullptr, false);
        if (!j.is_discarded() && j.is_object()) {
            stopped = j.value("stopped", "");
            input = j.value("input", "");
            last_check = j.value("last_check", "");
            out_of_memory = j.value("out_of_memory", false);
            const auto calls = j.value("calls", 0u);
            const std::string fn = j.value("last_function", "");
            where = calls == 0 ? std::string(" before its first call into your code")
                               : " in or after call " + std::to_string(calls) + " (" + fn + ")";
            if (!test.suite.empty()) where += ", in '" + test.suite + "'";
        }
    }
    // The performer stopped (crash, time limit, exit): one message replaces the judge's "your program stopped":
    // what happened, where, the input the test was on (its INFO contexts: the fixture) and the last check passed.
    const std::string context = lines_of(input);  // the contexts, one per line
    const std::string found = (context.empty() ? "" : "\ninput: " + context) + (last_check.empty() ? "" : "\n" + last_check);
    auto override_with = [&](Status s, const std::string& why) {
        r.status = s;
        r.score = 0;
        if (stopped == "eof" && !r.messages.empty() && r.messages.back().rfind("your program stopped", 0) == 0) {
            r.messages.pop_back();  // the judge's note at the stop: said better below
            r.messages.insert(r.messages.begin(), why + found);
        } else {
            r.messages.insert(r.messages.begin(), why);
        }
    };
    if (out_of_memory && r.status == Status::failed && !perf.timed_out && !perf.signal) name_memory_limit(r, opt, where, last_check.empty() ? "" : "\n" + last_check);
    if (perf.timed_out)
        override_with(Status::timeout, "killed after the time limit (" + seconds_text(test, opt) + ")" + where +
                                            ": an endless loop (a walk that never gets back to its start?), or far too slow?");
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

std::string isolation_problem(const Sandbox& sb) {
    if (::geteuid() != 0)
        return "the grader does not run as root: tests get neither a uid nor a file system of their own";
    RunOptions o;
    o.sandbox = sb;
    o.sandbox.require_isolation = true;
    o.sandbox.prepare = nullptr;
    o.sandbox.collect = nullptr;
    o.memory_mb = 0;
    try {
        ChildOutcome c = run_child({"/bin/true"}, "", 30, o, 0);
        if (!c.exited || c.exit_code != 0)
            return "a trial run in the sandbox failed (exit status " + std::to_string(c.exit_code) + "): " + tail(c.output, 500);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

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
    if (!opt.only_test.empty()) {
        std::vector<TestInfo> picked;
        for (const auto& t : tests)
            if (t.name == opt.only_test) picked = {t};
        if (picked.empty())
            for (const auto& t : tests)
                if (t.name.find(opt.only_test) != std::string::npos) picked.push_back(t);
        if (picked.size() != 1) {
            report.error = (picked.empty() ? "no test of " + lab + " is named '" + opt.only_test + "'; its tests:"
                                           : "'" + opt.only_test + "' names " + std::to_string(picked.size()) +
                                                 " tests of " + lab + "; say which:");
            for (const auto& t : picked.empty() ? tests : picked) report.error += "\n  " + t.name;
            return report;
        }
        tests = picked;
    }
    report.results.resize(tests.size());
    std::atomic<std::size_t> next{0}, done{0};
    std::mutex progress_mutex;
    std::string failure;  // the sandbox failed (fail closed): no further test starts
    auto worker = [&] {
        for (std::size_t i; (i = next++) < tests.size();) {
            try {
                report.results[i] = run_test(program, tests[i], opt);
            } catch (const std::exception& e) {
                std::lock_guard lock(progress_mutex);
                if (failure.empty()) failure = e.what();
                next = tests.size();
                return;
            }
            std::lock_guard lock(progress_mutex);
            ++done;
            if (opt.on_result) opt.on_result(report.results[i], done, tests.size());
        }
    };
    std::vector<std::thread> pool;
    for (int j = 0; j < std::max(1, opt.jobs); ++j) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
    if (!failure.empty()) {
        report.error = failure;
        report.results.clear();
    }
    report.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return report;
}

}  // namespace geolab::grading
