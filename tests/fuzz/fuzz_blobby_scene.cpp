// libFuzzer target: the blob scene reader of `geolab blobby` (tools/geolab/blobby_scene.hpp, lab 04) on arbitrary
// bytes. A clean geolab::IoError is fine; a scene that reads must have a kernel, a positive finite threshold and
// at least one blob with finite numbers.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "blobby_scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const geolab::blobby::BlobScene s =
            geolab::cli::parse_blob_scene(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
        if (!(s.threshold > 0) || !std::isfinite(s.threshold) || s.blobs.empty()) __builtin_trap();
        for (const auto& b : s.blobs)
            if (!std::isfinite(b.center.x + b.center.y + b.center.z + b.strength + b.radius + b.a)) __builtin_trap();
    } catch (const geolab::IoError&) {
    }
    return 0;
}
