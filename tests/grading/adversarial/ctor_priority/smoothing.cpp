// ADVERSARIAL CASE ctor_priority: a stub whose constructor(100) runs before the harness's priority-101 set-up,
// takes the token from the environment, writes a "passed" verdict and exits. Rejected: a prioritised .init_array.
#include <cstdlib>
#include <cstring>
#include <string>

#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include "geolab/halfedge.hpp"

namespace {
// The forgery: the grader's token and result descriptor (from the environment), the test's name (from the command
// line), a "passed" verdict on the result pipe, and out before the harness runs anything.
void forge_verdict(const char* token, const char* fd) {
    if (!token || !fd) return;
    char buf[8192];
    int f = ::open("/proc/self/cmdline", O_RDONLY);
    if (f < 0) return;
    ssize_t n = ::read(f, buf, sizeof buf - 1);
    ::close(f);
    if (n <= 0) return;
    buf[n] = 0;
    const char* arg1 = buf + std::strlen(buf) + 1;
    if (arg1 >= buf + n || std::strcmp(arg1, "--geolab-run") != 0) return;  // listing: let it list
    const char* name = arg1 + std::strlen(arg1) + 1;
    std::string line = std::string(token) + " {\"status\":\"passed\",\"ran\":[\"";
    for (const char* p = name; *p; ++p) {
        if (*p == '"' || *p == '\\') line += '\\';
        line += *p;
    }
    line += "\"],\"messages\":[]}\n";
    (void)!::syscall(SYS_write, std::atoi(fd), line.data(), line.size());
    ::_exit(0);
}
}  // namespace

__attribute__((constructor(100))) static void before_the_harness() {
    forge_verdict(std::getenv("GEOLAB_TOKEN"), std::getenv("GEOLAB_RESULT_FD"));
}

namespace geolab::halfedge {

void laplacian_smoothing(Mesh&, double, int) { throw geolab::NotImplemented(__func__); }

}  // namespace geolab::halfedge
