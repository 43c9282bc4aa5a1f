// Lab 03 hidden tests: run by the grader, left out of the student release. Same tasks (suites) as the public ones;
// the same independent references (helpers.hpp): types by construction, long double bisection, numerical integrals.
#include <limits>

#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab03;

namespace {
const double inf = std::numeric_limits<double>::infinity();

double log_uniform(Rng& rng, double lo, double hi) { return std::exp(rng.uniform(std::log(lo), std::log(hi))); }

// The smallest root of the ray's quadratic in (0, t_hi], by bisection in long double; NaN if none.
double first_root(const glm::dmat4& Q, const Ray& r, long double t_hi) {
    const auto roots = roots_by_bisection(ray_poly(Q, r), 0, t_hi);
    for (LD t : roots)
        if (t > 0) return double(t);
    return std::numeric_limits<double>::quiet_NaN();
}
// α, β, γ as a double implementation computes them (for the self-check that the textbook formula fails).
void double_coefficients(const glm::dmat4& Q, const Ray& r, double& al, double& be, double& ga) {
    const glm::dvec4 X(r.origin, 1.0), D(r.direction, 0.0);
    al = glm::dot(D, Q * D);
    be = 2 * glm::dot(X, Q * D);
    ga = glm::dot(X, Q * X);
}
}  // namespace

TEST_SUITE("Task 1: the matrix form") {
    TEST_CASE("matrix form hidden: large and small coefficients; far points" * geolab::points(2) * geolab::hidden() *
              geolab::hint("The same formulas hold at every scale; nothing should be rounded to a fixed tolerance.")) {
        Rng rng(101);
        for (int n = 0; n < 60; ++n) {
            const double scale = n % 3 == 0 ? 1e8 : n % 3 == 1 ? 1e-8 : 1.0;
            Coefficients k;
            double* v[10] = {&k.a, &k.b, &k.c, &k.f, &k.g, &k.h, &k.p, &k.q, &k.r, &k.d};
            for (double* x : v) *x = rng.uniform(-3, 3) * scale;
            const glm::dmat4 Q = to_matrix(k), want = matrix_of(k);
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r)
                    CHECK_MESSAGE(Q[c][r] == want[c][r], "coefficients " << str(k) << ": entry [" << c << "][" << r
                                                                         << "] should be " << want[c][r] << ", got " << Q[c][r]);
            const glm::dvec3 x{rng.uniform(-1e3, 1e3), rng.uniform(-1e3, 1e3), rng.uniform(-1e3, 1e3)};
            const double w = double(poly(k, x));
            const double magnitude = scale * 3 * 4 * (1 + glm::dot(x, x));
            CHECK_MESSAGE(std::abs(evaluate(want, x) - w) <= 1e-13 * magnitude,
                          "evaluate at " << str(x) << " of " << str(k) << ": expected " << w << ", got " << evaluate(want, x));
            const glm::dvec3 g = gradient(want, x);
            const glm::dvec3 gw{2 * (k.a * x.x + k.h * x.y + k.g * x.z + k.p), 2 * (k.h * x.x + k.b * x.y + k.f * x.z + k.q),
                                2 * (k.g * x.x + k.f * x.y + k.c * x.z + k.r)};
            CHECK(glm::length(g - gw) <= 1e-13 * scale * 24 * (1 + glm::length(x)));
        }
    }
}

