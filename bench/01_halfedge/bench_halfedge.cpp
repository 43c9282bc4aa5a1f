// Lab 01 benchmark: half-edge construction from a 1M-face triangle soup, and a full one-ring sweep (sum of the
// neighbours' positions at every vertex), geolab's reference vs OpenMesh, in one run; prints the ratios.
// Goals: build ≤ 0.5× OpenMesh's time on the shared 2-core development machine (issue 13; ≤ 1.0× since issue 2),
// one-ring sweep ≤ 1.0×, the 400k fan ≤ 1.0×.
// Also the build of a 400,000-triangle fan (one vertex of valence 400,001; issue 13: 55 s when the build was
// quadratic in valence) and of one 1,000,000-vertex polygon (geolab only: OpenMesh's TriMesh triangulates it).
// Each build reports its minor page faults per iteration in the timing loop ("faults"; memory that malloc kept from
// the previous iteration costs none), the page faults of one build in a freshly trimmed forked child
// ("faults_fresh": every page the build touches) and the peak memory it adds above what the process held before
// it ("peak_MiB", the same child). The summary prints wall and CPU medians, faults and peak for both sides, the
// ratios, and the load average before and after the run (the machine is shared: quote CPU ratios from busy runs).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "common/process_stats.hpp"
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

const geolab::PolygonSoup& polygon_soup() {
    static const geolab::PolygonSoup s = geolab::hostile::big_polygon(1000000);
    return s;
}

using geolab::bench::fresh_cost;
using geolab::bench::FreshCost;
using geolab::bench::minor_faults;

// Times `build` (which returns something to keep), with its page faults per iteration, and its fresh cost. The
// soup `build` reads must exist before (the lambdas capture it), or the child would count making it.
template <class Build>
void timed_build(benchmark::State& state, Build build) {
    const FreshCost fresh = fresh_cost([&] { benchmark::DoNotOptimize(build()); });
    state.counters["peak_MiB"] = fresh.peak_mib;
    state.counters["faults_fresh"] = fresh.faults;
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
    timed_build(state, [&s = torus_soup()] { return geolab::halfedge::build_mesh(s).n_edges(); });
    state.counters["faces"] = static_cast<double>(torus_soup().n_faces());
}

void build_fan_geolab(benchmark::State& state) {
    timed_build(state, [&s = fan_soup()] { return geolab::halfedge::build_mesh(s).n_edges(); });
}

void build_polygon_geolab(benchmark::State& state) {
    timed_build(state, [&s = polygon_soup()] { return geolab::halfedge::build_mesh(s).n_edges(); });
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
    timed_build(state, [&s = torus_soup()] { return build_openmesh_mesh(s).n_edges(); });
}

