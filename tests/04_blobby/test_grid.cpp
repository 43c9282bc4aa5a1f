// Lab 04, Task 3: fast evaluation through a uniform grid of the blobs. Expected lists from distances of cells to
// blobs; expected values from the sums in long double (helpers.hpp); kernel evaluations counted by your code and
// bounded by what the grid allows.
#include "helpers.hpp"
#include "geolab/grading/chain.hpp"

using namespace lab04;

namespace {
// Distance from p to the box [lo, hi].
double box_distance(const glm::dvec3& p, const glm::dvec3& lo, const glm::dvec3& hi) {
    const glm::dvec3 q = glm::max(lo - p, glm::max(glm::dvec3(0.0), p - hi));
    return glm::length(q);
}
std::vector<std::uint32_t> list_of(const BlobGrid& g, std::size_t c) {
    return {g.blob_ids.begin() + g.cell_start[c], g.blob_ids.begin() + g.cell_start[c + 1]};
}
// A scene of n blobs of radius R at density about one blob per unit volume·rho: box side grows with n.
BlobScene spread_scene(Rng& rng, Kernel k, int n, double R) {
    BlobScene s;
    s.kernel = k;
    s.threshold = 0.3;
    const double side = std::cbrt(double(n)) * R * 1.5;
    for (int i = 0; i < n; ++i) {
        Blob b;
        b.center = rng.point(0, side);
        b.radius = R;
        s.blobs.push_back(b);
    }
    return s;
}
}  // namespace

