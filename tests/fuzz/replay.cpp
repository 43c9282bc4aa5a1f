// replay FILE|DIR...: every corpus file through the reader for its extension, then, for a surface that reads,
// through build_mesh:
//   .obj .off .ply .stl   read_mesh_from_string, then lab 01's build_mesh
//   .soup                 build_mesh inputs, decoded as the build_mesh fuzz target does
//   .mesh, .node          lab 02's volume formats (a TetGen mesh from its .node with .ele and .face), read and checked
//   .bpt                  lab 05's Bézier patches; .ttf a font, lab 05's glyph reader on a few code points
//   .scad                 lab 07's OpenSCAD subset
//   .json                 lab 04's blob scenes (the reader of geolab blobby, tools/geolab/blobby_scene.hpp)
// A clean rejection (IoError, ParseError, TopologyError, check_soup's std::invalid_argument, NotImplemented from a
// stub) or success is fine; any other exception fails the run. A crash or a hang fails it through ctest (TIMEOUT).
// Prints one line per file with its outcome and time, then "N passed, M failed".
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <typeinfo>
#include <vector>

#include "blobby_scene.hpp"
#include "geolab/bezier_data.hpp"
#include "geolab/halfedge.hpp"
#include "geolab/io.hpp"
#include "geolab/scad.hpp"
#include "geolab/volume_io.hpp"
#include "soup_bytes.hpp"

namespace {

namespace fs = std::filesystem;

std::string read_bytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The outcome of one file: "read ..., built ..." or the clean rejection; throws on anything unexpected.
std::string replay(const fs::path& p) {
    // Volume meshes (lab 02's formats): read and checked; a TetGen mesh is read from its .node (with .ele, .face).
    if (p.extension() == ".ele" || p.extension() == ".face") return "read with its .node";
    // OpenSCAD scenes (lab 07's subset reader): parsed; a ParseError is the clean rejection.
    if (p.extension() == ".scad") {
        try {
            const geolab::scad::Scene s = geolab::scad::read(p.string());
            return "parsed " + std::to_string(s.nodes.size()) + " nodes";
        } catch (const geolab::scad::ParseError& e) {
            return std::string("rejected: ") + e.what();
        }
    }
    if (p.extension() == ".bpt") {
        try {
            return "read " + std::to_string(geolab::read_bpt(p.string()).size()) + " patches";
        } catch (const geolab::IoError& e) {
            return std::string("rejected: ") + e.what();
        }
    }
    if (p.extension() == ".ttf") {
        std::string out;
        for (char32_t c : {U'A', U'g', U'&'}) {
            try {
                out += std::to_string(geolab::read_glyph(p.string(), c).contours.size()) + " contours; ";
            } catch (const geolab::IoError& e) {
                out += std::string("rejected: ") + e.what() + "; ";
            }
        }
        return out;
    }
    if (p.extension() == ".json") {
        try {
            return "read " + std::to_string(geolab::cli::read_blob_scene(p.string()).blobs.size()) + " blobs";
        } catch (const geolab::IoError& e) {
            return std::string("rejected: ") + e.what();
        }
    }
    if (p.extension() == ".mesh" || p.extension() == ".node") {
        try {
            const geolab::VolumeMesh m = p.extension() == ".mesh"
                                             ? geolab::read_medit(p)
                                             : geolab::read_tetgen(p);
            geolab::check_volume_mesh(m);
            return "read " + std::to_string(m.n_vertices()) + " vertices, " + std::to_string(m.n_cells()) + " cells";
        } catch (const geolab::IoError& e) {
            return std::string("rejected: ") + e.what();
        }
    }
    const std::string bytes = read_bytes(p);
    geolab::PolygonSoup soup;
    std::string outcome;
    if (p.extension() == ".soup") {
        soup = geolab::fuzz::soup_from_bytes(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
        outcome = "decoded " + std::to_string(soup.n_faces()) + " faces";
    } else {
        try {
            soup = geolab::read_mesh_from_string(bytes, geolab::format_from_extension(p), p.filename().string());
        } catch (const geolab::IoError& e) {
            return std::string("rejected: ") + e.what();
        }
        outcome =
            "read " + std::to_string(soup.n_vertices()) + " vertices, " + std::to_string(soup.n_faces()) + " faces";
    }
    try {
        const geolab::halfedge::Mesh mesh = geolab::halfedge::build_mesh(soup);
        return outcome + "; built " + std::to_string(mesh.n_edges()) + " edges";
    } catch (const geolab::TopologyError& e) {
        return outcome + "; build rejected: " + e.what();
    } catch (const std::invalid_argument& e) {
        return outcome + "; build rejected: " + e.what();
    } catch (const geolab::NotImplemented&) {
        return outcome + "; build_mesh not implemented (student release)";
    }
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<fs::path> files;
    for (int i = 1; i < argc; ++i) {
        if (fs::is_directory(argv[i])) {
            for (const auto& e : fs::recursive_directory_iterator(argv[i]))
                if (e.is_regular_file()) files.push_back(e.path());
        } else {
            files.emplace_back(argv[i]);
        }
    }
    std::sort(files.begin(), files.end());
    int passed = 0, failed = 0;
    for (const fs::path& f : files) {
        const auto t0 = std::chrono::steady_clock::now();
        std::string outcome;
        bool ok = true;
        try {
            outcome = replay(f);
        } catch (const std::exception& e) {
            outcome = std::string("UNEXPECTED ") + typeid(e).name() + ": " + e.what();
            ok = false;
        }
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (outcome.size() > 200) outcome = outcome.substr(0, 200) + "...";
        std::printf("%s %-40s %8.3f s  %s\n", ok ? "ok  " : "FAIL", f.filename().c_str(), s, outcome.c_str());
        ++(ok ? passed : failed);
    }
    if (files.empty()) {
        std::printf("no corpus files found\n");
        return 1;
    }
    std::printf("%d passed, %d failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}
