// The main() of every geolab test program. Besides plain doctest use (developers run the binary directly), it
// speaks the grader's protocol (docs/architecture.md):
//   PROG --geolab-list            one JSON object per test case on stdout (name, suite, file, line, metadata);
//                                 the grader lists the judge, never a program with student code in it
//   PROG --geolab-run NAME        run exactly that test; the verdict goes to the pipe whose number is in
//                                 GEOLAB_RESULT_FD, prefixed by the per-run token from GEOLAB_TOKEN (a lab
//                                 without a boundary list: that verdict is not isolated from student code)
//   PERFORMER --geolab-record NAME   run that test with the student's code; every call across the lab's boundary
//                                 is recorded to fd 3; a timed call waits for the judge's go on fd 4. No verdict.
//   JUDGE --geolab-replay NAME [--geolab-record-fd N] [--geolab-go-fd M]
//                                 run that test against the recording (default stdin; no timed calls without a
//                                 go fd) and send the verdict as --geolab-run does.
// The grader trusts only the verdict line (with the right token), never stdout or the exit status.
#define DOCTEST_CONFIG_IMPLEMENT
#define DOCTEST_CONFIG_NO_POSIX_SIGNALS  // a crash must reach the grader as a signal, not a report
#include <doctest/doctest.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include <csignal>
#include <random>

#include <fcntl.h>
#include <sys/time.h>

#include "geolab/errors.hpp"
#include "geolab/grading/boundary_calls.hpp"
#include "geolab/grading/chain.hpp"
#include "geolab/grading/test.hpp"

namespace {

using nlohmann::json;

std::string g_token;
char g_token_buf[128] = {};  // constant-initialized: usable before any dynamic initialization
int g_result_fd = -1;
int g_seq_fd = -1;  // --geolab-run-seq: one verdict line per test, no token (geolab mutate, trusted code only)
bool g_seq_passed = false;  // --geolab-run-seq: the last test's verdict
std::chrono::steady_clock::time_point g_seq_start;  // --geolab-run-seq: when the current test started
struct VerdictListener;
VerdictListener* g_verdict = nullptr;

std::string short_path(const char* file) {
    std::string f = file ? file : "";
    for (const char* root : {"/tests/", "/labs/", "/solutions/", "/lib/"}) {
        auto pos = f.rfind(root);
        if (pos != std::string::npos) return f.substr(pos + 1);
    }
    return f;
}

// The last check that passed, kept as pointers into the program's static strings (no formatting per check):
// a crash report and a stopped replay name it.
struct LastCheck {
    const char* file = nullptr;
    int line = 0;
    const char* macro = nullptr;
    const char* expr = nullptr;
};
LastCheck g_last_check;
bool g_out_of_memory = false;  // a std::bad_alloc reached the test (an allocation failed: the memory cap)
bool g_not_implemented_failure = false;  // a failure of this test came from a geolab::NotImplemented

std::string clip(std::string s, std::size_t n = 2000) {
    if (s.size() > n) s = s.substr(0, n) + " ...(cut)";
    return s;
}

std::string last_check_text() {
    if (!g_last_check.file) return "last check passed: none (no check of this test had passed yet)";
    return "last check passed: " + short_path(g_last_check.file) + ":" + std::to_string(g_last_check.line) + ": " +
           g_last_check.macro + "( " + g_last_check.expr + " )";
}

// Characters that doctest's --test-case filter would interpret.
bool name_is_filter_safe(const std::string& n) { return n.find_first_of("*?,\\[]") == std::string::npos; }

// The tasks a test is declared to build on (grading/chain.hpp), "" for none.
std::string builds_on(const std::string& name) {
    const auto& all = geolab::detail::builds_on_tests();
    const auto it = all.find(name);
    return it == all.end() ? std::string() : it->second;
}

// Lists test cases as JSON lines.
struct ListReporter : doctest::IReporter {
    explicit ListReporter(const doctest::ContextOptions&) {}
    void report_query(const doctest::QueryData& q) override {
        if (!q.data) return;
        for (unsigned i = 0; i < q.num_data; ++i) {
            const doctest::TestCaseData& tc = *q.data[i];
            const geolab::TestMeta meta = geolab::test_registry()[tc.m_name];
            json j{{"name", tc.m_name},     {"suite", tc.m_test_suite ? tc.m_test_suite : ""},
                   {"file", short_path(tc.m_file.c_str())}, {"line", tc.m_line},
                   {"points", meta.points}, {"hidden", meta.hidden},
                   {"hint", meta.hint},     {"timeout", meta.timeout_s}, {"builds_on", builds_on(tc.m_name)},
                   {"filter_safe", name_is_filter_safe(tc.m_name)}};
            std::cout << j.dump() << "\n";
        }
    }
    void test_run_start() override {}
    void test_run_end(const doctest::TestRunStats&) override {}
    void test_case_start(const doctest::TestCaseData&) override {}
    void test_case_reenter(const doctest::TestCaseData&) override {}
    void test_case_end(const doctest::CurrentTestCaseStats&) override {}
    void test_case_exception(const doctest::TestCaseException&) override {}
    void subcase_start(const doctest::SubcaseSignature&) override {}
    void subcase_end() override {}
    void log_assert(const doctest::AssertData&) override {}
    void log_message(const doctest::MessageData&) override {}
    void test_case_skipped(const doctest::TestCaseData&) override {}
};

// Collects the verdict of the one test that runs and sends it to the grader's pipe at the end of the run.
struct VerdictListener : doctest::IReporter {
    explicit VerdictListener(const doctest::ContextOptions&) {
        g_verdict = this;
        // The judge: a recording that cannot answer a call ends the test as a failure, with what is known so far.
        geolab::boundary::channel().stop = [this](const std::string& kind, const std::string& message) {
            note(message + "\n" + contexts() + last_check_text());
            send("failed", false, kind, contexts());
            std::cout.flush();
            ::_exit(0);
        };
    }
    std::vector<std::string> messages;
    std::vector<std::string> ran;
    int asserts = 0, failed_asserts = 0;
    bool success = false, exception = false;

