// Lab 03, Task 6: tessellation. Closedness, orientation, χ and volume are measured here on the returned soup.
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab03;

TEST_SUITE("Task 6: tessellation") {
    TEST_CASE("tessellation: the superquadric mesh is closed; outward; χ = 2; with its vertices on the surface" *
              geolab::points(3) * geolab::builds_on("Task 5") *
              geolab::hint("Vertex 0 = south pole, 1 = north pole, then the rings; fans at the poles, two triangles per "
                           "quad; wrap ω around (j + 1) % n_omega. Counter-clockwise seen from outside.")) {
        for (auto [e1, e2, ne, no] : {std::tuple{1.0, 1.0, 8, 12}, std::tuple{0.3, 0.3, 5, 3}, std::tuple{2.0, 2.0, 2, 4},
                                      std::tuple{0.5, 2.5, 16, 9}, std::tuple{3.0, 0.7, 7, 20}}) {
            const Superquadric s{{1.5, 0.7, 1.1}, e1, e2};
            const PolygonSoup m = tessellate_superquadric(s, ne, no);
            INFO(str(s) << ", n_eta = " << ne << ", n_omega = " << no << ": " << m.n_vertices() << " vertices, "
                        << m.n_faces() << " faces");
            REQUIRE(m.n_vertices() == std::size_t(2 + (ne - 1) * no));
            REQUIRE(m.n_faces() == std::size_t(2 * no * (ne - 1)));
            CHECK(m.is_triangle_soup());
            const std::string err = closed_oriented(m);
            CHECK_MESSAGE(err.empty(), err);
            CHECK(euler(m) == 2);
            CHECK(glm::length(m.positions[0] - glm::dvec3(0, 0, -1.1)) <= 1e-12);
            CHECK(glm::length(m.positions[1] - glm::dvec3(0, 0, 1.1)) <= 1e-12);
            for (const auto& p : m.positions) CHECK(close(double(F_ld(s, p)), 1.0, 1e-9));
            // ring i at η = −π/2 + iπ/n_eta, vertex j at ω = −π + 2πj/n_omega (the contract's grid), written out here
            const auto sp = [](LD x, LD e) { return x == 0 ? LD(0) : (x < 0 ? -1 : 1) * std::pow(std::abs(x), e); };
            for (int i = 1; i < ne; ++i)
                for (int j = 0; j < no; ++j) {
                    const LD eta = -LD(pi) / 2 + LD(pi) * i / ne, om = -LD(pi) + 2 * LD(pi) * j / no;
                    const glm::dvec3 want{double(1.5L * sp(std::cos(eta), e1) * sp(std::cos(om), e2)),
                                          double(0.7L * sp(std::cos(eta), e1) * sp(std::sin(om), e2)),
                                          double(1.1L * sp(std::sin(eta), e1))};
                    const glm::dvec3 got = m.positions[2 + (i - 1) * no + j];
                    CHECK_MESSAGE(glm::length(got - want) <= 1e-9, "vertex " << 2 + (i - 1) * no + j << " (ring " << i
                                                                             << ", j = " << j << ") should be " << str(want)
                                                                             << ", got " << str(got));
                }
            CHECK_MESSAGE(signed_volume(m) > 0, "the enclosed signed volume is " << double(signed_volume(m))
                                                                                 << ": the faces point inwards");
        }
        CHECK_THROWS_AS(tessellate_superquadric({{1, 1, 1}, 1, 1}, 1, 8), std::invalid_argument);
        CHECK_THROWS_AS(tessellate_superquadric({{1, 1, 1}, 1, 1}, 4, 2), std::invalid_argument);
    }

    TEST_CASE("tessellation: the mesh volume converges to the exact one at second order" * geolab::points(2) *
              geolab::builds_on("Task 5") *
              geolab::hint("An inscribed mesh on an (η, ω) grid with spacing h misses O(h²) of the volume: doubling the "
                           "resolution divides the error by about 4. Use the formulas of §7, not another angle range.")) {
        for (const Superquadric& s : {Superquadric{{1, 1, 1}, 1, 1}, Superquadric{{2, 1, 0.5}, 1, 1},
                                      Superquadric{{1, 1.3, 0.8}, 0.8, 1.2}}) {
            const double exact = double(volume_by_integral(s));
            double prev = 0;
            for (int n : {16, 32, 64}) {
                const double v = double(signed_volume(tessellate_superquadric(s, n, 2 * n)));
                const double err = std::abs(v - exact) / exact;
                INFO(str(s) << ", n_eta = " << n << ", n_omega = " << 2 * n << ": mesh volume " << v << ", exact " << exact
                            << ", relative error " << err);
                CHECK(v < exact);  // inscribed
                CHECK(err < 5.0 / (n * n));
                if (prev > 0) CHECK_MESSAGE((prev / err > 3.3 && prev / err < 4.7),
                                            "halving h should divide the error by about 4: " << prev << " -> " << err);
                prev = err;
            }
        }
    }

    TEST_CASE("tessellation: tessellate_ellipsoid of a moved; rotated; scaled ellipsoid" * geolab::points(3) *
              geolab::hint("Centre c = −A⁻¹b; semi-axes from A's eigenvalues λᵢ and k = XᵀQX at c: rᵢ = √(−k/λᵢ); axes "
                           "= A's eigenvectors, made right-handed so that the orientation stays outward.")) {
        Rng rng(61);
        for (int n = 0; n < 12; ++n) {
            double a, b, c;
            random_axes(rng, a, b, c);
            const double s = rng.uniform(0.5, 2);
            const Mat4L M = similarity(rng, s, 3.0);
            const LD sign = n % 3 == 0 ? -2.5 : 1.0;  // −Q is the same ellipsoid
            const glm::dmat4 Q = to_glm(sign * moved(canonical(QuadricType::real_ellipsoid, a, b, c), M));
            const PolygonSoup m = tessellate_ellipsoid(Q, 24, 48);
            INFO("ellipsoid with axes " << a << " " << b << " " << c << " scaled by " << s << ", Q = " << str(Q));
            REQUIRE(m.n_vertices() == std::size_t(2 + 23 * 48));
            const std::string err = closed_oriented(m);
            CHECK_MESSAGE(err.empty(), err);
            CHECK(euler(m) == 2);
            const double qn = max_abs(Q);
            for (const auto& p : m.positions)
                CHECK(std::abs(double(value_ld(Q, p))) <= 1e-10 * qn * std::max(1.0, glm::dot(p, p)));
            // the poles and the equator's points at ω = 0 and ω = π/2 end the principal semi-axes: mutually orthogonal
            // from the centre, and the surface normal there points straight away from the centre
            const glm::dvec3 centre = apply(M, glm::dvec3(0.0));
            const std::size_t ring0 = 2 + 11 * 48;  // η = 0 is ring 12
            const glm::dvec3 ends[3] = {m.positions[1], m.positions[ring0 + 24], m.positions[ring0 + 36]};
            for (int i = 0; i < 3; ++i) {
                const glm::dvec3 axis = glm::normalize(ends[i] - centre);
                const glm::dvec3 g = glm::normalize(glm::dvec3(Q * glm::dvec4(ends[i], 1.0)));
                CHECK_MESSAGE(std::abs(std::abs(glm::dot(axis, g)) - 1) <= 1e-9,
                              "vertex " << (i == 0 ? std::string("1 (north pole)") : std::to_string(ring0 + (i == 1 ? 24 : 36)))
                                        << " at " << str(ends[i]) << " should end a principal semi-axis (normal ∥ "
                                        << "vertex − centre): use A's eigenvectors as the axes");
                for (int k = 0; k < i; ++k)
                    CHECK_MESSAGE(std::abs(glm::dot(axis, glm::normalize(ends[k] - centre))) <= 1e-9,
                                  "the principal semi-axes to vertices of the pole and the equator must be orthogonal");
            }
            const double exact = 4 * pi / 3 * a * b * c * s * s * s, v = double(signed_volume(m));
            CHECK_MESSAGE((v > 0 && std::abs(v - exact) / exact < 0.01),
                          "mesh volume " << v << ", exact " << exact << " (negative: the faces point inwards)");
        }
        // A singular for the rank tolerance (|λ| <= 1e-9 max |λ|, as classify): a cylinder, not an ellipsoid
        for (int axis = 0; axis < 3; ++axis)
            for (double k : {1.0, 1e3}) {
                glm::dmat4 Q(0.0);
                Q[0][0] = Q[1][1] = Q[2][2] = k;
                Q[3][3] = -k;
                Q[axis][axis] = 0.5e-9 * k;
                INFO("x² + y² + z² = 1 with axis " << axis << " scaled by 0.5e-9 (times " << k
                                                   << "): a real elliptic cylinder for the rank tolerance");
                CHECK_THROWS_AS(tessellate_ellipsoid(Q, 8, 8), std::invalid_argument);
                Q[axis][axis] = 1e-9 * k;  // |λ| = 1e-9 max |λ| still counts as zero
                CHECK_THROWS_AS(tessellate_ellipsoid(Q, 8, 8), std::invalid_argument);
                Q[axis][axis] = 2e-9 * k;  // above the tolerance: a (very long) real ellipsoid
                CHECK_NOTHROW(tessellate_ellipsoid(Q, 8, 8));
            }
        for (QuadricType t : {QuadricType::imaginary_ellipsoid, QuadricType::hyperboloid_one_sheet,
                              QuadricType::elliptic_paraboloid, QuadricType::imaginary_cone}) {
            INFO(type_name(t) << " is not a real ellipsoid");
            CHECK_THROWS_AS(tessellate_ellipsoid(to_glm(canonical(t, 1, 2, 3)), 8, 8), std::invalid_argument);
        }
    }
}  // TEST_SUITE
