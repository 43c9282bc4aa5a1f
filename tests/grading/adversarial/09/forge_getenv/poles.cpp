// ADVERSARIAL CASE forge_getenv: a student-defined extern "C" getenv() is what the harness calls to read its token;
// it hands the token over, forges a "passed" verdict for the test named on the command line, and exits.
// A modified copy of the lab 09 poles.cpp (Task 11), graded by tests/grading/adversarial_09/run.sh.
#include <cstring>

#include <fcntl.h>
#include <unistd.h>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"

extern char** environ;

namespace {
const char* lookup(const char* key) {
    const std::size_t k = std::strlen(key);
    for (char** e = environ; e && *e; ++e)
        if (!std::strncmp(*e, key, k) && (*e)[k] == '=') return *e + k + 1;
    return nullptr;
}
std::size_t read_cmdline(char* buf, std::size_t size) {
    const int fd = ::open("/proc/self/cmdline", 0);
    if (fd < 0) return 0;
    const ssize_t n = ::read(fd, buf, size - 1);
    ::close(fd);
    return n > 0 ? static_cast<std::size_t>(n) : 0;
}
}  // namespace

extern "C" char* getenv(const char* key) {
    const char* value = lookup(key);
    static bool done = false;
    if (!done && !std::strcmp(key, "GEOLAB_TOKEN") && value) {
        done = true;
        char cmd[4096];
        const std::size_t n = read_cmdline(cmd, sizeof cmd);
        const char* name = nullptr;
        for (std::size_t i = 0; i < n; i += std::strlen(cmd + i) + 1)
            if (!std::strcmp(cmd + i, "--geolab-run") && i + std::strlen(cmd + i) + 1 < n) name = cmd + i + std::strlen(cmd + i) + 1;
        const char* fd = lookup("GEOLAB_RESULT_FD");
        if (name && fd) {
            char line[4096];
            std::size_t m = 0;
            for (const char* s : {value, " {\"ran\":[\"", name, "\"],\"status\":\"passed\",\"messages\":[]}\n"})
                while (*s && m + 1 < sizeof line) line[m++] = *s++;
            (void)!::write(fd[0] - '0', line, m);
            ::_exit(0);
        }
    }
    return const_cast<char*>(value);
}

namespace geolab::dc {

PoleFillResult fill_poles(PolygonSoup& soup, std::span<const PoleRing> rings, const ScalarField& f,
                          const glm::dvec3& origin, PoleFill::Method method) {
    throw geolab::NotImplemented(__func__);  // the honest part: nothing done
}

}  // namespace geolab::dc
