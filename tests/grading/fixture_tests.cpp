// A test program whose cases misbehave on purpose, one way each: the grader must isolate and classify them.
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <thread>
#include <vector>

#include <unistd.h>

#include "geolab/errors.hpp"
#include "geolab/soup.hpp"
#include "geolab/grading/chain.hpp"
#include "geolab/grading/test.hpp"

TEST_SUITE("fixtures") {
TEST_CASE("passes" * geolab::points(1)) { CHECK(1 + 1 == 2); }
TEST_CASE("fails an assertion" * geolab::points(1) * geolab::hint("look at the sum")) {
    int sum = 1 + 1;
    INFO("input: 1 + 1");
    CHECK(sum == 3);
}
TEST_CASE("expects an exception that never comes" * geolab::points(1)) {
    CHECK_THROWS_AS([] { return 1; }(), std::invalid_argument);
}
TEST_CASE("not implemented" * geolab::points(1)) { CHECK(([]() -> int { throw geolab::NotImplemented("answer"); })() == 42); }
TEST_CASE("segfaults" * geolab::points(1)) {
    std::raise(SIGSEGV);
    CHECK(true);
}
TEST_CASE("aborts" * geolab::points(1)) {
    std::abort();
}
TEST_CASE("hangs" * geolab::points(1) * geolab::time_limit(1)) {
    for (;;) ::pause();
}
TEST_CASE("a stub that escapes the test" * geolab::points(1)) { throw geolab::NotImplemented("answer2"); }
TEST_CASE("a stub caught then a wrong value" * geolab::points(1)) {
    int value = 0;
    try {
        throw geolab::NotImplemented("helper");
    } catch (const std::logic_error&) {
        value = -1;
    }
    CHECK(value == 1);
}
TEST_CASE("segfaults on a named input" * geolab::points(1)) {
    INFO("fixture 'triangle'");
    CHECK(1 + 1 == 2);
    std::raise(SIGSEGV);
}
TEST_CASE("exits early with status 0" * geolab::points(1)) {
    std::exit(0);
}
TEST_CASE("quick_exit" * geolab::points(1)) {
    std::quick_exit(0);
}
TEST_CASE("floods stdout" * geolab::points(1)) {
    std::string line(1000, 'x');
    for (;;) std::cout << line << "\n";
}
TEST_CASE("prints a fake success" * geolab::points(1)) {
    std::cout << "[doctest] Status: SUCCESS!\n0123456789abcdef0123456789abcdef {\"status\":\"passed\"}\n";
    CHECK(false);
}
TEST_CASE("leaves a child that sleeps forever" * geolab::points(1) * geolab::time_limit(5)) {
    if (::fork() == 0) {
        for (;;) ::pause();
    }
    CHECK(true);
}
TEST_CASE("allocates without bound" * geolab::points(1)) {
    std::vector<std::vector<char>> hog;
    for (;;) hog.emplace_back(std::size_t(64) << 20, 'x');
}
TEST_CASE("throws an unexpected exception" * geolab::points(1)) { throw std::runtime_error("boom"); }
TEST_CASE("hidden and passes" * geolab::points(2) * geolab::hidden() * geolab::builds_on("Task 2")) { CHECK(true); }
TEST_CASE("ungraded" * geolab::whole_chain()) { CHECK(true); }
TEST_CASE("attaches a figure") {
    geolab::PolygonSoup tri;
    tri.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    tri.add_face({0, 1, 2});
    geolab::attach_mesh_figure("triangle", tri, tri);
    CHECK(true);
}
}
