// Lab 04 benchmark (single thread; 5 repetitions of 3 iterations by default, medians):
//   MC sphere 256³/geolab, /OpenVDB      marching_cubes vs tools::volumeToMesh on the same 256³ samples (sampled
//                                        once, outside the timing)
//   MC 20 blobs 256³/geolab, /OpenVDB    the same for a 20-blob Wyvill scene
//   sample 20 blobs 128³/geolab          sample_lattice alone: samples per second, kernel evaluations per sample
//   sample+MC 20 blobs 128³/geolab       sample_lattice + marching_cubes (goal ≤ 0.1 s)
// Every run reports its minor page faults per iteration ("faults"). The ratio tables pair geolab with OpenVDB from
// this run's medians, wall and CPU time (the machine is shared: CPU time is the fairer number under load); the
// absolute goals (sphere ≤ 0.25 s, sample+MC ≤ 0.1 s) are printed with both.
// The variant being built runs: the reference in the instructor's tree. OpenVDB gets the samples as active voxels
// of a FloatGrid (floats, no gradients; it outputs quads and no normals) and TBB is limited to one thread; geolab
// reads doubles and interpolates a normal per vertex from the sampled gradients.
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>


#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include "common/process_stats.hpp"
#include "common/ratio_main.hpp"
#include "geolab/blobby.hpp"

#ifdef GEOLAB_WITH_OPENVDB
#include <openvdb/openvdb.h>
#include <openvdb/tools/VolumeToMesh.h>
#include <tbb/global_control.h>
#endif

namespace {
using namespace geolab::blobby;

using geolab::bench::minor_faults;

BlobScene twenty_blobs() {
    BlobScene s;
    s.kernel = Kernel::wyvill;
    s.threshold = 0.5;
    std::uint64_t x = 12345;
    auto u = [&] {  // a small LCG: the same scene on every machine
        x = x * 6364136223846793005ull + 1442695040888963407ull;
        return double(x >> 11) / double(1ull << 53);
    };
    for (int i = 0; i < 20; ++i) {
        Blob b;
        b.center = {1.4 * u() - 0.7, 1.4 * u() - 0.7, 1.4 * u() - 0.7};
        b.radius = 0.25 + 0.2 * u();
        b.strength = 1.0;
        s.blobs.push_back(b);
    }
    return s;
}

// One 256³ lattice at a time (about 0.5 GB with gradients).
struct Cache {
    std::string name;
    std::unique_ptr<Lattice> lattice;
#ifdef GEOLAB_WITH_OPENVDB
    openvdb::FloatGrid::Ptr grid;
#endif
} cache;

const Lattice& lattice(const std::string& name) {
    if (cache.name == name) return *cache.lattice;
    cache = Cache{};
    const int n = 256;
    const double h = 2.0 / (n - 1);
    if (name == "sphere") {
        auto L = std::make_unique<Lattice>();
        L->origin = glm::dvec3(-1.0);
        L->h = h;
        L->n = glm::ivec3(n);
        L->values.resize(std::size_t(n) * n * n);
        L->gradients.resize(L->values.size());
        std::size_t s = 0;
        for (int k = 0; k < n; ++k)
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i, ++s) {
                    const glm::dvec3 p = L->origin + h * glm::dvec3(i, j, k);
                    const double r = glm::length(p);
                    L->values[s] = r - 0.8;
                    L->gradients[s] = r > 0 ? p / r : glm::dvec3(0.0);
                }
        cache.lattice = std::move(L);
    } else {
        std::uint64_t evals = 0;
        cache.lattice = std::make_unique<Lattice>(sample_lattice(twenty_blobs(), glm::dvec3(-1.0), h, glm::ivec3(n), evals));
    }
    cache.name = name;
    return *cache.lattice;
}

#ifdef GEOLAB_WITH_OPENVDB
openvdb::FloatGrid::Ptr grid(const std::string& name) {
    const Lattice& L = lattice(name);
    if (cache.grid) return cache.grid;
    auto g = openvdb::FloatGrid::create(1.0f);
    auto acc = g->getAccessor();
    std::size_t s = 0;
    for (int k = 0; k < L.n.z; ++k)
        for (int j = 0; j < L.n.y; ++j)
            for (int i = 0; i < L.n.x; ++i, ++s) acc.setValue(openvdb::Coord(i, j, k), float(L.values[s]));
    cache.grid = g;
    return g;
}
#endif

void mc_geolab(benchmark::State& state, const std::string& name) {
    const Lattice& L = lattice(name);
    std::size_t tris = 0, verts = 0;
    long faults = 0;
    for (auto _ : state) {
        const long f0 = minor_faults();
        const McMesh m = marching_cubes(L, 0.0);
        faults += minor_faults() - f0;
        tris = m.soup.n_faces();
        verts = m.soup.n_vertices();
        benchmark::DoNotOptimize(tris);
    }
    state.counters["triangles"] = double(tris);
    state.counters["vertices"] = double(verts);
    state.counters["faults"] = benchmark::Counter(double(faults), benchmark::Counter::kAvgIterations);
}

#ifdef GEOLAB_WITH_OPENVDB
void mc_openvdb(benchmark::State& state, const std::string& name) {
    const auto g = grid(name);
    std::size_t quads_n = 0, points_n = 0;
    long faults = 0;
    for (auto _ : state) {
        const long f0 = minor_faults();
        std::vector<openvdb::Vec3s> points;
        std::vector<openvdb::Vec4I> quads;
        openvdb::tools::volumeToMesh(*g, points, quads, 0.0);
        faults += minor_faults() - f0;
        quads_n = quads.size();
        points_n = points.size();
        benchmark::DoNotOptimize(quads_n);
    }
    state.counters["quads"] = double(quads_n);
    state.counters["vertices"] = double(points_n);
    state.counters["faults"] = benchmark::Counter(double(faults), benchmark::Counter::kAvgIterations);
}
#endif

