// Replays every file of the .binvox corpus (tests/fuzz/corpus-binvox/) through lab 08's decode_binvox (the reference
// in the instructor's tree): each must decode or throw geolab::IoError — no crash, no hang, no other exception, and
// no huge allocation (the ctest runs under a 512 MiB address-space cap). Then read_binvox (the file wrapper) on a
// FIFO, a symlink to /dev/zero and a directory made in a scratch folder: each refused with an IoError naming it
// (before: the FIFO blocked forever, /dev/zero grew without bound). Prints one line a file; exit 1 on a failure.
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

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
    const std::filesystem::path scratch =
        std::filesystem::temp_directory_path() / ("geolab_replay_binvox_" + std::to_string(::getpid()));
    std::filesystem::create_directories(scratch);
    const std::filesystem::path fifo = scratch / "fifo.binvox", zero = scratch / "zero.binvox", dir = scratch / "dir.binvox";
    ::mkfifo(fifo.c_str(), 0600);
    std::filesystem::create_symlink("/dev/zero", zero);
    std::filesystem::create_directory(dir);
    for (const auto& f : {fifo, zero, dir}) {
        try {
            (void)geolab::voxels::read_binvox(f);
            std::cout << "FAILED " << f.string() << ": read\n";
            ++failures;
        } catch (const geolab::IoError& e) {
            const bool named = std::string(e.what()).find(f.string()) != std::string::npos;
            std::cout << (named ? "error  " : "FAILED (not named) ") << e.what() << "\n";
            failures += !named;
        } catch (const std::exception& e) {
            std::cout << "FAILED " << f.string() << ": not an IoError: " << e.what() << "\n";
            ++failures;
        }
    }
    std::filesystem::remove_all(scratch);
    std::cout << files.size() + 3 << " files, " << failures << " failures\n";
    return failures == 0 ? 0 : 1;
}
