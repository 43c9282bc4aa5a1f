// lib's reference polygonizer (marching tetrahedra): closed, 2-manifold, outward, converging volumes, the tie
// rule on samples equal to the iso-value, random lattices full of ambiguous cases, and its errors.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geolab/implicits.hpp"
#include "geolab/polygonize.hpp"
#include "geolab/surface_checks.hpp"

using geolab::Box;
using geolab::PolygonSoup;
using glm::dvec3;

namespace {

double volume(const PolygonSoup& m) {
    double v = 0.0;
    for (std::size_t f = 0; f < m.n_faces(); ++f) {
        const auto t = m.face(f);
        v += glm::dot(m.positions[t[0]], glm::cross(m.positions[t[1]], m.positions[t[2]]));
    }
    return v / 6.0;
}

// A field given by values on the lattice polygonize() samples (nearest lattice point), for hand-made cases.
class LatticeField final : public geolab::ScalarField {
public:
    LatticeField(Box box, int n) : box_(box), n_(n), values_((n + 1) * (n + 1) * (n + 1), 1.0) {}
    double& at(int i, int j, int k) { return values_[(k * (n_ + 1) + j) * (n_ + 1) + i]; }
    double value(const dvec3& p) const override {
        const dvec3 q = (p - box_.lo) / box_.size() * double(n_);
        const int i = int(std::lround(q.x)), j = int(std::lround(q.y)), k = int(std::lround(q.z));
        return values_[(k * (n_ + 1) + j) * (n_ + 1) + i];
    }
    Box bounds() const override { return box_; }

private:
    Box box_;
    int n_;
    std::vector<double> values_;
};

const Box kCube{dvec3(-1.0), dvec3(1.0)};

}  // namespace

