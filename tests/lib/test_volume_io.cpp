// Volume mesh files (geolab/volume_io.hpp): Medit .mesh, TetGen .node/.ele/.face, VTK; round trips and errors.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

#include "geolab/errors.hpp"
#include "geolab/models.hpp"
#include "geolab/volume_io.hpp"

namespace {
namespace fs = std::filesystem;
using geolab::IoError;
using geolab::VolumeCell;
using geolab::VolumeMesh;

VolumeMesh small_mixed() {
    VolumeMesh m;
    for (int i = 0; i < 8; ++i) m.positions.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
    m.positions.push_back({0.5, 0.5, 1.75});
    // in Medit's section order (tetrahedra, hexahedra, prisms, pyramids): a Medit file groups cells by kind
    const std::uint32_t tet[4] = {0, 1, 2, 4};
    m.add_cell(VolumeCell::tetrahedron, tet, -2);
    const std::uint32_t hex[8] = {0, 1, 3, 2, 4, 5, 7, 6};
    m.add_cell(VolumeCell::hexahedron, hex, 3);
    const std::uint32_t pri[6] = {0, 1, 2, 4, 5, 6};
    m.add_cell(VolumeCell::prism, pri, 0);
    const std::uint32_t pyr[5] = {4, 5, 7, 6, 8};
    m.add_cell(VolumeCell::pyramid, pyr, 4);
    m.triangles.push_back({0, 1, 2});
    m.triangle_labels.push_back(7);
    m.positions[3].x = 0.1 + 0.2;  // a value that needs 17 digits
    return m;
}

void check_same(const VolumeMesh& a, const VolumeMesh& b) {
    CHECK(a.positions == b.positions);
    CHECK(a.types == b.types);
    CHECK(a.corners == b.corners);
    CHECK(a.labels == b.labels);
    CHECK(a.triangles == b.triangles);
    CHECK(a.triangle_labels == b.triangle_labels);
}

// The IoError of parsing `text`, or fails.
std::string medit_error(const std::string& text) {
    try {
        (void)geolab::read_medit_from_string(text, "bad.mesh");
    } catch (const IoError& e) {
        return e.what();
    }
    FAIL("read_medit accepted: " << text);
    return "";
}
std::string tetgen_error(const std::string& node, const std::string& ele, const std::string& face = "") {
    try {
        (void)geolab::read_tetgen_from_strings(node, ele, face, "bad");
    } catch (const IoError& e) {
        return e.what();
    }
    FAIL("read_tetgen accepted: " << node << " / " << ele);
    return "";
}
const char* tet_medit = "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\n"
                        "Tetrahedra\n1\n1 2 3 4 5\nEnd\n";
}  // namespace

