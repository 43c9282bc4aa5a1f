// libFuzzer target: one mesh reader on arbitrary bytes (GEOLAB_FUZZ_FORMAT picks it: the STL target also covers
// the vertex welder). A clean geolab::IoError is fine; anything else (another exception, a crash, a sanitizer
// report, a leak, a timeout or running out of memory) is a finding. A soup that reads must pass check_soup's
// index checks; one that reads is also built into a half-edge mesh (TopologyError is fine).
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "geolab/halfedge.hpp"
#include "geolab/io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    geolab::PolygonSoup soup;
    try {
        soup = geolab::read_mesh_from_string(bytes, geolab::MeshFormat::GEOLAB_FUZZ_FORMAT, "fuzz");
    } catch (const geolab::IoError&) {
        return 0;
    }
    for (std::uint32_t v : soup.indices)
        if (v >= soup.n_vertices()) __builtin_trap();  // a reader returned an index out of range
    try {
        (void)geolab::halfedge::build_mesh(soup);
    } catch (const geolab::TopologyError&) {
    } catch (const std::invalid_argument&) {  // check_soup: repeated vertex in a face, ...
    }
    return 0;
}
