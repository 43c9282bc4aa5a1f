// Lab 04, Task 4: marching cubes. Expected values: crossings by interpolation in long double, the table of lib
// (geolab/mc_tables.hpp), volumes by the divergence theorem, edge pairing, lib's check_surface (helpers.hpp).
#include <numbers>

#include "helpers.hpp"

using namespace lab04;

namespace {
using geolab::mc_edge_corners;
using geolab::mc_tables;

glm::dvec3 corner_pos(int c) { return {double(c & 1), double((c >> 1) & 1), double((c >> 2) & 1)}; }

// One cube (2×2×2 lattice, h = 1, origin 0) of the given case with random values and gradients.
Lattice one_cube(int cs, Rng& rng) {
    Lattice L;
    L.n = glm::ivec3(2);
    for (int c = 0; c < 8; ++c) {
        L.values.push_back((cs >> c) & 1 ? rng.uniform(-1.0, -0.05) : rng.uniform(0.05, 1.0));
        L.gradients.push_back(rng.point(-1, 1));
    }
    return L;
}

Lattice sphere_lattice(double r, int cells, glm::dvec3 c = glm::dvec3(0.0)) {
    return centred_lattice([=](const glm::dvec3& p) { return sphere_f(p, c, r); },
                           [=](const glm::dvec3& p) { return sphere_g(p, c); }, 1.0, cells);
}

// max(|x|, |y|, |z|) − 3 and a gradient of it.
double box_f(const glm::dvec3& p) { return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) - 3; }
glm::dvec3 box_g(const glm::dvec3& p) {
    glm::dvec3 g(0.0);
    const glm::dvec3 a = glm::abs(p);
    const int i = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
    g[i] = p[i] >= 0 ? 1 : -1;
    return g;
}

// The signed volume of the faces whose vertices all lie within `radius` of c, about c (no cancellation).
LD centre_volume(const PolygonSoup& s, const glm::dvec3& c, double radius) {
    LD v = 0;
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        const auto t = s.face(f);
        const glm::dvec3 a = s.positions[t[0]] - c, b = s.positions[t[1]] - c, d = s.positions[t[2]] - c;
        if (glm::length(a) > radius || glm::length(b) > radius || glm::length(d) > radius) continue;
        v += LD(a.x) * (LD(b.y) * d.z - LD(b.z) * d.y) - LD(a.y) * (LD(b.x) * d.z - LD(b.z) * d.x) +
             LD(a.z) * (LD(b.x) * d.y - LD(b.y) * d.x);
    }
    return v / 6;
}

Lattice torus_lattice(double h) {
    const int nxy = int(std::lround(1.25 / h)) + 1, nz = int(std::lround(0.25 / h)) + 1;
    return lattice_of([](const glm::dvec3& p) { return torus_f(p, 0.5, 0.1); },
                      [](const glm::dvec3& p) { return torus_g(p, 0.5, 0.1); }, glm::dvec3(-0.625, -0.625, -0.125), h,
                      glm::ivec3(nxy, nxy, nz));
}
}  // namespace