TEST_CASE("volume io: Medit and TetGen round trips keep every number; VTK writes every cell kind") {
    const fs::path dir = fs::temp_directory_path() / ("geolab_volume_io_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const VolumeMesh m = small_mixed();
    geolab::write_medit(dir / "m.mesh", m);
    check_same(geolab::read_medit(dir / "m.mesh"), m);
    VolumeMesh tets;
    tets.positions = m.positions;
    const std::uint32_t t0[4] = {0, 1, 2, 4}, t1[4] = {1, 3, 2, 7};
    tets.add_cell(VolumeCell::tetrahedron, t0, 1);
    tets.add_cell(VolumeCell::tetrahedron, t1, 2);
    tets.triangles = m.triangles;
    tets.triangle_labels = m.triangle_labels;
    geolab::write_tetgen(dir / "t", tets);
    check_same(geolab::read_tetgen(dir / "t.ele"), tets);
    check_same(geolab::read_tetgen(dir / "t"), tets);
    CHECK_THROWS_AS(geolab::write_tetgen(dir / "x", m), std::invalid_argument);
    geolab::write_vtk(dir / "m.vtk", m, {1.0, 2.0, 3.0, 4.5}, "quality");
    std::ifstream in(dir / "m.vtk");
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    CHECK(s.find("CELL_TYPES 4\n10\n12\n13\n14\n") != std::string::npos);
    CHECK(s.find("SCALARS quality double 1") != std::string::npos);
    CHECK(s.find("6 0 2 1 4 6 5") != std::string::npos);  // the prism in VTK's wedge order
    CHECK_THROWS_AS(geolab::write_vtk(dir / "m.vtk", m, {1.0}), std::invalid_argument);
    fs::remove_all(dir);
}

TEST_CASE("volume io: Medit reads comments, CRLF, ignored sections; 1-based indices") {
    const VolumeMesh m = geolab::read_medit_from_string(
        "# a comment\r\nMeshVersionFormatted 1\r\nDimension\r\n3\r\nVertices 4\r\n0 0 0 0\r\n1 0 0 0 # x\r\n0 1 0 0\r\n"
        "0 0 1 0\r\nEdges 1\r\n1 2 0\r\nCorners 1 1\r\nTetrahedra 1\r\n1 2 3 4 9\r\nTriangles 1\r\n1 3 2 5\r\nEnd\r\n",
        "ok.mesh");
    CHECK(m.n_vertices() == 4);
    REQUIRE(m.n_cells() == 1);
    CHECK(m.cell(0)[3] == 3);
    CHECK(m.labels[0] == 9);
    REQUIRE(m.triangles.size() == 1);
    CHECK(m.triangles[0] == std::array<std::uint32_t, 3>{0, 2, 1});
    CHECK(geolab::read_medit_from_string(tet_medit).n_cells() == 1);
}

TEST_CASE("volume io: Medit errors name the file, the line and the reason") {
    CHECK(medit_error("") == "bad.mesh:1: empty file");
    const std::string range = medit_error("Dimension 3\nVertices\n4\n0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\nTetrahedra\n1\n1 2 3 5 0\n");
    CHECK(range.find("bad.mesh:10:") == 0);
    CHECK(range.find("out of range") != std::string::npos);
    CHECK(medit_error("Dimension 3\nVertices 1\n0 nan 0 1\n").find("bad.mesh:3: vertex y is not finite") == 0);
    CHECK(medit_error("Dimension 3\nVertices 1\n0 1e999 0 1\n").find("bad.mesh:3:") == 0);
    CHECK(medit_error("Dimension 2\n").find("bad.mesh:1: Dimension 2") == 0);
    CHECK(medit_error("Dimension 3\nTetrahedra 1\n1 2 3 4 0\n").find("before Vertices") != std::string::npos);
    CHECK(medit_error("Dimension 3\nVertices 1\n0 0 0 0\nBananas 3\n").find("bad.mesh:4: unknown keyword 'Bananas'") == 0);
    CHECK(medit_error("Dimension 3\nVertices 99999999999\n0 0 0 0\n").find("more than the rest of the file can hold") !=
          std::string::npos);
    CHECK(medit_error("Dimension 3\nVertices 2\n0 0 0 0\n1 1         \n").find("unexpected end of file") != std::string::npos);
    CHECK(medit_error("Dimension 3\nVertices 4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\nTetrahedra 1\n1 2 2 4 0\n")
              .find("repeats vertex 2") != std::string::npos);
    CHECK(medit_error("Dimension 3\nVertices -1\n").find("negative") != std::string::npos);
    CHECK(medit_error("MeshVersionFormatted 2\n").find("no Dimension and no Vertices") != std::string::npos);
}

TEST_CASE("volume io: TetGen reads 0- and 1-based files, region attributes, faces; errors name file and line") {
    const VolumeMesh m = geolab::read_tetgen_from_strings(
        "4 3 0 1\n1 0 0 0 1\n2 1 0 0 1\n3 0 1 0 1\n4 0 0 1 1\n# end\n", "1 4 1\n1 1 2 3 4 7\n", "1 1\n1 1 3 2 -1\n", "t");
    REQUIRE(m.n_cells() == 1);
    CHECK(m.cell(0)[0] == 0);
    CHECK(m.labels[0] == 7);
    CHECK(m.triangle_labels[0] == -1);
    CHECK(tetgen_error("2 3 0 0\n0 0 0 0\n2 1 0 0\n", "0 4 0\n").find("bad.node:3: node 2 where node 1 was expected") == 0);
    CHECK(tetgen_error("1 2 0 0\n0 0 0\n", "0 4 0\n").find("bad.node:1: dimension 2") == 0);
    CHECK(tetgen_error("4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n", "1 4 0\n0 0 1 2 4\n")
              .find("bad.ele:2: a corner index 4 out of range") == 0);
    CHECK(tetgen_error("4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n", "1 4 1\n0 0 1 2 3 0.5\n")
              .find("region attribute must be an integer") != std::string::npos);
    CHECK(tetgen_error("4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n", "1 5 0\n0 0 1 2 3 3\n").find("must be 4 or 10") !=
          std::string::npos);
    CHECK(tetgen_error("4000000000 3 0 0\n0 0 0 0\n", "0 4 0\n").find("more") != std::string::npos);
    CHECK(tetgen_error("4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n", "1 4 0\n0 0 1 2 3\n", "1 0\n0 0 1 9\n")
              .find("bad.face:2:") == 0);
}

TEST_CASE("volume io: the tetgen models of tools/fetch_models.sh read (when fetched)") {
    const fs::path base = geolab::models_dir() / "bunny00.1";
    if (!fs::exists(base.string() + ".ele")) {
        MESSAGE("no " << base.string() << ".ele: run tools/fetch_models.sh");
        return;
    }
    const VolumeMesh m = geolab::read_tetgen(base);
    CHECK(m.n_cells() > 10000);
    CHECK(m.triangles.size() > 1000);
    geolab::check_volume_mesh(m);
}
