// Tests of the grader itself: every misbehaving fixture case costs only its own points and is classified
// correctly; the reports are well-formed; the generator rejects bad markers.
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <csignal>
#include <cstdio>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "geolab/grading/release.hpp"
#include "geolab/grading/report.hpp"
#include "geolab/grading/runner.hpp"
#include "geolab/grading/test.hpp"

using geolab::grading::Status;

#ifndef GEOLAB_FIXTURE_PROGRAM
#error "GEOLAB_FIXTURE_PROGRAM must name the fixture test program"
#endif

namespace {

const geolab::grading::LabReport& fixture_report() {
    static const geolab::grading::LabReport report = [] {
        geolab::grading::RunOptions opt;
        opt.timeout_s = 10;
        opt.memory_mb = 1024;
        opt.output_cap = 256 << 10;
        opt.figure_dir = std::filesystem::temp_directory_path() / "geolab_grader_test_figures";
        return geolab::grading::grade_program("fixtures", "student", GEOLAB_FIXTURE_PROGRAM, opt);
    }();
    return report;
}

const geolab::grading::TestResult& result(const std::string& name) {
    for (const auto& r : fixture_report().results)
        if (r.info.name == name) return r;
    FAIL("no result for " << name);
    throw 0;
}

}  // namespace

TEST_CASE("the grader lists every fixture with its metadata") {
    const auto& rep = fixture_report();
    REQUIRE(rep.error == "");
    CHECK(rep.results.size() == 20);
    CHECK(result("hidden and passes").info.hidden);
    CHECK(result("hidden and passes").info.points == 2);
    CHECK(result("fails an assertion").info.hint == "look at the sum");
    CHECK(result("ungraded").info.points == 0);
    CHECK(result("passes").info.suite == "fixtures");
    // declared dependencies on other tasks (grading/chain.hpp): only the independence check reads them
    CHECK(result("hidden and passes").info.builds_on == "Task 2");
    CHECK(result("ungraded").info.builds_on == "*");
    CHECK(result("passes").info.builds_on.empty());
}

TEST_CASE("--geolab-run-all runs every listed test in one process, failures or not, one verdict line each") {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("geolab_run_all_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    {
        std::ofstream list(dir / "list.txt");
        list << "5\tpasses\n5\tfails an assertion\n5\tnot implemented\n5\thidden and passes\n";
    }
    geolab::grading::RunOptions o;
    o.sandbox.no_network = false;
    const auto c = geolab::grading::run_command(
        {std::string(GEOLAB_FIXTURE_PROGRAM), "--geolab-run-all", (dir / "list.txt").string(), (dir / "out.jsonl").string()},
        30, o);
    CHECK(c.exit_code == 0);
    std::ifstream in(dir / "out.jsonl");
    std::vector<std::string> status;
    for (std::string line; std::getline(in, line);) {
        const auto j = nlohmann::json::parse(line);
        status.push_back(j.at("status").get<std::string>() + (j.value("not_implemented", false) ? " (stub)" : ""));
    }
    CHECK(status == std::vector<std::string>{"passed", "failed", "failed (stub)", "passed"});
    fs::remove_all(dir);
}

TEST_CASE("each misbehaviour is isolated and classified") {
    const std::map<std::string, Status> expected = {
        {"passes", Status::passed},
        {"fails an assertion", Status::failed},
        {"expects an exception that never comes", Status::failed},
        {"not implemented", Status::not_implemented},
        {"a stub that escapes the test", Status::not_implemented},
        {"a stub caught then a wrong value", Status::failed},
        {"segfaults on a named input", Status::crashed},
        {"segfaults", Status::crashed},
        {"aborts", Status::crashed},
        {"hangs", Status::timeout},
        {"exits early with status 0", Status::error},
        {"quick_exit", Status::error},
        {"floods stdout", Status::error},
        {"prints a fake success", Status::failed},
        {"leaves a child that sleeps forever", Status::passed},
        {"allocates without bound", Status::failed},
        {"throws an unexpected exception", Status::failed},
        {"hidden and passes", Status::passed},
        {"ungraded", Status::passed},
        {"attaches a figure", Status::passed},
    };
    for (const auto& [name, status] : expected) {
        const auto& r = result(name);
        CAPTURE(name);
        CAPTURE(geolab::grading::first_message(r));
        CHECK(std::string(to_string(r.status)) == std::string(to_string(status)));
        CHECK(r.score == (status == Status::passed ? r.info.points : 0.0));
    }
    CHECK(fixture_report().score() == 4);
    CHECK(fixture_report().max_score() == 19);
}

