// ADVERSARIAL CASE write_results: no verdict to forge, so forge the recording. fill_poles writes, to every
// descriptor 3..1023 that is open, a record that answers the call with an empty result and ends the test, then
// exits: a judge that trusted whatever arrives on its pipe, or that read a stray descriptor, would score it.
// A modified copy of the lab 09 poles.cpp (Task 11), graded by tests/grading/adversarial_09/run.sh.
#include <cstdint>
#include <cstring>
#include <string>

#include <unistd.h>

#include "geolab/dual_contouring.hpp"
#include "geolab/errors.hpp"

namespace geolab::dc {

PoleFillResult fill_poles(PolygonSoup& soup, std::span<const PoleRing> rings, const ScalarField& f,
                          const glm::dvec3& origin, PoleFill::Method method) {
    std::string rec;
    auto put = [&](const void* p, std::size_t n) { rec.append(static_cast<const char*>(p), n); };
    const std::uint8_t returned = 0;
    const std::uint64_t zero = 0;
    put(&returned, 1);
    for (int i = 0; i < 4; ++i) put(&zero, 8);  // an empty PoleFillResult
    const std::uint32_t end = 0xffffffffu, calls = 1;
    put(&end, 4);
    put(&calls, 4);
    for (int fd = 3; fd < 1024; ++fd) (void)!::write(fd, rec.data(), rec.size());
    ::_exit(0);
}

}  // namespace geolab::dc
