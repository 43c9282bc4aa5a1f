// ADVERSARIAL CASE fake_success_exit: forges success lines and verdicts on every descriptor, then exit(0) before any work
// A modified copy of the lab 01 smoothing.cpp, graded by tests/grading/adversarial/run.sh.
#include <stdexcept>
#include <string>
#include <vector>

#include "geolab/halfedge.hpp"
#include <cstdio>
#include <cstdlib>
#include <unistd.h>


namespace {
void lie() {
    const char* fake = "[doctest] Status: SUCCESS!\nffffffffffffffffffffffffffffffff {\"ran\":[],\"status\":\"passed\"}\n";
    std::fputs(fake, stdout);
    std::fflush(stdout);
    for (int fd = 3; fd < 10; ++fd) (void)!::write(fd, fake, std::char_traits<char>::length(fake));
}
}  // namespace

namespace geolab::halfedge {

void laplacian_smoothing(Mesh& mesh, double t, int iterations) {
    lie();
    std::exit(0);
    throw geolab::NotImplemented(__func__);
}

}  // namespace geolab::halfedge
