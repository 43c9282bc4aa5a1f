// Lab 04 hidden tests: run by the grader, left out of the student release. Same tasks (suites) as the public ones;
// the same independent references (helpers.hpp).
#include "../helpers.hpp"
#include "geolab/grading/chain.hpp"
#include "geolab/polygonize.hpp"

using namespace lab04;

namespace {
const Kernel kernels[3] = {Kernel::blinn, Kernel::nishimura, Kernel::wyvill};
Lattice lattice_of_scene(const BlobScene& s, double h, double half) {
    const int n = int(std::lround(2 * half / h)) + 1;
    // Lattice from the reference sums, not from your sample_lattice (in double: the inputs must be the same bits in
    // every build of the tests).
    auto value = [&](const glm::dvec3& p) {
        double v = s.threshold;
        for (const Blob& b : s.blobs) {
            const double r = glm::length(p - b.center);
            if (r < b.radius) v -= double(ref_density(s.kernel, b, r));
        }
        return std::round(v * 1e12) / 1e12;  // 12 digits: the same however ref_density rounds its last bits
    };
    return lattice_of(value, [&](const glm::dvec3&) { return glm::dvec3(0.0, 0.0, 1.0); }, glm::dvec3(-half), h,
                      glm::ivec3(n));
}
}  // namespace

TEST_SUITE("Task 1: the kernels") {
    TEST_CASE("kernels hidden: thousands of random blobs; derivatives continuous at R/3 and R" * geolab::points(4) *
              geolab::hidden()) {
        Rng rng(81);
        for (Kernel k : kernels)
            for (int n = 0; n < 1500; ++n) {
                Blob b;
                b.strength = rng.uniform(-5, 5);
                b.a = std::exp(rng.uniform(-3, 3));
                b.radius = std::exp(rng.uniform(-3, 3));
                const double r = rng.uniform(0, 1.2) * (k == Kernel::blinn ? 2 / std::sqrt(b.a) : b.radius);
                const double d = density(k, b, r), want = double(ref_density(k, b, r));
                CHECK_MESSAGE(close(d, want, 1e-11, std::abs(b.strength)), str(k) << " " << str(b) << " r=" << r << ": D " << want << ", got " << d);
                const double dd = density_derivative(k, b, r), dwant = double(ref_derivative(k, b, r));
                const double sc = std::abs(b.strength) * (k == Kernel::blinn ? std::sqrt(b.a) : 1 / b.radius);
                CHECK_MESSAGE(close(dd, dwant, 1e-10, sc), str(k) << " " << str(b) << " r=" << r << ": D' " << dwant << ", got " << dd);
            }
        for (double R : {0.3, 3.0}) {
            Blob b;
            b.radius = R;
            const double e = 1e-9 * R;
            CHECK(close(density_derivative(Kernel::nishimura, b, R / 3 - e), density_derivative(Kernel::nishimura, b, R / 3 + e), 1e-6, 1 / R));
            CHECK(std::abs(density_derivative(Kernel::wyvill, b, R - e)) < 1e-6 / R);
            CHECK(std::abs(density_derivative(Kernel::nishimura, b, R - e)) < 1e-6 / R);
            for (double T : {0.01, 0.3, 0.66, 0.7, 0.99}) {
                const double r = isolated_radius(Kernel::wyvill, b, T);
                CHECK_MESSAGE(std::abs(double(ref_density(Kernel::wyvill, b, r)) - T) < 1e-12, "wyvill R=" << R << " T=" << T << ": r=" << r);
                const double q = isolated_radius(Kernel::nishimura, b, T);
                CHECK_MESSAGE(std::abs(double(ref_density(Kernel::nishimura, b, q)) - T) < 1e-12, "nishimura R=" << R << " T=" << T << ": r=" << q);
            }
        }
    }
}