// sample_lattice of the 20-blob scene at 128³, and with `polygonize` its marching cubes too.
void sample_blobs(benchmark::State& state, bool polygonize) {
    cache = Cache{};
    const BlobScene s = twenty_blobs();
    const int n = 128;
    const double h = 2.0 / (n - 1);
    std::uint64_t evals = 0;
    long faults = 0;
    for (auto _ : state) {
        const long f0 = minor_faults();
        const Lattice L = sample_lattice(s, glm::dvec3(-1.0), h, glm::ivec3(n), evals);
        if (polygonize) {
            const McMesh m = marching_cubes(L, 0.0);
            benchmark::DoNotOptimize(m.soup.n_faces());
        }
        faults += minor_faults() - f0;
        benchmark::DoNotOptimize(L.values.data());
    }
    const double samples = double(n) * n * n;
    state.counters["samples_per_s"] = benchmark::Counter(samples, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["evals_per_sample"] = double(evals) / samples;
    state.counters["faults"] = benchmark::Counter(double(faults), benchmark::Counter::kAvgIterations);
}

//! The harness's reporter, also keeping the median CPU times (ratios and goals are printed on both).
class McReporter : public geolab::bench::RatioReporter {
public:
    std::map<std::string, double> cpu_seconds;  // full benchmark name → median CPU time (s)

    void ReportRuns(const std::vector<Run>& runs) override {
        RatioReporter::ReportRuns(runs);
        for (const auto& r : runs) {
            const bool aggregate = r.run_type == Run::RT_Aggregate;
            if (aggregate && r.aggregate_name != "median") continue;
            const double t = r.GetAdjustedCPUTime() / benchmark::GetTimeUnitMultiplier(r.time_unit);
            double& slot = cpu_seconds[r.run_name.function_name];
            if (aggregate || slot == 0) slot = t;
        }
    }
    double cpu(const std::string& name) const {
        auto t = cpu_seconds.find(name);
        return t == cpu_seconds.end() ? 0.0 : t->second;
    }
    double wall(const std::string& name) const {
        const auto slash = name.rfind('/');
        auto t = seconds.find(name.substr(0, slash));
        if (t == seconds.end()) return 0.0;
        auto s = t->second.find(name.substr(slash + 1));
        return s == t->second.end() ? 0.0 : s->second;
    }
};

}  // namespace

BENCHMARK_CAPTURE(mc_geolab, sphere, std::string("sphere"))->Name("MC sphere 256^3/geolab")->Unit(benchmark::kMillisecond)->Iterations(3);
#ifdef GEOLAB_WITH_OPENVDB
BENCHMARK_CAPTURE(mc_openvdb, sphere, std::string("sphere"))->Name("MC sphere 256^3/OpenVDB")->Unit(benchmark::kMillisecond)->Iterations(3);
#endif
BENCHMARK_CAPTURE(mc_geolab, blobs, std::string("blobs"))->Name("MC 20 blobs 256^3/geolab")->Unit(benchmark::kMillisecond)->Iterations(3);
#ifdef GEOLAB_WITH_OPENVDB
BENCHMARK_CAPTURE(mc_openvdb, blobs, std::string("blobs"))->Name("MC 20 blobs 256^3/OpenVDB")->Unit(benchmark::kMillisecond)->Iterations(3);
#endif
BENCHMARK_CAPTURE(sample_blobs, sample, false)->Name("sample 20 blobs 128^3/geolab")->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(sample_blobs, sample_mc, true)->Name("sample+MC 20 blobs 128^3/geolab")->Unit(benchmark::kMillisecond)->Iterations(3);

int main(int argc, char** argv) {
#ifdef GEOLAB_WITH_OPENVDB
    openvdb::initialize();
    tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
#endif
    // run_with_ratios of common/ratio_main.hpp, with a reporter that also keeps the CPU medians
    geolab::bench::initialize_with_repetitions(argc, argv);
    McReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    std::printf("\nwall-time medians:");
    reporter.print_ratios({{"MC sphere 256^3", 1.0}, {"MC 20 blobs 256^3", 1.0}});

    std::printf("\nCPU-time medians:\n%-28s %12s %12s %10s %8s  %s\n", "task", "geolab (s)", "peer (s)", "peer", "ratio", "goal");
    for (const char* task : {"MC sphere 256^3", "MC 20 blobs 256^3"}) {
        const double g = reporter.cpu(std::string(task) + "/geolab"), p = reporter.cpu(std::string(task) + "/OpenVDB");
        if (g > 0 && p > 0)
            std::printf("%-28s %12.4f %12.4f %10s %8.3f  <= 1.00  %s\n", task, g, p, "OpenVDB", g / p,
                        g <= p ? "met" : "NOT met");
    }

    std::printf("\nabsolute goals (medians):\n");
    auto goal_line = [&](const std::string& name, double goal) {
        const double wall = reporter.wall(name), cpu = reporter.cpu(name);
        if (wall <= 0) return;
        std::printf("%-36s wall %8.4f s %-8s cpu %8.4f s %-8s goal <= %.2f s\n", name.c_str(), wall,
                    wall <= goal ? "(met)" : "(NOT met)", cpu, cpu <= goal ? "(met)" : "(NOT met)", goal);
    };
    goal_line("MC sphere 256^3/geolab", 0.25);
    goal_line("sample+MC 20 blobs 128^3/geolab", 0.1);
    benchmark::Shutdown();
    return 0;
}
