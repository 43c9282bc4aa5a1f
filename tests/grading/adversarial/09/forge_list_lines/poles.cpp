// ADVERSARIAL CASE forge_list_lines: a correct fill_poles that, when its program lists the tests, prints every
// test's JSON line 9 more times (a grader that takes every '{' line of the listing as a test counts it 10x).
// A modified copy of the lab 09 poles.cpp (Task 11), graded by tests/grading/adversarial_09/run.sh.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"
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

namespace geolab::dc {

PoleFillResult fill_poles(PolygonSoup& soup, std::span<const PoleRing> rings, const ScalarField& f,
                          const glm::dvec3& origin, PoleFill::Method method) {
    PoleFillResult out;
    out.first_face = soup.n_faces();
    if (method == PoleFill::none) return out;
    for (const PoleRing& pr : rings) {
        // a ring of 2 vertices bounds a hole whose two sides are the one edge {ring[0], ring[1]}, already shared by
        // two faces: the mesh is closed there, and a fan would put that edge into 4 faces
        if (pr.ring.size() < 3) continue;
        const glm::dvec3 axis(0.0, 0.0, pr.north ? 1.0 : -1.0);
        // vertical projection: the mean axial coordinate of the ring
        double s_vertical = 0.0;
        for (std::uint32_t v : pr.ring) s_vertical += glm::dot(axis, soup.positions[v] - origin);
        s_vertical /= double(pr.ring.size());
        double s = s_vertical;
        if (method == PoleFill::normal_projection) {
            // least-squares point of the axis on the ring's tangent planes: min Σ (nᵢ·(o + s a − vᵢ))²
            double num = 0.0, den = 0.0;
            for (std::uint32_t v : pr.ring) {
                glm::dvec3 g = f.gradient(soup.positions[v]);
                double len = glm::length(g);
                if (!(len > 0.0)) continue;
                glm::dvec3 n = g / len;
                double na = glm::dot(n, axis);
                num += na * glm::dot(n, soup.positions[v] - origin);
                den += na * na;
            }
            if (den >= 1e-12 * double(pr.ring.size())) s = num / den;
        }
        s = std::clamp(s, pr.r_lo, pr.r_hi);
        const std::uint32_t ghost = std::uint32_t(soup.positions.size());
        soup.positions.push_back(origin + s * axis);
        out.ghost_vertices.push_back(ghost);
        for (std::size_t i = 0; i < pr.ring.size(); ++i) {
            out.ring_vertices.push_back(pr.ring[i]);
            soup.add_face({ghost, pr.ring[i], pr.ring[(i + 1) % pr.ring.size()]});
        }
    }
    out.n_faces = soup.n_faces() - out.first_face;
    return out;
}

}  // namespace geolab::dc