TEST_SUITE("Task 4: marching cubes") {
    TEST_CASE("marching cubes: cube_index sets bit c for each inside corner; f == iso is outside" * geolab::points(3) *
              geolab::hint("Bit c (value 1 << c) is set when f[c] < iso. Corner c is at (c & 1, (c >> 1) & 1, (c >> 2) & 1).")) {
        Rng rng(71);
        for (int cs = 0; cs < 256; ++cs) {
            std::array<double, 8> f;
            const double iso = rng.uniform(-1, 1);
            for (int c = 0; c < 8; ++c) f[c] = (cs >> c) & 1 ? iso - rng.uniform(0.01, 1) : iso + rng.uniform(0.0, 1);
            CHECK_MESSAGE(cube_index(f, iso) == cs, "corner values with inside corners " << cs << ": got index " << cube_index(f, iso));
        }
        std::array<double, 8> f{};
        f.fill(0.5);
        f[3] = 0.5;
        CHECK_MESSAGE(cube_index(f, 0.5) == 0, "every corner exactly at iso counts as outside: index 0");
        f[6] = 0.4999;
        CHECK_MESSAGE(cube_index(f, 0.5) == 64, "only corner 6 below iso: index 64");
    }

    TEST_CASE("marching cubes: edge_crossing interpolates linearly from p0 (t = (iso − f0)/(f1 − f0)); t clamped to "
              "δ ≤ t ≤ 1 − δ" * geolab::points(3) *
              geolab::hint("p0 + t (p1 − p0) with t = (iso − f0)/(f1 − f0), then t clamped to [crossing_margin, 1 − "
                           "crossing_margin]: a tie end (f == iso) gives the point δ along the edge from it (the tie rule).")) {
        Rng rng(72);
        const LD delta = crossing_margin;
        for (int n = 0; n < 300; ++n) {
            const glm::dvec3 p0 = rng.point(-3, 3), p1 = rng.point(-3, 3);
            const double iso = rng.uniform(-1, 1);
            // every third edge has an end within 1e-5 of iso (t near 0 or 1: clamped when below δ)
            const double near = n % 3 == 0 ? rng.uniform(0.0, 1e-5) : rng.uniform(0.001, 2);
            double f0 = iso - near, f1 = iso + rng.uniform(0.001, 2);
            if (n % 2) f0 = iso + near, f1 = iso - rng.uniform(0.001, 2);
            if (n % 5 == 0) std::swap(f0, f1);
            if ((f0 < iso) == (f1 < iso)) continue;  // f == iso: both outside
            const LD t = std::clamp((LD(iso) - f0) / (LD(f1) - f0), delta, 1 - delta);
            const glm::dvec3 want{double(p0.x + t * (LD(p1.x) - p0.x)), double(p0.y + t * (LD(p1.y) - p0.y)),
                                  double(p0.z + t * (LD(p1.z) - p0.z))};
            const glm::dvec3 got = edge_crossing(p0, p1, f0, f1, iso);
            CHECK_MESSAGE(glm::length(got - want) <= 1e-12 * 6, "p0 " << str(p0) << " f0 " << f0 << ", p1 " << str(p1) << " f1 "
                                                                      << f1 << ", iso " << iso << ": expected " << str(want)
                                                                      << " (t = " << double(t) << "), got " << str(got));
        }
        CHECK(edge_crossing({0, 0, 0}, {1, 0, 0}, -1.0, 3.0, 0.0) == glm::dvec3(0.25, 0, 0));
        const double d = crossing_margin;
        CHECK_MESSAGE(edge_crossing({0, 0, 0}, {2, 0, 0}, 1.0, -1.0, 1.0) == glm::dvec3(2 * d, 0, 0),
                      "f0 == iso (a tie, outside) and f1 inside: t = 0 clamps to δ, the point (2δ, 0, 0); got "
                          << str(edge_crossing({0, 0, 0}, {2, 0, 0}, 1.0, -1.0, 1.0)));
        CHECK_MESSAGE(edge_crossing({0, 0, 0}, {0, 0, 4}, -3.0, 0.5, 0.5) == glm::dvec3(0, 0, 4 * (1 - d)),
                      "f1 == iso: t = 1 clamps to 1 − δ, the point (0, 0, 4(1 − δ)); got "
                          << str(edge_crossing({0, 0, 0}, {0, 0, 4}, -3.0, 0.5, 0.5)));
        CHECK_MESSAGE(edge_crossing({1, 0, 0}, {1, 1, 0}, -1e-300, 1.0, 0.0) == glm::dvec3(1, d, 0),
                      "f0 = −1e-300 (t = 1e-300): clamped to δ; got " << str(edge_crossing({1, 0, 0}, {1, 1, 0}, -1e-300, 1.0, 0.0)));
        CHECK_THROWS_AS(edge_crossing({0, 0, 0}, {1, 0, 0}, 1.0, 2.0, 0.0), std::invalid_argument);
        CHECK_THROWS_AS(edge_crossing({0, 0, 0}, {1, 0, 0}, 0.0, 2.0, 0.0), std::invalid_argument);
        CHECK_THROWS_AS(edge_crossing({0, 0, 0}, {1, 0, 0}, -1.0, -2.0, 0.0), std::invalid_argument);
    }

    TEST_CASE("marching cubes: every one of the 256 cases on one cube: the table's triangles on the right edges; "
              "normals from the gradients" * geolab::points(3) *
              geolab::hint("Edge e of the table joins corners mc_edge_corners[e][0] and [1]; interpolate from the lower "
                           "sample. The normal is the gradient interpolated with the same t, normalized — not the "
                           "triangle's normal.")) {
        Rng rng(73);
        for (int cs = 0; cs < 256; ++cs) {
            const Lattice L = one_cube(cs, rng);
            const McMesh m = marching_cubes(L, 0.0);
            // Expected vertex of each crossed edge.
            std::array<glm::dvec3, 12> pos{}, nrm{};
            int crossed = 0;
            for (int e = 0; e < 12; ++e) {
                if (!((mc_tables.edge_mask[cs] >> e) & 1)) continue;
                ++crossed;
                const int a = mc_edge_corners[e][0], b = mc_edge_corners[e][1];
                const double t = (0 - L.values[a]) / (L.values[b] - L.values[a]);
                pos[e] = corner_pos(a) + t * (corner_pos(b) - corner_pos(a));
                nrm[e] = glm::normalize(L.gradients[a] + t * (L.gradients[b] - L.gradients[a]));
            }
            REQUIRE_MESSAGE(m.soup.n_vertices() == std::size_t(crossed),
                            "case " << cs << ": " << crossed << " crossed edges, so " << crossed << " vertices; got " << m.soup.n_vertices());
            REQUIRE_MESSAGE(m.normals.size() == m.soup.n_vertices(), "case " << cs << ": one normal per vertex");
            std::vector<int> edge_of(m.soup.n_vertices(), -1);
            for (std::size_t v = 0; v < m.soup.n_vertices(); ++v) {
                for (int e = 0; e < 12; ++e)
                    if (((mc_tables.edge_mask[cs] >> e) & 1) && glm::length(m.soup.positions[v] - pos[e]) < 1e-12) edge_of[v] = e;
                CHECK_MESSAGE(edge_of[v] >= 0, "case " << cs << ": vertex " << str(m.soup.positions[v])
                                                        << " is not the crossing point of any crossed edge");
                if (edge_of[v] >= 0)
                    CHECK_MESSAGE(glm::length(m.normals[v] - nrm[edge_of[v]]) < 1e-12,
                                  "case " << cs << ", edge " << edge_of[v] << ": expected normal " << str(nrm[edge_of[v]])
                                          << " (the interpolated gradient), got " << str(m.normals[v]));
            }
            REQUIRE_MESSAGE(m.soup.n_faces() == mc_tables.n_triangles[cs],
                            "case " << cs << ": the table has " << int(mc_tables.n_triangles[cs]) << " triangles, got " << m.soup.n_faces());
            // Each table triangle, as a cyclic triple of edges, must be among the output's.
            std::vector<std::array<int, 3>> got;
            for (std::size_t f = 0; f < m.soup.n_faces(); ++f) {
                const auto t = m.soup.face(f);
                std::array<int, 3> a{edge_of[t[0]], edge_of[t[1]], edge_of[t[2]]};
                std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
                got.push_back(a);
            }
            for (int t = 0; t < mc_tables.n_triangles[cs]; ++t) {
                std::array<int, 3> a{mc_tables.triangles[cs][3 * t], mc_tables.triangles[cs][3 * t + 1], mc_tables.triangles[cs][3 * t + 2]};
                std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
                CHECK_MESSAGE(std::find(got.begin(), got.end(), a) != got.end(),
                              "case " << cs << ": the table's triangle on edges (" << a[0] << ", " << a[1] << ", " << a[2]
                                      << ") is missing (or reversed) in your output");
            }
        }
    }

    TEST_CASE("marching cubes: a sphere is closed; χ = 2; vertices on the sphere; normals along the gradient" *
              geolab::points(3)) {
        for (int cells : {10, 23, 40}) {
            const double r = 0.61;
            const glm::dvec3 c{0.013, -0.021, 0.034};
            const McMesh m = marching_cubes(sphere_lattice(r, cells, c), 0.0);
            const geolab::SurfaceCheck sc = geolab::check_surface(m.soup);
            CHECK_MESSAGE(sc.closed_manifold(), cells << " cells: " << sc.summary());
            CHECK_MESSAGE(sc.euler_characteristic == 2, cells << " cells: χ = " << sc.euler_characteristic);
            const double h = 2.0 / cells;
            for (std::size_t v = 0; v < m.soup.n_vertices(); ++v) {
                const glm::dvec3 p = m.soup.positions[v];
                // Linear interpolation of the distance along an edge: off by at most h²/(2r).
                CHECK_MESSAGE(std::abs(glm::length(p - c) - r) <= h * h / (2 * r), "vertex " << str(p) << " is off the sphere by "
                                                                                  << glm::length(p - c) - r << " (cell " << h << ")");
                CHECK_MESSAGE(glm::dot(m.normals[v], (p - c) / glm::length(p - c)) > std::cos(h), "vertex " << str(p) << ": normal "
                                                                              << str(m.normals[v]) << " far from the gradient");
            }
        }
    }

    TEST_CASE("marching cubes: each crossed lattice edge gives exactly one vertex; shared by its cubes" *
              geolab::points(2) * geolab::hint("Key the vertices by lattice edge (lower sample, axis), not by cube.")) {
        Rng rng(74);
        for (int n = 0; n < 4; ++n) {
            const glm::dvec3 c = rng.point(-0.1, 0.1);
            const Lattice L = sphere_lattice(rng.uniform(0.3, 0.7), 17 + n, c);
            const McMesh m = marching_cubes(L, 0.0);
            const std::size_t want = crossed_edges(L, 0.0);
            CHECK_MESSAGE(m.soup.n_vertices() == want, "sphere: " << want << " lattice edges are crossed, so " << want
                                                                  << " vertices; got " << m.soup.n_vertices());
            CHECK_MESSAGE(pairing_defect(m.soup) == "", pairing_defect(m.soup));
        }
    }

    TEST_CASE("marching cubes: triangles face outwards: the enclosed volume is positive and near 4/3 π r³" *
              geolab::points(3) * geolab::hint("The table's triangles are counter-clockwise seen from outside; keep "
                                                "their order (a, b, c).")) {
        for (double r : {0.35, 0.8}) {
            const McMesh m = marching_cubes(sphere_lattice(r, 30), 0.0);
            const double v = volume(m.soup), want = 4.0 / 3.0 * std::numbers::pi * r * r * r;
            CHECK_MESSAGE(std::abs(v - want) < 0.03 * want, "sphere r = " << r << ": volume " << v << ", expected about " << want
                                                                          << " (negative: triangles face inwards)");
            // Triangles of a fanned non-planar polygon may tilt a little; their area facing inwards stays tiny.
            double total = 0, inward = 0;
            for (std::size_t f = 0; f < m.soup.n_faces(); ++f) {
                const auto t = m.soup.face(f);
                const glm::dvec3 a = m.soup.positions[t[0]], b = m.soup.positions[t[1]], c = m.soup.positions[t[2]];
                const glm::dvec3 n = glm::cross(b - a, c - a);
                total += glm::length(n);
                if (glm::dot(n, a + b + c) < 0) inward += glm::length(n);
            }
            CHECK_MESSAGE(inward <= 0.005 * total, "sphere r = " << r << ": " << 100 * inward / total
                                                                 << "% of the area faces inwards (at most 0.5% expected)");
        }
    }

    TEST_CASE("marching cubes: random fields full of ambiguous faces give closed; consistently oriented surfaces" *
              geolab::points(3) * geolab::hint("Use geolab::mc_tables as it is: its ambiguous faces are resolved the "
                                                "same way by both cubes that share them.")) {
        Rng rng(75);
        for (int n = 0; n < 12; ++n) {
            Lattice L;
            L.n = glm::ivec3(6 + n % 3, 7, 5 + n % 4);
            L.h = 0.5;
            for (int k = 0; k < L.n.z; ++k)
                for (int j = 0; j < L.n.y; ++j)
                    for (int i = 0; i < L.n.x; ++i) {
                        const bool border = i == 0 || j == 0 || k == 0 || i == L.n.x - 1 || j == L.n.y - 1 || k == L.n.z - 1;
                        const bool checker = (i + j + k + n) % 2 == 0;
                        L.values.push_back(border ? 1.0 : (checker ? -1 : 1) * rng.uniform(0.1, 1.0) * (rng.uniform(0, 1) < 0.2 ? -1 : 1));
                        L.gradients.push_back(rng.point(-1, 1));
                    }
            const McMesh m = marching_cubes(L, 0.0);
            CHECK_MESSAGE(m.soup.n_faces() > 0, "random field " << n << ": no triangles");
            const std::string d = pairing_defect(m.soup);
            CHECK_MESSAGE(d == "", "random field " << n << " (" << L.n.x << "×" << L.n.y << "×" << L.n.z << "): " << d);
            CHECK_MESSAGE(m.soup.n_vertices() == crossed_edges(L, 0.0), "random field " << n << ": one vertex per crossed edge");
        }
    }

    TEST_CASE("marching cubes: torus R = 0.5; r = 0.1: χ = 0; volume 2π²Rr² = 0.098696; error falling with the cell" *
              geolab::points(3)) {
        const double want = 2 * std::numbers::pi * std::numbers::pi * 0.5 * 0.01;
        CHECK(std::abs(want - 0.098696) < 5e-7);
        double last = 1e9;
        for (double h : {0.05, 0.025, 0.0125}) {
            const McMesh m = marching_cubes(torus_lattice(h), 0.0);
            const long chi = euler(m.soup);
            CHECK_MESSAGE(chi == 0, "cell " << h << ": χ = " << chi << ", a torus has 0");
            CHECK_MESSAGE(pairing_defect(m.soup) == "", "cell " << h << ": " << pairing_defect(m.soup));
            const double err = std::abs(volume(m.soup) - want);
            CHECK_MESSAGE(err < last, "cell " << h << ": volume error " << err << " did not fall (previous " << last << ")");
            last = err;
        }
        CHECK_MESSAGE(last < 0.01 * want, "finest cell: volume error " << last << " ≥ 1%");
    }

    TEST_CASE("marching cubes: samples exactly at the iso-value (ties) count as outside: closed; no hole" *
              geolab::points(2) * geolab::hint("f == iso is outside in cube_index AND in deciding which edges are "
                                                "crossed.")) {
        // |p|² − 25 on the integer lattice: zero at (5,0,0), (3,4,0), ... exactly.
        const McMesh s = marching_cubes(lattice_of([](const glm::dvec3& p) { return glm::dot(p, p) - 25; },
                                                   [](const glm::dvec3& p) { return 2.0 * p; }, glm::dvec3(-7), 1.0,
                                                   glm::ivec3(15)),
                                        0.0);
        CHECK_MESSAGE(pairing_defect(s.soup) == "", "|p|² = 25 with ties: " << pairing_defect(s.soup));
        CHECK_MESSAGE(euler(s.soup) == 2, "|p|² = 25 with ties: χ = " << euler(s.soup));
        // max(|x|, |y|, |z|) − 3: whole faces of ties.
        const McMesh b = marching_cubes(lattice_of(box_f, box_g, glm::dvec3(-5), 1.0, glm::ivec3(11)), 0.0);
        CHECK_MESSAGE(pairing_defect(b.soup) == "", "max-norm cube with faces of ties: " << pairing_defect(b.soup));
        CHECK_MESSAGE(euler(b.soup) == 2, "max-norm cube with faces of ties: χ = " << euler(b.soup));
        CHECK_MESSAGE(b.soup.n_vertices() == crossed_edges(lattice_of(box_f, box_g, glm::dvec3(-5), 1.0, glm::ivec3(11)), 0.0),
                      "one vertex per crossed edge (ties are outside)");
    }

    TEST_CASE("marching cubes: the tie rule — no zero-area triangle; no two vertices at one point (exact checks)" *
              geolab::points(3) *
              geolab::hint("Clamp t to [δ, 1 − δ] (δ = crossing_margin) in edge_crossing, and use the same t for the "
                           "normal: every vertex then lies strictly inside its edge (blobby.hpp, the tie rule).")) {
        // |p|² − 25 on the integer lattice: the tie (3, 4, 0) has the inside neighbours (2, 4, 0) and (3, 3, 0),
        // so two edges end on it; vertices put on the sample itself would coincide.
        const Lattice sphere = lattice_of([](const glm::dvec3& p) { return glm::dot(p, p) - 25; },
                                          [](const glm::dvec3& p) { return 2.0 * p; }, glm::dvec3(-7), 1.0, glm::ivec3(15));
        const McMesh s = marching_cubes(sphere, 0.0);
        check_tie_output(s, sphere, 0.0, "|p|² − 25 on the integer lattice (ties on the sphere)", 1, 2);
        int near_tie = 0;
        for (const glm::dvec3& p : s.soup.positions) {
            const double d = glm::length(p - glm::dvec3(3, 4, 0));
            CHECK_MESSAGE(d > 0, "a vertex sits exactly on the tie sample (3, 4, 0)");
            near_tie += d <= 1.5 * crossing_margin;
        }
        CHECK_MESSAGE(near_tie == 2, "the two crossed edges ending on the tie (3, 4, 0) put their vertices δ from it: "
                                     "expected 2 vertices within 1.5δ of it, got " << near_tie);
        // Two boxes with the tie plane x = 0 between them: max(max-norm − 3, −|x|).
        auto twin_f = [](const glm::dvec3& p) { return std::max(box_f(p), -std::abs(p.x)); };
        const Lattice twin = lattice_of(twin_f, box_g, glm::dvec3(-5), 1.0, glm::ivec3(11));
        check_tie_output(marching_cubes(twin, 0.0), twin, 0.0, "two boxes split by the tie plane x = 0", 2, 4);
        // A lone inside sample among ties, and a lone tie inside the solid (a cavity of size 2δ).
        for (const double inner : {-1.0, 1.0}) {
            Lattice L;
            L.n = glm::ivec3(5);
            for (int k = 0; k < 5; ++k)
                for (int j = 0; j < 5; ++j)
                    for (int i = 0; i < 5; ++i) {
                        const bool border = i == 0 || j == 0 || k == 0 || i == 4 || j == 4 || k == 4;
                        const bool centre = i == 2 && j == 2 && k == 2;
                        L.values.push_back(inner < 0 ? (centre ? -1.0 : 0.0) : (border ? 1.0 : centre ? 0.0 : -1.0));
                        L.gradients.push_back(glm::dvec3(i - 2, j - 2, k - 2));
                    }
            const McMesh m = marching_cubes(L, 0.0);
            check_tie_output(m, L, 0.0, inner < 0 ? std::string("a lone inside sample among ties") : "a lone tie inside the solid",
                             inner < 0 ? 1 : 2, inner < 0 ? 2 : 4);
            // The piece around the centre (2, 2, 2): an octahedron of half-diagonal 1 − δ around the inside sample,
            // or a cavity of half-diagonal δ around the tie (facing inwards: negative volume).
            const double d = crossing_margin;
            const double want = inner < 0 ? 4.0 / 3.0 * std::pow(1 - d, 3) : -4.0 / 3.0 * d * d * d;
            const LD got = centre_volume(m.soup, glm::dvec3(2.0), inner < 0 ? 1.5 : 0.5);
            const std::string name = inner < 0 ? "lone inside sample" : "lone tie";
            CHECK_MESSAGE(std::abs(double(got) - want) < 1e-6 * std::abs(want),
                          name << ": the piece around the centre encloses " << double(got) << ", expected " << want);
        }
        // Random lattices where a third of the samples are exact ties.
        Rng rng(77);
        for (int n = 0; n < 8; ++n) {
            Lattice L;
            L.n = glm::ivec3(6 + n % 3, 5 + n % 2, 7);
            for (int k = 0; k < L.n.z; ++k)
                for (int j = 0; j < L.n.y; ++j)
                    for (int i = 0; i < L.n.x; ++i) {
                        const bool border = i == 0 || j == 0 || k == 0 || i == L.n.x - 1 || j == L.n.y - 1 || k == L.n.z - 1;
                        const int c = rng.integer(-1, 1);
                        L.values.push_back(border ? std::max(c, 0) : c * rng.uniform(0.5, 2.0));
                        L.gradients.push_back(rng.point(-1, 1));
                    }
            check_tie_output(marching_cubes(L, 0.0), L, 0.0, "random lattice " + std::to_string(n) + " with ties", 0, 0);
        }
        // The margin δ·h must survive rounding: a lattice more than 2^30 cells from 0 is refused.
        Lattice far = sphere;
        far.origin.x = -std::ldexp(1.0, 30);
        check_tie_output(marching_cubes(far, 0.0), far, 0.0, "|p|² − 25 moved to x = −2^30 (h = 1)", 1, 2);
        far.origin.x = -1.5 * std::ldexp(1.0, 30);
        CHECK_THROWS_AS(marching_cubes(far, 0.0), std::invalid_argument);
        far.origin.x = std::ldexp(1.0, 30) - 14;  // its last sample, origin + 14h, is 2^30 h: allowed
        CHECK_NOTHROW(marching_cubes(far, 0.0));
        far.origin.x = std::ldexp(1.0, 30) - 13;
        CHECK_THROWS_AS(marching_cubes(far, 0.0), std::invalid_argument);
        for (int a = 0; a < 3; ++a) {  // every axis is checked
            Lattice axis = sphere;
            axis.origin[a] = -1.5 * std::ldexp(1.0, 30);
            CHECK_THROWS_AS(marching_cubes(axis, 0.0), std::invalid_argument);
            axis.origin[a] = std::ldexp(1.0, 30) - 13;
            CHECK_THROWS_AS(marching_cubes(axis, 0.0), std::invalid_argument);
        }
    }
}