    static std::string contexts() {
        std::ostringstream os;
        const int n = doctest::IReporter::get_num_active_contexts();
        auto ctx = doctest::IReporter::get_active_contexts();
        for (int i = 0; i < n; ++i) {
            ctx[i]->stringify(&os);
            os << "\n";
        }
        return os.str();
    }
    void note(std::string m) {
        if (messages.size() < 20) messages.push_back(clip(std::move(m)));
    }

    void report_query(const doctest::QueryData&) override {}
    void test_run_start() override {}
    void test_case_start(const doctest::TestCaseData& tc) override {
        ran.push_back(tc.m_name);
        geolab::detail::current_test() = tc.m_name;
        g_last_check = {};
        g_not_implemented_failure = false;  // per test (--geolab-run-seq runs several in one process)
        g_out_of_memory = false;
        if (geolab::boundary::channel().mode == geolab::boundary::Channel::Mode::off)
            geolab::boundary::channel().last_function = "";
    }
    void test_case_reenter(const doctest::TestCaseData&) override {}
    void test_case_end(const doctest::CurrentTestCaseStats& st) override {
        geolab::boundary::record_end();          // performer: the test is over
        geolab::boundary::replay_end_of_test();  // judge: so must the recording be (or the verdict is a failure)
        asserts += st.numAssertsCurrentTest;
        failed_asserts += st.numAssertsFailedCurrentTest;
        success = st.testCaseSuccess;
    }
    void test_case_exception(const doctest::TestCaseException& e) override {
        exception = true;
        const std::string what = e.error_string.c_str();
        // A stub's own message says what happened ("not implemented: f (...)"): no second prefix before it.
        const bool stub = what.rfind("not implemented: ", 0) == 0 && geolab::NotImplemented::count() > 0;
        if (stub && messages.empty()) g_not_implemented_failure = true;
        // The INFO/CAPTURE scopes the exception unwound (innermost first): the input the test was on.
        std::string unwound;
        const int n = doctest::IReporter::get_num_stringified_contexts();
        const doctest::String* c = doctest::IReporter::get_stringified_contexts();
        for (int i = n; i > 0; --i) unwound += std::string(c[i - 1].c_str()) + "\n";
        note((stub ? what : "unexpected exception: " + what) + "\n" + contexts() + unwound);
    }
    void subcase_start(const doctest::SubcaseSignature&) override {}
    void subcase_end() override {}
    void log_assert(const doctest::AssertData& a) override {
        if (!a.m_failed) {
            g_last_check = {a.m_file, a.m_line, doctest::assertString(a.m_at), a.m_expr};
            return;
        }
        std::string thrown = a.m_exception.c_str();  // doctest quotes it
        if (thrown.size() >= 2 && thrown.front() == '"' && thrown.back() == '"') thrown = thrown.substr(1, thrown.size() - 2);
        const bool stub = a.m_threw && thrown.rfind("not implemented: ", 0) == 0 && geolab::NotImplemented::count() > 0;
        if (messages.empty() && stub) g_not_implemented_failure = true;
        std::ostringstream os;
        if (stub) {  // the stub's own words first, once; then where the test met it
            os << thrown << "\nin " << short_path(a.m_file) << ":" << a.m_line << ": " << doctest::assertString(a.m_at)
               << "( " << a.m_expr << " )\n" << contexts();
            note(os.str());
            return;
        }
        os << short_path(a.m_file) << ":" << a.m_line << ": " << doctest::assertString(a.m_at) << "( " << a.m_expr
           << " )";
        // by the kind of assertion (m_exception_type is "" for plain CHECKs, not null: it tells nothing)
        namespace at = doctest::assertType;
        if (a.m_at & (at::is_throws | at::is_throws_as | at::is_throws_with))
            os << (a.m_threw ? std::string(" threw a different exception: ") + a.m_exception.c_str()
                             : std::string(" did not throw"));
        else if (a.m_threw)
            os << " threw: " << a.m_exception.c_str();
        else if (a.m_decomp.size())
            os << " is false: " << a.m_decomp.c_str();
        else
            os << " is false";
        os << "\n" << contexts();
        note(os.str());
    }
    void log_message(const doctest::MessageData& m) override {
        if (m.m_severity & doctest::assertType::is_warn) return;
        note(short_path(m.m_file) + ":" + std::to_string(m.m_line) + ": " + m.m_string.c_str() + "\n" + contexts());
    }
    void test_case_skipped(const doctest::TestCaseData&) override {}

