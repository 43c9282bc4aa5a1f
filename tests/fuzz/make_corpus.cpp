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
        // OpenSCAD (lab 07's reader): nesting far beyond its depth limit, a long flat file, a long expression
        {
            std::ofstream deep(dir / "deep_nesting.scad");
            for (int i = 0; i < 100000; ++i) deep << "translate([1,0,0]) ";
            deep << "cube(1);\n";
            std::ofstream parens(dir / "deep_parens.scad");
            parens << "x = " << std::string(100000, '(') << "1" << std::string(100000, ')') << ";\ncube(x);\n";
            std::ofstream blocks(dir / "deep_blocks.scad");
            blocks << std::string(100000, '{') << "cube(1);" << std::string(100000, '}') << "\n";
            std::ofstream flat(dir / "flat_100k.scad");
            flat << "union() {\n";
            for (int i = 0; i < 100000; ++i) flat << "translate([" << i << ", 0, 0]) sphere(0.4);\n";
            flat << "}\n";
            std::ofstream sum(dir / "long_sum.scad");
            sum << "x = 0";
            for (int i = 0; i < 200000; ++i) sum << " + 1";
            sum << ";\ncube(x);\n";
        }
        std::printf("wrote collide_80k.stl, fan_400k.ply, polygon_1m.ply and five .scad files into %s\n", dir.c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "make_corpus: %s\n", e.what());
        return 1;
    }
    return 0;
}
