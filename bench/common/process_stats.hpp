#pragma once
// What a benchmark reports beside its times: minor page faults, and the peak resident memory one call adds,
// measured in a forked child so that earlier runs do not hide it. Linux only (/proc); -1 where it is not allowed.
#include <malloc.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace geolab::bench {

//! Minor page faults of this process so far (getrusage): the pages it touched for the first time.
inline long minor_faults() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_minflt;
}

//! A field of /proc/self/status in KiB ("VmRSS", "VmHWM"), or -1.
inline long status_kib(const char* field) {
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

//! What one call costs in memory on fresh pages: the peak resident memory it adds (MiB) and its minor page faults.
struct FreshCost {
    double peak_mib = -1;
    double faults = -1;
};

//! Runs `run` once in a forked child that first gives back freed heap memory (malloc_trim) and resets its
//! high-water mark (/proc/self/clear_refs "5"), so every page the call touches is fresh there. What `run` reads
//! must exist before the fork (or the child counts making it). -1 fields where /proc does not allow it.
template <class Run>
FreshCost fresh_cost(Run run) {
    int fds[2];
    if (pipe(fds) != 0) return {};
    const pid_t pid = fork();
    if (pid == 0) {
        FreshCost cost;
        malloc_trim(0);  // give back what earlier runs freed, so that reusing it counts as new memory again
        if (std::FILE* f = std::fopen("/proc/self/clear_refs", "w")) {
            const bool reset = std::fputs("5", f) >= 0;
            if (std::fclose(f) == 0 && reset) {
                const long before = status_kib("VmRSS"), f0 = minor_faults();
                run();
                cost.faults = static_cast<double>(minor_faults() - f0);
                const long peak = status_kib("VmHWM");
                if (before >= 0 && peak >= 0) cost.peak_mib = static_cast<double>(peak - before) / 1024;
            }
        }
        _exit(write(fds[1], &cost, sizeof cost) == sizeof cost ? 0 : 1);
    }
    close(fds[1]);
    FreshCost cost;
    if (read(fds[0], &cost, sizeof cost) != sizeof cost) cost = {};
    close(fds[0]);
    waitpid(pid, nullptr, 0);
    return cost;
}

//! The peak resident memory (MiB) one call of `run` adds (fresh_cost), or -1.
template <class Run>
double peak_mib(Run run) {
    return fresh_cost(run).peak_mib;
}

}  // namespace geolab::bench
