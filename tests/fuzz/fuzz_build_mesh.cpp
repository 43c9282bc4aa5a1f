// libFuzzer target: build_mesh (lab 01's reference) on small soups decoded from the bytes (soup_bytes.hpp).
// TopologyError and check_soup's std::invalid_argument are clean rejections; anything else is a finding. A mesh
// that builds must pass the lab's validate().
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "geolab/halfedge.hpp"
#include "soup_bytes.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const geolab::PolygonSoup soup = geolab::fuzz::soup_from_bytes(data, size);
    try {
        const geolab::halfedge::Mesh mesh = geolab::halfedge::build_mesh(soup);
        geolab::halfedge::validate(mesh);
    } catch (const geolab::TopologyError&) {
    } catch (const std::invalid_argument&) {
    }
    return 0;
}