TEST_SUITE("Task 3: fast evaluation") {
    TEST_CASE("grid: each cell lists every blob whose support reaches it; in increasing order; and no far blob" *
              geolab::points(3) * geolab::builds_on("Task 1") *
              geolab::hint("Put each blob in every cell its box [c − R, c + R]³ overlaps; a blob in the wrong cell or "
                           "with a too-small box (support radius off) loses samples.")) {
        Rng rng(61);
        for (Kernel k : {Kernel::nishimura, Kernel::wyvill})
            for (double cell : {0.0, 0.15, 0.5, 1.0}) {
                BlobScene s = random_scene(rng, k, 15);
                if (cell == 1.0) {  // blobs on integer points, R = 1, cell 1: boxes end exactly on cell faces
                    s.blobs.resize(4);
                    const glm::dvec3 at[4] = {{0, 0, 0}, {5, 0, 0}, {0, 3, 1}, {2, 2, 4}};
                    for (int i = 0; i < 4; ++i) s.blobs[i].center = at[i], s.blobs[i].radius = 1;
                }
                const BlobGrid g = build_blob_grid(s, cell);
                const double c = g.cell;
                REQUIRE_MESSAGE(g.cell_start.size() == std::size_t(g.dims.x) * g.dims.y * g.dims.z + 1,
                                "cell_start must have one entry per cell plus one");
                REQUIRE(g.cell_start.back() == g.blob_ids.size());
                // (an empty grid lists nothing wrongly): the cell of each blob's centre lists that blob
                for (std::uint32_t b = 0; b < s.blobs.size(); ++b) {
                    const glm::ivec3 at = glm::ivec3(glm::floor((s.blobs[b].center - g.origin) / g.cell));
                    const bool in_grid = glm::all(glm::greaterThanEqual(at, glm::ivec3(0))) && glm::all(glm::lessThan(at, g.dims));
                    REQUIRE_MESSAGE(in_grid, str(s) << ": blob " << b << "'s centre is outside the grid");
                    const auto L = list_of(g, at.x + std::size_t(g.dims.x) * (at.y + std::size_t(g.dims.y) * at.z));
                    CHECK_MESSAGE(std::find(L.begin(), L.end(), b) != L.end(), str(s) << ": blob " << b << " is not listed in the cell of its centre");
                }
                for (int kk = 0; kk < g.dims.z; ++kk)
                    for (int j = 0; j < g.dims.y; ++j)
                        for (int i = 0; i < g.dims.x; ++i) {
                            const std::size_t n = i + std::size_t(g.dims.x) * (j + std::size_t(g.dims.y) * kk);
                            const glm::dvec3 lo = g.origin + c * glm::dvec3(i, j, kk), hi = lo + c;
                            const auto L = list_of(g, n);
                            CHECK_MESSAGE(std::is_sorted(L.begin(), L.end()), str(s) << ": cell " << n << "'s list is not in increasing order");
                            for (std::uint32_t b = 0; b < s.blobs.size(); ++b) {
                                const Blob& B = s.blobs[b];
                                const bool listed = std::find(L.begin(), L.end(), b) != L.end();
                                const double d = box_distance(B.center, lo, hi);
                                if (d < B.radius * (1 - 1e-9))
                                    CHECK_MESSAGE(listed, str(k) << " cell size " << c << ": blob " << b << " reaches cell ("
                                                                 << i << ", " << j << ", " << kk << ") (distance " << d
                                                                 << " < R = " << B.radius << ") but is not listed there");
                                const glm::dvec3 blo = B.center - B.radius, bhi = B.center + B.radius;
                                const bool overlaps = glm::all(glm::lessThanEqual(blo, hi + 1e-9 * c)) &&
                                                      glm::all(glm::lessThanEqual(lo - 1e-9 * c, bhi));
                                if (!overlaps)
                                    CHECK_MESSAGE(!listed, str(k) << " cell size " << c << ": blob " << b << " is listed in cell ("
                                                                  << i << ", " << j << ", " << kk
                                                                  << ") which its support box does not overlap");
                            }
                        }
            }
    }

    TEST_CASE("grid: origin; cell and dims cover the union of the supports; blinn and empty scenes" * geolab::points(2) *
              geolab::builds_on("Task 1")) {
        Rng rng(62);
        const BlobScene s = random_scene(rng, Kernel::wyvill, 9);
        glm::dvec3 lo(1e300), hi(-1e300);
        double rmax = 0;
        for (const Blob& b : s.blobs) {
            lo = glm::min(lo, b.center - b.radius);
            hi = glm::max(hi, b.center + b.radius);
            rmax = std::max(rmax, b.radius);
        }
        const BlobGrid g = build_blob_grid(s, 0.0);
        CHECK_MESSAGE(g.cell == rmax, "cell ≤ 0 picks the largest support radius " << rmax << ", got " << g.cell);
        CHECK_MESSAGE(glm::length(g.origin - lo) < 1e-12, "origin should be the lowest corner " << str(lo) << ", got " << str(g.origin));
        for (int a = 0; a < 3; ++a)
            CHECK_MESSAGE(g.dims[a] == std::max(1, int(std::ceil((hi[a] - lo[a]) / rmax))),
                          "axis " << a << ": dims should be ceil(extent / cell) = " << std::ceil((hi[a] - lo[a]) / rmax)
                                  << ", got " << g.dims[a]);
        BlobScene one;
        one.blobs.resize(1);
        one.blobs[0].center = {0.25, -0.5, 1.0};
        CHECK_MESSAGE(build_blob_grid(one, 5.0).dims == glm::ivec3(1), "one blob of R = 1, cell 5: dims (1, 1, 1)");
        CHECK_MESSAGE(build_blob_grid(one, 0.0).dims == glm::ivec3(2), "one blob of R = 1, cell R: dims (2, 2, 2)");
        BlobScene b = s;
        b.kernel = Kernel::blinn;
        CHECK_THROWS_AS(build_blob_grid(b, 0.0), std::invalid_argument);
        BlobScene e;
        const BlobGrid ge = build_blob_grid(e, 0.0);
        CHECK_MESSAGE(ge.dims == glm::ivec3(0), "a scene without blobs gives dims (0, 0, 0)");
        for (const glm::dvec3 p : {glm::dvec3(0.1), glm::dvec3(0.0)}) {
            const FieldSample fe = evaluate(e, ge, p);
            CHECK_MESSAGE((fe.value == e.threshold && fe.kernel_evaluations == 0), "no blobs, at " << str(p) << ": F = T with 0 evaluations");
        }
        BlobScene w = s;
        const BlobGrid gw = build_blob_grid(w, 0.0);
        const FieldSample at_centre = evaluate(w, gw, w.blobs[0].center);
        CHECK_MESSAGE((std::isfinite(at_centre.gradient.x) && std::isfinite(at_centre.gradient.y) && std::isfinite(at_centre.gradient.z)), "at a blob's centre the gradient must be finite (skip r = 0), got "
                                                                      << str(at_centre.gradient));
    }

    TEST_CASE("grid: evaluate equals field everywhere; inside and outside the grid" * geolab::points(2) *
              geolab::builds_on("Task 1") *
              geolab::hint("Find p's cell by floor((p − origin)/cell); outside the grid F = T, ∇F = 0.")) {
        Rng rng(63);
        for (Kernel k : {Kernel::nishimura, Kernel::wyvill})
            for (double cell : {0.0, 0.1, 0.37, 2.0}) {
                const BlobScene s = random_scene(rng, k, 20);
                const BlobGrid g = build_blob_grid(s, cell);
                for (int m = 0; m < 300; ++m) {
                    glm::dvec3 p = rng.point(-2.2, 2.2);
                    if (m % 10 == 0) p[m % 3] = g.origin[m % 3];  // on the grid's lower faces: inside the grid
                    if (m % 10 == 5) p[m % 3] = g.origin[m % 3] + g.cell * g.dims[m % 3];  // upper faces: inside too
                    const FieldSample got = evaluate(s, g, p);
                    // The blobs of p's cell (when p is in the grid): one evaluation each.
                    const glm::dvec3 u = (p - g.origin) / g.cell;
                    if (glm::all(glm::greaterThanEqual(u, glm::dvec3(0.0))) && glm::all(glm::lessThanEqual(u, glm::dvec3(g.dims)))) {
                        const glm::ivec3 c = glm::min(glm::ivec3(glm::floor(u)), g.dims - 1);
                        const std::size_t n = c.x + std::size_t(g.dims.x) * (c.y + std::size_t(g.dims.y) * c.z);
                        const std::uint64_t listed = g.cell_start[n + 1] - g.cell_start[n];
                        CHECK_MESSAGE(got.kernel_evaluations == listed, "at " << str(p) << ": its cell lists " << listed
                                                                              << " blobs, you counted " << got.kernel_evaluations);
                    } else if (glm::any(glm::lessThan(u, glm::dvec3(0.0))) || glm::any(glm::greaterThan(u, glm::dvec3(g.dims)))) {
                        CHECK_MESSAGE(got.kernel_evaluations == 0, "at " << str(p) << ", outside the grid: 0 evaluations");
                    }
                    const double want = double(ref_value(s, p));
                    const glm::dvec3 gw = ref_gradient(s, p);
                    CHECK_MESSAGE(close(got.value, want, 1e-12, scale_of(s)),
                                  str(s) << ", cell " << g.cell << ", at " << str(p) << ": expected F = " << want << ", got "
                                         << got.value);
                    CHECK_MESSAGE(glm::length(got.gradient - gw) <= 1e-10 * 10 * scale_of(s),
                                  str(s) << " at " << str(p) << ": expected ∇F = " << str(gw) << ", got " << str(got.gradient));
                }
            }
    }

    TEST_CASE("grid: evaluate with large blobs (R from 1.2 to 3.2): every blob that reaches p counts" * geolab::points(1) *
              geolab::builds_on("Task 1") *
              geolab::hint("Skipping a listed blob must depend on its own R (a blob contributes 0 from r = R on), not on a "
                           "fixed distance.")) {
        Rng rng(67);
        for (Kernel k : {Kernel::nishimura, Kernel::wyvill}) {
            BlobScene s = random_scene(rng, k, 12);
            for (Blob& b : s.blobs) b.center *= 4.0, b.radius *= 4.0;
            const BlobGrid g = build_blob_grid(s, 0.0);
            for (int m = 0; m < 300; ++m) {
                const glm::dvec3 p = rng.point(-7, 7);
                const FieldSample got = evaluate(s, g, p);
                const double want = double(ref_value(s, p));
                const glm::dvec3 gw = ref_gradient(s, p);
                CHECK_MESSAGE(close(got.value, want, 1e-12, scale_of(s)),
                              str(s) << " (radii 1.2 to 3.2) at " << str(p) << ": expected F = " << want << ", got " << got.value);
                CHECK_MESSAGE(glm::length(got.gradient - gw) <= 1e-10 * 10 * scale_of(s),
                              str(s) << " at " << str(p) << ": expected ∇F = " << str(gw) << ", got " << str(got.gradient));
            }
        }
    }

    TEST_CASE("grid: kernel evaluations per sample do not grow with the number of blobs" * geolab::points(3) *
              geolab::builds_on("Task 1") *
              geolab::hint("Count one evaluation per blob of p's cell. With the grid, a sample only sees the blobs "
                           "whose support box overlaps its cell.")) {
        const double R = 0.3;
        double per_sample[3] = {0, 0, 0};
        int idx = 0;
        for (int n : {30, 300, 3000}) {
            Rng rng(64 + n);
            const BlobScene s = spread_scene(rng, Kernel::wyvill, n, R);
            const BlobGrid g = build_blob_grid(s, 0.0);
            std::uint64_t total = 0;
            const double side = std::cbrt(double(n)) * R * 1.5;
            for (int m = 0; m < 400; ++m) {
                const glm::dvec3 p = rng.point(0, side);
                const FieldSample f = evaluate(s, g, p);
                // Lower bound: every blob whose support contains p must be evaluated. Upper bound: blobs whose
                // centre lies within R + one cell diagonal of p.
                std::uint64_t need = 0, allowed = 0;
                for (const Blob& b : s.blobs) {
                    const double d = glm::length(p - b.center);
                    if (d < R) ++need;
                    if (d <= R + std::sqrt(3.0) * g.cell * (1 + 1e-9) + R) ++allowed;
                }
                CHECK_MESSAGE(f.kernel_evaluations >= need, n << " blobs, at " << str(p) << ": " << need
                                                              << " blobs reach this point, you counted only "
                                                              << f.kernel_evaluations << " evaluations");
                CHECK_MESSAGE(f.kernel_evaluations <= allowed, n << " blobs, at " << str(p) << ": only " << allowed
                                                                 << " blobs are near enough to be in its cell, you counted "
                                                                 << f.kernel_evaluations);
                total += f.kernel_evaluations;
            }
            per_sample[idx++] = double(total) / 400;
        }
        CHECK_MESSAGE(per_sample[2] <= 2.0 * per_sample[0] + 5,
                      "evaluations per sample: " << per_sample[0] << " (30 blobs), " << per_sample[1] << " (300), "
                                                 << per_sample[2] << " (3000) at the same density: must not grow with n");
    }

    TEST_CASE("grid: sample_lattice gives F and ∇F at every lattice point; and the total evaluations" *
              geolab::points(3) * geolab::builds_on("Task 1, Task 2")) {
        Rng rng(65);
        for (Kernel k : {Kernel::blinn, Kernel::nishimura, Kernel::wyvill}) {
            const BlobScene s = random_scene(rng, k, 8);
            const glm::dvec3 o{-1.3, -1.1, -1.2};
            const double h = 0.17;
            const glm::ivec3 n{14, 12, 15};
            std::uint64_t evals = 12345;
            const Lattice L = sample_lattice(s, o, h, n, evals);
            REQUIRE_MESSAGE(L.values.size() == std::size_t(n.x) * n.y * n.z, "one value per sample");
            REQUIRE_MESSAGE(L.gradients.size() == L.values.size(), "one gradient per sample");
            CHECK((L.n == n && L.h == h && L.origin == o));
            for (int m = 0; m < 300; ++m) {
                const int i = rng.integer(0, n.x - 1), j = rng.integer(0, n.y - 1), kk = rng.integer(0, n.z - 1);
                const std::size_t id = i + std::size_t(n.x) * (j + std::size_t(n.y) * kk);
                const glm::dvec3 p = o + h * glm::dvec3(i, j, kk);
                const double want = double(ref_value(s, p));
                CHECK_MESSAGE(close(L.values[id], want, 1e-12, scale_of(s)),
                              str(s) << ": sample (" << i << ", " << j << ", " << kk << ") at " << str(p) << ": expected "
                                     << want << ", got " << L.values[id]);
                CHECK(glm::length(L.gradients[id] - ref_gradient(s, p)) <= 1e-9 * scale_of(s));
            }
            if (k == Kernel::blinn)
                CHECK_MESSAGE(evals == std::uint64_t(n.x) * n.y * n.z * s.blobs.size(),
                              "blinn: every blob at every sample, got " << evals);
            else {
                const BlobGrid g = build_blob_grid(s, 0.0);
                std::uint64_t sum = 0;
                for (int kk = 0; kk < n.z; ++kk)
                    for (int j = 0; j < n.y; ++j)
                        for (int i = 0; i < n.x; ++i) {
                            const glm::dvec3 p = o + h * glm::dvec3(i, j, kk);
                            const glm::dvec3 u = (p - g.origin) / g.cell;
                            if (glm::any(glm::lessThan(u, glm::dvec3(0.0))) || glm::any(glm::greaterThan(u, glm::dvec3(g.dims)))) continue;
                            const glm::ivec3 c = glm::min(glm::ivec3(glm::floor(u)), g.dims - 1);
                            const std::size_t cn = c.x + std::size_t(g.dims.x) * (c.y + std::size_t(g.dims.y) * c.z);
                            sum += g.cell_start[cn + 1] - g.cell_start[cn];
                        }
                CHECK_MESSAGE(evals == sum, str(k) << ": through build_blob_grid(scene, 0) the samples' cells list " << sum
                                                   << " blobs in all; your total is " << evals);
                CHECK_MESSAGE((evals > 0 && evals < std::uint64_t(n.x) * n.y * n.z * s.blobs.size()),
                              str(k) << ": the grid must save evaluations (total " << evals << ")");
            }
        }
    }

    TEST_CASE("grid: bad lattices and cells throw std::invalid_argument" * geolab::points(2) *
              geolab::builds_on("Task 1")) {
        Rng rng(66);
        const BlobScene s = random_scene(rng, Kernel::wyvill, 3);
        std::uint64_t e = 0;
        CHECK_THROWS_AS(sample_lattice(s, glm::dvec3(0.0), 0.0, glm::ivec3(4), e), std::invalid_argument);
        CHECK_THROWS_AS(sample_lattice(s, glm::dvec3(0.0), -1.0, glm::ivec3(4), e), std::invalid_argument);
        CHECK_THROWS_AS(sample_lattice(s, glm::dvec3(0.0), 0.1, glm::ivec3(4, 1, 4), e), std::invalid_argument);
        CHECK_THROWS_AS(sample_lattice(s, glm::dvec3(0.0), 0.1, glm::ivec3(1, 4, 4), e), std::invalid_argument);
        CHECK_THROWS_AS(sample_lattice(s, glm::dvec3(0.0), 0.1, glm::ivec3(4, 4, 1), e), std::invalid_argument);
        CHECK_THROWS_AS(build_blob_grid(s, 1e-6), std::invalid_argument);
        CHECK_MESSAGE(sample_lattice(s, glm::dvec3(0.0), 0.1, glm::ivec3(2, 3, 2), e).values.size() == 12,
                      "n = (2, 3, 2) is the smallest lattice: 12 samples");
        CHECK_MESSAGE(sample_lattice(s, glm::dvec3(0.0), 0.1, glm::ivec3(3, 2, 3), e).values.size() == 18,
                      "n = (3, 2, 3): 18 samples (2 samples along y are allowed)");
        CHECK_MESSAGE(sample_lattice(s, glm::dvec3(0.0), 0.1, glm::ivec3(3, 3, 2), e).values.size() == 18,
                      "n = (3, 3, 2): 18 samples (2 samples along z are allowed)");
        // More than 2^28 samples: refused before allocating (1024 · 1024 · 257 = 2^28 + 2^20).
        CHECK_THROWS_AS(sample_lattice(s, glm::dvec3(0.0), 0.1, glm::ivec3(1024, 1024, 257), e), std::invalid_argument);
        CHECK_THROWS_AS(sample_lattice(s, glm::dvec3(0.0), 0.1, glm::ivec3(257, 1024, 1024), e), std::invalid_argument);
        // More than 2^24 cells (258³ for one blob of R = 1 in cells of 2/257): refused.
        BlobScene one;
        one.blobs.resize(1);
        CHECK_THROWS_AS(build_blob_grid(one, 2.0 / 257), std::invalid_argument);
        // Exactly 2^24 cells is allowed: blobs of R = 1 at x = 0 and x = 2^25 − 2 in cells of 2 give (2^24, 1, 1).
        BlobScene wide;
        wide.blobs.resize(2);
        wide.blobs[1].center.x = 33554430.0;
        const BlobGrid gw = build_blob_grid(wide, 2.0);
        CHECK_MESSAGE(gw.dims == glm::ivec3(16777216, 1, 1), "two blobs 2^25 − 2 apart, cells of 2: exactly 2^24 cells "
                                                             "(allowed), dims (16777216, 1, 1); got (" << gw.dims.x << ", "
                                                             << gw.dims.y << ", " << gw.dims.z << ")");
        BlobScene bad = s;
        bad.blobs[1].radius = 0;
        CHECK_THROWS_AS(build_blob_grid(bad, 0.0), std::invalid_argument);
    }
}
