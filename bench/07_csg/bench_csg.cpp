// Lab 07 benchmark (the variant being built: the reference here, the student's code in the release):
//  - ray-cast the CSG logo (data/scenes/csg_logo.scad, read by lib's OpenSCAD reader) at 1024×1024, one first_hit
//    per pixel, single thread and 2 threads (rows interleaved); reports rays/s (goal ≥ 5M rays/s single thread);
//  - polygonize the logo at resolution 256 (mesh_tree: lib's polygonizer on sdf) and report the time.
// Quote medians (5 repetitions by default; --benchmark_repetitions=N) and the machine's load.
#include <atomic>
#include <cmath>
#include <numbers>
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

constexpr int N = 1024;

// Casts the rows y ≡ first (mod step); returns the number of hits.
long cast_rows(const Tree& t, const PinholeCamera& cam, int first, int step) {
    long hits = 0;
    for (int y = first; y < N; y += step)
        for (int x = 0; x < N; ++x) hits += first_hit(t, cam.ray(x, y, N, N), 0.0).has_value();
    return hits;
}

void raycast(benchmark::State& state) {
    const int threads = int(state.range(0));
    const Tree& t = logo();
    const PinholeCamera cam = camera();
    long hits = 0;
    for (auto _ : state) {
        std::atomic<long> total{0};
        std::vector<std::thread> pool;
        for (int k = 0; k < threads; ++k) pool.emplace_back([&, k] { total += cast_rows(t, cam, k, threads); });
        for (auto& th : pool) th.join();
        hits = total;
        benchmark::DoNotOptimize(hits);
    }
    state.SetItemsProcessed(state.iterations() * N * N);  // items/s = rays/s
    state.counters["hit_fraction"] = double(hits) / (double(N) * N);
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

BENCHMARK(raycast)->Name("ray-cast logo 1024x1024/1 thread")->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
BENCHMARK(raycast)->Name("ray-cast logo 1024x1024/2 threads")->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
BENCHMARK(polygonize256)->Name("polygonize logo 256^3")->Unit(benchmark::kMillisecond)->Iterations(1);

int main(int argc, char** argv) { return geolab::bench::run_with_ratios(argc, argv, {}); }