    void test_run_end(const doctest::TestRunStats&) override {
        send((success && !exception && ran.size() == 1) ? "passed" : "failed", g_not_implemented_failure, "", "");
    }

    // The verdict line to the grader's pipe. `stopped`: why a replay ended the test early (empty: it did not);
    // `input`: the test's INFO/CAPTURE contexts where it stopped (the fixture it was on).
    void send(const char* status, bool not_implemented, const std::string& stopped, const std::string& input) {
        if (g_seq_fd >= 0) {  // --geolab-run-seq: the verdict of this test; the next one follows
            g_seq_passed = std::strcmp(status, "passed") == 0;
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - g_seq_start).count();
            const std::string line =
                json{{"ran", ran}, {"status", status}, {"not_implemented", not_implemented}, {"messages", messages},
                     {"seconds", seconds}, {"last_call", geolab::boundary::channel().last_function}}.dump() + "\n";
            for (std::size_t done = 0; done < line.size();) {
                const ssize_t w = ::write(g_seq_fd, line.data() + done, line.size() - done);
                if (w <= 0) break;
                done += static_cast<std::size_t>(w);
            }
            return;
        }
        if (g_result_fd < 0) return;
        const geolab::boundary::Channel& ch = geolab::boundary::channel();
        json j{{"ran", ran},
               {"status", status},
               {"not_implemented", not_implemented},
               {"asserts", asserts},
               {"failed_asserts", failed_asserts},
               {"messages", messages},
               {"figures", geolab::detail::attached_figures()},
               {"calls", ch.calls},
               {"last_function", ch.last_function},
               {"stopped", stopped},
               {"input", clip(input)},
               {"last_check", last_check_text()},
               {"out_of_memory", g_out_of_memory}};
        std::string line = g_token + " " + j.dump() + "\n";
        const char* p = line.data();
        std::size_t left = line.size();
        while (left > 0) {
            ssize_t w = ::write(g_result_fd, p, left);
            if (w <= 0) break;
            p += w;
            left -= static_cast<std::size_t>(w);
        }
        ::close(g_result_fd);
        g_result_fd = -1;
    }
};

