// The "student" code of the replay fixture: right answers, wrong ones, and attacks on the recording.
#include <csignal>
#include <stdexcept>
#include <thread>

#include <unistd.h>

#include "geolab/errors.hpp"
#include "geolab/grading/boundary_calls.hpp"
#include "replay_fixture.hpp"

namespace replay_fixture {
namespace {
// The recording's descriptor, as any code in the performer can find it (here: from the channel in memory).
int record_fd() { return geolab::boundary::channel().data_fd; }
void raw(geolab::wire::Writer& w) { (void)!::write(record_fd(), w.buffer().data(), w.buffer().size()); }
}  // namespace

int add(int a, int b) { return a + b; }
int add_wrong(int a, int b) { return a + b + 1; }
int not_written(int) { throw geolab::NotImplemented("not_written"); }
void fill(int n, std::vector<int>& out) {
    out.clear();
    for (int i = 0; i < n; ++i) out.push_back(i);
}
Stats stats(const std::vector<double>& xs) { return {static_cast<int>(xs.size()), xs, "stats"}; }
int checked_sqrt(int x) {
    if (x < 0) throw std::invalid_argument("checked_sqrt: x < 0");
    int r = 0;
    while ((r + 1) * (r + 1) <= x) ++r;
    return r;
}
int crash_in_call(int x) {
    std::raise(SIGSEGV);
    return x;
}
int exit_in_call(int) { ::_exit(0); }
int hang_in_call(int) {
    for (;;) ::pause();
}
int forge_record(int x) {
    const char junk[] = "passed passed passed";
    (void)!::write(record_fd(), junk, sizeof junk);
    return x;
}
std::vector<int> huge_count(int x) {
    geolab::wire::Writer w;  // call 1 "returned" a vector of 2^60 ints
    w.u32(huge_count_line);
    w.u32(1);
    w.u64(geolab::boundary::arg_digest<int>(x));  // the argument's digest, as the recorder writes it
    w.u8(0);
    w.u64(std::uint64_t{1} << 60);
    raw(w);
    ::_exit(0);
}
int answer_early(int x) {
    geolab::wire::Writer w;  // this call's answer (call 1), then the next call's (slow, call 2) before its "go"
    w.u32(answer_early_line);
    w.u32(1);
    w.u64(geolab::boundary::arg_digest<int>(x));
    w.u8(0);
    w.u32(static_cast<std::uint32_t>(x));
    int ms = 300;  // what the test passes to slow
    w.u32(slow_line);
    w.u32(2);
    w.u64(geolab::boundary::arg_digest<int>(ms));
    w.u8(0);
    const double fast = 0.0;
    w.bytes(&fast, sizeof fast);
    raw(w);
    return x;
}
double slow(int ms) {
    std::this_thread::sleep_for(std::chrono::milliseconds(ms));
    return ms;
}
int inc(int x) { return x + 1; }
int outer(int x) { return add(x, 0) + twice_inc(x); }
std::size_t bad_index(int) { return 1000000000; }
void Acc::add(int x) { total += x; }
int Acc::get() const { return total; }
double sum_calls(Fn f, int n) {
    double s = 0;
    for (int i = 0; i < n; ++i) s += f(i);
    return s;
}
int poke(const std::vector<int>& v) {
    const int n = int(v.size());
    const_cast<std::vector<int>&>(v).clear();
    return n;
}
}  // namespace replay_fixture

std::vector<int> replay_fixture::walk_forever(int x) {
    std::vector<int> seen;
    while (seen.size() < seen.max_size()) seen.push_back(x);  // never gets back to where it started
    return seen;
}
geolab::PolygonSoup replay_fixture::long_face(int) {
    geolab::PolygonSoup s;
    s.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    s.indices = {0, 1, 2};
    s.offsets = {0, 3, 1u << 28};
    return s;
}
geolab::PolygonSoup replay_fixture::bad_index_soup(int) {
    geolab::PolygonSoup s;
    s.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    s.add_face({0, 1, 5});
    return s;
}
geolab::render::Image replay_fixture::short_image(int w) {
    geolab::render::Image img;
    img.width = img.height = w;
    img.rgba = {1, 2, 3, 4};
    return img;
}
void replay_fixture::fill_soup(int x, std::vector<geolab::PolygonSoup>& out) {
    out.clear();
    out.push_back(bad_index_soup(x));
    out.back().indices.back() = 2;
    out.push_back(long_face(x));
}
