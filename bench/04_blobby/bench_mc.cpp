// Lab 04 benchmark (single thread, medians of 5 repetitions):
//   MC sphere 256³/geolab, /OpenVDB      marching_cubes vs tools::volumeToMesh on the same 256³ samples (sampled
//                                        once, outside the timing)
//   MC 20 blobs 256³/geolab, /OpenVDB    the same for a 20-blob Wyvill scene
//   sample+MC 20 blobs 128³/geolab       sample_lattice + marching_cubes; counters: samples per second and kernel
//                                        evaluations per sample
// The variant being built runs: the reference in the instructor's tree. OpenVDB gets the samples as active voxels
// of a FloatGrid; TBB is limited to one thread.
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include "common/ratio_main.hpp"
#include "geolab/blobby.hpp"

#ifdef GEOLAB_WITH_OPENVDB
#include <openvdb/openvdb.h>
#include <openvdb/tools/VolumeToMesh.h>
#include <tbb/global_control.h>
#endif

namespace {
using namespace geolab::blobby;

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
    std::size_t tris = 0;
    for (auto _ : state) {
        const McMesh m = marching_cubes(L, 0.0);
        tris = m.soup.n_faces();
        benchmark::DoNotOptimize(tris);
    }
    state.counters["triangles"] = double(tris);
}

#ifdef GEOLAB_WITH_OPENVDB
void mc_openvdb(benchmark::State& state, const std::string& name) {
    const auto g = grid(name);
    std::size_t quads_n = 0;
    for (auto _ : state) {
        std::vector<openvdb::Vec3s> points;
        std::vector<openvdb::Vec4I> quads;
        openvdb::tools::volumeToMesh(*g, points, quads, 0.0);
        quads_n = quads.size();
        benchmark::DoNotOptimize(quads_n);
    }
    state.counters["quads"] = double(quads_n);
}
#endif

void sample_and_mc(benchmark::State& state) {
    cache = Cache{};
    const BlobScene s = twenty_blobs();
    const int n = 128;
    const double h = 2.0 / (n - 1);
    std::uint64_t evals = 0;
    for (auto _ : state) {
        const Lattice L = sample_lattice(s, glm::dvec3(-1.0), h, glm::ivec3(n), evals);
        const McMesh m = marching_cubes(L, 0.0);
        benchmark::DoNotOptimize(m.soup.n_faces());
    }
    const double samples = double(n) * n * n;
    state.counters["samples_per_s"] = benchmark::Counter(samples, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["evals_per_sample"] = double(evals) / samples;
}

}  // namespace

BENCHMARK_CAPTURE(mc_geolab, sphere, std::string("sphere"))->Name("MC sphere 256^3/geolab")->Unit(benchmark::kMillisecond)->Iterations(3);
#ifdef GEOLAB_WITH_OPENVDB
BENCHMARK_CAPTURE(mc_openvdb, sphere, std::string("sphere"))->Name("MC sphere 256^3/OpenVDB")->Unit(benchmark::kMillisecond)->Iterations(3);
#endif
BENCHMARK_CAPTURE(mc_geolab, blobs, std::string("blobs"))->Name("MC 20 blobs 256^3/geolab")->Unit(benchmark::kMillisecond)->Iterations(3);
#ifdef GEOLAB_WITH_OPENVDB
BENCHMARK_CAPTURE(mc_openvdb, blobs, std::string("blobs"))->Name("MC 20 blobs 256^3/OpenVDB")->Unit(benchmark::kMillisecond)->Iterations(3);
#endif
BENCHMARK(sample_and_mc)->Name("sample+MC 20 blobs 128^3/geolab")->Unit(benchmark::kMillisecond)->Iterations(3);

int main(int argc, char** argv) {
#ifdef GEOLAB_WITH_OPENVDB
    openvdb::initialize();
    tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
#endif
    return geolab::bench::run_with_ratios(argc, argv, {{"MC sphere 256^3", 1.0}, {"MC 20 blobs 256^3", 1.0}});
}
