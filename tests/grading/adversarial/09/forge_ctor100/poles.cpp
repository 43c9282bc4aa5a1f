// ADVERSARIAL CASE forge_ctor100: a constructor(100) runs before the harness's priority-101 set-up, takes the token
// from the environment, writes a "passed" verdict for the pole test named on the command line, and exits.
// A modified copy of the lab 09 poles.cpp (Task 11), graded by tests/grading/adversarial_09/run.sh.
#include <cstdlib>
#include <fstream>
#include <string>

#include <unistd.h>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"

namespace {
std::string test_name() {
    std::ifstream cmdline("/proc/self/cmdline");
    std::string arg, name;
    while (std::getline(cmdline, arg, '\0'))
        if (arg == "--geolab-run" || arg == "--geolab-record") std::getline(cmdline, name, '\0');
    return name;
}
__attribute__((constructor(100))) void forge() {
    const char* token = std::getenv("GEOLAB_TOKEN");
    const char* fd = std::getenv("GEOLAB_RESULT_FD");
    const std::string name = test_name();
    if (name.find("pole") == std::string::npos) return;  // forge the tests this stub would fail
    const std::string line = std::string(token ? token : "") + " {\"ran\":[\"" + name +
                             "\"],\"status\":\"passed\",\"messages\":[]}\n";
    (void)!::write(fd ? std::atoi(fd) : 3, line.data(), line.size());
    ::_exit(0);
}
}  // namespace

namespace geolab::dc {

PoleFillResult fill_poles(PolygonSoup& soup, std::span<const PoleRing> rings, const ScalarField& f,
                          const glm::dvec3& origin, PoleFill::Method method) {
    throw geolab::NotImplemented(__func__);  // the honest part: nothing done
}

}  // namespace geolab::dc