TEST_SUITE("Task 2: transforms") {
    TEST_CASE("transform hidden: a map then its inverse gives Q back; two maps compose" * geolab::points(3) *
              geolab::hidden() * geolab::hint("Q' = M⁻ᵀ Q M⁻¹ composes: moving by M1 then M2 is moving by M2·M1.")) {
        Rng rng(102);
        for (int n = 0; n < 30; ++n) {
            Mat4L Q;
            for (int r = 0; r < 4; ++r)
                for (int c = r; c < 4; ++c) Q(r, c) = Q(c, r) = rng.uniform(-2, 2);
            const Mat4L M1 = affine(rng), M2 = n % 2 ? affine(rng) : similarity(rng, rng.uniform(0.2, 5), 4);
            const glm::dmat4 q = to_glm(Q);
            const glm::dmat4 back = transform_quadric(transform_quadric(q, to_glm(M1)), to_glm(Mat4L(M1.inverse())));
            const glm::dmat4 two = transform_quadric(transform_quadric(q, to_glm(M1)), to_glm(M2));
            const glm::dmat4 want2 = to_glm(moved(Q, M2 * M1));
            INFO("Q = " << str(q) << ", M1 = " << str(to_glm(M1)) << ", M2 = " << str(to_glm(M2)) << ": back " << str(back)
                        << ", composed " << str(two) << ", expected " << str(want2));
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) {
                    CHECK(std::abs(back[c][r] - q[c][r]) <= 1e-10 * max_abs(q));
                    CHECK(std::abs(two[c][r] - want2[c][r]) <= 1e-10 * max_abs(want2));
                }
        }
    }
}

TEST_SUITE("Task 3: classification") {
    TEST_CASE("classify hidden: thousands of random rigid motions; uniform scalings and signs" * geolab::points(4) *
              geolab::hidden() *
              geolab::hint("Zero eigenvalues relative to the largest |eigenvalue| of the same matrix; a fixed absolute "
                           "threshold breaks under scaling.")) {
        Rng rng(103);
        int wrong = 0;
        for (int i = 0; i < n_types; ++i)
            for (int n = 0; n < 150; ++n) {
                double a, b, c;
                random_axes(rng, a, b, c);
                const double s = log_uniform(rng, 0.1, 10);
                const LD k = (n % 2 ? -1 : 1) * LD(log_uniform(rng, 1e-3, 1e3));
                const glm::dmat4 Q = to_glm(k * moved(canonical(type_at(i), a, b, c), similarity(rng, s, 3.0)));
                QuadricType got{};
                bool threw = false;
                try {
                    got = classify(Q);
                } catch (const geolab::NotImplemented&) {
                    throw;
                } catch (const std::exception&) {
                    threw = true;
                }
                if ((threw || got != type_at(i)) && wrong++ < 8)
                    FAIL_CHECK(type_name(type_at(i)) << " (axes " << a << " " << b << " " << c << ") moved, scaled by " << s
                                                     << ", times " << double(k) << ": Q = " << str(Q) << ", got "
                                                     << (threw ? std::string("an exception") : type_name(got)));
            }
        CHECK_MESSAGE(wrong == 0, wrong << " of " << 150 * n_types << " random copies misclassified");
    }

    TEST_CASE("classify hidden: degenerate types at very different scales" * geolab::points(3) * geolab::hidden() *
              geolab::hint("x² = 10⁻⁶ is still two real planes and x² = −10⁻⁶ two imaginary ones: the sign of the 4×4's "
                           "eigenvalue decides, whatever its size relative to the others (above the rank tolerance).")) {
        Rng rng(104);
        using T = QuadricType;
        for (double a : {1e-3, 0.05, 1.0, 20.0, 300.0})
            for (T t : {T::real_parallel_planes, T::imaginary_parallel_planes, T::coincident_planes,
                        T::real_elliptic_cylinder, T::imaginary_elliptic_cylinder, T::hyperbolic_cylinder,
                        T::real_intersecting_planes, T::imaginary_intersecting_planes, T::parabolic_cylinder}) {
                const double b = t == T::parabolic_cylinder ? 1.0 : a * rng.uniform(0.5, 2);
                const Mat4L M = similarity(rng, 1.0, 1.0);
                const glm::dmat4 Q = to_glm(LD(rng.uniform(-2, 2) < 0 ? -1 : 1) * moved(canonical(t, a, b, 1.0), M));
                QuadricType got{};
                try {
                    got = classify(Q);
                } catch (const geolab::NotImplemented&) {
                    throw;
                } catch (const std::exception& e) {
                    FAIL_CHECK(type_name(t) << " with a = " << a << ": classify threw " << e.what());
                    continue;
                }
                CHECK_MESSAGE(got == t, type_name(t) << " with a = " << a << ", b = " << b << ", Q = " << str(Q)
                                                     << ": got " << type_name(got));
            }
    }
}

