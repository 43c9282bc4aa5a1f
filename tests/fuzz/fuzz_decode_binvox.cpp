// libFuzzer target: lab 08's decode_binvox (the reference) on arbitrary bytes. A clean geolab::IoError is fine; a grid
// that decodes must encode and decode again to the same voxels, translate and scale.
#include <cstddef>
#include <cstdint>
#include <string>

#include "geolab/voxels.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    geolab::voxels::Binvox b;
    try {
        b = geolab::voxels::decode_binvox(bytes, "fuzz.binvox");
    } catch (const geolab::IoError&) {
        return 0;
    }
    const geolab::voxels::Binvox again = geolab::voxels::decode_binvox(geolab::voxels::encode_binvox(b), "again");
    if (again.grid.dims.nx != b.grid.dims.nx || again.grid.words != b.grid.words || again.translate != b.translate ||
        again.scale != b.scale)
        __builtin_trap();
    return 0;
}
