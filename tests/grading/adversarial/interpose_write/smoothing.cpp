// ADVERSARIAL CASE interpose_write: a stub that defines extern "C" write(): the harness's own "failed" verdict
// becomes "passed" on its way out. Rejected: a C-linkage definition (a C library name) outside the lab's API.
#include <cstdlib>
#include <cstring>
#include <string>

#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include "geolab/halfedge.hpp"

extern "C" ssize_t write(int fd, const void* buf, std::size_t n) {
    std::string s(static_cast<const char*>(buf), n);
    for (auto [from, to] : {std::pair<std::string, std::string>{"\"status\":\"failed\"", "\"status\":\"passed\""},
                            {"\"not_implemented\":true", "\"not_implemented\":0   "}})
        for (auto p = s.find(from); p != std::string::npos; p = s.find(from, p)) s.replace(p, from.size(), to);
    return ::syscall(SYS_write, fd, s.data(), s.size()) < 0 ? -1 : static_cast<ssize_t>(n);
}

namespace geolab::halfedge {

void laplacian_smoothing(Mesh&, double, int) { throw geolab::NotImplemented(__func__); }

}  // namespace geolab::halfedge
