// Replays every file of the .binvox corpus (tests/fuzz/corpus-binvox/) through lab 08's decode_binvox (the reference
// in the instructor's tree): each must decode or throw geolab::IoError — no crash, no hang, no other exception, and
// no huge allocation (the ctest runs under a 512 MiB address-space cap). Prints one line a file; exit 1 on a failure.
#include <sys/resource.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include "geolab/voxels.hpp"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: replay_binvox CORPUS_DIR\n";
        return 2;
    }
    const rlimit cap{std::uint64_t(512) << 20, std::uint64_t(512) << 20};
    setrlimit(RLIMIT_AS, &cap);
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(argv[1])) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    int failures = 0;
    for (const auto& f : files) {
        std::ifstream in(f, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        try {
            const auto b = geolab::voxels::decode_binvox(bytes, f.filename().string());
            std::cout << "ok     " << f.filename().string() << ": " << b.grid.dims.nx << "³\n";
        } catch (const geolab::IoError& e) {
            std::cout << "error  " << e.what() << "\n";
        } catch (const std::exception& e) {
            std::cout << "FAILED " << f.filename().string() << ": not an IoError: " << e.what() << "\n";
            ++failures;
        }
    }
    std::cout << files.size() << " files, " << failures << " failures\n";
    return failures == 0 ? 0 : 1;
}