TEST_SUITE("Task 2: the field") {
    TEST_CASE("field hidden: merging seen by marching cubes — Blinn blobs at d = 2.2 (one piece) and 2.5 (two)" *
              geolab::points(4) * geolab::hidden() * geolab::builds_on("Task 1")) {
        for (double d : {2.2, 2.5}) {
            BlobScene s;
            s.kernel = Kernel::blinn;
            s.threshold = 0.5;
            Blob a, b;
            a.center = {-d / 2, 0.01, 0.02};
            b.center = {d / 2, 0.01, 0.02};
            s.blobs = {a, b};
            // The surface from YOUR field's values.
            Lattice L;
            const double h = 0.05, half = 2.2;
            const int n = int(std::lround(2 * half / h)) + 1;
            L.origin = glm::dvec3(-half);
            L.h = h;
            L.n = glm::ivec3(n);
            for (int k = 0; k < n; ++k)
                for (int j = 0; j < n; ++j)
                    for (int i = 0; i < n; ++i) {
                        const FieldValue f = field(s, L.origin + h * glm::dvec3(i, j, k));
                        L.values.push_back(f.value);
                        L.gradients.push_back(f.gradient);
                    }
            // polygonized by lib's marching tetrahedra on the same lattice, not by your Task 4 (rule 6)
            struct Sampled : geolab::ScalarField {
                const Lattice& l;
                explicit Sampled(const Lattice& lattice) : l(lattice) {}
                double value(const glm::dvec3& p) const override {
                    const glm::ivec3 i(glm::round((p - l.origin) / l.h));
                    return l.values.at(std::size_t(i.x) + std::size_t(l.n.x) * (std::size_t(i.y) + std::size_t(l.n.y) * std::size_t(i.z)));
                }
                geolab::Box bounds() const override { return {l.origin, l.origin + l.h * glm::dvec3(l.n - 1)}; }
            };
            const geolab::PolygonSoup soup = geolab::polygonize(Sampled(L), {glm::dvec3(-half), glm::dvec3(half)}, n - 1);
            const int want = d < 2.35482 ? 1 : 2;
            CHECK_MESSAGE(components(soup) == want, "d = " << d << ": " << components(soup) << " pieces, expected " << want);
            CHECK_MESSAGE(euler(soup) == 2 * want, "d = " << d << ": χ = " << euler(soup));
        }
        // Wyvill, R = 1, T = 0.5, b = 1: midpoint sum 2C(d/2) = 0.5 → C(s) = 1/4.
        for (double d : {1.2, 1.6}) {
            BlobScene s;
            s.kernel = Kernel::wyvill;
            s.threshold = 0.5;
            Blob a, b;
            a.center = {-d / 2, 0, 0};
            b.center = {d / 2, 0, 0};
            s.blobs = {a, b};
            double lo = 0, hi = 1;  // C(s) = 1/4 on [0, 1], by bisection here (not your Task 1's isolated_radius)
            for (int it = 0; it < 200; ++it) {
                const double m = 0.5 * (lo + hi), m2 = m * m;
                (1 - 22.0 / 9 * m2 + 17.0 / 9 * m2 * m2 - 4.0 / 9 * m2 * m2 * m2 > 0.25 ? lo : hi) = m;
            }
            const double s_merge = 0.5 * (lo + hi);
            const bool merged = d / 2 < s_merge;
            CHECK_MESSAGE((field(s, glm::dvec3(0.0)).value < 0) == merged, "wyvill d = " << d << ": merging is at d = " << 2 * s_merge);
        }
    }
}

TEST_SUITE("Task 3: fast evaluation") {
    TEST_CASE("grid hidden: tiny and huge cells; clustered blobs; evaluations never miss a blob that reaches p" *
              geolab::points(4) * geolab::builds_on("Task 1") * geolab::hidden()) {
        Rng rng(83);
        for (Kernel k : {Kernel::nishimura, Kernel::wyvill})
            for (double cell : {0.05, 0.31, 5.0}) {
                BlobScene s = random_scene(rng, k, 40, 0.3);
                const BlobGrid g = build_blob_grid(s, cell);
                for (int m = 0; m < 500; ++m) {
                    const glm::dvec3 p = rng.point(-1.2, 1.2);
                    const FieldSample f = evaluate(s, g, p);
                    std::uint64_t need = 0;
                    for (const Blob& b : s.blobs) need += glm::length(p - b.center) < b.radius;
                    CHECK_MESSAGE(f.kernel_evaluations >= need, "cell " << cell << " at " << str(p) << ": " << need << " blobs reach p, counted " << f.kernel_evaluations);
                    CHECK_MESSAGE(close(f.value, double(ref_value(s, p)), 1e-12, scale_of(s)), "cell " << cell << " at " << str(p));
                }
                // A point exactly on the grid's upper faces is inside the grid.
                const glm::dvec3 top = g.origin + g.cell * glm::dvec3(g.dims);
                CHECK(close(evaluate(s, g, top).value, double(ref_value(s, top)), 1e-12, scale_of(s)));
            }
    }
}

