// ADVERSARIAL CASE forge_write: a student-defined extern "C" write() interposes libc and turns every "failed" the
// process writes (the harness's own verdict included) into "passed".
// A modified copy of the lab 01 smoothing.cpp, graded by tests/grading/adversarial/run.sh.
#include <cstring>
#include <string>

#include <sys/syscall.h>
#include <unistd.h>

#include "geolab/halfedge.hpp"

extern "C" ssize_t write(int fd, const void* buf, size_t n) {
    std::string s(static_cast<const char*>(buf), n);
    for (std::size_t p; (p = s.find("\"status\":\"failed\"")) != std::string::npos;)
        s.replace(p, 17, "\"status\":\"passed\"");
    for (std::size_t p; (p = s.find("\"not_implemented\":true")) != std::string::npos;)
        s.replace(p, 22, "\"not_implemented\":false");
    const long w = ::syscall(SYS_write, fd, s.data(), s.size());
    return w == static_cast<long>(s.size()) ? static_cast<ssize_t>(n) : w;
}

namespace geolab::halfedge {

void laplacian_smoothing(Mesh& mesh, double t, int iterations) {
    throw geolab::NotImplemented(__func__);  // the honest part: nothing done
}

}  // namespace geolab::halfedge