// ---- a crash, when no judge watches (a test program run by hand, or a lab without a judge) ----------------------
// The handler prints what a student needs to find the bug: the test, the input it was on (its INFO/CAPTURE
// contexts: the fixture) and the last check that passed; then the signal takes its default course (the grader
// still sees the signal). Formatting the contexts allocates: if the crash left the heap locked, an alarm ends
// the wait and the signal is raised all the same.
volatile std::sig_atomic_t g_crash_signal = 0;

void write_str(const char* s) {
    if (!s) return;
    std::size_t n = std::strlen(s);
    while (n > 0) {
        const ssize_t w = ::write(2, s, n);
        if (w <= 0) return;
        s += w;
        n -= static_cast<std::size_t>(w);
    }
}

[[noreturn]] void die_with(int sig) {
    std::signal(sig, SIG_DFL);
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, sig);
    ::sigprocmask(SIG_UNBLOCK, &set, nullptr);
    ::raise(sig);
    ::_exit(128 + sig);
}

void on_alarm(int) { die_with(g_crash_signal ? g_crash_signal : SIGABRT); }

void on_crash(int sig) {
    if (g_crash_signal) die_with(sig);  // a second fault while reporting the first
    g_crash_signal = sig;
    const char* abbrev = ::sigabbrev_np(sig);
    write_str("\ngeolab: crashed with SIG");
    write_str(abbrev ? abbrev : "?");
    write_str(" (");
    write_str(::strsignal(sig));
    write_str(") in test '");
    write_str(geolab::detail::current_test().c_str());
    write_str("'\n");
    std::signal(SIGALRM, on_alarm);
    ::alarm(2);
    const std::string input = VerdictListener::contexts();
    if (!input.empty()) write_str(("input: " + input).c_str());
    write_str((last_check_text() + "\n").c_str());
    die_with(sig);
}

void install_crash_report() {
    static char stack[64 * 1024];  // a stack overflow (endless recursion) must still be reported
    stack_t ss{};
    ss.ss_sp = stack;
    ss.ss_size = sizeof stack;
    ::sigaltstack(&ss, nullptr);
    struct sigaction sa {};
    sa.sa_handler = on_crash;
    sa.sa_flags = SA_ONSTACK;
    sigemptyset(&sa.sa_mask);
    for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) ::sigaction(sig, &sa, nullptr);
}

}  // namespace

// An allocation that failed: under the grader's RLIMIT_AS that is the memory cap; the grader names it.
DOCTEST_REGISTER_EXCEPTION_TRANSLATOR(const std::bad_alloc& e) {
    g_out_of_memory = true;
    return doctest::String(e.what());
}

DOCTEST_REGISTER_REPORTER("geolab-list", 1, ListReporter);
DOCTEST_REGISTER_LISTENER("geolab-verdict", 1, VerdictListener);

// Take the grader's secrets before any other code of the program runs: a constructor with priority 101 runs
// before every ordinary static initializer (students' globals included), so they never see the token.
__attribute__((constructor(101))) static void take_grader_secrets() {
    char* t = std::getenv("GEOLAB_TOKEN");
    if (t) {
        std::strncpy(g_token_buf, t, sizeof g_token_buf - 1);
        for (char* p = t; *p; ++p) *p = 'x';  // also scrub the original bytes, not only the environ entry
        ::unsetenv("GEOLAB_TOKEN");
    }
    if (const char* fd = std::getenv("GEOLAB_RESULT_FD")) {
        g_result_fd = std::atoi(fd);
        ::unsetenv("GEOLAB_RESULT_FD");
    }
}

