// ADVERSARIAL CASE interpose_getenv: a stub that defines extern "C" getenv(): the harness reads its token through
// it, and it forges the verdict. Rejected: a C-linkage definition outside the lab's API.
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

extern "C" char** environ;
static const char* lookup(const char* name) {
    const std::size_t n = std::strlen(name);
    for (char** e = environ; e && *e; ++e)
        if (std::strncmp(*e, name, n) == 0 && (*e)[n] == '=') return *e + n + 1;
    return nullptr;
}
static char token_copy[128];
extern "C" char* getenv(const char* name) {
    const char* value = lookup(name);
    if (std::strcmp(name, "GEOLAB_TOKEN") == 0 && value) std::strncpy(token_copy, value, sizeof token_copy - 1);
    if (std::strcmp(name, "GEOLAB_RESULT_FD") == 0 && token_copy[0]) forge_verdict(token_copy, value);
    return const_cast<char*>(value);
}

namespace geolab::halfedge {

void laplacian_smoothing(Mesh&, double, int) { throw geolab::NotImplemented(__func__); }

}  // namespace geolab::halfedge
