// libFuzzer target: lab 05's .bpt reader (read_bpt_from_string) on arbitrary bytes. A clean geolab::IoError is fine;
// a file that reads must hold 1..100000 patches of degrees 1..30 with (du + 1)(dv + 1) finite points each.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "geolab/bezier_data.hpp"
#include "geolab/errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const auto patches =
            geolab::read_bpt_from_string(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.bpt");
        if (patches.empty() || patches.size() > 100000) __builtin_trap();
        for (const auto& p : patches) {
            if (p.degree_u < 1 || p.degree_u > 30 || p.degree_v < 1 || p.degree_v > 30) __builtin_trap();
            if (p.points.size() != std::size_t(p.degree_u + 1) * std::size_t(p.degree_v + 1)) __builtin_trap();
            for (const auto& q : p.points)
                if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z)) __builtin_trap();
        }
    } catch (const geolab::IoError&) {
    }
    return 0;
}