int main(int argc, char** argv) {
    g_token = g_token_buf;

    doctest::Context context;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--geolab-list") == 0) {
            const char* args[] = {argv[0], "--list-test-cases", "--reporters=geolab-list", "--no-version"};
            context.applyCommandLine(4, args);
            return context.run();
        }
        if (std::strcmp(argv[i], "--geolab-run") == 0 && i + 1 < argc) {
            install_crash_report();
            const std::string filter = std::string("--test-case=") + argv[i + 1];
            const char* args[] = {argv[0], filter.c_str(), "--case-sensitive", "--no-breaks", "--no-version"};
            context.applyCommandLine(5, args);
            context.run();
            std::cout.flush();
            return 0;  // the verdict went through the pipe; the exit status means nothing to the grader
        }
    }
    // geolab mutate (the reference with one mutant, trusted code): PROG --geolab-run-seq LIST OUT runs the tests
    // named in LIST (one "SECONDS<tab>NAME" per line) in that order in this one process, appends one JSON verdict
    // line per test to OUT, and stops after the first failure. A test past its SECONDS is ended by SIGALRM; a
    // crash or hang ends the process: the first test not answered in OUT is the culprit.
    // --geolab-run-all LIST OUT: the same, but every listed test runs, failures or not (the independence check
    // of the course's own code, which stubs one file of the reference).
    for (int i = 1; i + 2 < argc; ++i) {
        const bool run_all = std::strcmp(argv[i], "--geolab-run-all") == 0;
        if (!run_all && std::strcmp(argv[i], "--geolab-run-seq") != 0) continue;
        std::ifstream list(argv[i + 1]);
        g_seq_fd = ::open(argv[i + 2], O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0644);
        if (!list || g_seq_fd < 0) {
            std::cerr << "--geolab-run-seq: cannot read " << argv[i + 1] << " or write " << argv[i + 2] << "\n";
            return 2;
        }
        std::signal(SIGALRM, SIG_DFL);
        for (std::string entry; std::getline(list, entry);) {
            const auto tab = entry.find('\t');
            if (tab == std::string::npos) continue;
            const double seconds = std::atof(entry.substr(0, tab).c_str());
            const std::string name = entry.substr(tab + 1);
            itimerval limit{};
            limit.it_value.tv_sec = static_cast<time_t>(seconds);
            limit.it_value.tv_usec = static_cast<suseconds_t>((seconds - static_cast<double>(limit.it_value.tv_sec)) * 1e6);
            if (seconds > 0) ::setitimer(ITIMER_REAL, &limit, nullptr);
            const std::string filter = "--test-case=" + name;
            const char* args[] = {argv[0], filter.c_str(), "--case-sensitive", "--no-breaks", "--no-version"};
            context.clearFilters();
            context.applyCommandLine(5, args);
            g_seq_passed = false;
            g_seq_start = std::chrono::steady_clock::now();
            context.run();
            const itimerval off{};
            ::setitimer(ITIMER_REAL, &off, nullptr);
            std::cout.flush();
            if (!g_seq_passed && !run_all) break;
        }
        ::close(g_seq_fd);
        return 0;
    }
    // Record and replay (geolab/grading/boundary_calls.hpp).
    for (int i = 1; i + 1 < argc; ++i) {
        const bool record = std::strcmp(argv[i], "--geolab-record") == 0;
        const bool replay = std::strcmp(argv[i], "--geolab-replay") == 0;
        if (!record && !replay) continue;
        geolab::boundary::Channel& ch = geolab::boundary::channel();
        if (record) {
            std::signal(SIGPIPE, SIG_IGN);  // the judge gone: a failed write ends the recording quietly
            ch.mode = geolab::boundary::Channel::Mode::record;
            // Out of the low numbers (fd 3 was the old verdict pipe's place): stray writes to 3..9 hit nothing.
            // Not a secret (code in this process can find them): writing into them only corrupts one's own answers.
            const int base = 100 + static_cast<int>(std::random_device{}() % 800);
            ch.data_fd = ::fcntl(3, F_DUPFD_CLOEXEC, base);
            ch.go_fd = ::fcntl(4, F_DUPFD_CLOEXEC, base);
            ::close(3);
            ::close(4);
        } else {
            ch.mode = geolab::boundary::Channel::Mode::replay;
            ch.data_fd = 0;
            for (int k = 1; k + 1 < argc; ++k) {
                if (std::strcmp(argv[k], "--geolab-record-fd") == 0) ch.data_fd = std::atoi(argv[k + 1]);
                if (std::strcmp(argv[k], "--geolab-go-fd") == 0) ch.go_fd = std::atoi(argv[k + 1]);
            }
            ch.reader = std::make_unique<geolab::wire::Reader>(ch.data_fd, std::uint64_t{1} << 32);
        }
        const std::string filter = std::string("--test-case=") + argv[i + 1];
        const char* args[] = {argv[0], filter.c_str(), "--case-sensitive", "--no-breaks", "--no-version"};
        context.applyCommandLine(5, args);
        context.run();
        std::cout.flush();
        return 0;
    }
    install_crash_report();
    context.applyCommandLine(argc, argv);
    return context.run();
}
