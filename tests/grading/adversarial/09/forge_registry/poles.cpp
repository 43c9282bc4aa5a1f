// ADVERSARIAL CASE forge_registry: edits the test registry once every test has registered (from a doctest
// listener, constructed when the run starts): the pole tests it fails are worth 0, every other test 10x,
// and no test is hidden.
// A modified copy of the lab 09 poles.cpp (Task 11), graded by tests/grading/adversarial_09/run.sh.
#include <string>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"
#include "geolab/grading/test.hpp"

namespace {
struct Editor : doctest::IReporter {
    explicit Editor(const doctest::ContextOptions&) {
        for (auto& [name, meta] : geolab::test_registry()) {
            meta.points = name.find("pole") != std::string::npos ? 0 : meta.points * 10;
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

namespace geolab::dc {

PoleFillResult fill_poles(PolygonSoup& soup, std::span<const PoleRing> rings, const ScalarField& f,
                          const glm::dvec3& origin, PoleFill::Method method) {
    throw geolab::NotImplemented(__func__);  // the honest part: nothing done
}

}  // namespace geolab::dc