TEST_CASE("messages say what happened") {
    CHECK(result("segfaults").messages.at(0).find("SIGSEGV") != std::string::npos);
    CHECK(result("fails an assertion").messages.at(0).find("CHECK( sum == 3 ) is false: 2 == 3") != std::string::npos);
    CHECK(result("expects an exception that never comes").messages.at(0).find("did not throw") != std::string::npos);
    CHECK(result("throws an unexpected exception").messages.at(0).find("boom") != std::string::npos);
    CHECK(result("fails an assertion").messages.at(0).find("input: 1 + 1") != std::string::npos);
    CHECK(result("not implemented").messages.at(0).find("not implemented: answer") == 0);
    CHECK(result("not implemented").messages.at(0).find("\nin tests/grading/fixture_tests.cpp:") != std::string::npos);
    CHECK(result("exits early with status 0").messages.at(0).find("exit") != std::string::npos);
    CHECK(result("hangs").seconds < 5);
    CHECK(result("floods stdout").output.size() <= (256u << 10));
}

TEST_CASE("failure reports a student can act on") {
    // A crash names the input (the test's INFO context) and the last check that passed.
    const std::string crash = result("segfaults on a named input").messages.at(0);
    CHECK(crash.find("crashed with SIGSEGV") == 0);
    CHECK(crash.find("input: fixture 'triangle'") != std::string::npos);
    CHECK(crash.find("last check passed: tests/grading/fixture_tests.cpp:") != std::string::npos);
    CHECK(crash.find("CHECK( 1 + 1 == 2 )") != std::string::npos);
    // The memory cap is named, not std::bad_alloc alone.
    CHECK(result("allocates without bound").messages.at(0).find("memory limit (1024 MiB) exceeded") == 0);
    // A stub's message once, without "unexpected exception: " before it; a wrong value after a caught stub fails.
    CHECK(result("a stub that escapes the test").messages.at(0).find("not implemented: answer2") == 0);
    CHECK(result("a stub caught then a wrong value").messages.at(0).find("CHECK( value == 1 ) is false") != std::string::npos);
    // The console: the status word once, whole messages (every line), the rest with --verbose.
    std::ostringstream quiet, verbose;
    geolab::grading::print_console(quiet, {fixture_report()}, geolab::grading::HiddenPolicy::show, false);
    geolab::grading::print_console(verbose, {fixture_report()}, geolab::grading::HiddenPolicy::show, false, true);
    const std::string q = quiet.str();
    CHECK(q.find("not implemented: not implemented") == std::string::npos);
    CHECK(q.find("unexpected exception: not implemented") == std::string::npos);
    CHECK(q.find("threw: \"not implemented") == std::string::npos);
    CHECK(q.find("        not implemented: answer2") != std::string::npos);
    CHECK(q.find("        input: fixture 'triangle'") != std::string::npos);
    CHECK(q.find("        last check passed: ") != std::string::npos);
    CHECK(q.find("failed: memory limit (1024 MiB) exceeded") != std::string::npos);
    CHECK(verbose.str().find("--- what the test printed ---") != std::string::npos);
    // One test by name (exact, or the one name containing the text); an unknown name lists the tests.
    geolab::grading::RunOptions one;
    one.timeout_s = 10;
    one.only_test = "on a named input";
    const auto single = geolab::grading::grade_program("fixtures", "student", GEOLAB_FIXTURE_PROGRAM, one);
    REQUIRE(single.results.size() == 1);
    CHECK(single.results[0].info.name == "segfaults on a named input");
    one.only_test = "no such test";
    const auto none = geolab::grading::grade_program("fixtures", "student", GEOLAB_FIXTURE_PROGRAM, one);
    CHECK(none.results.empty());
    CHECK(none.error.find("no test of fixtures is named 'no such test'; its tests:\n  passes") == 0);
    std::ostringstream error_console;
    geolab::grading::print_console(error_console, {none}, geolab::grading::HiddenPolicy::show, false);
    CHECK(error_console.str().find("0 / ?") == std::string::npos);
}

