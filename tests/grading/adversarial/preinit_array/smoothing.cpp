// ADVERSARIAL CASE preinit_array: a stub with a .preinit_array entry (runs before every constructor) that forges
// the verdict. Rejected: a .preinit_array section.
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

// Called by the loader with the program's environment, before the C library has set up its own.
static void before_everything(int, char**, char** envp) {
    const char *token = nullptr, *fd = nullptr;
    for (char** e = envp; e && *e; ++e) {
        if (std::strncmp(*e, "GEOLAB_TOKEN=", 13) == 0) token = *e + 13;
        if (std::strncmp(*e, "GEOLAB_RESULT_FD=", 17) == 0) fd = *e + 17;
    }
    forge_verdict(token, fd);
}
__attribute__((section(".preinit_array"), used)) static void (*preinit_entry)(int, char**, char**) = &before_everything;

namespace geolab::halfedge {

void laplacian_smoothing(Mesh&, double, int) { throw geolab::NotImplemented(__func__); }

}  // namespace geolab::halfedge