TEST_SUITE("Task 4: rays") {
    TEST_CASE("rays hidden: near-asymptotic rays; the surface 1e6 away: the near root to 1e-9 relative" *
              geolab::points(4) * geolab::hidden() *
              geolab::hint("When DᵀQD is tiny, (−β ± √Δ)/(2α) loses the near root to cancellation: use q = −(β + "
                           "sign(β)√Δ)/2 and t = γ/q.")) {
        Rng rng(105);
        using T = QuadricType;
        int naive_fails = 0, cases = 0;
        for (int n = 0; n < 60; ++n) {
            const double eps = n % 2 ? 1e-7 : 1e-8;
            const double far = n % 3 == 0 ? 1e6 : n % 3 == 1 ? 1e3 : 2.0;
            Mat4L Q0;
            Ray r0;
            const double phi = rng.uniform(0, 2 * pi);
            switch (n % 4) {
                case 0:  // z = x² + y², from far below, almost along the axis
                    Q0 = canonical(T::elliptic_paraboloid, 1, 1, 1);
                    r0 = {{0.3, -0.2, -far}, {eps * std::cos(phi), eps * std::sin(phi), 1}};
                    break;
                case 1:  // z = x² − y²
                    Q0 = canonical(T::hyperbolic_paraboloid, 1, 1, 1);
                    r0 = {{0.1, 0.4, -far}, {eps * std::cos(phi), eps * std::sin(phi), 1}};
                    break;
                case 2:  // x² = 2z (parabolic cylinder)
                    Q0 = canonical(T::parabolic_cylinder, 1, 1, 1);
                    r0 = {{0.5, 1, -far}, {eps * std::cos(phi), 0.3, 1}};
                    break;
                default: {  // x² + y² = z², almost along a generator, from far out along it
                    Q0 = canonical(T::real_cone, 1, 1, 1);
                    const glm::dvec3 g{std::cos(phi), std::sin(phi), 1};
                    r0 = {-far * g + glm::dvec3(0.5 * std::sin(phi), -0.5 * std::cos(phi), 0.7), g + glm::dvec3(0, 0, eps)};
                }
            }
            const Mat4L M = n < 8 ? Mat4L(Mat4L::Identity()) : similarity(rng, 1.0, 0.0);  // rotations keep |X| ~ far
            const glm::dmat4 Q = to_glm(moved(Q0, M));
            const Ray ray{apply(M, r0.origin), apply(M, r0.direction) - apply(M, glm::dvec3(0.0))};
            const double want = first_root(Q, ray, 1e20L);
            if (std::isnan(want)) continue;
            ++cases;
            double al, be, ga;
            double_coefficients(Q, ray, al, be, ga);
            if (!close(naive_near_root(al, be, ga), want, 1e-9)) ++naive_fails;
            const auto hits = intersect(Q, ray, 0, inf);
            INFO(str(ray) << " on Q = " << str(Q) << " (case " << n << "): the first root is " << want
                          << " (long double bisection); got " << (hits.empty() ? std::string("no hit") : std::to_string(hits[0].t)));
            REQUIRE(!hits.empty());
            CHECK(close(hits[0].t, want, 1e-9));
        }
        CHECK(cases >= 50);
        CHECK_MESSAGE(naive_fails * 2 >= cases, "test self-check: the textbook formula should fail most of these cases ("
                                                    << naive_fails << " of " << cases << ")");
    }

    TEST_CASE("rays hidden: coincident planes (ax + by + cz + d)² = 0 are hit once by every ray that crosses them" *
              geolab::points(1) * geolab::hidden() *
              geolab::hint("Along any ray Δ is exactly 0 but rounds to ±tiny: treat |Δ| <= 1e-12 (β² + 4|αγ|) as a double "
                           "root (the contract), or half the rays miss.")) {
        Rng rng(44);
        int wrong = 0, cases = 0, rounded_negative = 0;
        for (int n = 0; n < 1000; ++n) {
            const glm::dvec3 nrm = rng.unit() * rng.uniform(0.3, 3);
            const double d = rng.uniform(-2, 2);
            glm::dmat4 Q;  // (n·x + d)²: Q = v vᵀ with v = (n, d)
            const glm::dvec4 v(nrm, d);
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) Q[c][r] = v[c] * v[r];
            const Ray ray{{rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(-4, 4)}, rng.unit()};
            const double dn = glm::dot(nrm, ray.direction);
            if (std::abs(dn) < 0.05 * glm::length(nrm)) continue;  // nearly parallel to the plane
            // starting near the plane, α, β, γ lose their digits to cancellation (XᵀQX ≈ 0 at the origin): beyond Δ's
            // tolerance; from a distance >= 1 the relative tolerance on Δ holds
            if (std::abs(glm::dot(nrm, ray.origin) + d) < glm::length(nrm)) continue;
            const double want = -(glm::dot(nrm, ray.origin) + d) / dn;
            ++cases;
            double al, be, ga;
            double_coefficients(Q, ray, al, be, ga);
            if (be * be - 4 * al * ga < 0) ++rounded_negative;  // an exact Δ = 0 test would miss these
            const auto hits = intersect(Q, ray, -inf, inf);
            const bool ok = hits.size() == 1 && close(hits[0].t, want, 1e-6, 1.0);
            if (!ok && wrong++ < 5)
                FAIL_CHECK("the plane pair (" << str(nrm) << "·x + " << d << ")² = 0, " << str(ray) << ": expected one hit at t = "
                                              << want << ", got " << hits.size() << " hits"
                                              << (hits.empty() ? std::string() : " (first at t = " + std::to_string(hits[0].t) + ")"));
        }
        CHECK_MESSAGE(wrong == 0, wrong << " rays through coincident planes got a wrong number of hits");
        CHECK(cases >= 300);
        CHECK_MESSAGE(rounded_negative * 5 >= cases, "test self-check: Δ rounds below 0 in only " << rounded_negative
                                                                                               << " of " << cases << " cases");
    }

    TEST_CASE("rays hidden: random rays on all 17 types; every root in (-100; 100)" * geolab::points(2) *
              geolab::hidden() * geolab::hint("Every real crossing, sorted; one hit for a double root; none for the "
                                              "imaginary types.")) {
        Rng rng(106);
        int bad = 0;
        for (int i = 0; i < n_types; ++i)
            for (int n = 0; n < 40; ++n) {
                double a, b, c;
                random_axes(rng, a, b, c);
                const Mat4L M = similarity(rng, rng.uniform(0.5, 2), 2.0);
                const glm::dmat4 Q = to_glm(moved(canonical(type_at(i), a, b, c), M));
                const Ray ray{{rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(-4, 4)}, rng.unit()};
                const RayPoly p = ray_poly(Q, ray);
                const LD disc = p.beta * p.beta - 4 * p.alpha * p.gamma;
                if (std::abs(disc) < 1e-6 * (p.beta * p.beta + std::abs(4 * p.alpha * p.gamma))) continue;  // near-tangent
                if (std::abs(p.alpha) < 1e-6 * (std::abs(p.beta) + std::abs(p.gamma))) continue;          // near-linear
                std::vector<LD> want = roots_by_bisection(p, -100, 100);
                const auto hits = intersect(Q, ray, -100, 100);
                bool ok = hits.size() == want.size();
                for (std::size_t k = 0; ok && k < hits.size(); ++k)
                    ok = close(hits[k].t, double(want[k]), 1e-9, 1e-6) && (k == 0 || hits[k - 1].t <= hits[k].t);
                if (!ok && bad++ < 6) {
                    std::ostringstream w, g;
                    for (LD t : want) w << double(t) << " ";
                    for (const Hit& h : hits) g << h.t << " ";
                    FAIL_CHECK(type_name(type_at(i)) << " Q = " << str(Q) << ", " << str(ray) << ": expected t = " << w.str()
                                                     << "got t = " << g.str());
                }
            }
        CHECK(bad == 0);
    }
}

