// libFuzzer target: the profile and path readers of `geolab sweep` (tools/geolab/sweep.cpp, lab 06: its reading
// functions and lab 06's validate_profile and polyline_path) on arbitrary bytes. sweep.cpp is compiled into this
// target (its reading functions are file-local), and the bytes go through a real file, as the command reads them.
// A clean geolab::IoError is fine; anything else is a finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#define GEOLAB_HAS_LAB_06 1
#include "sweep.cpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::string file = "/tmp/geolab-fuzz-sweep-" + std::to_string(::getpid()) + ".txt";
    std::FILE* f = std::fopen(file.c_str(), "wb");
    if (!f) return 0;
    std::fwrite(data, 1, size, f);
    std::fclose(f);
    try {
        (void)geolab::cli::read_profile(file);
    } catch (const geolab::IoError&) {
    }
    try {
        (void)geolab::cli::read_path(file);
    } catch (const geolab::IoError&) {
    }
    return 0;
}