TEST_CASE("a crash run by hand prints the input and the last check that passed, as the grader does") {
    const std::string cmd = std::string("'") + GEOLAB_FIXTURE_PROGRAM + "' -tc='segfaults on a named input' 2>&1; echo \"status=$?\"";
    FILE* p = ::popen(cmd.c_str(), "r");
    REQUIRE(p);
    std::string out;
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
    ::pclose(p);
    CAPTURE(out);
    CHECK(out.find("geolab: crashed with SIGSEGV (Segmentation fault) in test 'segfaults on a named input'") !=
          std::string::npos);
    CHECK(out.find("input: fixture 'triangle'") != std::string::npos);
    CHECK(out.find("last check passed: tests/grading/fixture_tests.cpp:") != std::string::npos);
    CHECK(out.find("status=" + std::to_string(128 + SIGSEGV)) != std::string::npos);  // the signal still ends it
}

TEST_CASE("reports: results.json and JUnit are written and well-formed") {
    const auto tmp = std::filesystem::temp_directory_path();
    const std::string json_path = (tmp / "geolab_grader_test_results.json").string(),
                      junit_path = (tmp / "geolab_grader_test_junit.xml").string();
    geolab::grading::write_gradescope_json(json_path, {fixture_report()});
    std::ifstream f(json_path);
    auto j = nlohmann::json::parse(f);
    CHECK(j["score"] == 4);
    CHECK(j["max_score"] == 19);
    REQUIRE(j["tests"].size() == 20);
    for (const auto& t : j["tests"]) {
        CHECK(t.contains("name"));
        CHECK(t.contains("number"));
        CHECK((t["status"] == "passed" || t["status"] == "failed"));
        CHECK((t["visibility"] == "visible" || t["visibility"] == "after_published"));
        CHECK(t["score"].get<double>() <= t["max_score"].get<double>());
    }
    geolab::grading::write_junit(junit_path, {fixture_report()});
    std::ifstream x(junit_path);
    std::string xml((std::istreambuf_iterator<char>(x)), {});
    CHECK(xml.find("<testsuites>") != std::string::npos);
    CHECK(xml.find("tests=\"20\"") != std::string::npos);
}

TEST_CASE("a test can attach a picture, which the grader collects") {
    const auto& r = result("attaches a figure");
    REQUIRE(r.figures.size() == 1);
    CHECK(std::filesystem::exists(r.figures[0]));
    CHECK(r.figures[0].find(".png") != std::string::npos);
}

TEST_CASE("the generator strips solution blocks and rejects bad markers") {
    using geolab::grading::strip_solutions;
    const std::string src = "int f(int x) {\n    // BEGIN SOLUTION\n    return 2 * x;\n    // END SOLUTION\n}\n";
    CHECK(strip_solutions(src, "a.cpp") == "int f(int x) {\n    throw geolab::NotImplemented(__func__);\n}\n");
    const std::string with_stub = "void g() {\n  // BEGIN SOLUTION\n  // STUB: return;\n  work();\n  // END SOLUTION\n}\n";
    CHECK(strip_solutions(with_stub, "b.cpp") == "void g() {\n  return;\n}\n");
    CHECK_THROWS_WITH_AS(strip_solutions("// BEGIN SOLUTION\nx\n", "c.cpp"), "c.cpp:1: BEGIN SOLUTION is never closed",
                         std::runtime_error);
    CHECK_THROWS_WITH_AS(strip_solutions("// BEGIN SOLUTION\n// BEGIN SOLUTION\n// END SOLUTION\n", "d.cpp"),
                         "d.cpp:2: nested BEGIN SOLUTION (the block opened at line 1 is not closed)", std::runtime_error);
    CHECK_THROWS_AS(strip_solutions("x\n// END SOLUTION\n", "e.cpp"), std::runtime_error);
    CHECK_THROWS_AS(strip_solutions("// BEGIN SOLUTION: f\n// END SOLUTION\n", "f.cpp"), std::runtime_error);
    CHECK_THROWS_AS(strip_solutions("// BEGIN SOLUTIONS\n", "g.cpp"), std::runtime_error);
}

