// ADVERSARIAL CASE forge_list_lines: a correct smoothing that, when its program lists the tests, prints every
// test's JSON line 9 more times (a grader that takes every '{' line of the listing as a test counts it 10x).
// A modified copy of the lab 01 smoothing.cpp, graded by tests/grading/adversarial/run.sh.
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "geolab/halfedge.hpp"
#include "geolab/grading/test.hpp"

namespace {
std::string quoted(const std::string& s) {
    std::string q = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') q += '\\';
        if (static_cast<unsigned char>(c) >= 0x20) q += c;
    }
    return q + "\"";
}
struct Repeater : doctest::IReporter {
    explicit Repeater(const doctest::ContextOptions&) {}
    void report_query(const doctest::QueryData& q) override {
        if (!q.data) return;
        for (unsigned i = 0; i < q.num_data; ++i)
            for (int k = 0; k < 9; ++k) {
                const doctest::TestCaseData& tc = *q.data[i];
                const geolab::TestMeta meta = geolab::test_registry()[tc.m_name];
                std::printf("{\"name\":%s,\"suite\":%s,\"points\":%g,\"hidden\":false,\"timeout\":0}\n",
                            quoted(tc.m_name).c_str(), quoted(tc.m_test_suite ? tc.m_test_suite : "").c_str(),
                            meta.points);
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
}  // namespace
DOCTEST_REGISTER_LISTENER("geolab-list-repeater", 0, Repeater);

namespace geolab::halfedge {

void laplacian_smoothing(Mesh& mesh, double t, int iterations) {
    if (!(t >= 0.0 && t <= 1.0))
        throw std::invalid_argument("laplacian_smoothing: t = " + std::to_string(t) + " is not in [0, 1]");
    if (iterations < 0)
        throw std::invalid_argument("laplacian_smoothing: iterations = " + std::to_string(iterations) + " < 0");
    std::vector<glm::dvec3> old;
    std::vector<Vertex> ring;
    for (int it = 0; it < iterations; ++it) {
        old = mesh.positions();
        for (Vertex v : mesh.vertices()) {
            if (mesh.is_boundary(v)) continue;
            one_ring_vertices(mesh, v, ring);
            glm::dvec3 mean(0.0);
            for (Vertex w : ring) mean += old[w.idx];
            mean /= static_cast<double>(ring.size());
            mesh.position(v) = old[v.idx] + t * (mean - old[v.idx]);
        }
    }
}

}  // namespace geolab::halfedge
