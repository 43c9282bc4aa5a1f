#pragma once
//! \file grading/runner.hpp
//! The grader: runs every test case of a test program in its own child process, with a hard wall-clock timeout
//! (the whole process group is killed), a memory cap, a file-size cap and an output cap. The child reports its
//! verdict through a private pipe, prefixed by a per-run random token; the parent alone decides the outcome.
#include <chrono>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <functional>
#include <string>
#include <vector>

namespace geolab::grading {

//! How one test case ended, as the parent saw it.
enum class Status {
    passed,           //!< the verdict line said passed
    failed,           //!< an assertion failed or an unexpected exception escaped
    not_implemented,  //!< failed, and a geolab::NotImplemented was thrown (an untouched stub)
    crashed,          //!< killed by a signal (SIGSEGV, SIGABRT, ...)
    timeout,          //!< ran past its wall-clock limit and was killed
    error,            //!< exited early, flooded its output, or broke the protocol
};
const char* to_string(Status s);

//! One test case as the test program lists it (see grading/test.hpp for the decorators).
struct TestInfo {
    std::string name, suite, file;
    int line = 0;
    double points = 0;
    bool hidden = false;
    std::string hint;
    double timeout_s = 0;  //!< 0: RunOptions::timeout_s
    //! The tasks this test may depend on besides its own, by declaration (grading/chain.hpp): "Task 2, Task 3",
    //! "*" for a whole-chain test, "" for none. Only the independence check reads it.
    std::string builds_on;
};

//! The outcome of one test case.
struct TestResult {
    TestInfo info;
    Status status = Status::error;
    double score = 0;
    std::vector<std::string> messages;  //!< failure messages (assertions, exceptions, the reason for crashes)
    std::string output;                 //!< what the test printed (stdout + stderr), capped
    std::vector<std::string> figures;   //!< pictures the test attached (paths, see attach_mesh_figure)
    double seconds = 0;
};

//! Extra isolation for untrusted code (grading a submission). The uid, the allow-list file system and the
//! network namespace need root (CAP_SYS_ADMIN); the per-test supervisor, the time, memory, output and process
//! limits work for everyone. With `require_isolation`, a part that cannot be set up throws SandboxError
//! (fail closed); without it, that part is skipped and `isolation_problem()` says what is missing.
struct Sandbox {
    bool drop_privileges = false;  //!< when root: run each test as its own unused uid/gid (see uid_pool_*)
    unsigned uid_pool_first = 61000;  //!< uids leased to running tests, one per running test (flock'ed)
    unsigned uid_pool_size = 512;
    //! The lease folder: must be a real folder owned by root and writable by root only, or no uid is leased.
    std::filesystem::path uid_dir = "/tmp/geolab-sandbox-uids";
    std::size_t max_processes = 64;  //!< RLIMIT_NPROC of a test run as its own uid (threads count too)
    bool no_network = true;          //!< unshare(CLONE_NEWNET) in the child (ignored when not permitted)
    std::vector<std::filesystem::path> hide;  //!< folders made empty for the test (tmpfs in a mount namespace)
    //! The allow-list file system (root only). When true the child runs in a new mount namespace whose root is
    //! built from nothing: the system's own folders (/usr, /bin, /lib*, a few files of /etc, /dev/null and its
    //! kind, /proc with other users' processes hidden), `visible` read-only, its working folder read-write, and
    //! private, empty /tmp, /var/tmp and /dev/shm. Nothing else of the host exists for it.
    bool allow_list = false;
    std::vector<std::filesystem::path> visible;  //!< folders or files shown read-only (symbolic links followed)
    bool clean_env = false;           //!< the child's environment: an allow-list (PATH, LANG, LC_*, TZ) + ours
    bool require_isolation = false;   //!< fail closed: throw SandboxError when a part cannot be set up
    std::filesystem::path workdir;            //!< the test's working folder (a fresh folder per test under it)
    //! Called with the fresh working folder (already owned by the test's uid) before the child starts, and
    //! after it ended, before the folder is removed: to put inputs in and take outputs out.
    std::function<void(const std::filesystem::path& dir, unsigned uid)> prepare;
    std::function<void(const std::filesystem::path& dir)> collect;
};

//! The sandbox could not be set up as `Sandbox::require_isolation` demands: nothing untrusted was run.
struct SandboxError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

//! Limits and parallelism of a grading run.
struct RunOptions {
    double timeout_s = 20;                      //!< default wall-clock limit per test
    std::size_t memory_mb = 4096;               //!< address-space cap per test process (RLIMIT_AS)
    std::size_t output_cap = 1 << 20;           //!< bytes of output before the test is killed
    std::size_t file_size_mb = 256;             //!< largest file a test may write (RLIMIT_FSIZE)
    int jobs = 2;                               //!< tests run at once
    Sandbox sandbox;                            //!< extra isolation for untrusted code
    std::vector<std::string> env;               //!< extra NAME=value entries for the test's environment
    //! Where tests' pictures go (attach_mesh_figure). Non-empty: each test gets GEOLAB_FIGURE_DIR (its own
    //! working folder when sandboxed) and its PNGs are moved here; TestResult::figures names them.
    std::filesystem::path figure_dir;
    std::function<void(const TestResult&, std::size_t done, std::size_t total)> on_result;  //!< progress
    //! A wall-clock cap shared by every child run with these options (e.g. a whole submission): a child is cut
    //! at the deadline, and after it nothing more starts (outcome: timed out). Unset: no cap.
    std::optional<std::chrono::steady_clock::time_point> deadline;
    //! The lab's judge (judge_NN_name: its tests, given code and the replayer, no student code). Non-empty: the
    //! tests, points, flags and limits come from the judge's listing, and each test's verdict from the judge
    //! replaying what the program (the performer) recorded. Empty: the program lists and judges itself, and the
    //! report says "verdict not isolated".
    std::filesystem::path judge;
    //! Non-empty: run only this test (its exact name, or the one test whose name contains it); no test or
    //! several matching is an error that lists the names.
    std::string only_test;
};

//! What grading one test program produced.
struct LabReport {
    std::string lab;      //!< e.g. "01_halfedge"
    std::string variant;  //!< "student" or "solution"
    std::vector<TestResult> results;
    std::string error;  //!< non-empty when the program could not be listed (then results is empty)
    bool isolated = false;  //!< the verdicts came from the judge (record and replay), not from the program
    double seconds = 0;
    double score() const;
    double max_score() const;
};

//! What one sandboxed command (a compiler, a linker) did.
struct CommandResult {
    int exit_code = -1;  //!< -1: killed (signal or time limit)
    bool timed_out = false;
    std::string output;  //!< stdout + stderr, capped
    double seconds = 0;
};

//! Run `argv` (argv[0] an absolute path) in a child with the limits and sandbox of `opt` and a wall-clock
//! limit; the whole process tree is killed at the end. Used for compiling untrusted code.
CommandResult run_command(const std::vector<std::string>& argv, double timeout_s, const RunOptions& opt);

//! Whether this process can drop privileges for tests (it runs as root).
bool can_drop_privileges();

//! What of `sb` cannot be set up here, in one sentence (empty: everything it asks for works). Tries it: leases
//! a uid and runs /bin/true in the full sandbox. Never throws.
std::string isolation_problem(const Sandbox& sb);

//! The test cases of `program` (runs `program --geolab-list` in a child with the same limits). Pass the judge
//! when there is one: a program with student code in it is never asked.
//! \throw std::runtime_error naming the program and the reason if it cannot be listed.
std::vector<TestInfo> list_tests(const std::filesystem::path& program, const RunOptions& opt);

//! Run one test case in a fresh child process and classify the outcome. With opt.judge: the program records
//! (--geolab-record) into the judge (--geolab-replay), both children at once, and the outcome combines what the
//! grader saw of the program (crash, time limit, output cap) with the judge's verdict.
TestResult run_test(const std::filesystem::path& program, const TestInfo& test, const RunOptions& opt);

//! List and run every test case of `program`, `opt.jobs` at a time; results in listing order.
LabReport grade_program(const std::string& lab, const std::string& variant, const std::filesystem::path& program,
                        const RunOptions& opt);

}  // namespace geolab::grading
