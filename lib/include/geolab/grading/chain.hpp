#pragma once
//! \file grading/chain.hpp
//! Tests that may depend on other tasks' answers, declared. DESIGN.md rule 6: a test of Task k must pass whatever
//! the student wrote for the other tasks, so a bug costs the points of its own task only. Two exceptions, each
//! declared at the test (and `geolab grade NN --independence`, which checks rule 6 on the reference one task file
//! stubbed at a time, leaves them out and lists them):
//!
//!  - a whole-chain test checks the tasks working together (one per lab, e.g. a one-shot pipeline):
//!
//!        TEST_CASE("sphere: the whole pipeline" * geolab::points(3) * geolab::whole_chain()) { ... }
//!
//!  - a test of a function the lab *defines* through another task's function (lab 08's voxelize_surface applies
//!    triangle_overlaps_voxel's rule, Task 2): the student's function calls their own, so no test data can
//!    separate the two. Name the tasks it builds on (comma-separated, "Task N" each):
//!
//!        TEST_CASE("surface: a cube on voxel boundaries" * geolab::points(4) * geolab::builds_on("Task 2")) { ... }
//!
//! A test that only *uses* another task's function to make its input is neither: give it that input another way
//! (stored with the fixture, or built by given or hidden code), as labs 01 and 09 do.
#include <map>
#include <string>

#include <doctest/doctest.h>

namespace geolab {

namespace detail {
//! Test name -> the tasks it may depend on ("*": every task, a whole-chain test).
std::map<std::string, std::string>& builds_on_tests();
}  // namespace detail

//! The test builds on these tasks' answers by the lab's design ("Task 2" or "Task 2, Task 3"; see above).
struct builds_on {
    const char* tasks;
    explicit builds_on(const char* t) : tasks(t) {}
    void fill(doctest::detail::TestCase& tc) const { detail::builds_on_tests()[tc.m_name] = tasks; }
    void fill(doctest::detail::TestSuite&) const {}
};
//! A whole-chain test: it may depend on every task (see above).
struct whole_chain {
    void fill(doctest::detail::TestCase& tc) const { detail::builds_on_tests()[tc.m_name] = "*"; }
    void fill(doctest::detail::TestSuite&) const {}
};

}  // namespace geolab
