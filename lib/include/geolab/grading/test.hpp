#pragma once
//! \file grading/test.hpp
//! Graded doctest cases. Every graded test declares its points, visibility and hint next to the test:
//!
//!     TEST_SUITE("Task 1: build") {
//!     TEST_CASE("tetrahedron: twins pair up" * geolab::points(2) * geolab::hint("h ^ 1 is the twin")) { ... }
//!     TEST_CASE("bunny: chi = 2" * geolab::points(3) * geolab::hidden()) { ... }
//!     }
//!
//! The suite name is the task the points count toward. A test without points() is ungraded (0 points).
//! Hidden tests live in tests/NN_lab/hidden/ so that the student release can leave them out.
#include <doctest/doctest.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace geolab {

//! What the grader knows of one test case, filled by the decorators below.
struct TestMeta {
    double points = 0;
    bool hidden = false;
    std::string hint;
    double timeout_s = 0;  //!< 0: the grader's default
};

//! The metadata of every registered test case, by test name (names are unique within one test program).
std::map<std::string, TestMeta>& test_registry();

namespace detail {
TestMeta& meta_for(const doctest::detail::TestCase& tc);
//! The pictures attached by the running test (paths), sent to the grader with the verdict.
std::vector<std::string>& attached_figures();
//! The name of the test case running now (empty outside one).
std::string& current_test();
}  // namespace detail

struct PolygonSoup;

//! Attach a picture to the running test: the student's mesh next to the reference, rendered headless into
//! $GEOLAB_FIGURE_DIR/<test>-<name>.png. Does nothing (and costs nothing) unless the grader set
//! GEOLAB_FIGURE_DIR; never fails the test (a rendering problem is silently skipped). Reports link the file.
void attach_mesh_figure(const std::string& name, const PolygonSoup& student, const PolygonSoup& reference);

//! The number of points this test is worth.
struct points {
    double value;
    explicit points(double v) : value(v) {}
    void fill(doctest::detail::TestCase& tc) const { detail::meta_for(tc).points = value; }
    void fill(doctest::detail::TestSuite&) const {}
};
//! The test runs in grading but its message is withheld from the student until it is released.
struct hidden {
    void fill(doctest::detail::TestCase& tc) const { detail::meta_for(tc).hidden = true; }
    void fill(doctest::detail::TestSuite&) const {}
};
//! A hint shown to the student when the test fails (what to look at, which handout section).
struct hint {
    const char* text;
    explicit hint(const char* t) : text(t) {}
    void fill(doctest::detail::TestCase& tc) const { detail::meta_for(tc).hint = text; }
    void fill(doctest::detail::TestSuite&) const {}
};
//! A wall-clock limit for this test, in seconds, if it needs more than the grader's default.
struct time_limit {
    double seconds;
    explicit time_limit(double s) : seconds(s) {}
    void fill(doctest::detail::TestCase& tc) const { detail::meta_for(tc).timeout_s = seconds; }
    void fill(doctest::detail::TestSuite&) const {}
};

//! Time one call into the student's code: runs f, which must make exactly one call of the lab's functions, and
//! returns that call's wall-clock seconds as the grader measures them. In a graded run the judge (which has no
//! student code) lets the student's process start the call and times it until the whole answer has arrived;
//! the student's process cannot report its own time (there it returns 0). Run directly (no grader), it is the
//! local wall clock. Like all test code, the code around it must be deterministic: the performer and the judge
//! run it alike, and the judge answers call N with the performer's answer to call N.
double time_student_call(const std::function<void()>& f);

//! Relative tolerance helper: |a - b| <= rel * scale, for messages that say what was compared.
inline bool near(double a, double b, double rel, double scale = 1.0) {
    double d = a - b;
    return (d < 0 ? -d : d) <= rel * scale;
}

}  // namespace geolab
