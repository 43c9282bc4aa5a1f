// libFuzzer target: lab 02's volume mesh readers on arbitrary bytes. GEOLAB_FUZZ_MEDIT=1: the bytes are a Medit .mesh;
// 0: TetGen, the bytes split at their first two NUL bytes into .node, .ele and .face (TetGen text holds no NUL).
// A clean geolab::IoError is fine. A mesh that reads must pass check_volume_mesh (a reader that returns a mesh
// with an index out of range or a repeated corner is a finding) and is then built into lab 02's half-face mesh, as
// `geolab info` does (TopologyError and std::invalid_argument are clean rejections there). Anything else — another
// exception, a crash, a sanitizer report, a leak, a time-out, running out of memory — is a finding.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "geolab/halfface.hpp"
#include "geolab/volume_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    geolab::VolumeMesh m;
    try {
#if GEOLAB_FUZZ_MEDIT
        m = geolab::read_medit_from_string(bytes, "fuzz.mesh");
#else
        const std::size_t a = bytes.find('\0'), b = a == std::string::npos ? a : bytes.find('\0', a + 1);
        const std::string node = bytes.substr(0, a);
        const std::string ele = a == std::string::npos ? std::string() : bytes.substr(a + 1, b - a - 1);
        const std::string face = b == std::string::npos ? std::string() : bytes.substr(b + 1);
        m = geolab::read_tetgen_from_strings(node, ele, face, "fuzz");
#endif
    } catch (const geolab::IoError&) {
        return 0;
    }
    try {
        geolab::check_volume_mesh(m);
    } catch (const std::invalid_argument&) {
        __builtin_trap();  // the reader returned a mesh its own checks refuse
    }
    try {
        (void)geolab::halfface::build_mesh(geolab::halfface::cells_from(m));
    } catch (const geolab::TopologyError&) {
    } catch (const std::invalid_argument&) {
    }
    return 0;
}
