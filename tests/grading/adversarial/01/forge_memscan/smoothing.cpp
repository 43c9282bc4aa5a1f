// ADVERSARIAL CASE forge_memscan: no early code. During the test it scans its own process's memory for the
// grader's token (32 hex digits), writes a "passed" verdict with it to every inherited descriptor, and exits.
// A modified copy of the lab 01 smoothing.cpp, graded by tests/grading/adversarial/run.sh.
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <unistd.h>

#include "geolab/halfedge.hpp"
#include "geolab/grading/test.hpp"

namespace {
bool hex(char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); }

// Every run of exactly 32 lowercase hex digits in the readable, writable memory of this process, by count.
std::map<std::string, int> candidates() {
    std::map<std::string, int> found;
    std::ifstream maps("/proc/self/maps");
    std::string line;
    while (std::getline(maps, line)) {
        unsigned long a = 0, b = 0;
        char perms[5] = {};
        if (std::sscanf(line.c_str(), "%lx-%lx %4s", &a, &b, perms) != 3 || perms[0] != 'r' || perms[1] != 'w') continue;
        if (line.find("[vvar]") != std::string::npos) continue;
        const char* p = reinterpret_cast<const char*>(a);
        std::size_t run = 0;
        for (unsigned long i = 0; i < b - a; ++i) {
            if (hex(p[i])) {
                ++run;
                continue;
            }
            if (run == 32) ++found[std::string(p + i - 32, 32)];
            run = 0;
        }
    }
    return found;
}
}  // namespace

namespace geolab::halfedge {

void laplacian_smoothing(Mesh& mesh, double t, int iterations) {
    std::string best;
    int most = 0;
    for (const auto& [token, n] : candidates())
        if (n > most) most = n, best = token;
    const std::string line = best + " {\"ran\":[\"" + geolab::detail::current_test() +
                             "\"],\"status\":\"passed\",\"messages\":[]}\n";
    for (int fd = 3; fd < 10; ++fd) (void)!::write(fd, line.data(), line.size());
    ::_exit(0);
}

}  // namespace geolab::halfedge
