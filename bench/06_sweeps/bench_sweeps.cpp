// Lab 06 benchmark: a trefoil knot swept with a 64-point circle, 100,000 path samples (12.8M triangles). Times
// rotation_minimizing_frames, sweep, and the two together (the goal: ≤ 1.0 s single thread), 5 repetitions;
// prints the medians and whether the goal is met. The variant being built (the reference here).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>

#include <glm/geometric.hpp>

#include "geolab/sweeps.hpp"

namespace {
using namespace geolab::sweeps;
constexpr int kSamples = 100000, kProfile = 64;

const Path& path() {
    static const Path p = trefoil_path(kSamples, 1.0);
    return p;
}
const Profile& profile() {
    static const Profile p{circle_loop({0, 0}, 0.3, kProfile), {}};
    return p;
}
glm::dvec3 first_normal() { return glm::cross(path().tangents[0], glm::dvec3(0, 0, 1)); }

void frames(benchmark::State& st) {
    for (auto _ : st) benchmark::DoNotOptimize(rotation_minimizing_frames(path(), first_normal()));
}
void mesh(benchmark::State& st) {
    const RmfResult r = rotation_minimizing_frames(path(), first_normal());
    std::size_t faces = 0;
    for (auto _ : st) {
        const geolab::PolygonSoup m = sweep(profile(), path(), r.frames);
        faces = m.n_faces();
        benchmark::DoNotOptimize(m.positions.data());
    }
    st.counters["triangles"] = static_cast<double>(faces);
}
void both(benchmark::State& st) {
    std::size_t faces = 0;
    for (auto _ : st) {
        const RmfResult r = rotation_minimizing_frames(path(), first_normal());
        const geolab::PolygonSoup m = sweep(profile(), path(), r.frames);
        faces = m.n_faces();
        benchmark::DoNotOptimize(m.positions.data());
    }
    st.counters["triangles"] = static_cast<double>(faces);
}

class MedianReporter : public benchmark::ConsoleReporter {
public:
    std::map<std::string, double> median;
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const auto& r : runs)
            if (r.run_type == Run::RT_Aggregate && r.aggregate_name == "median")
                median[r.run_name.function_name] = r.GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(r.time_unit);
    }
};
}  // namespace

BENCHMARK(frames)->Name("trefoil 100k: RMF frames")->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(mesh)->Name("trefoil 100k x 64: sweep mesh")->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(both)->Name("trefoil 100k x 64: frames + mesh")->Unit(benchmark::kMillisecond)->Iterations(3);

int main(int argc, char** argv) {
    std::vector<char*> args(argv, argv + argc);
    static std::string reps = "--benchmark_repetitions=5";
    bool has = false;
    for (int i = 1; i < argc; ++i) has |= std::string(argv[i]).rfind("--benchmark_repetitions", 0) == 0;
    if (!has) args.push_back(reps.data());
    int n = static_cast<int>(args.size());
    benchmark::Initialize(&n, args.data());
    MedianReporter rep;
    benchmark::RunSpecifiedBenchmarks(&rep);
    benchmark::Shutdown();
    std::printf("\n%-36s %12s  %s\n", "task", "median (s)", "goal");
    for (const auto& [name, t] : rep.median) {
        const bool goal = name.find("frames + mesh") != std::string::npos;
        std::printf("%-36s %12.4f  %s\n", name.c_str(), t, goal ? (t <= 1.0 ? "<= 1.0 s  met" : "<= 1.0 s  NOT met") : "");
    }
    return 0;
}
