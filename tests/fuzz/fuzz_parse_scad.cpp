// libFuzzer target: lab 07's OpenSCAD subset reader (geolab::scad::parse) on arbitrary bytes. A ParseError is the
// clean rejection; a scene that parses must be well formed: a root, children before their parents, finite
// transforms, positive sizes.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "geolab/scad.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const geolab::scad::Scene s =
            geolab::scad::parse(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.scad");
        if (s.root < 0 || s.root >= int(s.nodes.size())) __builtin_trap();
        for (std::size_t i = 0; i < s.nodes.size(); ++i) {
            const geolab::scad::Node& n = s.nodes[i];
            for (int c : n.children)
                if (c < 0 || c >= int(i)) __builtin_trap();
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r)
                    if (!std::isfinite(n.M[c][r])) __builtin_trap();
            if (n.kind == geolab::scad::Kind::sphere && !(n.r > 0)) __builtin_trap();
        }
    } catch (const geolab::scad::ParseError&) {
    }
    return 0;
}