TEST_SUITE("Task 5: superquadrics") {
    TEST_CASE("superquadrics hidden: volumes for random radii and exponents" * geolab::points(2) * geolab::hidden() *
              geolab::hint("B(ε₁/2 + 1, ε₁) and B(ε₂/2, ε₂/2): check which argument gets the +1.")) {
        Rng rng(107);
        for (int n = 0; n < 30; ++n) {
            const Superquadric s{{rng.uniform(0.2, 3), rng.uniform(0.2, 3), rng.uniform(0.2, 3)}, rng.uniform(0.15, 3.5),
                                 rng.uniform(0.15, 3.5)};
            const double want = double(volume_by_integral(s)), got = superquadric_volume(s);
            CHECK_MESSAGE(close(got, want, 1e-7), str(s) << ": expected " << want << " (integral), got " << got);
        }
    }

    TEST_CASE("superquadrics hidden: ray hits agree with a long double bisection of F along the ray" * geolab::points(3) *
              geolab::hidden() * geolab::hint("Bracket, then bisect to full precision; a coarse march alone is not enough.")) {
        Rng rng(108);
        for (int n = 0; n < 60; ++n) {
            const Superquadric s{{rng.uniform(0.4, 2), rng.uniform(0.4, 2), rng.uniform(0.4, 2)}, rng.uniform(0.2, 3),
                                 rng.uniform(0.2, 3)};
            const glm::dvec3 aim{rng.uniform(-0.1, 0.1) * s.radii.x, rng.uniform(-0.1, 0.1) * s.radii.y,
                                 rng.uniform(-0.1, 0.1) * s.radii.z};
            const bool inside = n % 4 == 3;
            const glm::dvec3 o = inside ? aim : aim + rng.uniform(3, 8) * rng.unit();
            const glm::dvec3 d = inside ? rng.unit() * rng.uniform(0.5, 2) : (aim - o) * rng.uniform(0.2, 1.5);
            const Ray ray{o, d};
            const auto G = [&](LD t) { return F_ld(s, ray.origin + double(t) * ray.direction) - 1; };
            // first sign change on a fine grid up to 20 box diagonals, then bisection
            const LD tmax = 20 * glm::length(s.radii) / glm::length(d) + 10;
            LD prev = 0, want = -1;
            const LD g0 = G(0);
            for (int k = 1; k <= 20000; ++k) {
                const LD t = tmax * k / 20000;
                if ((G(t) < 0) != (g0 < 0)) {
                    want = bisect(G, prev, t);
                    break;
                }
                prev = t;
            }
            REQUIRE(want > 0);
            const auto got = intersect_superquadric(s, ray, 0, inf);
            INFO(str(s) << ", " << str(ray) << ": expected t = " << double(want) << ", got "
                        << (got ? std::to_string(got->t) : std::string("no hit")));
            REQUIRE(got.has_value());
            CHECK(close(got->t, double(want), 1e-9, 1.0));
            const glm::dvec3 n3 = got->normal;
            CHECK(std::abs(glm::length(n3) - 1) <= 1e-9);
            CHECK_MESSAGE(glm::dot(n3, got->point / (s.radii * s.radii)) > 0, "the normal must point outwards, got " << str(n3));
        }
    }
}

