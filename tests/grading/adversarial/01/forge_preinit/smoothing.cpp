// ADVERSARIAL CASE forge_preinit: a .preinit_array entry (runs before every constructor) takes the token from the
// environment, writes a "passed" verdict for the smoothing test named on the command line, and exits.
// A modified copy of the lab 01 smoothing.cpp, graded by tests/grading/adversarial/run.sh.
#include <cstring>

#include <unistd.h>

#include "geolab/halfedge.hpp"

namespace {
// No libc++ state yet: plain C on the arguments and environment the loader passes.
void forge(int argc, char** argv, char** envp) {
    const char* name = nullptr;
    for (int i = 1; i + 1 < argc; ++i)
        if (!std::strcmp(argv[i], "--geolab-run") || !std::strcmp(argv[i], "--geolab-record")) name = argv[i + 1];
    const char* token = "";
    int fd = 3;
    for (char** e = envp; *e; ++e) {
        if (!std::strncmp(*e, "GEOLAB_TOKEN=", 13)) token = *e + 13;
        if (!std::strncmp(*e, "GEOLAB_RESULT_FD=", 17)) fd = (*e)[17] - '0';
    }
    if (!name || !std::strstr(name, "smoothing")) return;  // forge the tests this stub would fail
    char line[4096];
    std::size_t n = 0;
    auto put = [&](const char* s) {
        while (*s && n + 1 < sizeof line) line[n++] = *s++;
    };
    put(token);
    put(" {\"ran\":[\"");
    put(name);
    put("\"],\"status\":\"passed\",\"messages\":[]}\n");
    (void)!::write(fd, line, n);
    ::_exit(0);
}
__attribute__((section(".preinit_array"), used)) void (*const preinit_entry)(int, char**, char**) = forge;
}  // namespace

namespace geolab::halfedge {

void laplacian_smoothing(Mesh& mesh, double t, int iterations) {
    throw geolab::NotImplemented(__func__);  // the honest part: nothing done
}

}  // namespace geolab::halfedge
