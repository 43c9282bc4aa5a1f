#pragma once
// A Google Benchmark main that, after the usual table, prints the ratio geolab / peer for every task measured on
// both sides in the same run. Benchmarks are named "<task>/geolab" and "<task>/<peer>". With repetitions the
// medians are compared (the machines are shared and noisy: quote medians and ratios, not single times).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace geolab::bench {

//! Captures the (median) real time of every run while the console reporter prints as usual.
class RatioReporter : public benchmark::ConsoleReporter {
public:
    std::map<std::string, std::map<std::string, double>> seconds;  // task → side → median real time (s)

    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const auto& r : runs) {
            const bool aggregate = r.run_type == Run::RT_Aggregate;
            if (aggregate && r.aggregate_name != "median") continue;
            std::string name = r.run_name.function_name;
            auto slash = name.rfind('/');
            if (slash == std::string::npos) continue;
            const double t = r.GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(r.time_unit);
            auto& slot = seconds[name.substr(0, slash)][name.substr(slash + 1)];
            if (aggregate || slot == 0) slot = t;  // the median wins over single repetitions
        }
    }

    //! Prints "task: geolab X s, peer Y s, ratio geolab/peer = R (goal ≤ G)" for every pair.
    void print_ratios(const std::map<std::string, double>& goals) const {
        std::printf("\n%-28s %12s %12s %10s %8s  %s\n", "task", "geolab (s)", "peer (s)", "peer", "ratio", "goal");
        for (const auto& [task, sides] : seconds) {
            auto g = sides.find("geolab");
            if (g == sides.end()) continue;
            for (const auto& [peer, t] : sides) {
                if (peer == "geolab") continue;
                const double ratio = g->second / t;
                auto goal = goals.find(task);
                std::printf("%-28s %12.4f %12.4f %10s %8.3f  %s\n", task.c_str(), g->second, t, peer.c_str(), ratio,
                            goal == goals.end() ? ""
                                                : (std::string("<= ") + std::to_string(goal->second).substr(0, 4) +
                                                   (ratio <= goal->second ? "  met" : "  NOT met"))
                                                      .c_str());
            }
        }
    }
};

//! benchmark::Initialize with 5 repetitions unless the command line asks for another number.
inline void initialize_with_repetitions(int argc, char** argv) {
    static std::string reps = "--benchmark_repetitions=5";
    std::vector<char*> args(argv, argv + argc);
    bool has_reps = false;
    for (int i = 1; i < argc; ++i) has_reps |= std::string(argv[i]).rfind("--benchmark_repetitions", 0) == 0;
    if (!has_reps) args.push_back(reps.data());
    int n = static_cast<int>(args.size());
    benchmark::Initialize(&n, args.data());
}

//! Run the registered benchmarks (default: 5 repetitions, medians) and print the ratios.
inline int run_with_ratios(int argc, char** argv, const std::map<std::string, double>& goals) {
    initialize_with_repetitions(argc, argv);
    RatioReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    reporter.print_ratios(goals);
    benchmark::Shutdown();
    return 0;
}

}  // namespace geolab::bench