TEST_SUITE("polygonize") {
    TEST_CASE("polygonize_lattice: cubic cells, the longest side gets the resolution, the others cover theirs") {
        const auto l = geolab::polygonize_lattice(Box{dvec3(0.0), dvec3(2.0, 1.0, 0.5)}, 10);
        CHECK(l.h == doctest::Approx(0.2));
        CHECK(l.cells == glm::ivec3(10, 5, 3));
        CHECK(l.lo == dvec3(0.0));
        CHECK(geolab::polygonize_lattice(Box{dvec3(0.0), dvec3(1.0, 1e-6, 1.0)}, 4).cells.y == 1);
    }

    TEST_CASE("sphere: closed 2-manifold, genus 0, outward, volume converging with the cell size") {
        const auto f = geolab::sphere(dvec3(0.1, -0.05, 0.02), 0.8);
        const double exact = 4.0 / 3.0 * std::numbers::pi * 0.8 * 0.8 * 0.8;
        double last_error = std::numeric_limits<double>::infinity();
        for (int n : {8, 16, 32, 64}) {
            const PolygonSoup m = geolab::polygonize(*f, kCube, n);
            CAPTURE(n);
            const auto check = geolab::check_surface(m);
            INFO(check.summary());
            CHECK(check.closed_manifold());
            CHECK(check.euler_characteristic == 2);
            CHECK(check.components == 1);
            const double error = std::abs(volume(m) - exact);
            CHECK(volume(m) > 0.0);
            CHECK(error < last_error);
            last_error = error;
            // every vertex within a cell of the sphere; every normal pointing away from the centre
            for (const dvec3& p : m.positions) CHECK(std::abs(f->value(p)) < 2.0 / n * std::sqrt(3.0));
            for (std::size_t t = 0; t < m.n_faces(); ++t) {
                const auto v = m.face(t);
                const dvec3 a = m.positions[v[0]], b = m.positions[v[1]], c = m.positions[v[2]];
                REQUIRE(glm::dot(glm::cross(b - a, c - a), (a + b + c) / 3.0 - dvec3(0.1, -0.05, 0.02)) > 0.0);
            }
        }
        CHECK(last_error < 0.01 * exact);
    }

    TEST_CASE("torus: χ = 0 and the volume 2π²Rr²") {
        const auto f = geolab::torus(dvec3(0.0), 0.6, 0.25);
        const PolygonSoup m = geolab::polygonize(*f, kCube, 64);
        const auto check = geolab::check_surface(m);
        INFO(check.summary());
        CHECK(check.closed_manifold());
        CHECK(check.euler_characteristic == 0);
        CHECK(volume(m) == doctest::Approx(2.0 * std::numbers::pi * std::numbers::pi * 0.6 * 0.25 * 0.25).epsilon(0.01));
    }

    TEST_CASE("samples equal to the iso-value count as outside: a box whose faces lie on lattice planes") {
        // h = 0.25: every lattice point on the box's faces has f == 0 exactly
        const auto f = geolab::box(dvec3(0.0), dvec3(0.5));
        const PolygonSoup m = geolab::polygonize(*f, kCube, 8);
        const auto check = geolab::check_surface(m);
        INFO(check.summary());
        CHECK(check.closed_manifold());  // no zero-area triangle, no coincident vertices
        CHECK(check.euler_characteristic == 2);
        for (const dvec3& p : m.positions) CHECK(std::abs(f->value(p)) < 1e-8);  // vertices on the box's faces
        // The surface is the boundary of the union of the tetrahedra around the inside lattice points (the
        // interpolant is < 0 only there); the box's edges and corners that no tetrahedron reaches are cut,
        // by less as the cells shrink.
        const double v8 = volume(m), v32 = volume(geolab::polygonize(*f, kCube, 32));
        CHECK(v8 > 0.8);
        CHECK(v8 < 1.0);
        CHECK(1.0 - v32 < 0.3 * (1.0 - v8));
        // iso = -0.25: only the origin is inside (its neighbours have f == iso exactly, so they are outside): the
        // surface is the boundary of the 24 tetrahedra around it, of volume 24 h³/6 = 4 h³, h = 1/4
        const PolygonSoup inner = geolab::polygonize(*f, kCube, 8, -0.25);
        const auto inner_check = geolab::check_surface(inner);
        INFO(inner_check.summary());
        CHECK(inner_check.closed_manifold());
        CHECK(inner_check.faces == 24);
        CHECK(volume(inner) == doctest::Approx(4.0 / 64.0).epsilon(1e-6));
    }

    TEST_CASE("random lattices full of ambiguous cubes and exact ties: always closed, 2-manifold, no intersections") {
        for (unsigned seed = 1; seed <= 6; ++seed) {
            std::mt19937 rng(seed);
            const int n = 10;
            LatticeField field(kCube, n);
            std::uniform_int_distribution<int> pick(-1, 1);      // -1, 0 (a tie: outside), 1
            std::uniform_real_distribution<double> real(-1.0, 1.0);
            for (int k = 1; k < n; ++k)
                for (int j = 1; j < n; ++j)
                    for (int i = 1; i < n; ++i) field.at(i, j, k) = seed % 2 ? double(pick(rng)) : real(rng);
            const PolygonSoup m = geolab::polygonize(field, kCube, n);
            CAPTURE(seed);
            const auto check = geolab::check_surface(m);
            INFO(check.summary());
            CHECK(m.n_faces() > 100);
            CHECK(check.boundary_edges == 0);
            CHECK(check.non_manifold_edges == 0);
            CHECK(check.misoriented_edges == 0);
            CHECK(check.non_manifold_vertices == 0);
            CHECK(check.zero_area_faces == 0);
            CHECK(check.coincident_vertices == 0);
            CHECK(check.self_intersecting_pairs() == 0);
            CHECK(volume(m) > 0.0);
            CHECK(check.vertices == m.n_vertices());  // every vertex used
        }
    }

    TEST_CASE("a solid reaching the lattice's boundary gives an open surface there") {
        const auto f = geolab::sphere(dvec3(1.0, 0.0, 0.0), 0.5);
        const auto check = geolab::check_surface(geolab::polygonize(*f, kCube, 16));
        CHECK(check.boundary_edges > 0);
        CHECK(check.non_manifold_edges == 0);
        CHECK(check.misoriented_edges == 0);
    }

    TEST_CASE("errors: a bad box, resolution or iso-value, a NaN field") {
        const auto f = geolab::sphere(dvec3(0.0), 0.5);
        CHECK_THROWS_WITH_AS(geolab::polygonize(*f, Box{dvec3(0.0), dvec3(1.0, 0.0, 1.0)}, 8),
                             doctest::Contains("side of length"), std::invalid_argument);
        CHECK_THROWS_WITH_AS(geolab::polygonize(*f, Box{dvec3(0.0), dvec3(1.0, INFINITY, 1.0)}, 8),
                             doctest::Contains("not finite"), std::invalid_argument);
        CHECK_THROWS_WITH_AS(geolab::polygonize(*f, kCube, 0), doctest::Contains("resolution 0"),
                             std::invalid_argument);
        CHECK_THROWS_AS(geolab::polygonize(*f, kCube, 5000), std::invalid_argument);
        CHECK_THROWS_WITH_AS(geolab::polygonize(*f, kCube, 8, NAN), doctest::Contains("iso-value"),
                             std::invalid_argument);
        LatticeField holes(kCube, 4);
        holes.at(2, 3, 1) = std::numeric_limits<double>::quiet_NaN();
        CHECK_THROWS_WITH_AS(geolab::polygonize(holes, kCube, 4), doctest::Contains("NaN at (0, 0.5, -0.5)"),
                             std::invalid_argument);
    }
}
