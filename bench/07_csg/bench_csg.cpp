// Lab 07 benchmark (the variant being built: the reference here, the student's code in the release):
//  - ray-cast the CSG logo (data/scenes/csg_logo.scad, read by lib's OpenSCAD reader) at 1024×1024: the tree
//    prepared once, one first_hit per pixel with a SpanLists per thread; single thread (on the benchmark's own
//    thread) and 2 threads (rows interleaved, one SpanLists each); render_image (the same casts plus shading);
//  - polygonize the logo at resolution 256 (mesh_tree: lib's polygonizer on sdf of the prepared tree).
// Goal (issue #19): ≥ 5M rays/s single thread. The machine is shared, so besides wall-clock rays/s the benchmark
// reports rays per CPU second (rays_per_cpu_s: the casting threads' CPU time), and the ratio of each to the goal.
// Quote medians (5 repetitions by default; --benchmark_repetitions=N) and the machine's load.
#include <atomic>
#include <chrono>
#include <cmath>
#include <ctime>
#include <thread>
#include <vector>

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include "common/ratio_main.hpp"
#include "geolab/config.hpp"
#include "geolab/csg.hpp"
#include "geolab/scad.hpp"

namespace {
using namespace geolab::csg;

constexpr int N = 1024;
constexpr double goal_rays_per_s = 5e6;

const Tree& logo() {
    static const Tree t = from_scad(geolab::scad::read(std::string(geolab::config::source_dir) + "/data/scenes/csg_logo.scad"));
    return t;
}

PinholeCamera camera() {
    PinholeCamera c;
    c.up = {0, 0, 1};
    c.eye = 7.5 * glm::normalize(glm::dvec3(1.0, 0.75, 0.65));
    c.fov_deg = 30;
    return c;
}

double seconds(clockid_t clock) {
    timespec ts{};
    clock_gettime(clock, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// Casts the rows y ≡ first (mod step) with the thread's own span lists; returns the number of hits.
long cast_rows(const PreparedTree& t, const PinholeCamera& cam, int first, int step) {
    SpanLists lists;
    long hits = 0;
    for (int y = first; y < N; y += step)
        for (int x = 0; x < N; ++x) hits += first_hit(t, cam.ray(x, y, N, N), 0.0, lists).has_value();
    return hits;
}

// Rays per wall second and per CPU second, and both against the goal.
void report(benchmark::State& state, double wall, double cpu, long hits) {
    const double rays = double(state.iterations()) * N * N;
    state.counters["rays_per_s"] = rays / wall;
    state.counters["rays_per_cpu_s"] = rays / cpu;
    state.counters["wall_vs_goal"] = rays / wall / goal_rays_per_s;
    state.counters["cpu_vs_goal"] = rays / cpu / goal_rays_per_s;
    state.counters["hit_fraction"] = double(hits) / (double(N) * N);
}

// Single thread: every ray on the benchmark's own thread (its CPU time is the casting's).
void raycast_1(benchmark::State& state) {
    const PreparedTree t = prepare(logo());
    const PinholeCamera cam = camera();
    long hits = 0;
    double wall = 0, cpu = 0;
    for (auto _ : state) {
        const double w0 = seconds(CLOCK_MONOTONIC), c0 = seconds(CLOCK_THREAD_CPUTIME_ID);
        hits = cast_rows(t, cam, 0, 1);
        wall += seconds(CLOCK_MONOTONIC) - w0;
        cpu += seconds(CLOCK_THREAD_CPUTIME_ID) - c0;
        benchmark::DoNotOptimize(hits);
    }
    report(state, wall, cpu, hits);
}

// Two threads sharing the prepared tree, each with its own span lists (CPU time: the whole process's).
void raycast_2(benchmark::State& state) {
    const PreparedTree t = prepare(logo());
    const PinholeCamera cam = camera();
    long hits = 0;
    double wall = 0, cpu = 0;
    for (auto _ : state) {
        const double w0 = seconds(CLOCK_MONOTONIC), c0 = seconds(CLOCK_PROCESS_CPUTIME_ID);
        std::atomic<long> total{0};
        std::vector<std::thread> pool;
        for (int k = 0; k < 2; ++k) pool.emplace_back([&, k] { total += cast_rows(t, cam, k, 2); });
        for (auto& th : pool) th.join();
        wall += seconds(CLOCK_MONOTONIC) - w0;
        cpu += seconds(CLOCK_PROCESS_CPUTIME_ID) - c0;
        hits = total;
        benchmark::DoNotOptimize(hits);
    }
    report(state, wall, cpu, hits);
}

// render_image: prepare, the same casts, and the Lambert shading into an image (single thread).
void render_1(benchmark::State& state) {
    const Tree& t = logo();
    const PinholeCamera cam = camera();
    long hits = 0;
    double wall = 0, cpu = 0;
    for (auto _ : state) {
        const double w0 = seconds(CLOCK_MONOTONIC), c0 = seconds(CLOCK_THREAD_CPUTIME_ID);
        const geolab::render::Image img = render_image(t, cam, N, N, {0.4, 0.6, 1.0});
        wall += seconds(CLOCK_MONOTONIC) - w0;
        cpu += seconds(CLOCK_THREAD_CPUTIME_ID) - c0;
        hits = 0;
        for (std::size_t i = 0; i < img.rgba.size(); i += 4) hits += img.rgba[i] != 255;
    }
    report(state, wall, cpu, hits);
}

void polygonize256(benchmark::State& state) {
    const Tree& t = logo();
    std::size_t faces = 0;
    double vol = 0;
    for (auto _ : state) {
        const auto m = mesh_tree(t, 256);
        faces = m.n_faces();
        vol = volume(m);
    }
    state.counters["triangles"] = double(faces);
    state.counters["volume"] = vol;
}
}  // namespace

BENCHMARK(raycast_1)->Name("ray-cast logo 1024x1024/1 thread")->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
BENCHMARK(raycast_2)->Name("ray-cast logo 1024x1024/2 threads")->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
BENCHMARK(render_1)->Name("render_image logo 1024x1024/1 thread")->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
BENCHMARK(polygonize256)->Name("polygonize logo 256^3")->Unit(benchmark::kMillisecond)->Iterations(1);

int main(int argc, char** argv) { return geolab::bench::run_with_ratios(argc, argv, {}); }