TEST_CASE("reports replace bytes that are not UTF-8, so results.json stays valid") {
    using geolab::grading::valid_utf8;
    const std::string ffd = "\xef\xbf\xbd";
    CHECK(valid_utf8("plain ascii") == "plain ascii");
    CHECK(valid_utf8("caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x99\x82") == "caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x99\x82");
    CHECK(valid_utf8("a\xff" "b") == "a" + ffd + "b");                  // a stray byte
    CHECK(valid_utf8("\xc3") == ffd);                                   // a sequence cut at the end
    CHECK(valid_utf8("\xc0\xaf") == ffd + ffd);                         // an overlong '/'
    CHECK(valid_utf8("\xed\xa0\x80") == ffd + ffd + ffd);               // a UTF-16 surrogate
    CHECK(valid_utf8("\xf4\x90\x80\x80") == ffd + ffd + ffd + ffd);     // above U+10FFFF
    // A whole report with a stray byte in a test's output and name: written, parsed, the byte replaced.
    geolab::grading::LabReport lab;
    lab.lab = "utf8";
    lab.variant = "student";
    geolab::grading::TestResult r;
    r.info.name = "prints \xff";
    r.info.points = 1;
    r.status = Status::failed;
    r.messages = {"bad \xfe byte"};
    r.output = "output \xff\xfe end";
    lab.results.push_back(r);
    const auto path = std::filesystem::temp_directory_path() / "geolab_grader_test_utf8.json";
    geolab::grading::write_gradescope_json(path, {lab}, "preamble \xff\n");
    std::ifstream f(path);
    const auto j = nlohmann::json::parse(f);  // throws on invalid UTF-8 or an empty file
    REQUIRE(j["tests"].size() == 1);
    CHECK(j["tests"][0]["output"].get<std::string>().find("output " + ffd + ffd + " end") != std::string::npos);
    CHECK(j["tests"][0]["name"] == "prints " + ffd);
    const auto junit = std::filesystem::temp_directory_path() / "geolab_grader_test_utf8.xml";
    geolab::grading::write_junit(junit, {lab});
    std::ifstream x(junit);
    const std::string xml((std::istreambuf_iterator<char>(x)), {});
    CHECK(xml.find('\xff') == std::string::npos);
    CHECK(xml.find("bad " + ffd + " byte") != std::string::npos);
}

TEST_CASE("given files are listed in labs/NN/given.txt, and the generator keeps the list honest") {
    namespace fs = std::filesystem;
    const fs::path root = fs::temp_directory_path() / "geolab_grader_test_given";
    fs::remove_all(root);
    fs::create_directories(root / "solutions/01_x/src");
    fs::create_directories(root / "labs/01_x/src");
    auto write = [](const fs::path& p, const std::string& text) { std::ofstream(p) << text; };
    write(root / "solutions/01_x/src/task.cpp", "int f() {\n    // BEGIN SOLUTION\n    return 1;\n    // END SOLUTION\n}\n");
    write(root / "solutions/01_x/src/given.cpp", "int g() { return 2; }\n");
    // Not listed: the generator says so.
    auto diffs = geolab::grading::generate_labs(root, true);
    bool unlisted = false;
    for (const auto& d : diffs) unlisted |= d.reason.find("not listed") != std::string::npos && d.file.filename() == "given.cpp";
    CHECK(unlisted);
    // Listed: clean; the grader's list has it.
    write(root / "labs/01_x/given.txt", "# given code\ngiven.cpp\n");
    CHECK(geolab::grading::generate_labs(root, false).empty());
    CHECK(geolab::grading::given_files(root / "labs/01_x") == std::set<std::string>{"given.cpp"});
    // A task file marked given is an error, and so is a listed file that does not exist or a path.
    write(root / "labs/01_x/given.txt", "given.cpp\ntask.cpp\nmissing.cpp\n");
    diffs = geolab::grading::generate_labs(root, false);
    CHECK(diffs.size() == 2);
    write(root / "labs/01_x/given.txt", "src/given.cpp\n");
    CHECK_THROWS_AS(geolab::grading::given_files(root / "labs/01_x"), std::runtime_error);
    fs::remove_all(root);
}

