// ADVERSARIAL CASE swallow_crash: installs handlers that turn crashes and std::terminate into fake success, then crashes
// A modified copy of the lab 01 smoothing.cpp, graded by tests/grading/adversarial/run.sh.
#include <stdexcept>
#include <string>
#include <vector>

#include "geolab/halfedge.hpp"
#include <csignal>
#include <cstdio>
#include <exception>
#include <unistd.h>


namespace {
void pretend(int) {
    const char msg[] = "[doctest] Status: SUCCESS!\n";
    (void)!::write(1, msg, sizeof msg - 1);
    ::_exit(0);
}
}  // namespace

namespace geolab::halfedge {

void laplacian_smoothing(Mesh& mesh, double t, int iterations) {
    std::signal(SIGSEGV, pretend);
    std::signal(SIGABRT, pretend);
    std::signal(SIGFPE, pretend);
    std::set_terminate([] { pretend(0); });
    volatile int* null = nullptr;
    *null = 42;
    throw 42;
}

}  // namespace geolab::halfedge
