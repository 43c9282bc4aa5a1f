// Lab 04, Task 2: the field F = T − Σ D and its gradient. Expected values: sums in long double (helpers.hpp).
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab04;

namespace {
const Kernel kernels[3] = {Kernel::blinn, Kernel::nishimura, Kernel::wyvill};
BlobScene two_blinn(double d) {
    BlobScene s;
    s.kernel = Kernel::blinn;
    s.threshold = 0.5;
    Blob a, b;
    a.center = {-d / 2, 0, 0};
    b.center = {d / 2, 0, 0};
    s.blobs = {a, b};
    return s;
}
}  // namespace

TEST_SUITE("Task 2: the field") {
    TEST_CASE("field: one blob gives T − D(r); negative inside" * geolab::points(2) * geolab::builds_on("Task 1") *
              geolab::hint("value = threshold − Σ density(kernel, blob, |p − centre|): NEGATIVE inside.")) {
        for (Kernel k : kernels) {
            BlobScene s;
            s.kernel = k;
            s.threshold = 0.4;
            Blob b;
            b.center = {0.3, -0.2, 0.1};
            b.radius = 1.2;
            b.a = 2;
            s.blobs = {b};
            for (double r : {0.0, 0.2, 0.5, 0.9, 1.5}) {
                const glm::dvec3 p = b.center + glm::dvec3(0.6, 0.0, 0.8) * r;
                const double want = double(ref_value(s, p)), got = field(s, p).value;
                CHECK_MESSAGE(close(got, want, 1e-12), str(s) << " at " << str(p) << ": expected F = " << want << ", got "
                                                              << got);
            }
            CHECK_MESSAGE(field(s, b.center).value < 0, str(k) << ": the centre of a blob with b > T is inside (F < 0)");
            const glm::dvec3 g0 = field(s, b.center).gradient;
            CHECK_MESSAGE(g0 == glm::dvec3(0.0), str(k) << ": at the blob's centre (r = 0) the gradient is (0, 0, 0), got " << str(g0)
                                                        << " (skip the term where r = 0: 0/0 is NaN)");
        }
    }

    TEST_CASE("field: sums every blob (random scenes of each kernel; negative blobs among them)" * geolab::points(3) *
              geolab::builds_on("Task 1")) {
        Rng rng(51);
        for (Kernel k : kernels)
            for (int n = 0; n < 10; ++n) {
                const BlobScene s = random_scene(rng, k, rng.integer(1, 12));
                for (int m = 0; m < 20; ++m) {
                    const glm::dvec3 p = rng.point(-1.5, 1.5);
                    const double want = double(ref_value(s, p)), got = field(s, p).value;
                    CHECK_MESSAGE(close(got, want, 1e-12, scale_of(s)),
                                  str(s) << " at " << str(p) << ": expected F = " << want << ", got " << got);
                }
            }
    }

    TEST_CASE("field: the gradient is ∇F (analytic; checked against finite differences of F)" * geolab::points(3) *
              geolab::builds_on("Task 1") *
              geolab::hint("∇F = −Σ D'(rᵢ) (p − cᵢ)/rᵢ: mind the sign (F = T − Σ D) and skip a blob with rᵢ = 0.")) {
        Rng rng(52);
        for (Kernel k : kernels)
            for (int n = 0; n < 8; ++n) {
                const BlobScene s = random_scene(rng, k, rng.integer(1, 8));
                for (int m = 0; m < 20; ++m) {
                    const glm::dvec3 p = rng.point(-1.2, 1.2);
                    const glm::dvec3 got = field(s, p).gradient, want = ref_gradient(s, p);
                    const double h = 1e-6;
                    glm::dvec3 fd;
                    for (int a = 0; a < 3; ++a) {
                        glm::dvec3 e(0.0);
                        e[a] = h;
                        fd[a] = (field(s, p + e).value - field(s, p - e).value) / (2 * h);
                    }
                    const double sc = 10 * scale_of(s);
                    CHECK_MESSAGE(glm::length(got - want) <= 1e-10 * sc,
                                  str(s) << " at " << str(p) << ": expected ∇F = " << str(want) << ", got " << str(got));
                    CHECK_MESSAGE(glm::length(got - fd) <= 1e-5 * sc, str(s) << " at " << str(p) << ": finite differences "
                                                                            << str(fd) << ", your gradient " << str(got));
                }
            }
    }

    TEST_CASE("field: two Blinn blobs (a = b = 1; T = 0.5) merge exactly when d ≤ 2√ln4 = 2.35482" * geolab::points(2) *
              geolab::builds_on("Task 1") *
              geolab::hint("At the midpoint F = 0.5 − 2 exp(−d²/4): it is 0 at d = 2√(ln 4).")) {
        for (double d : {2.0, 2.3, 2.354, 2.356, 2.4, 3.0}) {
            const BlobScene s = two_blinn(d);
            const double v = field(s, glm::dvec3(0.0)).value;
            const bool merged = d <= 2.35482;
            CHECK_MESSAGE((v < 0) == merged, "centres " << d << " apart: F at the midpoint = " << v << ", so the blobs are "
                                                        << (v < 0 ? "merged" : "apart") << ", expected "
                                                        << (merged ? "merged" : "apart"));
        }
        const double v = field(two_blinn(2 * std::sqrt(std::log(4.0))), glm::dvec3(0.0)).value;
        CHECK_MESSAGE(std::abs(v) < 1e-14, "at d = 2√ln4 the midpoint is on the surface: F = " << v);
    }

    TEST_CASE("field: a negative blob subtracts and can carve a hole" * geolab::points(2) *
              geolab::builds_on("Task 1")) {
        for (Kernel k : kernels) {
            BlobScene s;
            s.kernel = k;
            s.threshold = 0.5;
            Blob big;
            big.radius = 2;
            big.a = 0.5;
            big.strength = 1;
            Blob neg = big;
            neg.strength = -1;
            neg.radius = 1;
            neg.a = 4;
            s.blobs = {big};
            const double before = field(s, glm::dvec3(0.0)).value;
            s.blobs.push_back(neg);
            const double after = field(s, glm::dvec3(0.0)).value;
            CHECK_MESSAGE(after > 0, str(k) << ": the negative blob at the centre makes the centre outside: F = " << after);
            CHECK_MESSAGE(close(after - before, 1.0, 1e-12), str(k) << ": it adds |b| = 1 at its centre, got " << after - before);
        }
    }

    TEST_CASE("field: bad blobs throw std::invalid_argument naming the blob" * geolab::points(2) *
              geolab::builds_on("Task 1") *
              geolab::hint("Let density's exception through, with the blob's index in the message (\"blob 2: ...\").")) {
        for (Kernel k : kernels) {
            BlobScene s;
            s.kernel = k;
            s.blobs.resize(3);
            s.blobs[2].radius = -1;
            s.blobs[2].a = -1;
            bool thrown = false;
            try {
                field(s, glm::dvec3(0.0));
            } catch (const std::invalid_argument& e) {
                thrown = true;
                CHECK_MESSAGE(std::string(e.what()).find('2') != std::string::npos,
                              str(k) << ": the message should name blob 2, got \"" << e.what() << "\"");
            }
            CHECK_MESSAGE(thrown, str(k) << ": a blob with R = −1 and a = −1 must throw std::invalid_argument");
            s.blobs[2] = Blob{};
            s.threshold = std::numeric_limits<double>::quiet_NaN();
            CHECK_THROWS_AS(field(s, glm::dvec3(0.0)), std::invalid_argument);
        }
    }
}