TEST_CASE("the sandbox shows only its allow-list, a private /tmp, a clean environment, and fails closed (root only)") {
    namespace fs = std::filesystem;
    using namespace geolab::grading;
    if (!can_drop_privileges()) {
        MESSAGE("not root: the sandbox's uid and file system need root (the report then says NOT ISOLATED)");
        return;
    }
    const fs::path base = fs::temp_directory_path() / "geolab_grader_test_sandbox";
    fs::remove_all(base);
    fs::create_directories(base / "shown");
    fs::create_directories(base / "secret");
    std::ofstream(base / "shown/a.txt") << "shown file\n";
    std::ofstream(base / "secret/b.txt") << "secret\n";
    std::ofstream(fs::temp_directory_path() / "geolab_grader_test_marker") << "left by someone else\n";
    ::setenv("GEOLAB_GRADER_TEST_CANARY", "the grader's environment", 1);
    RunOptions o;
    o.memory_mb = 0;
    o.sandbox.drop_privileges = true;
    o.sandbox.allow_list = true;
    o.sandbox.clean_env = true;
    o.sandbox.require_isolation = true;
    o.sandbox.workdir = base / "work";
    o.sandbox.visible = {base / "shown"};
    REQUIRE(isolation_problem(o.sandbox) == "");
    const std::string b = base.string();
    const std::string script =
        "cat " + b + "/shown/a.txt; test -e " + b + "/secret/b.txt && echo SEES_SECRET; test -e /tmp/geolab_grader_test_marker && "
        "echo SEES_HOST_TMP; test -e /root && echo SEES_ROOT_HOME; env | grep -q GEOLAB_GRADER_TEST_CANARY && echo SEES_ENV; "
        "echo uid=$(id -u); touch /tmp/x && echo TMP_WRITABLE; touch " + b + "/shown/c 2>/dev/null && echo SHOWN_WRITABLE; "
        "touch ./w && echo WORK_WRITABLE";
    CommandResult r = run_command({"/bin/sh", "-c", script}, 30, o);
    CAPTURE(r.output);
    CHECK(r.output.find("shown file") != std::string::npos);
    CHECK(r.output.find("SEES_") == std::string::npos);
    CHECK(r.output.find("uid=0") == std::string::npos);
    CHECK(r.output.find("TMP_WRITABLE") != std::string::npos);
    CHECK(r.output.find("WORK_WRITABLE") != std::string::npos);
    CHECK(r.output.find("SHOWN_WRITABLE") == std::string::npos);
    // Each run gets an empty /tmp: what one left, the next does not see.
    CommandResult second = run_command({"/bin/sh", "-c", "test -e /tmp/x && echo SEES_LAST_TMP; echo done"}, 30, o);
    CHECK(second.output.find("SEES_LAST_TMP") == std::string::npos);
    // The lease folder made by another user: no uid, and with require_isolation nothing runs (never as root).
    o.sandbox.uid_dir = base / "uids";
    fs::create_directories(o.sandbox.uid_dir);
    REQUIRE(::chown(o.sandbox.uid_dir.c_str(), 12345, 12345) == 0);
    CHECK(isolation_problem(o.sandbox).find("owned by uid 12345") != std::string::npos);
    CHECK_THROWS_AS(run_command({"/bin/sh", "-c", "touch " + b + "/ran_as_root"}, 30, o), SandboxError);
    CHECK(!fs::exists(base / "ran_as_root"));
    fs::remove_all(base);
    fs::remove(fs::temp_directory_path() / "geolab_grader_test_marker");
    ::unsetenv("GEOLAB_GRADER_TEST_CANARY");
}

// ---- record and replay (replay_fixture/): the judge decides, from what the performer's calls returned ----------
#if defined(GEOLAB_REPLAY_PERFORMER) && defined(GEOLAB_REPLAY_JUDGE)
namespace {
const geolab::grading::LabReport& replay_report() {
    static const geolab::grading::LabReport report = [] {
        geolab::grading::RunOptions opt;
        opt.timeout_s = 10;
        opt.memory_mb = 1024;
        opt.judge = GEOLAB_REPLAY_JUDGE;
        return geolab::grading::grade_program("replay_fixture", "student", GEOLAB_REPLAY_PERFORMER, opt);
    }();
    return report;
}
const geolab::grading::TestResult& replayed(const std::string& name) {
    for (const auto& r : replay_report().results)
        if (r.info.name == name) return r;
    FAIL("no result for " << name);
    throw 0;
}
bool says(const geolab::grading::TestResult& r, const std::string& part) {
    for (const auto& m : r.messages)
        if (m.find(part) != std::string::npos) return true;
    return false;
}
}  // namespace

