// ADVERSARIAL CASE forge_registry: edits the test registry once every test has registered (from a doctest
// listener, constructed when the run starts): the smoothing tests it fails are worth 0, every other test 10x,
// and no test is hidden.
// A modified copy of the lab 01 smoothing.cpp, graded by tests/grading/adversarial/run.sh.
#include <string>

#include "geolab/halfedge.hpp"
#include "geolab/grading/test.hpp"

namespace {
struct Editor : doctest::IReporter {
    explicit Editor(const doctest::ContextOptions&) {
        for (auto& [name, meta] : geolab::test_registry()) {
            meta.points = name.find("smooth") != std::string::npos ? 0 : meta.points * 10;
            meta.hidden = false;
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
DOCTEST_REGISTER_LISTENER("geolab-registry-editor", 0, Editor);

namespace geolab::halfedge {

void laplacian_smoothing(Mesh& mesh, double t, int iterations) {
    throw geolab::NotImplemented(__func__);  // the honest part: nothing done
}

}  // namespace geolab::halfedge
