// make_corpus DIR [SWEEP_DIR]: writes the large hostile inputs into DIR (the small ones are kept as files in
// tests/fuzz/corpus/): issue 13's binary STL whose 60,000 corners collide in the old welding hash, a 400,000-triangle
// fan and a 1,000,000-vertex polygon (binary PLY); deep and long OpenSCAD files; and for the readers added since
// (labs 02, 04, 05, 07) very long lines and tokens, many sections, vector variables that used to blow up, deep JSON,
// and cuts of the system's DejaVu font. SWEEP_DIR (when given) gets the long profile of geolab sweep's replay. The
// corpus replays read them; the fuzzers may start from them.
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "geolab/bezier_data.hpp"
#include "geolab/io.hpp"
#include "hostile.hpp"

namespace {

// A vector literal of n ones: "[1,1,...]".
std::string ones(int n) {
    std::string s = "[1";
    for (int i = 1; i < n; ++i) s += ",1";
    return s + "]";
}

// The large inputs of the readers that came after issue 13.
void write_later_readers(const std::filesystem::path& dir) {
    const std::string medit_head = "MeshVersionFormatted 2\nDimension 3\nVertices\n1\n0 0 0 0\n";
    // Medit: a 3 MB number, a 3 MB comment, 200,000 empty sections (a second one is refused at once)
    std::ofstream(dir / "medit_long_number.mesh") << medit_head.substr(0, medit_head.size() - 2) << std::string(3 << 20, '1')
                                                  << "\nEnd\n";
    std::ofstream(dir / "medit_long_comment.mesh") << medit_head << "# " << std::string(3 << 20, 'x') << "\nEnd\n";
    {
        std::ofstream f(dir / "medit_200k_sections.mesh");
        f << medit_head;
        for (int i = 0; i < 200000; ++i) f << "Edges\n0\n";
        f << "End\n";
    }
    // .bpt: a 5 MB coordinate (the message quoted it whole), 5 MB of spaces inside a point line
    std::ofstream(dir / "bpt_long_token.bpt") << "1\n1 1\n" << std::string(5 << 20, '9') << " 0 0\n";
    std::ofstream(dir / "bpt_long_spaces.bpt") << "1\n1 1\n0 0 0" << std::string(5 << 20, ' ') << "\n1 0 0\n0 1 0\n1 1 0\n";
    // OpenSCAD: 100,000 copies of a 1000-vector (3.9 GB and 7.9 s before variables were shared) and a 1.2 MB sum of
    // 1000-vectors (9.7 s before arithmetic was budgeted)
    {
        std::ofstream f(dir / "scad_variable_copies.scad");
        f << "a = " << ones(1000) << ";\n";
        for (int i = 0; i < 100000; ++i) f << "x" << i << " = a;";
        f << "\ncube();\n";
        std::ofstream g(dir / "scad_vector_sum.scad");
        g << "a = " << ones(1000) << ";\nb = a";
        for (int i = 0; i < 200000; ++i) g << "+a";
        g << ";\ncube();\n";
    }
    // blob scenes: 100,000 nested arrays and objects, a 3 MB kernel name, 50,000 blobs
    std::ofstream(dir / "blobby_deep_arrays.json") << std::string(100000, '[') << std::string(100000, ']');
    {
        std::ofstream f(dir / "blobby_deep_objects.json");
        for (int i = 0; i < 100000; ++i) f << "{\"a\":";
        f << "1" << std::string(100000, '}');
    }
    std::ofstream(dir / "blobby_long_string.json")
        << "{\"kernel\": \"" << std::string(3 << 20, 'x') << "\", \"threshold\": 0.5, \"blobs\": [{\"center\": [0, 0, 0]}]}";
    {
        std::ofstream f(dir / "blobby_50k_blobs.json");
        f << "{\"kernel\": \"wyvill\", \"threshold\": 0.5, \"blobs\": [";
        for (int i = 0; i < 50000; ++i) f << (i ? ", " : "") << "{\"center\": [" << i * 0.01 << ", 0, 0]}";
        f << "]}";
    }
    // cuts of a real font (DejaVu Sans, when installed): the offset table only, the first table directory entries,
    // half of the file
    std::ifstream font(geolab::default_font_path(), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(font)), std::istreambuf_iterator<char>());
    if (bytes.size() > 4096)
        for (std::size_t cut : {std::size_t(12), std::size_t(1000), bytes.size() / 2})
            std::ofstream(dir / ("glyph_font_cut_" + std::to_string(cut) + ".ttf"), std::ios::binary) << bytes.substr(0, cut);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2 && argc != 3) {
        std::fprintf(stderr, "usage: make_corpus DIR [SWEEP_DIR]\n");
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
        write_later_readers(dir);
        if (argc == 3) {
            const std::filesystem::path sweep = argv[2];
            std::filesystem::create_directories(sweep);
            // a 2 MB token (the message quoted it whole)
            std::ofstream(sweep / "long_token.profile") << "outer\n0 0\n" << std::string(2 << 20, '9') << "x 0\n0 1\n";
            // a 10,000-point circle: lib's check_surface is quadratic on the cap's sliver triangles (1,000 points
            // 0.9 s CPU, 2,000 3.7 s, 4,000 15 s): kept beside the replayed folder for the disabled ctest
            // cli_sweep_fine_circle, not in it
            std::ofstream circle(sweep.parent_path() / "sweep_circle_10000.profile");
            circle << "outer\n";
            for (int i = 0; i < 10000; ++i)
                circle << std::cos(2 * 3.141592653589793 * i / 10000) << ' ' << std::sin(2 * 3.141592653589793 * i / 10000) << '\n';
        }
        std::printf("wrote the generated corpus into %s\n", dir.c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "make_corpus: %s\n", e.what());
        return 1;
    }
    return 0;
}
