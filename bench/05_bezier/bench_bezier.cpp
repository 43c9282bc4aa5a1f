// Lab 05 benchmark. Timings: Google Benchmark medians of 5 repetitions; "geolab" is de Casteljau
// (geolab::bezier::de_casteljau), the peer "bernstein" the Bernstein form (evaluate_bernstein) on the same points.
// Before the timings: the largest error of three evaluation forms against a long double reference.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "common/ratio_main.hpp"
#include "geolab/bezier.hpp"
#include "geolab/bezier_data.hpp"

namespace {
using geolab::bezier::Poly3;
using LD = long double;

Poly3 random_poly(int n, unsigned seed) {
    std::mt19937_64 g(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    Poly3 P(n + 1);
    for (auto& p : P) p = {u(g), u(g), u(g)};
    return P;
}

// The reference: Σ C(n,k) t^k (1−t)^(n−k) P_k in long double.
glm::dvec3 reference(const Poly3& P, LD t) {
    const int n = int(P.size()) - 1;
    LD x = 0, y = 0, z = 0, b = 1;
    for (int k = 0; k <= n; ++k) {
        const LD w = b * std::pow(t, LD(k)) * std::pow(1 - t, LD(n - k));
        x += w * P[k].x, y += w * P[k].y, z += w * P[k].z;
        b = b * (n - k) / (k + 1);
    }
    return {double(x), double(y), double(z)};
}

// The power (monomial) form: a_j = C(n, j) Σ_i (−1)^(j−i) C(j, i) P_i, evaluated by Horner, all in double.
std::vector<glm::dvec3> power_coefficients(const Poly3& P) {
    const int n = int(P.size()) - 1;
    std::vector<glm::dvec3> a(n + 1, glm::dvec3(0.0));
    for (int j = 0; j <= n; ++j) {
        double cnj = 1;
        for (int k = 1; k <= j; ++k) cnj = cnj * (n - j + k) / k;
        glm::dvec3 s(0.0);
        double cji = 1;
        for (int i = 0; i <= j; ++i) {
            s += ((j - i) % 2 ? -cji : cji) * P[i];
            cji = cji * (j - i) / (i + 1);
        }
        a[j] = cnj * s;
    }
    return a;
}
glm::dvec3 horner(const std::vector<glm::dvec3>& a, double t) {
    glm::dvec3 r = a.back();
    for (int j = int(a.size()) - 2; j >= 0; --j) r = r * t + a[j];
    return r;
}

void print_accuracy() {
    std::printf("accuracy: largest |error| over 201 parameters in [0, 1], control points uniform in [-1, 1]^3,\n"
                "          reference = the Bernstein form in long double (median of 5 random curves per degree)\n");
    std::printf("%8s %16s %16s %16s\n", "degree", "power (Horner)", "Bernstein form", "de Casteljau");
    for (int n : {5, 10, 15, 20, 30, 40, 60}) {
        std::vector<double> ep, eb, ed;
        for (unsigned s = 0; s < 5; ++s) {
            const Poly3 P = random_poly(n, 1000 + s);
            const auto a = power_coefficients(P);
            double mp = 0, mb = 0, md = 0;
            for (int i = 0; i <= 200; ++i) {
                const double t = i / 200.0;
                const glm::dvec3 r = reference(P, t);
                mp = std::max(mp, glm::length(horner(a, t) - r));
                mb = std::max(mb, glm::length(geolab::bezier::evaluate_bernstein(P, t) - r));
                md = std::max(md, glm::length(geolab::bezier::de_casteljau(P, t) - r));
            }
            ep.push_back(mp), eb.push_back(mb), ed.push_back(md);
        }
        std::sort(ep.begin(), ep.end()), std::sort(eb.begin(), eb.end()), std::sort(ed.begin(), ed.end());
        std::printf("%8d %16.3e %16.3e %16.3e\n", n, ep[2], eb[2], ed[2]);
    }
    std::printf("\n");
}

void eval(benchmark::State& state, bool casteljau) {
    const Poly3 P = random_poly(int(state.range(0)), 7);
    std::size_t count = 0;
    for (auto _ : state) {
        glm::dvec3 s(0.0);
        for (int i = 0; i <= 1000; ++i) {
            const double t = i / 1000.0;
            s += casteljau ? geolab::bezier::de_casteljau(P, t) : geolab::bezier::evaluate_bernstein(P, t);
        }
        benchmark::DoNotOptimize(s);
        count += 1001;
    }
    state.counters["points/s"] = benchmark::Counter(double(count), benchmark::Counter::kIsRate);
}

void teapot(benchmark::State& state) {
    const auto patches = geolab::read_bpt(geolab::teapot_path());
    std::size_t vertices = 0;
    for (auto _ : state) {
        const auto mesh = geolab::bezier::tessellate_patches(patches, 64, 1e-9, true);
        vertices = mesh.soup.n_vertices();
        benchmark::DoNotOptimize(mesh.normals.data());
    }
    state.counters["vertices"] = double(vertices);
}

}  // namespace

BENCHMARK_CAPTURE(eval, casteljau, true)->Name("eval degree 3/geolab")->Arg(3)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(eval, bernstein, false)->Name("eval degree 3/bernstein")->Arg(3)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(eval, casteljau, true)->Name("eval degree 7/geolab")->Arg(7)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(eval, bernstein, false)->Name("eval degree 7/bernstein")->Arg(7)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(eval, casteljau, true)->Name("eval degree 15/geolab")->Arg(15)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(eval, bernstein, false)->Name("eval degree 15/bernstein")->Arg(15)->Unit(benchmark::kMicrosecond);
BENCHMARK(teapot)->Name("teapot 64x64 with normals/geolab")->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) {
    print_accuracy();
    return geolab::bench::run_with_ratios(argc, argv, {});
}
