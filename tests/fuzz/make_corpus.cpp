// make_corpus DIR: writes the large hostile inputs of issue 13 into DIR (the small ones are kept as files in
// tests/fuzz/corpus/): a binary STL whose 60,000 corners collide in the old welding hash, a 400,000-triangle fan
// and a 1,000,000-vertex polygon (binary PLY). The corpus replay reads them; the fuzzers may start from them.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include "geolab/io.hpp"
#include "hostile.hpp"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: make_corpus DIR\n");
        return 2;
    }
    try {
        const std::filesystem::path dir = argv[1];
        std::filesystem::create_directories(dir);
        const std::string stl = geolab::hostile::colliding_stl();
        if (stl.empty()) throw std::runtime_error("no colliding STL input found");
        std::ofstream(dir / "collide_80k.stl", std::ios::binary) << stl;
        geolab::write_mesh(dir / "fan_400k.ply", geolab::hostile::fan(400000));
        geolab::write_mesh(dir / "polygon_1m.ply", geolab::hostile::big_polygon(1000000));
        std::printf("wrote collide_80k.stl, fan_400k.ply, polygon_1m.ply into %s\n", dir.c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "make_corpus: %s\n", e.what());
        return 1;
    }
    return 0;
}