TEST_CASE("record and replay: the judge lists the tests and decides each verdict") {
    const auto& rep = replay_report();
    REQUIRE(rep.error == "");
    CHECK(rep.isolated);
    CHECK(rep.results.size() == 21);
    CHECK(replayed("a timed call is timed by the judge").info.hidden);
    CHECK(replayed("hangs in a call").info.timeout_s == 1);
    const std::map<std::string, Status> expected = {
        {"right answers pass", Status::passed},
        {"a wrong answer fails", Status::failed},
        {"not implemented", Status::not_implemented},
        {"crashes in its second call", Status::crashed},
        {"exits in a call", Status::error},
        {"hangs in a call", Status::timeout},
        {"forges bytes on the record pipe", Status::failed},
        {"claims a vector larger than the recording", Status::failed},
        {"a timed call is timed by the judge", Status::passed},
        {"answers a timed call before it starts", Status::failed},
        {"calls among the student's functions are not recorded", Status::passed},
        {"an index out of range stops the judge", Status::failed},
        {"member functions cross the boundary", Status::passed},
        {"callbacks are replayed into the judge's own function", Status::passed},
        {"changing the test's data shows as different arguments", Status::failed},
        {"a soup whose face runs past its indices is refused", Status::failed},
        {"a soup whose index names no position is refused", Status::failed},
        {"an image shorter than its size is refused", Status::failed},
        {"a broken soup in an out-argument is refused", Status::failed},
    };
    for (const auto& [name, status] : expected) {
        const auto& r = replayed(name);
        CAPTURE(name);
        CAPTURE(geolab::grading::first_message(r));
        CHECK(std::string(to_string(r.status)) == std::string(to_string(status)));
        CHECK(r.score == (status == Status::passed ? r.info.points : 0.0));
    }
}

TEST_CASE("record and replay: messages name the call the student's program was in") {
    CHECK(says(replayed("crashes in its second call"), "SIGSEGV"));
    CHECK(says(replayed("crashes in its second call"), "call 2 (crash_in_call)"));
    CHECK(says(replayed("exits in a call"), "call 1 (exit_in_call)"));
    CHECK(says(replayed("hangs in a call"), "hang_in_call"));
    CHECK(says(replayed("forges bytes on the record pipe"), "does not match call 1 (forge_record)"));
    CHECK(says(replayed("claims a vector larger than the recording"), "exceeds what the recording holds"));
    CHECK(says(replayed("answers a timed call before it starts"), "before the grader let the call start"));
    CHECK(says(replayed("an index out of range stops the judge"), "the test stopped on your code's answers"));
    CHECK(says(replayed("not implemented"), "not implemented: not_written"));
    CHECK(says(replayed("changing the test's data shows as different arguments"),
               "does not match call 2 (poke): argument 1 differs"));
    CHECK(replayed("hangs in a call").seconds < 5);
    // answers that break their type's invariants never reach the judge's test code (it would read outside them)
    CHECK(says(replayed("a soup whose face runs past its indices is refused"),
               "last offset 268435456 is not its number of indices 3"));
    CHECK(says(replayed("a soup whose index names no position is refused"), "index 2 is 5, but it has 3 positions"));
    CHECK(says(replayed("an image shorter than its size is refused"),
               "64 x 64 pixels with 4 bytes of rgba instead of 16384"));
    CHECK(says(replayed("a broken soup in an out-argument is refused"), "(in the answer of call 1, fill_soup)"));
}

TEST_CASE("record and replay: a crash names the input and the last check passed; the memory cap is named") {
    const auto& crash = replayed("crashes on a named input");
    CHECK(crash.status == Status::crashed);
    REQUIRE(!crash.messages.empty());
    CAPTURE(crash.messages.front());
    CHECK(crash.messages.front().find("crashed with SIGSEGV") == 0);
    CHECK(crash.messages.front().find("call 2 (crash_in_call)") != std::string::npos);
    CHECK(crash.messages.front().find("\ninput: fixture 'pair'") != std::string::npos);
    CHECK(crash.messages.front().find("\nlast check passed: tests/grading/replay_fixture/tests.cpp:") != std::string::npos);
    CHECK(crash.messages.front().find("CHECK( add(1, 1) == 2 )") != std::string::npos);
    CHECK(!says(crash, "your program stopped"));
    const auto& walk = replayed("walks without end");
    CHECK(walk.status == Status::failed);
    REQUIRE(!walk.messages.empty());
    CAPTURE(walk.messages.front());
    CHECK(walk.messages.front().find("memory limit (1024 MiB) exceeded (std::bad_alloc) in or after call 2 "
                                     "(walk_forever)") == 0);
    CHECK(walk.messages.front().find("an endless walk") != std::string::npos);
    CHECK(walk.messages.front().find("\ninput: fixture 'loop'") != std::string::npos);
    CHECK(walk.messages.front().find("\nlast check passed: tests/grading/replay_fixture/tests.cpp:") != std::string::npos);
}
#endif
