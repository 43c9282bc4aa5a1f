// Lab 01 benchmark: half-edge construction from a 1M-face triangle soup, and a full one-ring sweep (sum of the
// neighbours' positions at every vertex), geolab's reference vs OpenMesh, in one run; prints the ratios.
// Goal (issue 2): ≤ 1.0× OpenMesh for both.
// Also the build of a 400,000-triangle fan (one vertex of valence 400,001; issue 13: 55 s when the build was
// quadratic in valence). Each build reports its minor page faults per iteration ("faults") and the peak memory
// it adds above what the process held before it ("peak_MiB", measured once in a forked child).
#include <benchmark/benchmark.h>
#include <malloc.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "common/ratio_main.hpp"
#include "fuzz/hostile.hpp"
#include "geolab/fixtures.hpp"
#include "geolab/halfedge.hpp"

#ifdef GEOLAB_WITH_OPENMESH
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
using OMesh = OpenMesh::TriMesh_ArrayKernelT<>;
#endif

namespace {

// 1000 × 500 torus, triangulated: exactly 1,000,000 triangles, 500,000 vertices.
const geolab::PolygonSoup& torus_soup() {
    static const geolab::PolygonSoup s = geolab::fixtures::torus(1000, 500, 1.0, 0.35, true);
    return s;
}

const geolab::PolygonSoup& fan_soup() {
    static const geolab::PolygonSoup s = geolab::hostile::fan(400000);
    return s;
}

long minor_faults() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_minflt;
}

// A field of /proc/self/status in KiB ("VmRSS", "VmHWM"), or -1.
long status_kib(const char* field) {
    std::FILE* f = std::fopen("/proc/self/status", "r");
    if (!f) return -1;
    char line[256];
    long kib = -1;
    const std::size_t n = std::strlen(field);
    while (std::fgets(line, sizeof line, f))
        if (std::strncmp(line, field, n) == 0 && line[n] == ':') kib = std::atol(line + n + 1);
    std::fclose(f);
    return kib;
}

// The peak resident memory (MiB) that one call of `build` adds to the process: run once in a forked child that
// returns freed heap memory (malloc_trim) and resets its high-water mark (/proc/self/clear_refs "5"), then
// compares the peak with its size at the start (the soup is resident in both). -1 where /proc does not allow it.
template <class Build>
double peak_mib(Build build) {
    int fds[2];
    if (pipe(fds) != 0) return -1;
    const pid_t pid = fork();
    if (pid == 0) {
        double added = -1;
        malloc_trim(0);  // give back what earlier runs freed, so that reusing it counts as new memory again
        if (std::FILE* f = std::fopen("/proc/self/clear_refs", "w")) {
            const bool reset = std::fputs("5", f) >= 0;
            if (std::fclose(f) == 0 && reset) {
                const long before = status_kib("VmRSS");
                build();
                const long peak = status_kib("VmHWM");
                if (before >= 0 && peak >= 0) added = static_cast<double>(peak - before) / 1024;
            }
        }
        _exit(write(fds[1], &added, sizeof added) == sizeof added ? 0 : 1);
    }
    close(fds[1]);
    double added = -1;
    if (read(fds[0], &added, sizeof added) != sizeof added) added = -1;
    close(fds[0]);
    waitpid(pid, nullptr, 0);
    return added;
}

// Times `build` (which returns something to keep), with its page faults per iteration and its peak memory.
template <class Build>
void timed_build(benchmark::State& state, Build build) {
    state.counters["peak_MiB"] = peak_mib([&] { benchmark::DoNotOptimize(build()); });
    long faults = 0;
    for (auto _ : state) {
        const long f0 = minor_faults();
        auto mesh = build();
        faults += minor_faults() - f0;
        benchmark::DoNotOptimize(mesh);
    }
    state.counters["faults"] = benchmark::Counter(static_cast<double>(faults), benchmark::Counter::kAvgIterations);
}

void build_geolab(benchmark::State& state) {
    timed_build(state, [] { return geolab::halfedge::build_mesh(torus_soup()).n_edges(); });
    state.counters["faces"] = static_cast<double>(torus_soup().n_faces());
}

void build_fan_geolab(benchmark::State& state) {
    timed_build(state, [] { return geolab::halfedge::build_mesh(fan_soup()).n_edges(); });
}

void one_ring_geolab(benchmark::State& state) {
    const auto mesh = geolab::halfedge::build_mesh(torus_soup());
    std::vector<geolab::halfedge::Vertex> ring;
    for (auto _ : state) {
        glm::dvec3 sum(0.0);
        for (auto v : mesh.vertices()) {
            geolab::halfedge::one_ring_vertices(mesh, v, ring);
            for (auto w : ring) sum += mesh.position(w);
        }
        benchmark::DoNotOptimize(sum);
    }
}

#ifdef GEOLAB_WITH_OPENMESH
OMesh build_openmesh_mesh(const geolab::PolygonSoup& s) {
    OMesh m;
    m.reserve(s.n_vertices(), s.n_vertices() + s.n_faces(), s.n_faces());
    std::vector<OMesh::VertexHandle> vh(s.n_vertices());
    for (std::size_t i = 0; i < s.n_vertices(); ++i) {
        const auto& p = s.positions[i];
        vh[i] = m.add_vertex(OMesh::Point(float(p.x), float(p.y), float(p.z)));
    }
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        auto c = s.face(f);
        m.add_face(vh[c[0]], vh[c[1]], vh[c[2]]);
    }
    return m;
}

void build_openmesh(benchmark::State& state) {
    timed_build(state, [] { return build_openmesh_mesh(torus_soup()).n_edges(); });
}

void build_fan_openmesh(benchmark::State& state) {
    timed_build(state, [] { return build_openmesh_mesh(fan_soup()).n_edges(); });
}

void one_ring_openmesh(benchmark::State& state) {
    const OMesh m = build_openmesh_mesh(torus_soup());
    for (auto _ : state) {
        OMesh::Point sum(0, 0, 0);
        for (auto v : m.vertices())
            for (auto w : m.vv_range(v)) sum += m.point(w);
        benchmark::DoNotOptimize(sum);
    }
}
#endif

}  // namespace

BENCHMARK(build_geolab)->Name("build 1M faces/geolab")->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(one_ring_geolab)->Name("one-ring sweep/geolab")->Unit(benchmark::kMillisecond)->Iterations(5);
BENCHMARK(build_fan_geolab)->Name("build 400k fan/geolab")->Unit(benchmark::kMillisecond)->Iterations(3);
#ifdef GEOLAB_WITH_OPENMESH
BENCHMARK(build_openmesh)->Name("build 1M faces/OpenMesh")->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(build_fan_openmesh)->Name("build 400k fan/OpenMesh")->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(one_ring_openmesh)->Name("one-ring sweep/OpenMesh")->Unit(benchmark::kMillisecond)->Iterations(5);
#endif

int main(int argc, char** argv) {
    return geolab::bench::run_with_ratios(argc, argv, {{"build 1M faces", 1.0}, {"one-ring sweep", 1.0}});
}
