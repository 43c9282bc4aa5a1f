// The tests of the replay fixture (one program per side: performer and judge), graded by test_grader.cpp.
#include <stdexcept>
#include <vector>

#include "geolab/grading/test.hpp"
#include "replay_fixture.hpp"

using namespace replay_fixture;

TEST_SUITE("Task 1: replay") {
TEST_CASE("right answers pass" * geolab::points(1)) {
    CHECK(add(2, 3) == 5);
    std::vector<int> out{7, 7};
    fill(3, out);
    CHECK(out == std::vector<int>{0, 1, 2});
    const Stats s = stats({1.5, 2.5});
    CHECK(s.count == 2);
    CHECK(s.values == std::vector<double>{1.5, 2.5});
    CHECK(s.label == "stats");
    CHECK(checked_sqrt(17) == 4);
    CHECK_THROWS_WITH_AS(checked_sqrt(-1), "checked_sqrt: x < 0", std::invalid_argument);
}
TEST_CASE("a wrong answer fails" * geolab::points(1)) { CHECK(add_wrong(2, 3) == 5); }
TEST_CASE("not implemented" * geolab::points(1)) { CHECK(not_written(1) == 1); }
TEST_CASE("crashes in its second call" * geolab::points(1)) {
    CHECK(add(1, 1) == 2);
    CHECK(crash_in_call(1) == 1);
}
TEST_CASE("crashes on a named input" * geolab::points(1)) {
    INFO("fixture 'pair'");
    CHECK(add(1, 1) == 2);
    CHECK(crash_in_call(1) == 1);
}
TEST_CASE("walks without end" * geolab::points(1)) {
    INFO("fixture 'loop'");
    CHECK(add(2, 2) == 4);
    CHECK(walk_forever(3).size() == 3);
}
TEST_CASE("exits in a call" * geolab::points(1)) { CHECK(exit_in_call(1) == 1); }
TEST_CASE("hangs in a call" * geolab::points(1) * geolab::time_limit(1)) { CHECK(hang_in_call(1) == 1); }
TEST_CASE("forges bytes on the record pipe" * geolab::points(1)) { CHECK(forge_record(1) == 1); }
TEST_CASE("claims a vector larger than the recording" * geolab::points(1)) { CHECK(huge_count(1).empty()); }
TEST_CASE("a timed call is timed by the judge" * geolab::points(1) * geolab::hidden()) {
    int got = 0;
    const double seconds = geolab::time_student_call([&] { got = static_cast<int>(slow(300)); });
    CHECK(got == 300);
    CHECK(seconds >= 0.29);
    CHECK(seconds < 5);
}
TEST_CASE("answers a timed call before it starts" * geolab::points(1)) {
    CHECK(answer_early(4) == 4);
    const double seconds = geolab::time_student_call([&] { slow(300); });
    CHECK(seconds < 0.1);
}
TEST_CASE("calls among the student's functions are not recorded" * geolab::points(1)) { CHECK(outer(1) == 4); }
TEST_CASE("an index out of range stops the judge" * geolab::points(1)) {
    std::vector<int> v(3, 0);
    CHECK(v[bad_index(0)] == 0);  // operator[]: the judge is built with _GLIBCXX_ASSERTIONS
}
TEST_CASE("member functions cross the boundary" * geolab::points(1)) {
    Acc a;
    a.add(2);
    a.add(3);
    CHECK(a.total == 5);
    CHECK(a.get() == 5);
}
TEST_CASE("callbacks are replayed into the judge's own function" * geolab::points(1)) {
    int calls = 0;
    auto g = [&](double t) {
        ++calls;
        return 2 * t;
    };
    CHECK(sum_calls(g, 4) == 12);
    CHECK(calls == 4);  // the judge's count: it replays the student's 4 calls into its own g
}
TEST_CASE("changing the test's data shows as different arguments" * geolab::points(1)) {
    const std::vector<int> v{1, 2, 3};
    CHECK(poke(v) == 3);
    CHECK(poke(v) == 3);  // the performer's v was cleared by the first call; the judge's was not
}
}
// Answers whose own invariants are broken: code in the judge that walks them would read outside them.
TEST_CASE("a soup whose face runs past its indices is refused" * geolab::points(1)) {
    const geolab::PolygonSoup s = long_face(1);
    std::size_t n = 0;
    for (std::size_t f = 0; f < s.n_faces(); ++f) n += s.face(f).size();
    CHECK(n == 3);
}
TEST_CASE("a soup whose index names no position is refused" * geolab::points(1)) {
    CHECK(bad_index_soup(1).positions.size() == 3);
}
TEST_CASE("an image shorter than its size is refused" * geolab::points(1)) {
    const geolab::render::Image img = short_image(64);
    CHECK(img.pixel(63, 63)[0] == 0);
}
TEST_CASE("a broken soup in an out-argument is refused" * geolab::points(1)) {
    std::vector<geolab::PolygonSoup> out;
    fill_soup(1, out);
    CHECK(out.size() == 2);
}

