// ADVERSARIAL CASE forge_timeout: sets every test's time limit to 10^6 s in the test registry (from a doctest
// listener, constructed when the run starts), then blocks forever in laplacian_smoothing: a grader that takes
// its limits from this process never ends.
// A modified copy of the lab 01 smoothing.cpp, graded by tests/grading/adversarial/run.sh.
#include <string>

#include <unistd.h>

#include "geolab/halfedge.hpp"
#include "geolab/grading/test.hpp"

namespace {
struct Editor : doctest::IReporter {
    explicit Editor(const doctest::ContextOptions&) {
        for (auto& [name, meta] : geolab::test_registry()) {
            meta.timeout_s = 1e6;
        }
    }
    void report_query(const doctest::QueryData&) override {}
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
}  // namespace
DOCTEST_REGISTER_LISTENER("geolab-timeout-editor", 0, Editor);

namespace geolab::halfedge {

void laplacian_smoothing(Mesh& mesh, double t, int iterations) {
    for (;;) ::pause();  // block
}

}  // namespace geolab::halfedge
