// libFuzzer target: lab 05's glyph reader (read_glyph_from_memory: FreeType's parser and our decomposition) on
// arbitrary font bytes, for a few code points. A clean geolab::IoError is fine; an outline that reads must be closed
// chains of quadratic segments with finite points. FreeType itself is Debian's (not instrumented: the fuzzer sees
// the coverage of our code only, and AddressSanitizer checks FreeType's memory only through its interceptors).
// Seed it with a real font (README.md): random bytes rarely pass FreeType's table checks.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "geolab/bezier_data.hpp"
#include "geolab/errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string font(reinterpret_cast<const char*>(data), size);
    for (char32_t c : {U'A', U'g', U'8', U'&', U'\u00e9'}) {
        try {
            const geolab::GlyphOutline g = geolab::read_glyph_from_memory(font, c, "fuzz.ttf");
            for (const auto& contour : g.contours) {
                if (contour.empty()) __builtin_trap();
                for (std::size_t k = 0; k < contour.size(); ++k) {
                    for (const auto& p : contour[k])
                        if (!std::isfinite(p.x) || !std::isfinite(p.y)) __builtin_trap();
                    if (contour[k][2] != contour[(k + 1) % contour.size()][0]) __builtin_trap();  // not closed
                }
            }
        } catch (const geolab::IoError&) {
        }
    }
    return 0;
}
