// ADVERSARIAL CASE forge_write: a student-defined extern "C" write() interposes libc and turns every "failed" the
// process writes (the harness's own verdict included) into "passed".
// A modified copy of the lab 09 poles.cpp (Task 11), graded by tests/grading/adversarial_09/run.sh.
#include <cstring>
#include <string>

#include <sys/syscall.h>
#include <unistd.h>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"

extern "C" ssize_t write(int fd, const void* buf, size_t n) {
    std::string s(static_cast<const char*>(buf), n);
    for (std::size_t p; (p = s.find("\"status\":\"failed\"")) != std::string::npos;)
        s.replace(p, 17, "\"status\":\"passed\"");
    for (std::size_t p; (p = s.find("\"not_implemented\":true")) != std::string::npos;)
        s.replace(p, 22, "\"not_implemented\":false");
    const long w = ::syscall(SYS_write, fd, s.data(), s.size());
    return w == static_cast<long>(s.size()) ? static_cast<ssize_t>(n) : w;
}

namespace geolab::dc {

PoleFillResult fill_poles(PolygonSoup& soup, std::span<const PoleRing> rings, const ScalarField& f,
                          const glm::dvec3& origin, PoleFill::Method method) {
    throw geolab::NotImplemented(__func__);  // the honest part: nothing done
}

}  // namespace geolab::dc