void build_fan_openmesh(benchmark::State& state) {
    timed_build(state, [&s = fan_soup()] { return build_openmesh_mesh(s).n_edges(); });
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

// The load average (1, 5, 15 minutes) from /proc/loadavg, or "?".
std::string load_average() {
    std::FILE* f = std::fopen("/proc/loadavg", "r");
    if (!f) return "?";
    double l1 = 0, l5 = 0, l15 = 0;
    const int n = std::fscanf(f, "%lf %lf %lf", &l1, &l5, &l15);
    std::fclose(f);
    if (n != 3) return "?";
    char text[64];
    std::snprintf(text, sizeof text, "%.2f, %.2f, %.2f", l1, l5, l15);
    return text;
}

// The ratio reporter that also keeps, per benchmark, the median CPU time and counters, and prints them side by
// side: wall and CPU time, page faults (timing loop and fresh) and peak memory, geolab and the peer, and the ratios.
class BuildReporter : public geolab::bench::RatioReporter {
public:
    struct Figures {
        double wall = 0, cpu = 0;
        std::map<std::string, double> counters;
    };
    std::map<std::string, std::map<std::string, Figures>> figures;  // task → side → medians

    void ReportRuns(const std::vector<Run>& runs) override {
        RatioReporter::ReportRuns(runs);
        for (const auto& r : runs) {
            const bool aggregate = r.run_type == Run::RT_Aggregate;
            if (aggregate && r.aggregate_name != "median") continue;
            const std::string name = r.run_name.function_name;
            const auto slash = name.rfind('/');
            if (slash == std::string::npos) continue;
            Figures& f = figures[name.substr(0, slash)][name.substr(slash + 1)];
            if (!aggregate && f.wall > 0) continue;  // the first repetition, until the median replaces it
            const double unit = benchmark::GetTimeUnitMultiplier(r.time_unit);
            f.wall = r.GetAdjustedRealTime() / unit;
            f.cpu = r.GetAdjustedCPUTime() / unit;
            for (const auto& [key, counter] : r.counters) f.counters[key] = counter.value;
        }
    }

    void print_figures() const {
        std::printf("\n%-24s %-9s %10s %10s %10s %13s %9s\n", "task", "side", "wall (s)", "CPU (s)", "faults",
                    "faults fresh", "peak MiB");
        auto counter = [](const Figures& f, const char* key) {
            const auto it = f.counters.find(key);
            return it == f.counters.end() ? -1.0 : it->second;
        };
        // a figure, or "-" where it was not measured (negative)
        auto cell = [](double x, int width, int decimals) {
            char text[32];
            if (x < 0)
                std::snprintf(text, sizeof text, "%*s", width, "-");
            else
                std::snprintf(text, sizeof text, "%*.*f", width, decimals, x);
            return std::string(text);
        };
        auto row = [&](const std::string& task, const std::string& side, const Figures& f) {
            std::printf("%-24s %-9s %10.4f %10.4f %s %s %s\n", task.c_str(), side.c_str(), f.wall, f.cpu,
                        cell(counter(f, "faults"), 10, 0).c_str(), cell(counter(f, "faults_fresh"), 13, 0).c_str(),
                        cell(counter(f, "peak_MiB"), 9, 1).c_str());
        };
        for (const auto& [task, sides] : figures) {
            const auto ours = sides.find("geolab");
            if (ours == sides.end()) continue;
            row(task, "geolab", ours->second);
            for (const auto& [peer, f] : sides) {
                if (peer == "geolab") continue;
                row("", peer, f);
                auto ratio = [](double a, double b) { return a >= 0 && b > 0 ? a / b : -1.0; };
                const Figures& g = ours->second;
                std::printf("%-24s %-9s %s %s %s %s %s\n", "", "ratio", cell(ratio(g.wall, f.wall), 10, 3).c_str(),
                            cell(ratio(g.cpu, f.cpu), 10, 3).c_str(),
                            cell(ratio(counter(g, "faults"), counter(f, "faults")), 10, 3).c_str(),
                            cell(ratio(counter(g, "faults_fresh"), counter(f, "faults_fresh")), 13, 3).c_str(),
                            cell(ratio(counter(g, "peak_MiB"), counter(f, "peak_MiB")), 9, 3).c_str());
            }
        }
    }
};

}  // namespace

BENCHMARK(build_geolab)->Name("build 1M faces/geolab")->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(one_ring_geolab)->Name("one-ring sweep/geolab")->Unit(benchmark::kMillisecond)->Iterations(5);
BENCHMARK(build_fan_geolab)->Name("build 400k fan/geolab")->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(build_polygon_geolab)->Name("build 1M-vertex polygon/geolab")->Unit(benchmark::kMillisecond)->Iterations(3);
#ifdef GEOLAB_WITH_OPENMESH
BENCHMARK(build_openmesh)->Name("build 1M faces/OpenMesh")->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(build_fan_openmesh)->Name("build 400k fan/OpenMesh")->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(one_ring_openmesh)->Name("one-ring sweep/OpenMesh")->Unit(benchmark::kMillisecond)->Iterations(5);
#endif

int main(int argc, char** argv) {
    // run_with_ratios of common/ratio_main.hpp, with a reporter that also keeps CPU times and counters
    const std::string load_before = load_average();
    geolab::bench::initialize_with_repetitions(argc, argv);
    BuildReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    reporter.print_ratios({{"build 1M faces", 0.5}, {"one-ring sweep", 1.0}, {"build 400k fan", 1.0}});
    reporter.print_figures();
    std::printf("\nload average before: %s; after: %s\n", load_before.c_str(), load_average().c_str());
    benchmark::Shutdown();
    return 0;
}
