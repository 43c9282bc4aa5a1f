// Lab 03 benchmark (issue 15): single-thread rays per second of
//   - ray–quadric: intersect(Q, ray, 0, ∞) on a rotated, moved ellipsoid (the API: it returns a std::vector of hits),
//     and the same ray's quadratic alone (α, β, γ from Q, then solve_quadratic: the test without building hits);
//   - ray–superquadric: intersect_superquadric on a superellipsoid (ε₁ = 0.5, ε₂ = 2.5), the same kind of rays;
// and the tessellation of a 1,000,000-triangle superquadric (n_eta = 501, n_omega = 1000).
// The share of rays that hit is printed. No peer is named by the issue: the medians (5 repetitions) and the goal
// (≥ 50M ray–quadric tests per second) are printed at the end.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "common/ratio_main.hpp"
#include "geolab/quadrics.hpp"

namespace {
namespace q = geolab::quadrics;

// (x/1.5)² + (y/0.8)² + (z/1.1)² = 1 rotated by 0.7 rad about (1, 1, 1)/√3 and moved by (0.3, -0.2, 0.5).
glm::dmat4 ellipsoid() {
    glm::dmat4 Q(0.0);
    Q[0][0] = 1 / (1.5 * 1.5), Q[1][1] = 1 / (0.8 * 0.8), Q[2][2] = 1 / (1.1 * 1.1), Q[3][3] = -1;
    const double a = 0.7, c = std::cos(a), s = std::sin(a), k = 1 / std::sqrt(3.0);
    glm::dmat4 M(1.0);  // Rodrigues about (k, k, k)
    const double K[3][3] = {{0, -k, k}, {k, 0, -k}, {-k, k, 0}};
    for (int r = 0; r < 3; ++r)
        for (int col = 0; col < 3; ++col) {
            double kk = 0;
            for (int m = 0; m < 3; ++m) kk += K[r][m] * K[m][col];
            M[col][r] = (r == col ? 1.0 : 0.0) + s * K[r][col] + (1 - c) * kk;
        }
    M[3] = glm::dvec4(0.3, -0.2, 0.5, 1.0);
    return q::transform_quadric(Q, M);
}

// Rays from a sphere of radius 6 around the origin towards a random point of [-2, 2]³.
const std::vector<q::Ray>& rays() {
    static const std::vector<q::Ray> r = [] {
        std::mt19937_64 gen(3);
        std::uniform_real_distribution<double> u(-1, 1);
        std::vector<q::Ray> out;
        while (out.size() < 4096) {
            glm::dvec3 o{u(gen), u(gen), u(gen)};
            if (glm::length(o) < 0.1 || glm::length(o) > 1) continue;
            o = 6.0 * glm::normalize(o);
            const glm::dvec3 aim{2 * u(gen), 2 * u(gen), 2 * u(gen)};
            out.push_back({o, glm::normalize(aim - o)});
        }
        return out;
    }();
    return r;
}

void ray_quadric_intersect(benchmark::State& state) {
    const glm::dmat4 Q = ellipsoid();
    const auto& rs = rays();
    std::size_t hits = 0;
    for (auto _ : state)
        for (const q::Ray& r : rs) hits += q::intersect(Q, r, 0.0, INFINITY).size();
    benchmark::DoNotOptimize(hits);
    state.SetItemsProcessed(static_cast<long>(state.iterations() * rs.size()));
    state.counters["hits/ray"] = double(hits) / double(state.iterations() * rs.size());
}

void ray_quadric_test(benchmark::State& state) {
    const glm::dmat4 Q = ellipsoid();
    const auto& rs = rays();
    int count = 0;
    for (auto _ : state)
        for (const q::Ray& r : rs) {
            const glm::dvec4 X(r.origin, 1.0), D(r.direction, 0.0), QD = Q * D;
            count += q::solve_quadratic(glm::dot(D, QD), 2 * glm::dot(X, QD), glm::dot(X, Q * X)).count;
        }
    benchmark::DoNotOptimize(count);
    state.SetItemsProcessed(static_cast<long>(state.iterations() * rs.size()));
}

void ray_superquadric(benchmark::State& state) {
    const q::Superquadric s{{1.5, 0.8, 1.1}, 0.5, 2.5};
    const auto& rs = rays();
    std::size_t hits = 0;
    for (auto _ : state)
        for (const q::Ray& r : rs) hits += q::intersect_superquadric(s, r, 0.0, INFINITY).has_value();
    benchmark::DoNotOptimize(hits);
    state.SetItemsProcessed(static_cast<long>(state.iterations() * rs.size()));
    state.counters["hit share"] = double(hits) / double(state.iterations() * rs.size());
}

void tessellate_1m(benchmark::State& state) {
    const q::Superquadric s{{1.5, 0.8, 1.1}, 0.5, 2.5};
    std::size_t faces = 0;
    for (auto _ : state) faces = q::tessellate_superquadric(s, 501, 1000).n_faces();
    state.counters["triangles"] = static_cast<double>(faces);
    state.SetItemsProcessed(static_cast<long>(state.iterations() * faces));
}

// Captures the median items per second of each benchmark.
class Reporter : public benchmark::ConsoleReporter {
public:
    std::map<std::string, double> per_second;
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const auto& r : runs) {
            if (r.run_type == Run::RT_Aggregate && r.aggregate_name != "median") continue;
            const auto it = r.counters.find("items_per_second");
            if (it == r.counters.end()) continue;
            double& slot = per_second[r.run_name.function_name];
            if (r.run_type == Run::RT_Aggregate || slot == 0) slot = it->second;
        }
    }
};
}  // namespace

BENCHMARK(ray_quadric_intersect)->Name("ray-quadric intersect")->Unit(benchmark::kMicrosecond)->MinTime(0.5);
BENCHMARK(ray_quadric_test)->Name("ray-quadric solve_quadratic")->Unit(benchmark::kMicrosecond)->MinTime(0.5);
BENCHMARK(ray_superquadric)->Name("ray-superquadric")->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(tessellate_1m)->Name("tessellate 1M triangles")->Unit(benchmark::kMillisecond)->Iterations(3);

int main(int argc, char** argv) {
    geolab::bench::initialize_with_repetitions(argc, argv);
    Reporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    std::printf("\n%-30s %16s\n", "task (median, one thread)", "per second");
    for (const auto& [name, v] : reporter.per_second) std::printf("%-30s %16.4g\n", name.c_str(), v);
    const auto it = reporter.per_second.find("ray-quadric solve_quadratic");
    if (it != reporter.per_second.end())
        std::printf("goal: >= 50M ray-quadric tests per second: %.1fM (%s); intersect (with its hit vector): %.1fM\n",
                    it->second / 1e6, it->second >= 50e6 ? "met" : "NOT met",
                    reporter.per_second["ray-quadric intersect"] / 1e6);
    benchmark::Shutdown();
    return 0;
}