TEST_SUITE("Task 6: tessellation") {
    TEST_CASE("tessellation hidden: random superquadrics and ellipsoids stay closed; outward; χ = 2" * geolab::points(2) *
              geolab::builds_on("Task 5") *
              geolab::hidden() * geolab::hint("Odd grid sizes and extreme exponents too.")) {
        Rng rng(109);
        for (int n = 0; n < 15; ++n) {
            const Superquadric s{{rng.uniform(0.2, 3), rng.uniform(0.2, 3), rng.uniform(0.2, 3)}, rng.uniform(0.1, 4),
                                 rng.uniform(0.1, 4)};
            const int ne = rng.integer(2, 40), no = rng.integer(3, 41);
            const PolygonSoup m = tessellate_superquadric(s, ne, no);
            INFO(str(s) << " on a " << ne << " x " << no << " grid");
            CHECK(m.n_vertices() == std::size_t(2 + (ne - 1) * no));
            const std::string err = closed_oriented(m);
            CHECK_MESSAGE(err.empty(), err);
            CHECK(euler(m) == 2);
            CHECK(signed_volume(m) > 0);
            double a, b, c;
            random_axes(rng, a, b, c);
            const glm::dmat4 Q = to_glm(moved(canonical(QuadricType::real_ellipsoid, a, b, c), affine(rng)));
            const PolygonSoup e = tessellate_ellipsoid(Q, ne, no);
            const std::string err2 = closed_oriented(e);
            CHECK_MESSAGE(err2.empty(), "ellipsoid Q = " << str(Q) << ": " << err2);
            CHECK(euler(e) == 2);
            CHECK(signed_volume(e) > 0);
        }
    }
}