TEST_SUITE("Task 4: marching cubes") {
    TEST_CASE("marching cubes hidden: normals are the interpolated gradient; not the triangles' normals" *
              geolab::points(3) * geolab::hidden()) {
        // A tilted plane's values with a constant gradient (0, 0, 1) that disagrees with the faces on purpose,
        // inside a closed box (values outside on the border).
        const Lattice L = lattice_of(
            [](const glm::dvec3& p) {
                const double plane = p.x + 0.3 * p.y - 0.2;
                const double border = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) - 0.9;
                return std::max(plane, border);
            },
            [](const glm::dvec3& p) { return glm::dvec3(0.0, 0.0, 2.0 + p.x); }, glm::dvec3(-1.05), 0.1,
            glm::ivec3(22));
        const McMesh m = marching_cubes(L, 0.0);
        REQUIRE(m.normals.size() == m.soup.n_vertices());
        REQUIRE_MESSAGE(m.soup.n_faces() > 100, "the plane in the box gives hundreds of triangles, got " << m.soup.n_faces());
        for (std::size_t v = 0; v < m.normals.size(); ++v)
            CHECK_MESSAGE(glm::length(m.normals[v] - glm::dvec3(0, 0, 1)) < 1e-12,
                          "vertex " << str(m.soup.positions[v]) << ": the gradients there are (0, 0, 2 + x): normal (0, 0, 1) expected, got "
                                    << str(m.normals[v]));
    }

    TEST_CASE("marching cubes hidden: non-cubic lattices; iso ≠ 0; shifted origins; blob scenes; bad lattices throw" *
              geolab::points(3) * geolab::hidden()) {
        Rng rng(85);
        std::vector<BlobScene> scenes;
        std::vector<Lattice> lattices;  // all alive at once
        for (int n = 0; n < 4; ++n) {
            scenes.push_back(random_scene(rng, n % 2 ? Kernel::wyvill : Kernel::nishimura, 6, 0.5, false));
            lattices.push_back(lattice_of_scene(scenes.back(), 0.07 + 0.01 * n, 1.45));
        }
        for (int n = 0; n < 4; ++n) {
            const BlobScene& s = scenes[n];
            const McMesh m = marching_cubes(lattices[n], 0.0);
            CHECK_MESSAGE(pairing_defect(m.soup) == "", str(s) << ": " << pairing_defect(m.soup));
            for (std::size_t v = 0; v < m.soup.n_vertices(); ++v)
                CHECK(std::abs(double(ref_value(s, m.soup.positions[v]))) < 0.05 * scale_of(s));
        }
        const double iso = 0.3;
        const Lattice L = lattice_of([](const glm::dvec3& p) { return glm::dot(p, p); },
                                     [](const glm::dvec3& p) { return 2.0 * p; }, glm::dvec3(-0.71, -0.93, -0.62), 0.06,
                                     glm::ivec3(25, 31, 22));
        const McMesh m = marching_cubes(L, iso);
        CHECK_MESSAGE(pairing_defect(m.soup) == "", pairing_defect(m.soup));
        CHECK_MESSAGE(euler(m.soup) == 2, "|p|² = 0.3: χ = " << euler(m.soup));
        const double want = 4.0 / 3.0 * 3.14159265358979 * std::pow(iso, 1.5);
        CHECK_MESSAGE(std::abs(volume(m.soup) - want) < 0.02 * want, "|p|² = 0.3: volume " << volume(m.soup) << ", expected about " << want);
        for (const glm::dvec3& p : m.soup.positions) CHECK(std::abs(glm::dot(p, p) - iso) < 0.06 * 0.06);
        Lattice bad = L;
        bad.values.pop_back();
        CHECK_THROWS_AS(marching_cubes(bad, 0.0), std::invalid_argument);
        bad = L;
        bad.gradients.clear();
        CHECK_THROWS_AS(marching_cubes(bad, 0.0), std::invalid_argument);
        bad = L;
        bad.n.y = 1;
        CHECK_THROWS_AS(marching_cubes(bad, 0.0), std::invalid_argument);
        bad = L;
        bad.h = 0;
        CHECK_THROWS_AS(marching_cubes(bad, 0.0), std::invalid_argument);
        bad.origin = glm::dvec3(0.0);  // h = 0 at the origin: every lattice point at 0
        CHECK_THROWS_AS(marching_cubes(bad, 0.0), std::invalid_argument);
        bad.h = std::numeric_limits<double>::infinity();
        CHECK_THROWS_AS(marching_cubes(bad, 0.0), std::invalid_argument);
        bad.h = std::numeric_limits<double>::quiet_NaN();
        CHECK_THROWS_AS(marching_cubes(bad, 0.0), std::invalid_argument);
        for (const glm::ivec3 fn : {glm::ivec3(1, 3, 3), glm::ivec3(3, 1, 3), glm::ivec3(3, 3, 1)}) {
            Lattice flat;
            flat.n = fn;
            flat.values.assign(9, 1.0);
            flat.gradients.assign(9, glm::dvec3(0.0));
            CHECK_THROWS_AS(marching_cubes(flat, 0.0), std::invalid_argument);
        }
        bad = L;
        bad.values[0] = std::numeric_limits<double>::quiet_NaN();
        CHECK_THROWS_AS(marching_cubes(bad, 0.0), std::invalid_argument);
        // Zero gradients give zero normals, not NaN.
        Lattice zero = L;
        for (auto& g : zero.gradients) g = glm::dvec3(0.0);
        const McMesh mz = marching_cubes(zero, iso);
        for (const glm::dvec3& nz : mz.normals)
            CHECK_MESSAGE(nz == glm::dvec3(0.0), "a zero interpolated gradient gives the normal (0, 0, 0), got " << str(nz));
        bad = L;
        bad.values[7] = std::numeric_limits<double>::quiet_NaN();
        CHECK_THROWS_AS(marching_cubes(bad, 0.0), std::invalid_argument);
    }

    TEST_CASE("marching cubes hidden: ties with iso ≠ 0 on shifted lattices; planes of ties between solids; normals "
              "with the clamped t" * geolab::points(4) * geolab::hidden()) {
        Rng rng(87);
        const double iso = 0.3;
        const glm::dvec3 origins[3] = {{-0.35, 0.7, 12.5}, {1e3, -2e3, 0.125}, {-5e4, 0.0, 3.3}};
        const double hs[3] = {0.1, 0.37, 0.013};
        for (int n = 0; n < 6; ++n) {
            Lattice L;
            L.origin = origins[n % 3];
            L.h = hs[n % 3];
            L.n = glm::ivec3(5 + n % 4, 6, 4 + n % 3);
            for (int k = 0; k < L.n.z; ++k)
                for (int j = 0; j < L.n.y; ++j)
                    for (int i = 0; i < L.n.x; ++i) {
                        const bool border = i == 0 || j == 0 || k == 0 || i == L.n.x - 1 || j == L.n.y - 1 || k == L.n.z - 1;
                        const int c = rng.integer(-1, 1);
                        L.values.push_back(iso + (border ? std::max(c, 0) : c) * 0.125 * rng.integer(1, 8));
                        L.gradients.push_back(rng.point(-1, 1));
                    }
            const McMesh m = marching_cubes(L, iso);
            check_tie_output(m, L, iso, "lattice " + std::to_string(n) + " with ties at iso 0.3, origin " + str(L.origin) +
                                            ", h " + std::to_string(L.h), 0, 0);
            // Normals: the gradient interpolated with the clamped t, normalized.
            for (std::size_t v = 0; v < m.soup.n_vertices() && v < 40; ++v) {
                const glm::dvec3 p = m.soup.positions[v];
                glm::ivec3 q0(0);
                int axis = -1;  // the coordinate that is not a lattice coordinate: the edge's direction
                for (int a = 0; a < 3; ++a) {
                    const double u = (p[a] - L.origin[a]) / L.h;
                    q0[a] = int(std::lround(u));
                    if (p[a] != L.origin[a] + L.h * q0[a]) axis = a, q0[a] = int(std::floor(u));
                }
                if (axis < 0) continue;  // reported by check_tie_output
                glm::ivec3 q1 = q0;
                ++q1[axis];
                auto id = [&](glm::ivec3 q) { return q.x + std::size_t(L.n.x) * (q.y + std::size_t(L.n.y) * q.z); };
                const double f0 = L.values[id(q0)], f1 = L.values[id(q1)];
                const LD t = std::clamp((LD(iso) - f0) / (LD(f1) - f0), LD(crossing_margin), 1 - LD(crossing_margin));
                const glm::dvec3 g0 = L.gradients[id(q0)], g1 = L.gradients[id(q1)];
                const glm::dvec3 g{double(g0.x + t * (LD(g1.x) - g0.x)), double(g0.y + t * (LD(g1.y) - g0.y)),
                                   double(g0.z + t * (LD(g1.z) - g0.z))};
                if (glm::length(g) < 1e-3) continue;
                CHECK_MESSAGE(glm::length(m.normals[v] - glm::normalize(g)) < 1e-9,
                              "lattice " << n << ", vertex " << str(p) << " on the edge from sample (" << q0.x << ", " << q0.y
                                         << ", " << q0.z << ") (f0 " << f0 << ", f1 " << f1 << "): expected normal "
                                         << str(glm::normalize(g)) << ", got " << str(m.normals[v]));
            }
        }
        // Planes of ties z = 3 and z = 5 inside a box: three solids stacked, faces 2δh apart.
        Lattice S;
        S.origin = glm::dvec3(-0.2, 0.1, 7.0);
        S.h = 0.25;
        S.n = glm::ivec3(6, 5, 9);
        for (int k = 0; k < S.n.z; ++k)
            for (int j = 0; j < S.n.y; ++j)
                for (int i = 0; i < S.n.x; ++i) {
                    const bool border = i == 0 || j == 0 || k == 0 || i == S.n.x - 1 || j == S.n.y - 1 || k == S.n.z - 1;
                    S.values.push_back(border ? 2.0 : (k == 3 || k == 5) ? -1.0 : -1.5);
                    S.gradients.push_back(glm::dvec3(0, 0, 1));
                }
        check_tie_output(marching_cubes(S, -1.0), S, -1.0, "three solids between the tie planes z = 3 and z = 5 (iso −1)", 3, 6);
    }
}
