// Lab 08 benchmark of Task 7 (the variant being built: the reference here, the student's code in the release):
//  - "solid bunny00 N^3/geolab": voxelize_gl along z (OSMesa, llvmpipe: one context, N slabs drawn and read back);
//  - "solid bunny00 N^3/cpu 2 threads": voxelize_solid with 2 threads on the same mesh and grid, same run;
//  - "OSMesa context NxN": creating and destroying a SliceRasterizer of that size (part of every voxelize_gl).
// Wall time, plus the process's CPU time (user + sys of every thread, llvmpipe's included) per run in the counter
// "process_cpu_ms" (the "CPU" column counts the main thread only). The goal: ≤ 2 s at 256³ slice by slice. 5 repetitions
// by default, medians; the table ends with the ratios GL / CPU. Quote the machine's load with the numbers.
#include <sys/resource.h>

#include <map>
#include <stdexcept>

#include <benchmark/benchmark.h>

#include "common/ratio_main.hpp"
#include "geolab/io.hpp"
#include "geolab/models.hpp"
#include "geolab/render/slicer.hpp"
#include "geolab/voxels.hpp"

namespace {
using namespace geolab::voxels;

// bunny00 in the grid units of a res³ grid (fit_grid, one empty layer around), loaded once per resolution.
const geolab::PolygonSoup& bunny_in_grid(std::int64_t res) {
    static std::map<std::int64_t, geolab::PolygonSoup> cache;
    auto it = cache.find(res);
    if (it == cache.end()) {
        const auto path = geolab::model_path("bunny00");
        if (!path) throw std::runtime_error("bunny00 not found: run tools/fetch_models.sh");
        const geolab::PolygonSoup m = geolab::read_mesh(*path);
        it = cache.emplace(res, to_grid_units(m, fit_grid(m, res, 1))).first;
    }
    return it->second;
}

// user + sys CPU seconds of the whole process so far.
double process_cpu_s() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

void solid_gl(benchmark::State& state) {
    const std::int64_t res = state.range(0);
    const auto& mesh = bunny_in_grid(res);
    std::uint64_t voxels = 0;
    const double cpu0 = process_cpu_s();
    for (auto _ : state) {
        const BitGrid g = voxelize_gl(mesh, {res, res, res}, 2);
        voxels = count_set(g);
    }
    state.counters["voxels"] = double(voxels);
    state.counters["process_cpu_ms"] = 1e3 * (process_cpu_s() - cpu0) / double(state.iterations());
}

void solid_cpu(benchmark::State& state) {
    const std::int64_t res = state.range(0);
    const auto& mesh = bunny_in_grid(res);
    std::uint64_t voxels = 0;
    const double cpu0 = process_cpu_s();
    for (auto _ : state) {
        const SolidResult s = voxelize_solid(mesh, {res, res, res}, 2);
        voxels = count_set(s.grid);
    }
    state.counters["voxels"] = double(voxels);
    state.counters["process_cpu_ms"] = 1e3 * (process_cpu_s() - cpu0) / double(state.iterations());
}

void context(benchmark::State& state) {
    const int n = int(state.range(0));
    for (auto _ : state) {
        geolab::render::SliceRasterizer r(n, n);
        benchmark::DoNotOptimize(r.width());
    }
}

}  // namespace

BENCHMARK(solid_gl)->Name("solid bunny00 128^3/geolab")->Arg(128)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(solid_cpu)->Name("solid bunny00 128^3/cpu 2 threads")->Arg(128)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(solid_gl)->Name("solid bunny00 256^3/geolab")->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(solid_cpu)->Name("solid bunny00 256^3/cpu 2 threads")->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(solid_gl)->Name("solid bunny00 512^3/geolab")->Arg(512)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(solid_cpu)->Name("solid bunny00 512^3/cpu 2 threads")->Arg(512)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(context)->Name("OSMesa context 256x256")->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

int main(int argc, char** argv) { return geolab::bench::run_with_ratios(argc, argv, {}); }