TEST_SUITE("Task 7: images") {
    TEST_CASE("images hidden: a cylinder clipped by the box; seen through its open end" * geolab::points(2) *
              geolab::builds_on("Task 4") *
              geolab::hidden() *
              geolab::hint("Take the first hit INSIDE the box: where the near side of the surface is clipped away, the "
                           "far side (seen from inside) shows.")) {
        const PinholeCamera cam{{0.8, 4, 3}, {0, 0, 0}, {0, 0, 1}, 45};
        Scene scene;
        scene.Q = to_glm(canonical(QuadricType::real_elliptic_cylinder, 1, 1, 1));  // x² + y² = 1
        scene.box = {{-2, -2, -1}, {2, 2, 1}};
        scene.light = {0.3, 1, 0.5};
        const int w = 40, h = 32;
        const auto img = render_lambert(scene, cam, w, h);
        REQUIRE((img.width == w && img.height == h));
        const glm::dvec3 l = glm::normalize(scene.light);
        int bad = 0, hits = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const Ray r = cam.ray(x, y, w, h);
                // x² + y² = 1 along the ray in long double: the quadratic formula in higher precision (a different
                // precision from any double implementation), then the first root whose point is in the box
                const LD ox = r.origin.x, oy = r.origin.y, dx = r.direction.x, dy = r.direction.y;
                const LD A = dx * dx + dy * dy, B = 2 * (ox * dx + oy * dy), C = ox * ox + oy * oy - 1;
                const LD disc = B * B - 4 * A * C;
                int want = 0;
                bool edge = false;
                if (disc > 0 && A > 0) {
                    for (LD t : {(-B - std::sqrt(disc)) / (2 * A), (-B + std::sqrt(disc)) / (2 * A)}) {
                        const double z = double(r.origin.z + t * r.direction.z);
                        if (t < 0) continue;
                        if (std::abs(std::abs(z) - 1) < 1e-3) edge = true;
                        if (std::abs(z) > 1) continue;
                        const glm::dvec3 p = r.origin + double(t) * r.direction;
                        want = int(std::lround(255 * (0.1 + 0.9 * std::abs(glm::dot(glm::dvec3(p.x, p.y, 0), l)))));
                        ++hits;
                        break;
                    }
                }
                if (edge || std::abs(disc) < 1e-6) continue;
                const auto px = img.pixel(x, y);
                if (std::abs(int(px[0]) - want) > 1 && bad++ < 5)
                    FAIL_CHECK("pixel (" << x << ", " << y << ") should be " << want << ", got " << int(px[0]));
            }
        CHECK(bad == 0);
        CHECK(hits > 100);
    }
}
