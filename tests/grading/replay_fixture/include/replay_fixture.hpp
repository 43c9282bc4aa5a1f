#pragma once
// A tiny lab with a grading boundary, for the grader's own tests of record and replay (test_grader.cpp): its
// "student" code (student.cpp) answers right, wrong, or attacks the recording; given.cpp is given code.
#include <cstddef>
#include <string>
#include <vector>

#include "geolab/boundary.hpp"
#include "geolab/render/image.hpp"
#include "geolab/soup.hpp"

namespace replay_fixture {

struct Stats {
    int count = 0;
    std::vector<double> values;
    std::string label;
    GEOLAB_FIELDS(count, values, label)
};

int add(int a, int b);                         // right
int add_wrong(int a, int b);                   // a + b + 1
int not_written(int a);                        // throws geolab::NotImplemented
void fill(int n, std::vector<int>& out);       // out = 0..n-1
Stats stats(const std::vector<double>& xs);    // count, values, label "stats"
int checked_sqrt(int x);                       // throws std::invalid_argument("checked_sqrt: x < 0") for x < 0
int crash_in_call(int x);                      // raises SIGSEGV
int exit_in_call(int x);                       // _exit(0)
int hang_in_call(int x);                       // blocks forever
int forge_record(int x);                       // writes garbage to the record pipe, returns x
std::vector<int> huge_count(int x);            // writes a record claiming 2^60 elements
int answer_early(int x);                       // writes its own record and the next (timed) call's before returning
double slow(int ms);                           // sleeps ms milliseconds, returns ms
int inc(int x);                                // x + 1
int outer(int x);                              // add(x, 0) + twice_inc(x): student -> student, student -> given -> student
std::size_t bad_index(int x);                  // 1'000'000'000
std::vector<int> walk_forever(int x);          // collects x without end (an endless walk): hits the memory cap

// A member function and a const one (the object is compared before and, non-const, recorded after the call).
struct Acc {
    int total = 0;
    GEOLAB_FIELDS(total)
    void add(int x);       // total += x
    int get() const;       // total
};
// A function reference like lab 09's FunctionRef: a callback the student's code calls.
class Fn {
public:
    template <class F>
    Fn(F& f)
        : obj_(const_cast<void*>(static_cast<const void*>(&f))),
          call_([](void* o, double t) { return double((*static_cast<F*>(o))(t)); }) {}
    double operator()(double t) const { return call_(obj_, t); }

private:
    void* obj_;
    double (*call_)(void*, double);
};
double sum_calls(Fn f, int n);                 // f(0) + ... + f(n - 1)
int poke(const std::vector<int>& v);           // returns v.size(), but first clears the test's vector (const cast)
geolab::PolygonSoup long_face(int x);          // 3 positions, offsets {0, 3, 2^28}: face 1 spans far past the indices
geolab::PolygonSoup bad_index_soup(int x);     // a triangle {0, 1, 5} of 3 positions
geolab::render::Image short_image(int w);      // w x w pixels with the bytes of one
void fill_soup(int x, std::vector<geolab::PolygonSoup>& out);  // out = {a good soup, long_face(x)}

// GIVEN: inc(inc(x)) (given code calls the student's inc).
int twice_inc(int x);

// The lines of two entries below, which the attacks need to forge records.
inline constexpr unsigned huge_count_line = __LINE__ + 15;
inline constexpr unsigned answer_early_line = __LINE__ + 15;
inline constexpr unsigned slow_line = __LINE__ + 15;

#ifdef GEOLAB_BOUNDARY
GEOLAB_BOUNDARY(add, int(int, int))
GEOLAB_BOUNDARY(add_wrong, int(int, int))
GEOLAB_BOUNDARY(not_written, int(int))
GEOLAB_BOUNDARY(fill, void(int, std::vector<int>&))
GEOLAB_BOUNDARY(stats, Stats(const std::vector<double>&))
GEOLAB_BOUNDARY(checked_sqrt, int(int))
GEOLAB_BOUNDARY(crash_in_call, int(int))
GEOLAB_BOUNDARY(exit_in_call, int(int))
GEOLAB_BOUNDARY(hang_in_call, int(int))
GEOLAB_BOUNDARY(forge_record, int(int))
GEOLAB_BOUNDARY(huge_count, std::vector<int>(int))
GEOLAB_BOUNDARY(answer_early, int(int))
GEOLAB_BOUNDARY(slow, double(int))
GEOLAB_BOUNDARY(inc, int(int))
GEOLAB_BOUNDARY(outer, int(int))
GEOLAB_BOUNDARY(bad_index, std::size_t(int))
GEOLAB_BOUNDARY(walk_forever, std::vector<int>(int))
GEOLAB_BOUNDARY(Acc::add, void (Acc::*)(int))
GEOLAB_BOUNDARY(Acc::get, int (Acc::*)() const)
GEOLAB_BOUNDARY(sum_calls, double(Fn, int))
GEOLAB_BOUNDARY(poke, int(const std::vector<int>&))
GEOLAB_BOUNDARY(long_face, geolab::PolygonSoup(int))
GEOLAB_BOUNDARY(bad_index_soup, geolab::PolygonSoup(int))
GEOLAB_BOUNDARY(short_image, geolab::render::Image(int))
GEOLAB_BOUNDARY(fill_soup, void(int, std::vector<geolab::PolygonSoup>&))
#endif

}  // namespace replay_fixture
